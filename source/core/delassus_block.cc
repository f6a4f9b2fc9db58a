/* The dense linear algebra of the Delassus operator's Newton step
   (delassus_kernels.h): products with D and W, the rotation to the nodes'
   local bases, and the solve of a step's block, factorised or by GMRES
   preconditioned with the last factor (DelassusOperator::solve_block()). */

#include <deal.II/base/exceptions.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <core/delassus_kernels.h>
#include <core/delassus_operator.h>

#include <algorithm>
#include <cmath>
#include <iterator>

extern "C" void dsymv_(const char   *uplo,
                       const int    *n,
                       const double *alpha,
                       const double *a,
                       const int    *lda,
                       const double *x,
                       const int    *incx,
                       const double *beta,
                       double       *y,
                       const int    *incy);

extern "C" void dtrsv_(const char   *uplo,
                       const char   *trans,
                       const char   *diag,
                       const int    *n,
                       const double *a,
                       const int    *lda,
                       double       *x,
                       const int    *incx);

namespace Contact
{
  // @sect4{Dense kernels}

  namespace DelassusKernels
  {
    // y = M x for the symmetric D or W: BLAS's symv reads one triangle,
    // half of what gemv (LAPACKFullMatrix::vmult) reads, and the product is
    // bound by reading M.
    void symmetric_vmult(const LAPACKFullMatrix<double> &M,
                         Vector<double>                 &y,
                         const Vector<double>           &x)
    {
      AssertDimension(x.size(), M.n());
      y.reinit(M.m(), /*omit_zeroing_entries=*/true);
      if (M.m() == 0)
        return;
      const int    n = M.m(), one_step = 1;
      const double one = 1., zero = 0.;
      dsymv_("L",
             &n,
             &one,
             &M(0, 0),
             &n,
             x.begin(),
             &one_step,
             &zero,
             y.begin(),
             &one_step);
    }

    // x = F^{-1} x for a factorised block F. A Cholesky factor L L^T (in
    // the lower triangle: deal.II 9.4's compute_cholesky_factorization calls
    // potrf with uplo = L) is applied by two triangular solves of BLAS
    // level 2. LAPACK's potrs goes through trsm, which OpenBLAS runs by
    // packing the factor into blocks (its gemm copy kernels in a profile),
    // even for the single right-hand side here, and GMRES applies the
    // factor at every iteration.
    void solve_with_factor(const LAPACKFullMatrix<double> &factor,
                           const bool                      cholesky,
                           Vector<double>                 &x)
    {
      AssertDimension(x.size(), factor.m());
      if (!cholesky)
        {
          factor.solve(x);
          return;
        }
      if (x.size() == 0)
        return;
      const int n = factor.m(), one_step = 1;
      dtrsv_("L", "N", "N", &n, &factor(0, 0), &n, x.begin(), &one_step);
      dtrsv_("L", "T", "N", &n, &factor(0, 0), &n, x.begin(), &one_step);
    }

    // M' = Q^T M Q in the nodes' local bases, on the rows and columns of
    // `unknowns`: column by column, each first combined from M's columns of
    // its node (contiguous in memory), then its rows.
    void fill_rotated_block(const LAPACKFullMatrix<double>        &M,
                            const std::vector<FullMatrix<double>> &Q,
                            const std::vector<unsigned int>       &unknowns,
                            LAPACKFullMatrix<double>              &block)
    {
      const unsigned int m = Q.empty() ? 1 : Q[0].m(), size = unknowns.size();
      Vector<double>     column(M.m());
      for (unsigned int b = 0; b < size; ++b)
        {
          const unsigned int q = unknowns[b] / m, j0 = unknowns[b] % m;
          column = 0.;
          for (unsigned int j = 0; j < m; ++j)
            {
              // LAPACKFullMatrix stores its columns contiguously.
              const double  factor = Q[q](j, j0);
              const double *entry  = &M(0, q * m + j);
              if (factor != 0.)
                for (double &c : column)
                  c += factor * *entry++;
            }
          for (unsigned int a = 0; a < size; ++a)
            {
              const unsigned int p = unknowns[a] / m, i0 = unknowns[a] % m;
              double             entry = 0;
              for (unsigned int i = 0; i < m; ++i)
                entry += Q[p](i, i0) * column[p * m + i];
              block(a, b) = entry;
            }
        }
    }

    // y = Q x (to the nodes' tangents) or Q^T x (to the local bases).
    void rotate(const std::vector<FullMatrix<double>> &Q,
                const Vector<double>                  &x,
                Vector<double>                        &y,
                const bool                             transpose)
    {
      const unsigned int n = Q.size(), m = n > 0 ? Q[0].m() : 1;
      y.reinit(x.size());
      for (unsigned int p = 0; p < n; ++p)
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int a = 0; a < m; ++a)
            y[p * m + i] +=
              (transpose ? Q[p](a, i) : Q[p](i, a)) * x[p * m + a];
    }
  } // namespace DelassusKernels

  using namespace DelassusKernels;


  // @sect4{The block of a Newton step, factorised or by GMRES}

  namespace
  {
    // x -> (Q^T M Q + diag(shift)) x on the unknowns U, without forming the
    // block: one product with the whole of M.
    class RotatedBlock
    {
    public:
      RotatedBlock(const LAPACKFullMatrix<double>        &matrix,
                   const std::vector<FullMatrix<double>> &node_rotations,
                   const std::vector<unsigned int>       &block_unknowns,
                   const Vector<double>                  &diagonal_shift)
        : M(matrix)
        , Q(node_rotations)
        , unknowns(block_unknowns)
        , shift(diagonal_shift)
      {}

      void vmult(Vector<double> &y, const Vector<double> &x) const
      {
        Vector<double> local(M.m()), global(M.m()), product(M.m());
        for (unsigned int a = 0; a < unknowns.size(); ++a)
          local[unknowns[a]] = x[a];
        rotate(Q, local, global, false);
        symmetric_vmult(M, product, global);
        rotate(Q, product, local, true);
        for (unsigned int a = 0; a < unknowns.size(); ++a)
          y[a] = local[unknowns[a]] + shift[a] * x[a];
      }

    private:
      const LAPACKFullMatrix<double>        &M;
      const std::vector<FullMatrix<double>> &Q;
      const std::vector<unsigned int>       &unknowns;
      const Vector<double>                  &shift;
    };

    // The factor of an earlier block on nearly the same unknowns applied to
    // this block's: on the unknowns both have, the factor's solve (with zero
    // on those only it has); on the new ones, division by the diagonal.
    class FactorPreconditioner
    {
    public:
      FactorPreconditioner(const LAPACKFullMatrix<double>  &last_factor,
                           const bool                       cholesky,
                           const std::vector<unsigned int> &factor_unknowns,
                           const std::vector<unsigned int> &unknowns,
                           const Vector<double>            &block_diagonal)
        : factor(last_factor)
        , factor_is_cholesky(cholesky)
        , position(factor_unknowns.size(), numbers::invalid_unsigned_int)
        , diagonal(block_diagonal)
      {
        for (unsigned int a = 0, b = 0; a < unknowns.size(); ++a)
          {
            while (b < factor_unknowns.size() &&
                   factor_unknowns[b] < unknowns[a])
              ++b;
            if (b < factor_unknowns.size() && factor_unknowns[b] == unknowns[a])
              position[b] = a;
          }
      }

      void vmult(Vector<double> &y, const Vector<double> &x) const
      {
        Vector<double> z(position.size());
        for (unsigned int b = 0; b < position.size(); ++b)
          if (position[b] != numbers::invalid_unsigned_int)
            z[b] = x[position[b]];
        solve_with_factor(factor, factor_is_cholesky, z);
        for (unsigned int a = 0; a < x.size(); ++a)
          y[a] = x[a] / diagonal[a];
        for (unsigned int b = 0; b < position.size(); ++b)
          if (position[b] != numbers::invalid_unsigned_int)
            y[position[b]] = z[b];
      }

    private:
      const LAPACKFullMatrix<double> &factor;
      const bool                      factor_is_cholesky;
      std::vector<unsigned int>       position;
      const Vector<double>           &diagonal;
    };

    // How many unknowns one sorted list has that the other has not.
    unsigned int n_differences(const std::vector<unsigned int> &a,
                               const std::vector<unsigned int> &b)
    {
      std::vector<unsigned int> difference;
      std::set_symmetric_difference(
        a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(difference));
      return difference.size();
    }
  } // namespace


  // The blocks of consecutive Newton steps on the same unknowns differ only
  // by the turn of the slip directions and the change of the shifts, so the
  // factor of the last one preconditions the next almost perfectly: GMRES
  // then costs a few products with M instead of forming and factorising a
  // block. Only if it has not converged within gmres_max_iterations (to
  // the relative residual gmres_reduction: an inexact Newton step, which
  // the Newton method's own residual test corrects) is the block formed
  // and factorised, and its factor kept for the next step.
  void DelassusOperator::solve_block(const StepBlock      &block,
                                     const Vector<double> &rhs,
                                     Vector<double>       &x) const
  {
    if (rhs.size() == 0)
      return;
    const FactorisedBlock &last = last_factorised_block;
    if (block.unknowns.size() >= min_unknowns_for_gmres && last.factor &&
        last.velocity_form == block.velocity_form &&
        n_differences(last.unknowns, block.unknowns) <= max_changed_unknowns &&
        solve_block_by_gmres(block, rhs, x))
      return;
    factorise_and_solve_block(block, rhs, x);
  }

  // GMRES on the block, preconditioned with the last factor; whether it
  // solved the block (x is then its solution).
  bool DelassusOperator::solve_block_by_gmres(const StepBlock      &block,
                                              const Vector<double> &rhs,
                                              Vector<double>       &x) const
  {
    const auto &[velocity_form, Q, unknowns, shift, weakening] = block;
    const LAPACKFullMatrix<double> &M    = (velocity_form ? W : D);
    const FactorisedBlock          &last = last_factorised_block;
    // The block's diagonal, for the unknowns the factor does not have
    // (|.| where the weakening makes it negative).
    Vector<double>     diagonal(unknowns.size());
    const unsigned int m = n_components;
    for (unsigned int a = 0; a < unknowns.size(); ++a)
      {
        const unsigned int r = unknowns[a], p = r / m;
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            diagonal[a] +=
              Q[p](i, r % m) * M(p * m + i, p * m + j) * Q[p](j, r % m);
        diagonal[a] = std::abs(diagonal[a] + shift[a]);
        if (diagonal[a] == 0.)
          diagonal[a] = 1.;
      }
    Vector<double>              solution(x);
    ReductionControl            control(gmres_max_iterations,
                             1e-14 * rhs.l2_norm(),
                             gmres_reduction,
                             false,
                             false);
    SolverGMRES<Vector<double>> gmres(
      control, SolverGMRES<Vector<double>>::AdditionalData(12, true));
    try
      {
        gmres.solve(RotatedBlock(M, Q, unknowns, shift),
                    solution,
                    rhs,
                    FactorPreconditioner(*last.factor,
                                         last.cholesky,
                                         last.unknowns,
                                         unknowns,
                                         diagonal));
      }
    catch (const SolverControl::NoConvergence &)
      {
        // Too far from the factor's block: factorise this one.
        return false;
      }
    // No GMRES iteration: the first guess (the current iterate) already
    // met GMRES's absolute tolerance, which near the solution can be above
    // what the Newton method needs; it would return the same iterate, so
    // the block is factorised instead.
    if (control.last_step() == 0)
      return false;
    x = solution;
    ++n_preconditioned_solves;
    return true;
  }

  // The block formed and factorised (its factor kept as the last one), and
  // solved.
  void DelassusOperator::factorise_and_solve_block(const StepBlock &step_block,
                                                   const Vector<double> &rhs,
                                                   Vector<double> &x) const
  {
    const auto &[velocity_form, Q, unknowns, shift, weakening] = step_block;
    const LAPACKFullMatrix<double> &M    = (velocity_form ? W : D);
    FactorisedBlock                &last = last_factorised_block;
    last.velocity_form                   = velocity_form;
    last.unknowns                        = unknowns;
    last.cholesky                        = false;
    last.factor = std::make_unique<LAPACKFullMatrix<double>>(unknowns.size());
    LAPACKFullMatrix<double> &block = *last.factor;
    fill_rotated_block(M, Q, unknowns, block);
    for (unsigned int a = 0; a < unknowns.size(); ++a)
      block(a, a) += shift[a];
    // Cholesky where the block is SPD (no weakening row); LU where the
    // force form has one (its shift 1/g' is large and negative); in the
    // velocity form the weakening's shift g' may leave the block definite,
    // so Cholesky is tried first, on a copy.
    const bool try_cholesky = !weakening || velocity_form;
    if (try_cholesky)
      {
        LAPACKFullMatrix<double> copy;
        if (weakening)
          copy = block;
        try
          {
            block.set_property(LAPACKSupport::symmetric);
            block.compute_cholesky_factorization();
            last.cholesky = true;
            x             = rhs;
            solve_with_factor(block, last.cholesky, x);
            return;
          }
        catch (const ExceptionBase &)
          {
            if (!weakening)
              last.factor.reset();
            AssertThrow(weakening,
                        ExcMessage("A Newton step on Gamma_3 met a block "
                                   "of the Delassus operator that is not "
                                   "positive definite: D = C K^{-1} C^T "
                                   "is singular to round-off."));
            block = copy;
            block.set_property(LAPACKSupport::general);
          }
      }
    block.compute_lu_factorization();
    x = rhs;
    block.solve(x);
  }
} // namespace Contact
