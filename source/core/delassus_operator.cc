/* The Delassus operator on Gamma_3 and the dense Newton step of the friction
   solvers on it (delassus_operator.h). */

#include <deal.II/base/exceptions.h>

#include <core/delassus_kernels.h>
#include <core/delassus_operator.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace Contact
{
  // @sect3{definiteness}

  // Whether a symmetric matrix is positive definite (its Cholesky
  // factorisation exists): the second-order test of a step's minimum, which
  // the Delassus operator and the parts' methods ask.
  Curvature definiteness(LAPACKFullMatrix<double> matrix)
  {
    for (unsigned int a = 0; a < matrix.m(); ++a)
      for (unsigned int b = 0; b < a; ++b)
        matrix(a, b) = matrix(b, a) = 0.5 * (matrix(a, b) + matrix(b, a));
    matrix.set_property(LAPACKSupport::symmetric);
    try
      {
        matrix.compute_cholesky_factorization();
      }
    catch (const ExceptionBase &)
      {
        return Curvature::not_positive;
      }
    return Curvature::positive;
  }


  using namespace DelassusKernels;

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

    // (Q^T x)_U: x in the nodes' local bases, on the unknowns U.
    Vector<double> local_entries(const std::vector<FullMatrix<double>> &Q,
                                 const Vector<double>                  &x,
                                 const std::vector<unsigned int> &unknowns)
    {
      Vector<double> rotated(x.size()), entries(unknowns.size());
      rotate(Q, x, rotated, true);
      for (unsigned int a = 0; a < unknowns.size(); ++a)
        entries[a] = rotated[unknowns[a]];
      return entries;
    }

    // The system of one form on its block of unknowns: the right-hand side,
    // the shifts of the diagonal, and the first guess.
    struct BlockSystem
    {
      Vector<double> rhs, shift, x;
    };

    // The velocity form's system for v'_U (below), with the current
    // velocities v as first guess; W v_free is given.
    BlockSystem
    velocity_form_system(const std::vector<LocalCondition>     &conditions,
                         const std::vector<FullMatrix<double>> &Q,
                         const std::vector<unsigned int>       &unknowns,
                         const Vector<double>                  &W_v_free,
                         const Vector<double>                  &v)
    {
      BlockSystem system{local_entries(Q, W_v_free, unknowns),
                         Vector<double>(unknowns.size()),
                         local_entries(Q, v, unknowns)};
      for (unsigned int a = 0; a < unknowns.size(); ++a)
        {
          system.rhs[a] -= conditions[unknowns[a]].force;
          system.shift[a] = conditions[unknowns[a]].sigma;
        }
      return system;
    }

    // eta = W (v_free - v) for the velocities v'_U = x of the velocity
    // form. Where the step fixes the force it is that force, not W's
    // approximation of it (cond(D) eps away), so that a converged active
    // set iteration is exact there as in the force form.
    void forces_of_velocities(const std::vector<LocalCondition>     &conditions,
                              const std::vector<FullMatrix<double>> &Q,
                              const std::vector<unsigned int>       &unknowns,
                              const LAPACKFullMatrix<double>        &W,
                              const Vector<double>                  &v_free,
                              const Vector<double>                  &x,
                              Vector<double>                        &eta)
    {
      const unsigned int size = conditions.size();
      Vector<double>     rotated_v(size), slip(size), rotated_eta(size);
      for (unsigned int a = 0; a < unknowns.size(); ++a)
        rotated_v[unknowns[a]] = x[a];
      rotate(Q, rotated_v, slip, false);
      slip.sadd(-1., 1., v_free);
      symmetric_vmult(W, eta, slip);
      rotate(Q, eta, rotated_eta, true);
      for (unsigned int r = 0; r < size; ++r)
        if (conditions[r].kind == LocalCondition::fixed_force)
          rotated_eta[r] = conditions[r].force;
      rotate(Q, rotated_eta, eta, false);
    }

    // The force form's system for eta'_F (below), with the current forces
    // eta as first guess; the fixed forces (in the local bases) in
    // fixed_forces.
    BlockSystem force_form_system(const std::vector<LocalCondition> &conditions,
                                  const std::vector<FullMatrix<double>> &Q,
                                  const std::vector<unsigned int> &unknowns,
                                  const LAPACKFullMatrix<double>  &D,
                                  const Vector<double>            &v_free,
                                  const Vector<double>            &eta,
                                  Vector<double>                  &fixed_forces)
    {
      const unsigned int size = conditions.size();
      Vector<double>     D_fixed(size), rotated(size);
      fixed_forces.reinit(size);
      for (unsigned int r = 0; r < size; ++r)
        if (conditions[r].kind == LocalCondition::fixed_force)
          fixed_forces[r] = conditions[r].force;
      rotate(Q, fixed_forces, rotated, false);
      symmetric_vmult(D, D_fixed, rotated);
      D_fixed.sadd(-1., 1., v_free);
      BlockSystem system{local_entries(Q, D_fixed, unknowns),
                         Vector<double>(unknowns.size()),
                         local_entries(Q, eta, unknowns)};
      for (unsigned int a = 0; a < unknowns.size(); ++a)
        if (conditions[unknowns[a]].kind == LocalCondition::robin)
          {
            const LocalCondition &cond = conditions[unknowns[a]];
            system.rhs[a] += cond.force / cond.sigma;
            system.shift[a] = 1. / cond.sigma;
          }
      return system;
    }
  } // namespace

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

    if (use_velocity_form)
      {
        if (last_v_free.size() != v_free.size() || !(v_free == last_v_free))
          {
            last_v_free = v_free;
            W_v_free.reinit(n * m);
            symmetric_vmult(W, W_v_free, v_free);
          }
        BlockSystem system =
          velocity_form_system(conditions, Q, velocity_unknowns, W_v_free, v);
        solve_block({true, Q, velocity_unknowns, system.shift, weakening},
                    system.rhs,
                    system.x);
        forces_of_velocities(
          conditions, Q, velocity_unknowns, W, v_free, system.x, eta);
      }
    else
      {
        Vector<double> rotated_eta;
        BlockSystem    system = force_form_system(
          conditions, Q, force_unknowns, D, v_free, eta, rotated_eta);
        solve_block({false, Q, force_unknowns, system.shift, weakening},
                    system.rhs,
                    system.x);
        for (unsigned int a = 0; a < force_unknowns.size(); ++a)
          rotated_eta[force_unknowns[a]] = system.x[a];
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
