/* The linear solvers beyond the core's CHOLMOD (factorization.h): the
   Trilinos Amesos solvers, which factorise distributed matrices, and CG
   with Trilinos ML's algebraic multigrid, for meshes whose factor does not
   fit. Each registers itself as a choice of 'Solver/Linear solver'. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_minres.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <core/factorization.h>
#include <core/friction.h>
#include <core/parameters.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <string>

namespace Contact
{
  namespace
  {
    /** The relative residual to which CG-AMG solves with K. */
    constexpr double cg_relative_residual = 1e-12;


    // @sect3{Amesos}

    class AmesosFactorization : public Factorization
    {
    public:
      AmesosFactorization(const std::string                    &solver_name,
                          const TrilinosWrappers::SparseMatrix &K)
        : name(solver_name)
        , control(1, 0)
        , solver(control,
                 TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                                solver_name))
      {
        solver.initialize(K);
      }

      void solve(TrilinosWrappers::MPI::Vector       &x,
                 const TrilinosWrappers::MPI::Vector &b) override
      {
        solver.solve(x, b);
      }

      std::unique_ptr<Factorization>
      for_variant(const TrilinosWrappers::SparseMatrix &variant) const override
      {
        return std::make_unique<AmesosFactorization>(name, variant);
      }

    private:
      const std::string              name;
      SolverControl                  control;
      TrilinosWrappers::SolverDirect solver;
    };


    // @sect3{CG with algebraic multigrid}

    // The relative residual 1e-12 makes the solutions agree with a direct
    // solver's to about 1e-10, the tolerance of the tests that compare
    // them. The AMG hierarchy is that of K (ML, smoothed aggregation,
    // Chebyshev smoothing, the displacement components as constant modes);
    // the variants of the constraints path keep it: CG stays correct with
    // any symmetric positive definite preconditioner, and K' differs from K
    // only in the rows of Gamma_3.
    class CgAmgSolver : public Factorization
    {
      struct PreconditionerWrapper
      {
        const CgAmgSolver &solver;
        void               vmult(TrilinosWrappers::MPI::Vector       &dst,
                                 const TrilinosWrappers::MPI::Vector &src) const
        {
          solver.precondition(dst, src);
        }
      };

    public:
      CgAmgSolver(const TrilinosWrappers::SparseMatrix &K,
                  const std::vector<std::vector<bool>> &constant_modes)
        : matrix(K)
        , preconditioner(std::make_shared<TrilinosWrappers::PreconditionAMG>())
        , total_iterations(std::make_shared<unsigned long int>(0))
      {
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic       = true;
        data.constant_modes = constant_modes;
        preconditioner->initialize(K, data);
      }

      void solve(TrilinosWrappers::MPI::Vector       &x,
                 const TrilinosWrappers::MPI::Vector &b) override
      {
        // x is the initial guess where it has b's layout.
        if (x.size() != b.size() ||
            x.locally_owned_elements() != b.locally_owned_elements() ||
            x.has_ghost_elements())
          x.reinit(b, /*omit_zeroing_entries=*/false);
        const double norm = b.l2_norm();
        if (norm == 0.)
          {
            x = 0.;
            return;
          }
        if (indefinite)
          return solve_by_minres(x, b);
        SolverControl control(10000, cg_relative_residual * norm);
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        try
          {
            cg.solve(matrix, x, b, PreconditionerWrapper{*this});
          }
        catch (const SolverControl::NoConvergence &failure)
          {
            AssertThrow(false,
                        ExcMessage(
                          "CG with AMG ('" + Entry::linear_solver +
                          " = CG-AMG') "
                          "did not reach the relative residual " +
                          number_text(cg_relative_residual) + " in " +
                          std::to_string(failure.last_step) +
                          " iterations (residual " +
                          std::to_string(failure.last_residual / norm) +
                          "); a direct solver (auto) avoids the question."));
          }
        *total_iterations += control.last_step();
      }

      std::unique_ptr<Factorization>
      for_variant(const TrilinosWrappers::SparseMatrix &variant) const override
      {
        return std::unique_ptr<Factorization>(new CgAmgSolver(variant, *this));
      }

      bool solves_indefinite_variants() const override
      {
        return true;
      }

      double relative_residual() const override
      {
        return cg_relative_residual;
      }

      std::unique_ptr<Factorization> for_indefinite_variant(
        const TrilinosWrappers::SparseMatrix &variant) const override
      {
        auto solver        = new CgAmgSolver(variant, *this);
        solver->indefinite = true;
        return std::unique_ptr<Factorization>(solver);
      }

      unsigned long int iterations() const override
      {
        return *total_iterations;
      }

    private:
      CgAmgSolver(const TrilinosWrappers::SparseMatrix &variant,
                  const CgAmgSolver                    &original)
        : matrix(variant)
        , preconditioner(original.preconditioner)
        , total_iterations(original.total_iterations)
      {
        const Epetra_CrsMatrix &epetra = variant.trilinos_matrix();
        for (int row = 0; row < epetra.NumMyRows(); ++row)
          {
            int     length;
            double *values;
            int    *columns;
            epetra.ExtractMyRowView(row, length, values, columns);
            const int diagonal = epetra.LCID(epetra.GRID64(row));
            double    entry    = 0;
            bool      coupled  = false;
            for (int k = 0; k < length; ++k)
              if (columns[k] == diagonal)
                entry = values[k];
              else
                coupled = coupled || (values[k] != 0.);
            if (!coupled)
              decoupled.emplace_back(row, entry);
          }
      }

      // MINRES measures the residual r in the norm of the preconditioner P,
      // (r . P r)^{1/2}; it stops at the relative residual of CG in that
      // norm. A matrix it cannot solve (singular) is reported as not
      // positive definite, which the Newton method answers with another
      // model.
      void solve_by_minres(TrilinosWrappers::MPI::Vector       &x,
                           const TrilinosWrappers::MPI::Vector &b)
      {
        TrilinosWrappers::MPI::Vector preconditioned(b);
        precondition(preconditioned, b);
        SolverControl                               control(10000,
                              cg_relative_residual *
                                std::sqrt(preconditioned * b));
        SolverMinRes<TrilinosWrappers::MPI::Vector> minres(control);
        try
          {
            minres.solve(matrix, x, b, PreconditionerWrapper{*this});
          }
        catch (const SolverControl::NoConvergence &)
          {
            *total_iterations += control.last_step();
            throw ExcIndefiniteNewtonMatrix();
          }
        *total_iterations += control.last_step();
      }

      // The preconditioner of a variant: the AMG of K on the coupled
      // unknowns, the diagonal on the decoupled ones (the sticking dofs of
      // the constraints path, whose rows and columns are zeroed). It is
      // symmetric positive definite, and much closer to the variant than
      // K's AMG alone.
      void precondition(TrilinosWrappers::MPI::Vector       &dst,
                        const TrilinosWrappers::MPI::Vector &src) const
      {
        if (decoupled.empty())
          return preconditioner->vmult(dst, src);
        TrilinosWrappers::MPI::Vector coupled_part(src);
        for (const auto &[row, diagonal] : decoupled)
          coupled_part.trilinos_vector()[0][row] = 0.;
        preconditioner->vmult(dst, coupled_part);
        for (const auto &[row, diagonal] : decoupled)
          dst.trilinos_vector()[0][row] =
            (diagonal != 0. ? src.trilinos_vector()[0][row] / diagonal : 0.);
      }

      const TrilinosWrappers::SparseMatrix              &matrix;
      std::shared_ptr<TrilinosWrappers::PreconditionAMG> preconditioner;
      std::shared_ptr<unsigned long int>                 total_iterations;
      // Solved by MINRES (for_indefinite_variant()).
      bool indefinite = false;
      // Local rows without off-diagonal entries, and their diagonal.
      std::vector<std::pair<int, double>> decoupled;
    };



    // @sect3{The registrations}

    // Amesos takes its solvers by the names that the .prm file uses. The
    // help text of 'Solver/Linear solver' joins the descriptions in the
    // order of the ranks: the first Amesos solver's speaks for all three.
    bool register_amesos(const std::string &name,
                         const unsigned int rank,
                         const std::string &description)
    {
      return LinearSolverRegistry::add(
        {name,
         description,
         rank,
         {},
         [name](const TrilinosWrappers::SparseMatrix &K,
                const std::vector<std::vector<bool>> &)
           -> std::unique_ptr<Factorization> {
           return std::make_unique<AmesosFactorization>(name, K);
         }});
    }

    const bool amesos_registered =
      register_amesos("Amesos_Klu",
                      20,
                      "or a Trilinos Amesos solver (Amesos_Mumps: MUMPS, "
                      "distributed over the processes) factorise K once per "
                      "run;") &&
      register_amesos("Amesos_Mumps", 30, "") &&
      register_amesos("Amesos_Lapack", 40, "");

    const bool cg_amg_registered = LinearSolverRegistry::add(
      {"CG-AMG",
       "CG-AMG: conjugate gradients with Trilinos ML's algebraic multigrid "
       "(built once per run), for meshes whose factor does not fit, relative "
       "residual " +
         number_text(cg_relative_residual) + ".",
       50,
       {},
       [](const TrilinosWrappers::SparseMatrix &K,
          const std::vector<std::vector<bool>> &constant_modes)
         -> std::unique_ptr<Factorization> {
         return std::make_unique<CgAmgSolver>(K, constant_modes);
       }});
  } // namespace
} // namespace Contact
