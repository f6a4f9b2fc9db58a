/* The Delassus operator on Gamma_3 and the dense Newton step of the friction
   solvers on it (delassus_operator.h). */

#include <deal.II/base/exceptions.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <gamma3/delassus_operator.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>

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
  namespace
  {
    // y = M x for the symmetric D or W: BLAS's symv reads one triangle,
    // half of what gemv (LAPACKFullMatrix::vmult) reads, and the product is
    // bound by reading M (0.079 against 0.150 ms for n = 1088 with
    // OpenBLAS on the machine of bench/friction_solver.md).
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
    // even for the single right-hand side here. GMRES applies the factor
    // at every iteration: on the 3D scene at h = k = 1/32 with OpenBLAS a
    // step took 78 ms with potrs, 65 ms with trsv (medians of four runs
    // each, taken in turn).
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
  } // namespace


  DelassusOperator::DelassusOperator(const FullMatrix<double> &matrix,
                                     const unsigned int        components)
    : n_components(components)
  {
    AssertDimension(matrix.m() % n_components, 0);
    for (unsigned int r = 0; r < matrix.m(); ++r)
      for (unsigned int s = 0; s < r; ++s)
        AssertThrow(matrix(r, s) == matrix(s, r),
                    ExcMessage("The Delassus operator must be exactly "
                               "symmetric (its products read one "
                               "triangle)."));
    D.reinit(matrix.m());
    D = matrix;

    // W only where D is definite and well conditioned: a zero diagonal
    // entry is a tangent whose dofs are all constrained, and the forces
    // eta = W (v_free - v) leave a velocity residual cond(D) times that of
    // a solve with D, so above cond(D) = 1e4 (at most four digits lost; a
    // floating body held by friction alone, tests/scenes/pure_stick, has
    // 1e8, the other test scenes 3 to 80, and 2000 with a nearly
    // incompressible material) the force form alone applies.
    for (unsigned int r = 0; r < matrix.m(); ++r)
      if (!(matrix(r, r) > 0))
        return;
    LAPACKFullMatrix<double> cholesky(D);
    const double             norm = cholesky.l1_norm();
    cholesky.set_property(LAPACKSupport::symmetric);
    try
      {
        cholesky.compute_cholesky_factorization();
        if (cholesky.reciprocal_condition_number(norm) <
            min_reciprocal_condition)
          return;
        W = D;
        W.set_property(LAPACKSupport::symmetric);
        W.invert();
      }
    catch (const ExceptionBase &)
      {
        W.reinit(0, 0);
        return;
      }
    for (unsigned int r = 0; r < W.m(); ++r)
      for (unsigned int s = 0; s < r; ++s)
        W(s, r) = W(r, s) = (W(r, s) + W(s, r)) / 2;
  }


  unsigned int DelassusOperator::size() const
  {
    return D.m();
  }


  void DelassusOperator::vmult(Vector<double> &y, const Vector<double> &x) const
  {
    symmetric_vmult(D, y, x);
  }


  unsigned int DelassusOperator::preconditioned_solves() const
  {
    return n_preconditioned_solves;
  }


  // @sect4{The Newton step}

  namespace
  {
    // What one Newton step fixes on an unknown in its node's local basis:
    // the velocity (v' = 0), the force (eta' = force), or a Robin relation
    // eta' = force + sigma v' (sigma = 1/beta across zhat, sigma = g'(s) < 0
    // along zhat for the full law).
    struct LocalCondition
    {
      enum Kind
      {
        fixed_velocity,
        fixed_force,
        robin
      } kind       = fixed_velocity;
      double force = 0;
      double sigma = 0;
    };

    // The conditions of the linearisation (friction.h). Along zhat of a slip
    // node the force is fixed unless the slope of the bound is above
    // round-off against D'_rr; a unit that cannot move (D'_rr = 0) takes
    // eta' = 0. D' = Q^T D Q in the nodes' local bases Q, m unknowns per
    // node.
    std::vector<LocalCondition>
    local_conditions(const std::vector<NodeLinearisation>  &linearisation,
                     const LAPACKFullMatrix<double>        &D,
                     const std::vector<FullMatrix<double>> &Q,
                     const unsigned int                     m)
    {
      const unsigned int  n = linearisation.size();
      std::vector<double> rotated_diagonal(n * m);
      for (unsigned int r = 0; r < n * m; ++r)
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            rotated_diagonal[r] += Q[r / m](i, r % m) *
                                   D((r / m) * m + i, (r / m) * m + j) *
                                   Q[r / m](j, r % m);
      std::vector<LocalCondition> conditions(n * m);
      for (unsigned int p = 0; p < n; ++p)
        {
          const NodeLinearisation &node = linearisation[p];
          const bool slip = (node.state == NodeState::slip && node.bound > 0);
          for (unsigned int i = 0; i < m; ++i)
            {
              const unsigned int r    = p * m + i;
              const double       d    = rotated_diagonal[r];
              LocalCondition    &cond = conditions[r];
              if (!slip && !(node.state == NodeState::stick && d > 0))
                cond.kind = LocalCondition::fixed_force;
              else if (slip && i == 0)
                {
                  cond.force = node.force;
                  if (-node.slope * d > 1e-14 * (1. + d * node.bound))
                    {
                      cond.kind  = LocalCondition::robin;
                      cond.sigma = node.slope;
                    }
                  else
                    cond.kind = LocalCondition::fixed_force;
                }
              else if (slip && node.beta > 0)
                {
                  cond.kind  = LocalCondition::robin;
                  cond.sigma = 1. / node.beta;
                }
              else if (slip && d == 0)
                cond.kind = LocalCondition::fixed_force;
            }
        }
      return conditions;
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

  } // namespace


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
  void DelassusOperator::solve_block(const bool velocity_form,
                                     const std::vector<FullMatrix<double>> &Q,
                                     const std::vector<unsigned int> &unknowns,
                                     const Vector<double>            &shift,
                                     const bool                       weakening,
                                     const Vector<double>            &rhs,
                                     Vector<double>                  &x) const
  {
    if (rhs.size() == 0)
      return;
    const LAPACKFullMatrix<double> &M    = (velocity_form ? W : D);
    FactorisedBlock                &last = last_factorised_block;
    if (unknowns.size() >= min_unknowns_for_gmres && last.factor &&
        last.velocity_form == velocity_form &&
        n_differences(last.unknowns, unknowns) <= max_changed_unknowns)
      {
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
            // No GMRES iteration: the first guess (the current iterate)
            // already met GMRES's absolute tolerance, which near the
            // solution can be above what the Newton method needs; it would
            // return the same iterate, so the block is factorised instead.
            if (control.last_step() > 0)
              {
                x = solution;
                ++n_preconditioned_solves;
                return;
              }
          }
        catch (const SolverControl::NoConvergence &)
          {
            // Too far from the factor's block: factorise this one.
          }
      }

    last.velocity_form = velocity_form;
    last.unknowns      = unknowns;
    last.cholesky      = false;
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


  // @sect4{The Newton step}

  // The force form: eta' = force where it is fixed, and on the others
  //   (D'_FF + diag(1/sigma)) eta'_F = v'_free,F + (force/sigma)_F
  //                                    - D'_FX eta'_X,
  // 1/sigma = 0 where the velocity is fixed (v'_r = 0 is row r of
  // v' = v'_free - D' eta'); a Robin row eta' = f + sigma v' divided by sigma
  // is symmetric. The velocity form: v' = 0 where the velocity is fixed, and
  // with eta' = W'(v'_free - v') on the others
  //   (W'_UU + diag(sigma)) v'_U = (W' v'_free)_U - force_U,
  // sigma = 0 where the force is fixed. Either way eta follows, and then
  // v = v_free - D eta.
  void DelassusOperator::newton_step(
    const std::vector<NodeLinearisation> &linearisation,
    const Vector<double>                 &v_free,
    Vector<double>                       &eta,
    Vector<double>                       &v,
    const Form                            form) const
  {
    const unsigned int n = linearisation.size(), m = n_components;
    AssertDimension(n * m, size());
    std::vector<FullMatrix<double>> Q;
    for (const NodeLinearisation &node : linearisation)
      Q.push_back(local_basis(node));
    const std::vector<LocalCondition> conditions =
      local_conditions(linearisation, D, Q, m);

    std::vector<unsigned int> force_unknowns, velocity_unknowns;
    bool                      weakening = false;
    for (unsigned int r = 0; r < n * m; ++r)
      {
        if (conditions[r].kind != LocalCondition::fixed_force)
          force_unknowns.push_back(r);
        if (conditions[r].kind != LocalCondition::fixed_velocity)
          velocity_unknowns.push_back(r);
        weakening |= (conditions[r].kind == LocalCondition::robin &&
                      conditions[r].sigma < 0);
      }
    const bool use_velocity_form =
      W.m() > 0 && (form == Form::velocity ||
                    (form == Form::smaller &&
                     velocity_unknowns.size() <= force_unknowns.size()));
    AssertThrow(form != Form::velocity || W.m() > 0,
                ExcMessage("The velocity form needs W = D^{-1}."));

    Vector<double> rotated_eta(n * m);
    if (use_velocity_form)
      {
        if (last_v_free.size() != v_free.size() || !(v_free == last_v_free))
          {
            last_v_free = v_free;
            W_v_free.reinit(n * m);
            symmetric_vmult(W, W_v_free, v_free);
          }
        Vector<double> rotated(n * m);
        rotate(Q, W_v_free, rotated, true);
        Vector<double> rhs(velocity_unknowns.size()), shift(rhs.size());
        for (unsigned int a = 0; a < rhs.size(); ++a)
          {
            const LocalCondition &cond = conditions[velocity_unknowns[a]];
            rhs[a]   = rotated[velocity_unknowns[a]] - cond.force;
            shift[a] = cond.sigma;
          }
        // The current velocities as first guess.
        Vector<double> rotated_v(n * m), slip(n * m), x(rhs.size());
        rotate(Q, v, rotated_v, true);
        for (unsigned int a = 0; a < rhs.size(); ++a)
          x[a] = rotated_v[velocity_unknowns[a]];
        solve_block(true, Q, velocity_unknowns, shift, weakening, rhs, x);
        rotated_v = 0.;
        for (unsigned int a = 0; a < rhs.size(); ++a)
          rotated_v[velocity_unknowns[a]] = x[a];
        rotate(Q, rotated_v, slip, false);
        slip.sadd(-1., 1., v_free);
        symmetric_vmult(W, eta, slip);
        // Where the step fixes the force it is that force, not W's
        // approximation of it (cond(D) eps away), so that a converged
        // active set iteration is exact there as in the force form.
        rotate(Q, eta, rotated_eta, true);
        for (unsigned int r = 0; r < n * m; ++r)
          if (conditions[r].kind == LocalCondition::fixed_force)
            rotated_eta[r] = conditions[r].force;
        rotate(Q, rotated_eta, eta, false);
      }
    else
      {
        Vector<double> fixed_forces(n * m), D_fixed(n * m), rotated(n * m);
        for (unsigned int r = 0; r < n * m; ++r)
          if (conditions[r].kind == LocalCondition::fixed_force)
            fixed_forces[r] = conditions[r].force;
        rotate(Q, fixed_forces, rotated, false);
        symmetric_vmult(D, D_fixed, rotated);
        D_fixed.sadd(-1., 1., v_free);
        rotate(Q, D_fixed, rotated, true);
        Vector<double> rhs(force_unknowns.size()), shift(rhs.size());
        for (unsigned int a = 0; a < rhs.size(); ++a)
          {
            const LocalCondition &cond = conditions[force_unknowns[a]];
            rhs[a]                     = rotated[force_unknowns[a]];
            if (cond.kind == LocalCondition::robin)
              {
                rhs[a] += cond.force / cond.sigma;
                shift[a] = 1. / cond.sigma;
              }
          }
        // The current forces as first guess.
        Vector<double> x(rhs.size());
        rotate(Q, eta, rotated_eta, true);
        for (unsigned int a = 0; a < rhs.size(); ++a)
          x[a] = rotated_eta[force_unknowns[a]];
        solve_block(false, Q, force_unknowns, shift, weakening, rhs, x);
        rotated_eta = fixed_forces;
        for (unsigned int a = 0; a < rhs.size(); ++a)
          rotated_eta[force_unknowns[a]] = x[a];
        rotate(Q, rotated_eta, eta, false);
      }

    symmetric_vmult(D, v, eta);
    v.sadd(-1., 1., v_free);
    for (unsigned int p = 0; p < n; ++p)
      if (linearisation[p].state == NodeState::stick)
        for (unsigned int i = 0; i < m; ++i)
          v[p * m + i] = 0.;
  }


  // @sect4{The curvature test}

  // The Hessian of E on the slip set, in the nodes' local bases, is the
  // matrix of the velocity form, W'_UU + diag(sigma) with W = D^{-1}, U
  // the unknowns whose velocity is not fixed and sigma = 0 where the force
  // is: one Cholesky factorisation of it decides. Where W is not formed (D
  // ill-conditioned), T = (W'_UU)^{-1} = D'_UU - D'_UX D'_XX^{-1} D'_XU
  // (X: the fixed velocities, the stick nodes) gives the congruent
  // T + T diag(sigma) T from D alone, at about six times the cost.
  Curvature DelassusOperator::curvature_on_slip_set(
    const std::vector<NodeLinearisation> &linearisation,
    const Form                            form) const
  {
    AssertThrow(form != Form::velocity || W.m() > 0,
                ExcMessage("The velocity form needs W = D^{-1}."));
    const unsigned int n = linearisation.size(), m = n_components;
    AssertDimension(n * m, size());
    std::vector<FullMatrix<double>> Q;
    for (const NodeLinearisation &node : linearisation)
      Q.push_back(local_basis(node));
    const std::vector<LocalCondition> conditions =
      local_conditions(linearisation, D, Q, m);
    std::vector<unsigned int> U, X;
    for (unsigned int r = 0; r < n * m; ++r)
      (conditions[r].kind == LocalCondition::fixed_velocity ? X : U)
        .push_back(r);
    if (U.empty())
      return Curvature::positive;
    if (W.m() > 0 && form != Form::force)
      {
        LAPACKFullMatrix<double> hessian(U.size(), U.size());
        fill_rotated_block(W, Q, U, hessian);
        for (unsigned int a = 0; a < U.size(); ++a)
          hessian(a, a) += conditions[U[a]].sigma;
        return definiteness(hessian);
      }

    std::vector<unsigned int> all(n * m);
    std::iota(all.begin(), all.end(), 0u);
    LAPACKFullMatrix<double> rotated(n * m, n * m);
    fill_rotated_block(D, Q, all, rotated);
    LAPACKFullMatrix<double> T(U.size(), U.size());
    for (unsigned int a = 0; a < U.size(); ++a)
      for (unsigned int b = 0; b < U.size(); ++b)
        T(a, b) = rotated(U[a], U[b]);
    if (!X.empty())
      {
        LAPACKFullMatrix<double> fixed(X.size(), X.size());
        for (unsigned int i = 0; i < X.size(); ++i)
          for (unsigned int j = 0; j < X.size(); ++j)
            fixed(i, j) = rotated(X[i], X[j]);
        fixed.set_property(LAPACKSupport::symmetric);
        try
          {
            fixed.compute_cholesky_factorization();
          }
        catch (const ExceptionBase &)
          {
            return Curvature::unknown;
          }
        Vector<double> column(X.size());
        for (unsigned int b = 0; b < U.size(); ++b)
          {
            for (unsigned int i = 0; i < X.size(); ++i)
              column[i] = rotated(X[i], U[b]);
            fixed.solve(column);
            for (unsigned int a = 0; a < U.size(); ++a)
              for (unsigned int i = 0; i < X.size(); ++i)
                T(a, b) -= rotated(U[a], X[i]) * column[i];
          }
      }

    LAPACKFullMatrix<double> T_sigma(U.size(), U.size()),
      hessian(U.size(), U.size());
    for (unsigned int a = 0; a < U.size(); ++a)
      for (unsigned int b = 0; b < U.size(); ++b)
        T_sigma(a, b) = T(a, b) * conditions[U[b]].sigma;
    T_sigma.mmult(hessian, T);
    for (unsigned int a = 0; a < U.size(); ++a)
      for (unsigned int b = 0; b < U.size(); ++b)
        hessian(a, b) += T(a, b);
    return definiteness(hessian);
  }

  TrescaResult solve_tresca(const DelassusOperator &D,
                            const Vector<double>   &v_free,
                            const Vector<double>   &g,
                            const Vector<double>   &c,
                            const unsigned int      max_iterations,
                            Vector<double>         &eta,
                            Vector<double>         &v,
                            std::vector<NodeState> &state)
  {
    AssertDimension(D.size(), v_free.size());
    const auto velocity = [&](const Vector<double> &force,
                              Vector<double>       &velocity_out) {
      D.vmult(velocity_out, force);
      velocity_out.sadd(-1., 1., v_free);
    };
    const auto step = [&](const std::vector<NodeLinearisation> &linearisation,
                          Vector<double>                       &force,
                          Vector<double>                       &velocity_out) {
      D.newton_step(linearisation, v_free, force, velocity_out);
    };
    return solve_tresca(
      velocity, step, D.size() / g.size(), g, c, max_iterations, eta, v, state);
  }
} // namespace Contact
