/* The two Delassus paths of 'Solver/Contact solver' between the body and
   the friction problem on Gamma_3 (friction_solver.h): D = C K^{-1} C^T
   from the triangular factor of K, or from the columns of K^{-1} C^T. */

#include <deal.II/base/exceptions.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <base/dimensions.h>
#include <core/delassus_operator.h>
#include <core/friction_solver.h>

#include <string>
#include <utility>

namespace Contact
{
  namespace
  {
    // @sect3{The Delassus paths}

    // What both Delassus paths do on Gamma_3 alone: v = v_free - D eta and
    // the Newton steps of DelassusOperator, for the step's v_free.
    template <int dim>
    class DelassusPath : public ContactPath<dim>
    {
    public:
      void velocity_of_force(const Vector<double> &eta,
                             Vector<double>       &v) override
      {
        delassus.vmult(v, eta);
        v.sadd(-1., 1., v_free);
      }

      void newton_step(const std::vector<NodeLinearisation> &linearisation,
                       Vector<double>                       &eta,
                       Vector<double>                       &v) override
      {
        delassus.newton_step(linearisation, v_free, eta, v);
      }

      void apply_delassus(const Vector<double> &x, Vector<double> &y) override
      {
        delassus.vmult(y, x);
      }

      double free_slip_speed() const override
      {
        return v_free.linfty_norm();
      }

      Curvature curvature_on_slip_set(
        const std::vector<NodeLinearisation> &linearisation) override
      {
        return delassus.curvature_on_slip_set(linearisation);
      }

      // Formed by begin_step(): every Newton step on D needs it.
      const Vector<double> &free_slip_velocity() override
      {
        return v_free;
      }

    protected:
      DelassusOperator delassus;
      Vector<double>   v_free;
    };


    // @sect3{The Delassus operator from the triangular factor of K}

    // The friction forces act on the body through C^T eta, and the velocity
    // of a step is
    //   w_n = K^{-1} (step_rhs - C^T eta),
    //   step_rhs = F_n + (1/k) M w_{n-1} - B u_{n-1},
    // so on Gamma_3 v = C w_n = v_free - D eta with the Delassus operator
    // D = C K^{-1} C^T, symmetric positive definite: the nonsmooth part of
    // every step lives on the few unknowns of Gamma_3 (doc/algorithm.md).
    //
    // With CHOLMOD's K = P^T L L^T P and Y = L^{-1} P C^T,
    //   D = Y^T Y,  v_free = Y^T y,  w_n = P^T L^{-T} (y - Y eta),
    // where y = L^{-1} P step_rhs: a step is one forward substitution, the
    // friction problem, and one backward substitution, i.e. one solve. Y is
    // sparse (column p is nonzero only on the elimination tree path from
    // node p's dofs to the root, a few separators), unlike K^{-1} C^T,
    // which is dense; it is stored transposed, as a sparse matrix with one
    // row per tangential unknown of Gamma_3.
    template <int dim>
    class DelassusFromFactor : public DelassusPath<dim>
    {
    public:
      DelassusFromFactor(const ContactBoundary<dim> &boundary,
                         Factorization              &factorization_of_K)
        : gamma3(boundary)
        , factorization(factorization_of_K)
      {
        const unsigned int n_columns = gamma3.n_unknowns();
        const unsigned int block     = 64;
        std::vector<std::vector<std::pair<unsigned int, double>>> columns_of_Y(
          n_columns);
        Vector<double> unit(n_columns);
        for (unsigned int first = 0; first < n_columns; first += block)
          {
            const unsigned int      size = std::min(block, n_columns - first);
            std::vector<VectorType> loads(size);
            std::vector<Vector<double>> columns;
            for (unsigned int c = 0; c < size; ++c)
              {
                unit[first + c] = 1.;
                loads[c]        = gamma3.friction_load(unit);
                unit[first + c] = 0.;
              }
            factorization.forward_substitution(columns, loads);
            for (unsigned int c = 0; c < size; ++c)
              for (unsigned int row = 0; row < columns[c].size(); ++row)
                if (columns[c][row] != 0.)
                  columns_of_Y[first + c].emplace_back(row, columns[c][row]);
          }

        const unsigned int n_rows = gamma3.locally_owned_dofs.n_elements();
        {
          DynamicSparsityPattern pattern(n_columns, n_rows);
          for (unsigned int s = 0; s < n_columns; ++s)
            for (const auto &entry : columns_of_Y[s])
              pattern.add(s, entry.first);
          factor_pattern.copy_from(pattern);
        }
        Y_transposed.reinit(factor_pattern);
        for (unsigned int s = 0; s < n_columns; ++s)
          for (const auto &[row, value] : columns_of_Y[s])
            Y_transposed.set(s, row, value);

        // D = Y^T Y, each entry once, so D is exactly symmetric.
        FullMatrix<double> D(n_columns, n_columns);
        Vector<double>     column(n_rows);
        for (unsigned int s = 0; s < n_columns; ++s)
          {
            for (const auto &[row, value] : columns_of_Y[s])
              column[row] = value;
            for (unsigned int r = 0; r <= s; ++r)
              {
                double entry = 0;
                for (const auto &[row, value] : columns_of_Y[r])
                  entry += value * column[row];
                D(r, s) = D(s, r) = entry;
              }
            for (const auto &[row, value] : columns_of_Y[s])
              column[row] = 0.;
          }
        this->delassus = DelassusOperator(D, dim - 1);
      }

      void begin_step(const VectorType &step_rhs, const VectorType &) override
      {
        Timer substitution;
        this->solves = 1;
        factorization.forward_substitution(y, {step_rhs});
        this->substitution_seconds = substitution.wall_time();
        this->v_free.reinit(gamma3.n_unknowns());
        Y_transposed.vmult(this->v_free, y[0]);
      }


      void velocity(const Vector<double> &eta, VectorType &w) override
      {
        Vector<double> minus_eta(eta);
        minus_eta *= -1.;
        Y_transposed.Tvmult_add(y[0], minus_eta);
        Timer substitution;
        factorization.backward_substitution(w, y[0]);
        this->substitution_seconds += substitution.wall_time();
        gamma3.constraints.distribute(w);
      }


      std::string description() const override
      {
        return "Delassus operator on the " +
               std::to_string(gamma3.n_unknowns()) +
               " tangential unknowns of Gamma_3, from the triangular factor "
               "of K";
      }

    private:
      const ContactBoundary<dim> &gamma3;
      Factorization              &factorization;
      SparsityPattern             factor_pattern;
      SparseMatrix<double>        Y_transposed;
      // The step's forward substitution y (v_free = Y^T y).
      std::vector<Vector<double>> y;
    };


    // @sect3{The Delassus operator from the columns of K^{-1} C^T}

    // Without a triangular factor (Amesos solvers, several processes), D
    // comes from the columns of Z = K^{-1} C^T, one solve each, kept as one
    // dense block over the locally owned unknowns: a step is then one solve
    // for w_free, the friction problem on Gamma_3 with v_free = C w_free,
    // and w_n = w_free - Z eta, one gemv (doc/algorithm.md).
    template <int dim>
    class DelassusFromSolves : public DelassusPath<dim>
    {
    public:
      DelassusFromSolves(const ContactBoundary<dim> &boundary,
                         Factorization              &factorization_of_K)
        : gamma3(boundary)
        , factorization(factorization_of_K)
      {
        const unsigned int n_columns = gamma3.n_unknowns();
        Z.reinit(gamma3.locally_owned_dofs.n_elements(), n_columns);
        FullMatrix<double> D(n_columns, n_columns);
        Vector<double>     unit(n_columns);
        VectorType column(gamma3.locally_owned_dofs, gamma3.mpi_communicator);
        for (unsigned int s = 0; s < n_columns; ++s)
          {
            unit[s] = 1.;
            factorization.solve(column, gamma3.friction_load(unit));
            unit[s] = 0.;
            gamma3.constraints.distribute(column);
            const Vector<double> v = gamma3.tangential_velocities(column);
            for (unsigned int r = 0; r < n_columns; ++r)
              D(r, s) = v[r];
            unsigned int row = 0;
            for (const double value : column)
              Z(row++, s) = value;
          }
        make_symmetric(D);
        this->delassus = DelassusOperator(D, dim - 1);
      }

      void begin_step(const VectorType &step_rhs,
                      const VectorType &last_velocity) override
      {
        Timer substitution;
        this->solves  = 1;
        free_velocity = last_velocity;
        factorization.solve(free_velocity, step_rhs);
        this->substitution_seconds = substitution.wall_time();
        gamma3.constraints.distribute(free_velocity);
        this->v_free = gamma3.tangential_velocities(free_velocity);
      }


      // w -= Z eta on this process's unknowns (Z's columns are distributed
      // already).
      void velocity(const Vector<double> &eta, VectorType &w) override
      {
        w = free_velocity;
        Vector<double> change(gamma3.locally_owned_dofs.n_elements());
        Z.vmult(change, eta);
        auto value = w.begin();
        for (const double c : change)
          *value++ -= c;
      }


      std::string description() const override
      {
        return "Delassus operator on the " +
               std::to_string(gamma3.n_unknowns()) +
               " tangential unknowns of Gamma_3, from Z = K^{-1} C^T";
      }

    private:
      // D is symmetric up to the round-off of the solves; the active set
      // method relies on it (Cholesky on the stick set), so it is made
      // exactly symmetric after checking that nothing more than round-off
      // is removed.
      static void make_symmetric(FullMatrix<double> &D)
      {
        double asymmetry = 0, largest = 0;
        for (unsigned int r = 0; r < D.m(); ++r)
          {
            largest = std::max(largest, D(r, r));
            for (unsigned int s = 0; s < r; ++s)
              {
                const double mean = (D(r, s) + D(s, r)) / 2;
                asymmetry = std::max(asymmetry, std::abs(D(r, s) - mean));
                D(r, s) = D(s, r) = mean;
              }
          }
        AssertThrow(asymmetry <= 1e-8 * largest,
                    ExcMessage(
                      "The Delassus operator C K^{-1} C^T is not "
                      "symmetric beyond round-off (largest deviation " +
                      number_text(asymmetry / largest) +
                      " of its largest entry): the solves with K are "
                      "not accurate enough for the Delassus path; "
                      "choose '" +
                      Entry::contact_solver + " = constraints'."));
      }

      const ContactBoundary<dim> &gamma3;
      Factorization              &factorization;
      LAPACKFullMatrix<double>    Z;
      VectorType                  free_velocity;
    };
  } // namespace


  namespace
  {
    // The path 'Delassus', the core's: D from the triangular factor of K
    // if it has one, else from the columns of K^{-1} C^T. Rank 10: before
    // the other paths in the Selection and the help text.
    template <int dim>
    bool register_delassus_path()
    {
      return ContactPathRegistry<dim>::add(
        {delassus_path_name,
         "on the tangential unknowns of Gamma_3 alone, with the dense "
         "Delassus operator D = C K^{-1} C^T built once per run: from "
         "Y = L^{-1} P C^T (sparse; K = P^T L L^T P by CHOLMOD), a step then "
         "costs one forward and one backward substitution and dense work on "
         "Gamma_3; with the other linear solvers from Z = K^{-1} C^T (dense, "
         "one solve per tangential unknown of Gamma_3), a step then costs one "
         "solve and a product with Z.",
         10,
         {},
         [](const ContactBoundary<dim> &gamma3,
            const MatrixType &,
            Factorization &factorization,
            TimerOutput &computing_timer) -> std::unique_ptr<ContactPath<dim>> {
           TimerOutput::Scope t(computing_timer, "Delassus operator");
           if (factorization.has_triangular_factor())
             return std::make_unique<DelassusFromFactor<dim>>(gamma3,
                                                              factorization);
           return std::make_unique<DelassusFromSolves<dim>>(gamma3,
                                                            factorization);
         }});
    }

#define REGISTER(dim) \
  const bool delassus_path_registered_##dim = register_delassus_path<dim>();
    CONTACT_INSTANTIATE(REGISTER)
#undef REGISTER
  } // namespace
} // namespace Contact
