/**
 * The solver of K = (1/k) M + A_h + k B_h, set up once per run, and its
 * forward/back substitutions (doc/algorithm.md): one interface, whose
 * implementations are the linear solvers registered as the choices of
 * 'Solver/Linear solver' (base/parts.h):
 *
 * - CHOLMOD (SuiteSparse), the core's: supernodal sparse Cholesky with
 *   BLAS-3 kernels, for one process. K is symmetric positive definite (the
 *   constraints are condensed symmetrically), so Cholesky applies. It
 *   exposes the halves of a solve with its factor L, and the forward one
 *   runs on blocks of right-hand sides, which is how Y = L^{-1} P C^T is
 *   computed.
 * - the part parts/linear_solvers: Trilinos Amesos (KLU, MUMPS, LAPACK)
 *   through deal.II's SolverDirect, for distributed matrices, and CG
 *   preconditioned by Trilinos ML's algebraic multigrid (CG-AMG): not a
 *   factorisation but the same interface, for meshes whose factor does not
 *   fit; the AMG hierarchy of K is built once per run.
 */
#ifndef contact_factorization_h
#define contact_factorization_h

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <base/parts.h>
#include <core/parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace Contact
{
  using namespace dealii;

  class Factorization
  {
  public:
    virtual ~Factorization() = default;

    /** x = K^{-1} b; an iterative solver starts from x where x has the
     *  layout of b. */
    virtual void solve(TrilinosWrappers::MPI::Vector       &x,
                       const TrilinosWrappers::MPI::Vector &b) = 0;

    /**
     * Whether the factorisation is K = P^T L L^T P with its triangular
     * factor L at hand (CHOLMOD). A solve is then a forward substitution
     * y = L^{-1} P b followed by a backward one, x = P^T L^{-T} y, and the
     * Delassus path works between the two halves (delassus_paths.cc).
     */
    virtual bool has_triangular_factor() const
    {
      return false;
    }

    /** y_i = L^{-1} P b_i for a block of right-hand sides. */
    virtual void
    forward_substitution(std::vector<Vector<double>>                      &y,
                         const std::vector<TrilinosWrappers::MPI::Vector> &b);

    /** x = P^T L^{-T} y. */
    virtual void backward_substitution(TrilinosWrappers::MPI::Vector &x,
                                       const Vector<double>          &y);

    /** Number of nonzeros of the factor, 0 where the solver does not
     *  tell. */
    virtual double factor_size() const
    {
      return 0;
    }

    /**
     * The solver of the same kind for a matrix K' that differs from K near
     * Gamma_3 only (the Newton steps of the constraints path): a direct
     * solver factorises K', CG-AMG keeps the AMG hierarchy of K.
     */
    virtual std::unique_ptr<Factorization>
    for_variant(const TrilinosWrappers::SparseMatrix &variant) const = 0;

    /**
     * A solver for a symmetric variant K' that may be indefinite (the
     * Newton matrix of the constraints path with the true weakening
     * slopes), where this solver has one: MINRES with the preconditioner of
     * CG-AMG's variants, which MINRES needs symmetric positive definite and
     * which they are. Only where solves_indefinite_variants(): the direct
     * solvers factorise without pivoting for indefiniteness (CHOLMOD refuses
     * an indefinite matrix).
     */
    virtual std::unique_ptr<Factorization>
    for_indefinite_variant(const TrilinosWrappers::SparseMatrix &variant) const;

    virtual bool solves_indefinite_variants() const
    {
      return false;
    }

    /** The relative residual at which a solve stops; 0 for the direct
     *  solvers. */
    virtual double relative_residual() const
    {
      return 0.;
    }

    /** Iterations of the iterative solver (CG-AMG) so far, summed over
     *  this solver and its variants; 0 for direct solvers. */
    virtual unsigned long int iterations() const
    {
      return 0;
    }

    /**
     * The registered linear solver `solver` ('auto' resolved) for K; the
     * constant modes (one per displacement component) tell an algebraic
     * multigrid the near null space of elasticity.
     */
    static std::unique_ptr<Factorization>
    create(const std::string                    &solver,
           const TrilinosWrappers::SparseMatrix &K,
           const std::vector<std::vector<bool>> &constant_modes = {});
  };


  /** The kind of the linear solvers (base/parts.h): a solver for K made
   *  from K and its constant modes. */
  using LinearSolverRegistry =
    PartRegistry<Factorization,
                 const TrilinosWrappers::SparseMatrix &,
                 const std::vector<std::vector<bool>> &>;

  /** The core's linear solver, and 'auto''s on one process. */
  inline const std::string cholmod_name = "CHOLMOD";

  /** The messages name a part of this kind a linear solver. */
  template <>
  inline std::string LinearSolverRegistry::noun()
  {
    return "linear solver";
  }
} // namespace Contact

#endif
