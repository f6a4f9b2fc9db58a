/* The path 'constraints' of 'Solver/Contact solver' between the body and
   the friction problem on Gamma_3 (ContactPath, friction_solver.h): the
   active set as constraints on the whole body, a solve with a variant of K
   per Newton step and no dense matrix. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <base/dimensions.h>
#include <core/friction_solver.h>

#include <Epetra_CrsMatrix.h>

#include <deque>
#include <string>
#include <utility>

namespace Contact
{
  namespace
  {
    // @sect3{The active set as constraints on the whole body}

    // The sticking dofs held at zero, symmetrically: their rows and columns
    // of the matrix are zeroed except the diagonal, their right-hand side
    // entries too. Each process edits the rows it owns (the columns of a
    // sticking dof lie in other processes' rows as well).
    void zero_rows_and_columns(const std::vector<bool> &fixed,
                               MatrixType              &matrix,
                               VectorType              &rhs)
    {
      // Epetra's views of the local rows: deal.II's entry iterator copies
      // a row per access and is far too slow for a pass over all rows.
      auto &epetra = const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
      for (int local_row = 0; local_row < epetra.NumMyRows(); ++local_row)
        {
          const auto row =
            static_cast<types::global_dof_index>(epetra.GRID64(local_row));
          int     length;
          double *values;
          int    *columns;
          epetra.ExtractMyRowView(local_row, length, values, columns);
          for (int k = 0; k < length; ++k)
            {
              const auto column = static_cast<types::global_dof_index>(
                epetra.ColMap().GID64(columns[k]));
              if (column != row && (fixed[row] || fixed[column]))
                values[k] = 0.;
            }
          if (fixed[row])
            rhs[row] = 0.;
        }
      rhs.compress(VectorOperation::insert);
    }


    // The slip nodes whose slope is steeper than the definite one: those
    // that the Newton matrix with the true slopes adds to H_d's.
    std::vector<unsigned int>
    steep_nodes(const std::vector<NodeLinearisation> &linearisation)
    {
      std::vector<unsigned int> steep;
      for (unsigned int p = 0; p < linearisation.size(); ++p)
        if (linearisation[p].state == NodeState::slip &&
            linearisation[p].bound > 0 &&
            linearisation[p].slope < linearisation[p].definite_slope)
          steep.push_back(p);
      return steep;
    }


    // The straightforward path of 'Solver/Contact solver = constraints':
    // every Newton step of the methods on Gamma_3 is a solve on the whole
    // body, with the sticking nodes held fixed as constraints and the
    // matrix refactorised (or, with CG-AMG, its preconditioner adapted). It
    // needs neither Z nor the Delassus operator, so its memory is that of K
    // and one factor; it is the reference the Delassus paths are tested
    // against (tests/verification/contact_solver_paths) and the path for
    // meshes where Z does not fit.
    template <int dim>
    class ActiveSetAsConstraints : public ContactPath<dim>
    {
    public:
      ActiveSetAsConstraints(const ContactBoundary<dim> &boundary,
                             const MatrixType           &matrix_K,
                             Factorization              &factorization_of_K)
        : gamma3(boundary)
        , system_matrix(matrix_K)
        , factorization(factorization_of_K)
      {}

      void begin_step(const VectorType &step_rhs,
                      const VectorType &last_velocity) override
      {
        // D eta = v_free - v for the last step's final forces, if it
        // formed its v_free (K does not change while the path lives).
        if (v_free.size() > 0 && last_force.size() > 0)
          {
            last_step_force        = last_force;
            delassus_of_last_force = v_free;
            delassus_of_last_force -= last_slip_velocity;
          }
        else
          last_step_force.reinit(0);
        recent_newton_solves.clear();
        rhs                        = step_rhs;
        start                      = last_velocity;
        this->solves               = 0;
        this->substitution_seconds = 0;
        v_free.reinit(0);
      }

      // Formed only when asked for, by the convexification (Newton's method
      // measures E without it).
      const Vector<double> &free_slip_velocity() override
      {
        if (v_free.size() == 0)
          {
            VectorType w;
            velocity(Vector<double>(gamma3.n_unknowns()), w);
            v_free = gamma3.tangential_velocities(w);
          }
        return v_free;
      }

      // The last step's final forces (where the convexification starts)
      // cost no solve beyond v_free where that step formed its v_free: D eta
      // is then known from it.
      void velocity_of_force(const Vector<double> &eta,
                             Vector<double>       &v) override
      {
        if (last_step_force.size() > 0 && eta == last_step_force)
          {
            v = free_slip_velocity();
            v -= delassus_of_last_force;
            return;
          }
        VectorType w;
        velocity(eta, w);
        v = last_slip_velocity;
      }

      void newton_step(const std::vector<NodeLinearisation> &linearisation,
                       Vector<double>                       &eta,
                       Vector<double>                       &v) override;

      // (5.2) with the friction term C^T eta moved to the right-hand side,
      //   K w = step_rhs - C^T eta,
      // or the velocity a recent Newton step found for these forces. The
      // step's last call is for its final forces: they and their slip
      // velocity are kept for the next step.
      void velocity(const Vector<double> &eta, VectorType &w) override
      {
        last_force = eta;
        for (const auto &[newton_force, newton_velocity] : recent_newton_solves)
          if (newton_force == eta)
            {
              w                  = newton_velocity;
              last_slip_velocity = gamma3.tangential_velocities(w);
              return;
            }
        VectorType load(rhs);
        load.add(-1., gamma3.friction_load(eta));
        w = start;
        solve(factorization, w, load);
        last_slip_velocity = gamma3.tangential_velocities(w);
      }

      void apply_delassus(const Vector<double> &x, Vector<double> &y) override
      {
        VectorType w(gamma3.locally_owned_dofs, gamma3.mpi_communicator);
        factorization.solve(w, gamma3.friction_load(x));
        gamma3.constraints.distribute(w);
        y = gamma3.tangential_velocities(w);
      }

      std::string description() const override
      {
        return "active set as constraints, one solve with K per Newton step";
      }

      double free_slip_speed() const override
      {
        return v_free.size() > 0 ? v_free.linfty_norm() : 0.;
      }

      // Every iterate is a solve of its own: with CG-AMG E differs by the
      // solves' error, about their relative residual (on the 3D scene at
      // h = k = 1/16 the round-off allowance made Newton damp three more
      // steps near the solution than the Delassus path).
      double energy_accuracy() const override
      {
        return std::max(energy_round_off, factorization.relative_residual());
      }

      // H is positive definite iff the capacitance matrix of its Woodbury
      // form is (see definite_newton_system()): |B| solves with H_d.
      Curvature curvature_on_slip_set(
        const std::vector<NodeLinearisation> &linearisation) override
      {
        const DefiniteNewtonSystem system =
          definite_newton_system(linearisation);
        if (system.steep.empty())
          return Curvature::positive;
        return definiteness(system.capacitance);
      }

    private:
      // The matrix and right-hand side of a Newton step (see newton_step())
      // with every slope at least its definite_slope, the forces along
      // zhat it puts on the slip nodes and the dofs it holds fixed.
      void assemble_newton_system(
        const std::vector<NodeLinearisation> &linearisation,
        const bool                            true_slopes,
        MatrixType                           &matrix,
        Vector<double>                       &slip_force,
        VectorType                           &load,
        std::vector<bool>                    &stick_dof) const;

      // The Newton matrix H_d with every slope at least definite_slope and
      // its solver, and what the Woodbury form of the matrix H with the
      // true slopes needs (see definite_newton_system()).
      struct DefiniteNewtonSystem
      {
        // Held by address: CG's variant keeps a reference to it.
        std::unique_ptr<MatrixType>    matrix;
        std::unique_ptr<Factorization> solver;
        Vector<double>                 slip_force;
        VectorType                     load;
        std::vector<unsigned int>      steep;
        std::vector<VectorType>        responses;
        LAPACKFullMatrix<double>       capacitance;
      };
      DefiniteNewtonSystem definite_newton_system(
        const std::vector<NodeLinearisation> &linearisation);

      void add_woodbury_correction(
        const std::vector<NodeLinearisation> &linearisation,
        DefiniteNewtonSystem                 &system,
        VectorType                           &w) const;

      // The slip velocities along zhat of the given nodes.
      Vector<double>
      velocity_along_slip(const std::vector<NodeLinearisation> &linearisation,
                          const std::vector<unsigned int>      &nodes,
                          const VectorType                     &w) const;

      // w = K'^{-1} load for K or a variant K', counted, and timed if it is
      // the step's first solve.
      void solve(Factorization &solver, VectorType &w, const VectorType &load)
      {
        Timer timer;
        solver.solve(w, load);
        if (this->solves++ == 0)
          this->substitution_seconds = timer.wall_time();
        gamma3.constraints.distribute(w);
      }

      const ContactBoundary<dim> &gamma3;
      const MatrixType           &system_matrix;
      Factorization              &factorization;
      VectorType                  rhs;
      Vector<double>              v_free;
      // Where CG starts: w_{n-1}, then the newest Newton step's velocity.
      VectorType start;
      // The forces of the last call of velocity() and their slip velocity;
      // the last step's final forces and D times them.
      Vector<double> last_force, last_slip_velocity;
      Vector<double> last_step_force, delassus_of_last_force;
      // The forces and velocities of the step's last Newton steps: the
      // methods on Gamma_3 ask again for the velocity of forces a Newton
      // step gave (the final forces, the start of a convexification step),
      // which then needs no solve; CG starts from the newest velocity.
      std::deque<std::pair<Vector<double>, VectorType>> recent_newton_solves;
    };


    // One Newton step of the method of friction.h on the whole body, for
    // the linearisation of every node:
    // - a sticking node has v_p = 0; with w.n = 0 from the bilateral
    //   constraint that is w_p = 0, imposed by zeroing the rows and columns
    //   of the node's free dofs (keeping the diagonal, so K stays SPD);
    // - a slipping node carries the force (force_p + slope_p zhat.v) zhat
    //   (force_p = g_p, slope_p = 0 for the Tresca problem; the tangent of
    //   g_p(|v_p|) for the full law): a load force_p zhat and a spring
    //   slope_p zhat zhat^T added to K at the node (assembled with the
    //   slope capped at definite_slope, so that the matrix stays positive
    //   definite; definite_newton_system() adds the rest); in 3D also the
    //   condition v.t = beta eta.t along the other tangent t = zhat turned
    //   by 90 degrees, i.e. eta.t = (v.t) / beta: a spring (1 / beta) t t^T.
    // This is the system (D + beta)_FF eta_F = ... of the Delassus path
    // before the body's unknowns are eliminated, so both give the same
    // iterates. The friction force of a sticking node is then its reaction,
    // the residual of the unconstrained equations at the node projected on
    // its tangents (the residual is C^T eta there and nothing else, since
    // only the node's own column of C^T has support at it).
    template <int dim>
    void ActiveSetAsConstraints<dim>::assemble_newton_system(
      const std::vector<NodeLinearisation> &linearisation,
      const bool                            true_slopes,
      MatrixType                           &matrix,
      Vector<double>                       &slip_force,
      VectorType                           &load,
      std::vector<bool>                    &stick_dof) const
    {
      const unsigned int n = gamma3.nodes.size(), m = dim - 1;
      matrix.copy_from(system_matrix);
      slip_force.reinit(n * m);
      stick_dof.assign(system_matrix.m(), false);
      std::vector<types::global_dof_index> node_dofs(dim);
      for (unsigned int p = 0; p < n; ++p)
        {
          const ContactNode<dim> &node = gamma3.nodes[p];
          if (linearisation[p].state == NodeState::stick)
            {
              // Its constrained (normal) dof has a trivial row and column
              // in the condensed K already, so all its dofs can be marked.
              for (const types::global_dof_index dof : node.dofs)
                stick_dof[dof] = true;
              continue;
            }
          const NodeLinearisation &slip  = linearisation[p];
          const FullMatrix<double> basis = local_basis(slip);
          for (unsigned int i = 0; i < m; ++i)
            slip_force[p * m + i] = slip.force * basis(i, 0);
          if (slip.bound == 0. || !node.locally_owned)
            continue;
          // The springs: slope zhat zhat^T (the full law; negative for a
          // weakening law) and (1 / beta) t t^T along the other tangent.
          std::array<Tensor<1, dim>, dim - 1> directions;
          for (unsigned int j = 0; j < m; ++j)
            for (unsigned int i = 0; i < m; ++i)
              directions[j] += basis(i, j) * node.tangents[i];
          FullMatrix<double> spring(dim, dim);
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              {
                spring(a, b) =
                  (true_slopes ? slip.slope :
                                 std::max(slip.slope, slip.definite_slope)) *
                  directions[0][a] * directions[0][b];
                if (m == 2)
                  spring(a, b) +=
                    directions[1][a] * directions[1][b] / slip.beta;
              }
          std::copy(node.dofs.begin(), node.dofs.end(), node_dofs.begin());
          gamma3.constraints.distribute_local_to_global(spring,
                                                        node_dofs,
                                                        matrix);
        }
      matrix.compress(VectorOperation::add);

      load.add(-1., gamma3.friction_load(slip_force));
      zero_rows_and_columns(stick_dof, matrix, load);
    }


    // The Newton matrix with the true slopes is H = H_d - Z Delta Z^T,
    // where H_d (slopes capped at definite_slope) is positive definite, B
    // are the slip nodes whose slope is steeper, Delta = diag(definite_slope
    // - slope) on them and the column z_b of Z is the load of a unit force
    // along zhat_b. By the Sherman-Morrison-Woodbury formula
    //   H^{-1} load = w + Y (Delta^{-1} - Z^T Y)^{-1} Z^T w,
    // w = H_d^{-1} load, Y = H_d^{-1} Z: |B| more solves, all with the
    // positive definite H_d (never CG on an indefinite matrix), and Z^T w
    // is the slip velocity along zhat. H is itself positive definite iff
    // the capacitance matrix Delta^{-1} - Z^T Y is (Haynsworth's inertia
    // formula for the block matrix [H_d, Z; Z^T, Delta^{-1}]); it is
    // invertible unless H is singular. A solver that refuses H_d (CHOLMOD,
    // if the convexity limit was overestimated by more than the cap's
    // margin) throws ExcIndefiniteNewtonMatrix.
    template <int dim>
    typename ActiveSetAsConstraints<dim>::DefiniteNewtonSystem
    ActiveSetAsConstraints<dim>::definite_newton_system(
      const std::vector<NodeLinearisation> &linearisation)
    {
      const unsigned int   n = gamma3.nodes.size(), m = dim - 1;
      DefiniteNewtonSystem system;
      std::vector<bool>    stick_dof;
      system.matrix = std::make_unique<MatrixType>();
      system.load   = rhs;
      assemble_newton_system(linearisation,
                             false,
                             *system.matrix,
                             system.slip_force,
                             system.load,
                             stick_dof);
      try
        {
          system.solver = factorization.for_variant(*system.matrix);
        }
      catch (const ExceptionBase &)
        {
          if (!factorization.has_triangular_factor())
            throw;
          throw ExcIndefiniteNewtonMatrix();
        }

      system.steep               = steep_nodes(linearisation);
      const unsigned int n_steep = system.steep.size();
      system.responses.resize(n_steep);
      system.capacitance.reinit(n_steep, n_steep);
      for (unsigned int b = 0; b < n_steep; ++b)
        {
          const NodeLinearisation &node = linearisation[system.steep[b]];
          Vector<double>           unit(n * m);
          for (unsigned int i = 0; i < m; ++i)
            unit[system.steep[b] * m + i] = node.direction[i];
          VectorType load = gamma3.friction_load(unit);
          for (const auto row : gamma3.locally_owned_dofs)
            if (stick_dof[row])
              load[row] = 0.;
          load.compress(VectorOperation::insert);
          system.responses[b].reinit(gamma3.locally_owned_dofs,
                                     gamma3.mpi_communicator);
          solve(*system.solver, system.responses[b], load);
          const Vector<double> column =
            velocity_along_slip(linearisation,
                                system.steep,
                                system.responses[b]);
          for (unsigned int a = 0; a < n_steep; ++a)
            system.capacitance(a, b) = -column[a];
          system.capacitance(b, b) += 1. / (node.definite_slope - node.slope);
        }
      return system;
    }


    template <int dim>
    Vector<double> ActiveSetAsConstraints<dim>::velocity_along_slip(
      const std::vector<NodeLinearisation> &linearisation,
      const std::vector<unsigned int>      &nodes,
      const VectorType                     &w) const
    {
      const unsigned int   m        = dim - 1;
      const Vector<double> velocity = gamma3.tangential_velocities(w);
      Vector<double>       result(nodes.size());
      for (unsigned int a = 0; a < nodes.size(); ++a)
        for (unsigned int i = 0; i < m; ++i)
          result[a] +=
            linearisation[nodes[a]].direction[i] * velocity[nodes[a] * m + i];
      return result;
    }


    // w += Y (Delta^{-1} - Z^T Y)^{-1} Z^T w: w = H_d^{-1} load becomes
    // H^{-1} load (see definite_newton_system()).
    template <int dim>
    void ActiveSetAsConstraints<dim>::add_woodbury_correction(
      const std::vector<NodeLinearisation> &linearisation,
      DefiniteNewtonSystem                 &system,
      VectorType                           &w) const
    {
      if (system.steep.empty())
        return;
      Vector<double> coefficients =
        velocity_along_slip(linearisation, system.steep, w);
      // Singular only where H is: no Newton step there.
      try
        {
          system.capacitance.compute_lu_factorization();
        }
      catch (const ExceptionBase &)
        {
          throw ExcIndefiniteNewtonMatrix();
        }
      system.capacitance.solve(coefficients);
      for (unsigned int b = 0; b < system.steep.size(); ++b)
        w.add(coefficients[b], system.responses[b]);
    }


    template <int dim>
    void ActiveSetAsConstraints<dim>::newton_step(
      const std::vector<NodeLinearisation> &linearisation,
      Vector<double>                       &eta,
      Vector<double>                       &v)
    {
      const unsigned int n = gamma3.nodes.size(), m = dim - 1;
      Vector<double>     slip_force;
      VectorType         w(start);
      if (!steep_nodes(linearisation).empty() &&
          factorization.solves_indefinite_variants())
        {
          // H itself, solved by MINRES: one solve instead of |B| + 1.
          MatrixType        matrix;
          VectorType        load(rhs);
          std::vector<bool> stick_dof;
          assemble_newton_system(
            linearisation, true, matrix, slip_force, load, stick_dof);
          solve(*factorization.for_indefinite_variant(matrix), w, load);
        }
      else
        {
          DefiniteNewtonSystem system = definite_newton_system(linearisation);
          slip_force                  = system.slip_force;
          solve(*system.solver, w, system.load);
          add_woodbury_correction(linearisation, system, w);
        }
      v = gamma3.tangential_velocities(w);

      VectorType residual(rhs);
      VectorType product(gamma3.locally_owned_dofs, gamma3.mpi_communicator);
      system_matrix.vmult(product, w);
      residual -= product;
      gamma3.constraints.set_zero(residual);
      eta = gamma3.tangential_velocities(residual);

      // On slip nodes eta is set from the linearisation, exactly as on the
      // Delassus path, rather than read back from the residual.
      for (unsigned int p = 0; p < n; ++p)
        if (linearisation[p].state == NodeState::slip)
          {
            const NodeLinearisation &slip  = linearisation[p];
            const FullMatrix<double> basis = local_basis(slip);
            // v in the local basis (zhat, t).
            std::array<double, dim - 1> local_v{};
            for (unsigned int j = 0; j < m; ++j)
              for (unsigned int i = 0; i < m; ++i)
                local_v[j] += basis(i, j) * v[p * m + i];
            for (unsigned int i = 0; i < m; ++i)
              {
                eta[p * m + i] = slip_force[p * m + i];
                if (slip.bound == 0.)
                  continue;
                eta[p * m + i] += basis(i, 0) * slip.slope * local_v[0];
                if (m == 2)
                  eta[p * m + i] += basis(i, 1) * local_v[1] / slip.beta;
              }
          }
        else
          for (unsigned int i = 0; i < m; ++i)
            v[p * m + i] = 0.;

      // Three: a convexification step inside the Newton method starts from
      // the iterate before a failed step and a failed step of the other
      // model.
      start = w;
      recent_newton_solves.emplace_back(eta, std::move(w));
      if (recent_newton_solves.size() > 3)
        recent_newton_solves.pop_front();
    }
  } // namespace


  namespace
  {
    // Rank 20: after the core's Delassus path in the Selection and the
    // help text.
    template <int dim>
    bool register_constraints_path()
    {
      return ContactPathRegistry<dim>::add(
        {"constraints",
         "the straightforward path; every Newton step of the active set "
         "method solves on the whole body with the sticking nodes held fixed "
         "as constraints, and refactorises; no D.",
         20,
         {},
         [](const ContactBoundary<dim> &gamma3,
            const MatrixType           &system_matrix,
            Factorization              &factorization,
            TimerOutput &) -> std::unique_ptr<ContactPath<dim>> {
           return std::make_unique<ActiveSetAsConstraints<dim>>(gamma3,
                                                                system_matrix,
                                                                factorization);
         }});
    }

#define REGISTER(dim)                            \
  const bool constraints_path_registered_##dim = \
    register_constraints_path<dim>();
    CONTACT_INSTANTIATE(REGISTER)
#undef REGISTER
  } // namespace
} // namespace Contact
