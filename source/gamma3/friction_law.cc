/* The slip threshold of the friction law and the nodal Tresca solver on
   Gamma_3. */

#include <deal.II/lac/lapack_full_matrix.h>

#include <gamma3/friction.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Contact
{
  // @sect3{The friction law}

  // The law itself is one file of source/base/friction_laws/; here only what
  // holds for every law: S = 0 leaves no friction term, and a rate
  // independent law has no derivative and the potential S mu(0) s (the law
  // is not asked, so that its formula need not handle its constant cases,
  // e.g. alpha = 0 in (6.1), where it would divide by zero).
  FrictionLaw::FrictionLaw(const FrictionParameters &parameters)
    : law(parameters.law)
    , S(parameters.bound_S)
    , frictionless(S == 0. || (law && law->is_frictionless()))
    , rate_independent(law && law->is_rate_independent())
  {
    AssertThrow(law,
                ExcMessage("FrictionLaw: the parameters hold no friction law "
                           "(FrictionParameters::parse_parameters() reads "
                           "it)."));
  }

  double FrictionLaw::coefficient(const double slip_rate) const
  {
    return law->coefficient(slip_rate);
  }

  double FrictionLaw::bound(const double slip_rate) const
  {
    return S * law->coefficient(slip_rate);
  }

  double FrictionLaw::bound_derivative(const double slip_rate) const
  {
    if (frictionless || rate_independent)
      return 0.;
    return law->bound_derivative(S, slip_rate);
  }

  double FrictionLaw::potential(const double slip_velocity) const
  {
    const double s = std::abs(slip_velocity);
    if (frictionless)
      return 0.;
    if (rate_independent)
      return S * law->coefficient(0.) * s;
    return law->potential(S, s);
  }

  bool FrictionLaw::is_frictionless() const
  {
    return frictionless;
  }

  bool FrictionLaw::is_rate_independent() const
  {
    return rate_independent;
  }

  double FrictionLaw::one_sided_lipschitz_constant() const
  {
    return rate_independent ? 0. : law->one_sided_lipschitz_constant();
  }

  double FrictionLaw::steepest_weakening() const
  {
    return frictionless ? 0. : S * one_sided_lipschitz_constant();
  }


  // @sect3{Anderson acceleration}

  AndersonAcceleration::AndersonAcceleration(const unsigned int history_depth)
    : depth(history_depth)
    , accelerated(false)
  {}

  void AndersonAcceleration::restart()
  {
    residual_differences.clear();
    image_differences.clear();
    previous_residual.reinit(0);
    previous_image.reinit(0);
    accelerated = false;
  }

  bool AndersonAcceleration::last_step_was_accelerated() const
  {
    return accelerated;
  }

  void AndersonAcceleration::next_iterate(Vector<double>       &x,
                                          const Vector<double> &image)
  {
    Vector<double> residual(image);
    residual -= x;
    if (depth > 0 && previous_residual.size() == x.size())
      {
        residual_differences.push_back(residual);
        residual_differences.back() -= previous_residual;
        image_differences.push_back(image);
        image_differences.back() -= previous_image;
        if (residual_differences.size() > depth)
          {
            residual_differences.erase(residual_differences.begin());
            image_differences.erase(image_differences.begin());
          }
      }
    previous_residual = residual;
    previous_image    = image;

    const unsigned int m = residual_differences.size();
    x                    = image;
    accelerated          = (m > 0);
    if (m == 0)
      return;

    // Least squares min |residual - dF gamma| by the normal equations,
    // regularised relative to their size (m is small).
    LAPACKFullMatrix<double> normal(m, m);
    Vector<double>           gamma(m);
    double                   trace = 0;
    for (unsigned int i = 0; i < m; ++i)
      {
        gamma[i] = residual_differences[i] * residual;
        for (unsigned int j = 0; j < m; ++j)
          normal(i, j) = residual_differences[i] * residual_differences[j];
        trace += normal(i, i);
      }
    if (trace == 0.)
      {
        accelerated = false;
        return;
      }
    // Tikhonov regularisation of the least-squares problem: consecutive
    // residual differences can be nearly dependent.
    constexpr double regularisation = 1e-10;
    for (unsigned int i = 0; i < m; ++i)
      normal(i, i) += regularisation * trace;
    normal.set_property(LAPACKSupport::symmetric);
    normal.compute_cholesky_factorization();
    normal.solve(gamma);
    for (unsigned int i = 0; i < m; ++i)
      x.add(-gamma[i], image_differences[i]);
  }


  // @sect3{The Tresca problem by the primal-dual active set method}

  namespace
  {
    // The linearisation of the complementarity function at one node: its
    // state, the unit vector zhat along z_p = eta_p + c_p v_p, and beta_p.
    // A node with g_p = 0 slips with eta_p = 0 whatever v_p does; its
    // direction is that of v_p (the first axis if v_p = 0) to keep it
    // deterministic.
    std::vector<NodeLinearisation> linearise(const unsigned int    m,
                                             const Vector<double> &eta,
                                             const Vector<double> &v,
                                             const Vector<double> &g,
                                             const Vector<double> &c)
    {
      std::vector<NodeLinearisation> result(g.size());
      for (unsigned int p = 0; p < g.size(); ++p)
        {
          NodeLinearisation &node = result[p];
          node.direction.assign(m, 0.);
          double z_norm = 0, v_norm = 0;
          for (unsigned int i = 0; i < m; ++i)
            {
              node.direction[i] = eta[p * m + i] + c[p] * v[p * m + i];
              z_norm += node.direction[i] * node.direction[i];
              v_norm += v[p * m + i] * v[p * m + i];
            }
          z_norm     = std::sqrt(z_norm);
          node.bound = g[p];
          node.force = g[p];
          if (g[p] == 0.)
            {
              node.state = NodeState::slip;
              for (unsigned int i = 0; i < m; ++i)
                node.direction[i] =
                  (v_norm > 0 ? v[p * m + i] / std::sqrt(v_norm) : i == 0);
            }
          else if (z_norm > g[p])
            {
              node.state = NodeState::slip;
              for (double &d : node.direction)
                d /= z_norm;
              node.beta = (z_norm - g[p]) / (g[p] * c[p]);
            }
        }
      return result;
    }

    // The sets that the cycle detection compares: stick, or slip with (in
    // 2D) its sign.
    std::vector<int>
    set_signature(const std::vector<NodeLinearisation> &linearisation)
    {
      std::vector<int> signature;
      for (const NodeLinearisation &node : linearisation)
        signature.push_back(node.state == NodeState::stick ? 0 :
                            node.direction.size() > 1      ? 1 :
                            node.direction[0] > 0          ? 1 :
                                                             -1);
      return signature;
    }

    // max_p |eta_p - P_{B(g_p)}(eta_p + c_p v_p)|, with the Euclidean norm
    // of the node's vector, not the largest component: a change of the
    // tangent basis (a rotated scene) must not move the decisions taken on
    // it. Zero at a solution.
    double complementarity_residual(const unsigned int    m,
                                    const Vector<double> &eta,
                                    const Vector<double> &v,
                                    const Vector<double> &g,
                                    const Vector<double> &c)
    {
      double residual = 0;
      for (unsigned int p = 0; p < g.size(); ++p)
        {
          std::vector<double> z(m);
          double              z_norm = 0;
          for (unsigned int i = 0; i < m; ++i)
            {
              z[i] = eta[p * m + i] + c[p] * v[p * m + i];
              z_norm += z[i] * z[i];
            }
          z_norm              = std::sqrt(z_norm);
          const double scale  = (z_norm > g[p] ? g[p] / z_norm : 1.);
          double       defect = 0;
          for (unsigned int i = 0; i < m; ++i)
            {
              const double difference = eta[p * m + i] - scale * z[i];
              defect += difference * difference;
            }
          residual = std::max(residual, std::sqrt(defect));
        }
      return residual;
    }
  } // namespace


  // The orthonormal basis of one node's tangential plane in which the
  // Newton step is diagonal: stick nodes keep the canonical basis; slip
  // nodes take (zhat, zhat rotated by 90 degrees) for m = 2.
  FullMatrix<double> local_basis(const NodeLinearisation &node)
  {
    const unsigned int m = node.direction.size();
    FullMatrix<double> basis(m, m);
    for (unsigned int i = 0; i < m; ++i)
      basis(i, i) = 1;
    if (node.state == NodeState::slip)
      for (unsigned int i = 0; i < m; ++i)
        {
          basis(i, 0) = node.direction[i];
          if (m == 2)
            basis(i, 1) = (i == 0 ? -node.direction[1] : node.direction[0]);
        }
    return basis;
  }

  TrescaResult solve_tresca(const TrescaVelocity   &velocity,
                            const TrescaNewtonStep &newton_step,
                            const unsigned int      m,
                            const Vector<double>   &g,
                            const Vector<double>   &c_initial,
                            const unsigned int      max_iterations,
                            Vector<double>         &eta,
                            Vector<double>         &v,
                            std::vector<NodeState> &state,
                            const double            relative_tolerance)
  {
    AssertDimension(eta.size(), g.size() * m);
    TrescaResult                  result;
    Vector<double>                c = c_initial;
    std::vector<std::vector<int>> history;
    const double                  tolerance =
      relative_tolerance *
      std::max(g.linfty_norm(), std::numeric_limits<double>::min());

    if (velocity)
      velocity(eta, v);
    auto linearisation = linearise(m, eta, v, g, c);

    // Progress test for m = 2, where the slip directions may keep turning
    // without a set repeating: if the residual has not halved within
    // `patience` steps, c is halved as for a cycle.
    const unsigned int patience      = 8;
    double             best_residual = std::numeric_limits<double>::max();
    unsigned int       steps_without_progress = 0;
    const auto         halve_c                = [&]() {
      c *= 0.5;
      ++result.cycles_cured;
      history.clear();
      best_residual          = std::numeric_limits<double>::max();
      steps_without_progress = 0;
      linearisation          = linearise(m, eta, v, g, c);
    };

    while (result.iterations < max_iterations)
      {
        ++result.iterations;
        newton_step(linearisation, eta, v);
        history.push_back(set_signature(linearisation));

        linearisation                    = linearise(m, eta, v, g, c);
        const std::vector<int> signature = set_signature(linearisation);
        const double residual = complementarity_residual(m, eta, v, g, c);
        if (signature == history.back() && residual <= tolerance)
          {
            result.converged = true;
            break;
          }
        if (residual <= 0.5 * best_residual)
          {
            best_residual          = residual;
            steps_without_progress = 0;
          }
        else
          ++steps_without_progress;
        if ((signature != history.back() &&
             std::find(history.begin(), history.end(), signature) !=
               history.end()) ||
            steps_without_progress >= patience)
          halve_c();
      }
    state.resize(g.size());
    for (unsigned int p = 0; p < g.size(); ++p)
      state[p] = linearisation[p].state;
    return result;
  }


  // @sect3{The full law by a globalised semismooth Newton method}

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

  namespace
  {
    double node_norm(const Vector<double> &x,
                     const unsigned int    p,
                     const unsigned int    m)
    {
      double sum = 0;
      for (unsigned int i = 0; i < m; ++i)
        sum += x[p * m + i] * x[p * m + i];
      return std::sqrt(sum);
    }

    // The linearisation at (eta, v) with the bound of the current slip rate,
    // g_p(|v_p|), and on slip nodes its tangent along zhat, capped at
    // law.weakening_cap if `capped`.
    std::vector<NodeLinearisation> linearise_law(const unsigned int    m,
                                                 const Vector<double> &eta,
                                                 const Vector<double> &v,
                                                 const NodalLaw       &law,
                                                 const Vector<double> &c,
                                                 const bool            capped)
    {
      const unsigned int n = c.size();
      Vector<double>     g(n);
      for (unsigned int p = 0; p < n; ++p)
        g[p] = law.bound(p, node_norm(v, p, m));
      std::vector<NodeLinearisation> result = linearise(m, eta, v, g, c);
      // The force along zhat is g_p(s) + g_p'(s) zhat . (v_new - v), with
      // the slip rate s = |v_p| of the iterate: at a fixed point it is
      // g_p(s) even where v_p is not along zhat.
      for (unsigned int p = 0; p < n; ++p)
        if (result[p].state == NodeState::slip && g[p] > 0)
          {
            double along = 0;
            for (unsigned int i = 0; i < m; ++i)
              along += result[p].direction[i] * v[p * m + i];
            result[p].definite_slope = -law.weakening_cap * law.weights[p];
            result[p].slope          = law.slope(p, node_norm(v, p, m));
            if (capped)
              result[p].slope =
                std::max(result[p].slope, result[p].definite_slope);
            result[p].force = g[p] - result[p].slope * along;
          }
      return result;
    }
  } // namespace


  bool NodalLaw::may_be_nonconvex() const
  {
    return !(law.steepest_weakening() <
             weakening_cap_fraction * convexity_limit);
  }

  double NodalLaw::bound(const unsigned int p, const double s) const
  {
    return weights[p] * law.bound(s);
  }

  double NodalLaw::slope(const unsigned int p, const double s) const
  {
    return weights[p] * law.bound_derivative(s);
  }

  // For two iterates with v = v_free - D eta (D symmetric),
  //   eta^T D eta - eta_0^T D eta_0 = (eta + eta_0) . D (eta - eta_0)
  //                                 = (eta + eta_0) . (v_0 - v),
  // so E - eta_0^T D eta_0 / 2, which orders the iterates as E does, needs
  // no v_free (which on the constraints path costs a solve with K). A
  // solve's error in v is relative to the body's velocities, and the
  // quadratic term pairs them with the mean forces: the sum of those
  // products is the scale of its error.
  double NodalLaw::energy(const Vector<double> &reference_eta,
                          const Vector<double> &reference_v,
                          const Vector<double> &eta,
                          const Vector<double> &v,
                          double               &scale) const
  {
    AssertDimension(reference_eta.size(), eta.size());
    AssertDimension(reference_v.size(), v.size());
    const unsigned int m         = v.size() / weights.size();
    double             quadratic = 0, friction = 0, forces = 0;
    double             speed = velocity_scale;
    for (unsigned int r = 0; r < v.size(); ++r)
      {
        const double mean_force = 0.5 * (eta[r] + reference_eta[r]);
        quadratic += mean_force * (reference_v[r] - v[r]);
        forces += std::abs(mean_force);
        speed = std::max({speed, std::abs(v[r]), std::abs(reference_v[r])});
      }
    for (unsigned int p = 0; p < weights.size(); ++p)
      friction += weights[p] * law.potential(node_norm(v, p, m));
    scale = std::abs(quadratic) + std::abs(friction) + forces * speed;
    return quadratic + friction;
  }


  namespace
  {
    // E of the step's iterates, measured from a reference iterate
    // (NodalLaw::energy()).
    struct StepEnergy
    {
      const NodalLaw &law;
      Vector<double>  reference_eta, reference_v;

      double operator()(const Vector<double> &eta,
                        const Vector<double> &v,
                        double               &scale) const
      {
        return law.energy(reference_eta, reference_v, eta, v, scale);
      }
    };

    // The directional derivative E'(v; dv) of E at an iterate (eta, v) with
    // v = v_free - D eta, whose quadratic term has the gradient
    // D^{-1} (v - v_free) = -eta: where v_p != 0 the potential contributes
    // g_p(|v_p|) v_p / |v_p| . dv_p, where v_p = 0 its kink g_p(0) |dv_p|.
    double directional_derivative(const unsigned int    m,
                                  const NodalLaw       &law,
                                  const Vector<double> &eta,
                                  const Vector<double> &v,
                                  const Vector<double> &dv)
    {
      double derivative = 0;
      for (unsigned int p = 0; p < law.weights.size(); ++p)
        {
          const double s = node_norm(v, p, m);
          for (unsigned int i = 0; i < m; ++i)
            derivative -= eta[p * m + i] * dv[p * m + i];
          if (s > 0)
            for (unsigned int i = 0; i < m; ++i)
              derivative += law.bound(p, s) * v[p * m + i] / s * dv[p * m + i];
          else
            derivative += law.bound(p, 0.) * node_norm(dv, p, m);
        }
      return derivative;
    }

    // x = from + t (to - from): the point at length t along the step from
    // `from` to `to`.
    void point_along(const Vector<double> &from,
                     const Vector<double> &to,
                     const double          t,
                     Vector<double>       &x)
    {
      x = from;
      x.add(t, to, -t, from);
    }

    // Backtracking on E from (eta, v) towards the Newton iterate
    // (new_eta, new_v), which (eta, v) move to together, v = v_free - D eta
    // being affine in eta, so that a shorter step costs no solve: halved
    // while the length stays above shortest_length (three times by default:
    // a third halving saves convexification steps, a fourth was rarely
    // taken in the 3D scenes; see solve_friction_newton() for the longer
    // search). A length t is accepted on sufficient decrease, E(t) <= E(0) +
    // sufficient_decrease t min(E', 0) up to the accuracy of E
    // (law.energy_accuracy; near the solution the decrease is below it).
    // Returns the step length, 0 if none was accepted.
    double backtrack(const NodalLaw       &law,
                     const StepEnergy     &energy_of,
                     const Vector<double> &eta,
                     const Vector<double> &v,
                     const double          energy,
                     Vector<double>       &new_eta,
                     Vector<double>       &new_v,
                     double               &new_energy,
                     const double          shortest_length = 0.1)
    {
      const unsigned int m = v.size() / law.weights.size();
      Vector<double>     dv(new_v);
      dv -= v;
      const double descent =
        std::min(directional_derivative(m, law, eta, v, dv), 0.);
      double     scale = 0;
      const auto full_eta(new_eta), full_v(new_v);
      const auto sufficient = [&](const double length) {
        new_energy = energy_of(new_eta, new_v, scale);
        // (A step whose solve broke down gives no finite E to compare.)
        return std::isfinite(new_energy) &&
               new_energy <= energy + sufficient_decrease * length * descent +
                               law.energy_accuracy * scale;
      };
      if (sufficient(1.))
        return 1.;
      for (double length = 0.5; length > shortest_length; length /= 2)
        {
          point_along(eta, full_eta, length, new_eta);
          point_along(v, full_v, length, new_v);
          if (sufficient(length))
            return length;
        }
      return 0.;
    }

    // Along a step that lowered E at full length, longer lengths 2, 4, ...
    // up to longest_extrapolation while each lowers E further (no solve:
    // eta and v move together). (new_eta, new_v, new_energy) are the full
    // step on entry and the longest such step on return.
    void extrapolate(const NodalLaw       &law,
                     const StepEnergy     &energy_of,
                     const Vector<double> &eta,
                     const Vector<double> &v,
                     Vector<double>       &new_eta,
                     Vector<double>       &new_v,
                     double               &new_energy)
    {
      const Vector<double> full_eta(new_eta), full_v(new_v);
      Vector<double>       trial_eta(eta.size()), trial_v(v.size());
      for (double length = 2.; length <= longest_extrapolation; length *= 2)
        {
          point_along(eta, full_eta, length, trial_eta);
          point_along(v, full_v, length, trial_v);
          double       scale        = 0;
          const double trial_energy = energy_of(trial_eta, trial_v, scale);
          if (!(std::isfinite(trial_energy) &&
                trial_energy < new_energy - law.energy_accuracy * scale))
            return;
          new_eta.swap(trial_eta);
          new_v.swap(trial_v);
          new_energy = trial_energy;
        }
    }

    // The responses of the capped model to more force along zhat_b on the
    // slip nodes B that weaken faster than `cap`, and the capacitance matrix
    // they give. With the true slopes the Newton matrix is
    // H = H_c - sum_{p in B} delta_p z_p z_p^T, where H_c caps the
    // weakening at `cap` (positive definite, below the convexity limit),
    // delta_p is the excess and z_p the load of a unit force along zhat_p.
    // H is positive definite iff the capacitance matrix
    // I - Delta^{1/2} Z^T H_c^{-1} Z Delta^{1/2} is (Sylvester's law of
    // inertia), and Z^T H_c^{-1} Z is the response of the slip velocities
    // along zhat to unit forces, which |B| + 1 Newton steps with the capped
    // model give (more force along zhat_b is the load -z_b; it is scaled
    // like the forces, so that the difference of two steps is not lost in
    // their round-off): |B| + 1 solves.
    struct SteepResponses
    {
      std::vector<unsigned int> nodes;
      std::vector<double>       excess;
      // Forces and velocities per unit force along zhat_b.
      std::vector<Vector<double>> eta, v;
      LAPACKFullMatrix<double>    capacitance;
    };

    SteepResponses steep_responses(const TrescaNewtonStep        &newton_step,
                                   const unsigned int             m,
                                   const NodalLaw                &law,
                                   const double                   cap,
                                   std::vector<NodeLinearisation> capped,
                                   const Vector<double>          &eta,
                                   const Vector<double>          &v)
    {
      SteepResponses result;
      for (unsigned int p = 0; p < capped.size(); ++p)
        if (capped[p].state == NodeState::slip &&
            capped[p].slope < -cap * law.weights[p])
          {
            result.nodes.push_back(p);
            result.excess.push_back(-capped[p].slope - cap * law.weights[p]);
            capped[p].slope = -cap * law.weights[p];
          }
      const auto response = [&](const std::vector<NodeLinearisation> &model,
                                Vector<double>                       &force,
                                Vector<double>                       &w) {
        force = eta;
        w     = v;
        newton_step(model, force, w);
      };
      double force_scale = 0;
      for (const NodeLinearisation &node : capped)
        force_scale = std::max(force_scale, node.bound);
      Vector<double> base_eta, base_v;
      response(capped, base_eta, base_v);
      const unsigned int n_steep = result.nodes.size();
      result.eta.resize(n_steep);
      result.v.resize(n_steep);
      result.capacitance.reinit(n_steep, n_steep);
      for (unsigned int b = 0; b < n_steep; ++b)
        {
          std::vector<NodeLinearisation> model = capped;
          model[result.nodes[b]].force += force_scale;
          response(model, result.eta[b], result.v[b]);
          result.eta[b] -= base_eta;
          result.eta[b] /= force_scale;
          result.v[b] -= base_v;
          result.v[b] /= force_scale;
          for (unsigned int a = 0; a < n_steep; ++a)
            {
              double along = 0;
              for (unsigned int i = 0; i < m; ++i)
                along += capped[result.nodes[a]].direction[i] *
                         result.v[b][result.nodes[a] * m + i];
              result.capacitance(a, b) =
                (a == b ? 1. : 0.) +
                std::sqrt(result.excess[a] * result.excess[b]) * along;
            }
        }
      return result;
    }

    // The curvature test from Newton steps alone, for a path whose own test
    // cannot tell (the Delassus path where D is singular on the stick
    // unknowns; tests/unit/friction_newton_minimum compares it with the
    // dense test).
    Curvature
    capacitance_test(const TrescaNewtonStep               &newton_step,
                     const unsigned int                    m,
                     const NodalLaw                       &law,
                     const double                          cap,
                     const std::vector<NodeLinearisation> &linearisation,
                     const Vector<double>                 &eta,
                     const Vector<double>                 &v)
    {
      return definiteness(
        steep_responses(newton_step, m, law, cap, linearisation, eta, v)
          .capacitance);
    }

    // The eigenvector of the symmetric part of `matrix` for its lowest
    // eigenvalue if that is negative, else an empty vector.
    Vector<double> most_negative_direction(LAPACKFullMatrix<double> matrix)
    {
      const unsigned int n = matrix.m();
      Vector<double>     direction;
      if (n == 0)
        return direction;
      double size = 1.;
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < a; ++b)
          matrix(a, b) = matrix(b, a) = 0.5 * (matrix(a, b) + matrix(b, a));
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          size += std::abs(matrix(a, b));
      Vector<double>     eigenvalues;
      FullMatrix<double> eigenvectors;
      matrix.compute_eigenvalues_symmetric(
        -size, 0., 1e-12 * size, eigenvalues, eigenvectors);
      if (eigenvalues.size() == 0)
        return direction;
      unsigned int lowest = 0;
      for (unsigned int k = 1; k < eigenvalues.size(); ++k)
        if (eigenvalues[k] < eigenvalues[lowest])
          lowest = k;
      direction.reinit(n);
      for (unsigned int a = 0; a < n; ++a)
        direction[a] = eigenvectors(a, lowest);
      return direction;
    }

    // The length t in +-reach 2^{-k}, k = 0, ..., 9, with the lowest
    // E(eta + t deta, v + t dv), if that is below `energy` (then lowered to
    // it) beyond round-off; 0 otherwise.
    double lowest_energy_along(const StepEnergy     &energy_of,
                               const Vector<double> &eta,
                               const Vector<double> &v,
                               const Vector<double> &direction_eta,
                               const Vector<double> &direction_v,
                               const double          reach,
                               double               &energy)
    {
      double         scale = 0, best_length = 0;
      Vector<double> trial_eta(eta), trial_v(v);
      for (const double sign : {1., -1.})
        for (double length = reach; length > 1e-3 * reach; length /= 2)
          {
            trial_eta = eta;
            trial_eta.add(sign * length, direction_eta);
            trial_v = v;
            trial_v.add(sign * length, direction_v);
            const double trial_energy = energy_of(trial_eta, trial_v, scale);
            if (trial_energy < energy - energy_of.law.energy_accuracy * scale)
              {
                energy      = trial_energy;
                best_length = sign * length;
              }
          }
      return best_length;
    }

    // Leaves a stationary point of E that is not a local minimum along the
    // direction of most negative curvature on the slip set: with y the
    // eigenvector of the capacitance matrix for its smallest eigenvalue
    // 1 - mu < 0, the response (deta, dv) of the capped model to the forces
    // Delta^{1/2} y along zhat has the curvature
    //   dv^T H dv = mu (1 - mu) |y|^2 < 0,
    // so E falls to both sides. v and eta move together (v = v_free - D
    // eta stays affine), so the line search costs no solve: the lengths
    // that change a slip rate by up to twice the fastest steep node's rate,
    // both ways, and the lowest E is taken if it is below the saddle's.
    // Returns whether E fell. Its |B| + 1 Newton steps are those of the
    // capacitance test.
    bool leave_saddle(const TrescaNewtonStep               &newton_step,
                      const unsigned int                    m,
                      const NodalLaw                       &law,
                      const StepEnergy                     &energy_of,
                      const std::vector<NodeLinearisation> &linearisation,
                      double                               &energy,
                      Vector<double>                       &eta,
                      Vector<double>                       &v)
    {
      const double cap = weakening_cap_fraction * law.convexity_limit;
      if (!(cap > 0))
        return false;
      const SteepResponses responses =
        steep_responses(newton_step, m, law, cap, linearisation, eta, v);
      const Vector<double> y = most_negative_direction(responses.capacitance);
      if (y.size() == 0)
        return false;
      Vector<double> direction_eta(eta.size()), direction_v(v.size());
      double         fastest = 0;
      for (unsigned int b = 0; b < y.size(); ++b)
        {
          const double force = std::sqrt(responses.excess[b]) * y[b];
          direction_eta.add(force, responses.eta[b]);
          direction_v.add(force, responses.v[b]);
          fastest = std::max(fastest, node_norm(v, responses.nodes[b], m));
        }
      double largest_change = 0;
      for (unsigned int p = 0; p < linearisation.size(); ++p)
        largest_change = std::max(largest_change, node_norm(direction_v, p, m));
      if (!(largest_change > 0))
        return false;
      const double length = lowest_energy_along(energy_of,
                                                eta,
                                                v,
                                                direction_eta,
                                                direction_v,
                                                2. * fastest / largest_change,
                                                energy);
      if (length == 0.)
        return false;
      eta.add(length, direction_eta);
      v.add(length, direction_v);
      return true;
    }

    // Whether a solution is a local minimum of E: certified without a test
    // where every slip node weakens slower than weakening_cap_fraction
    // times the convexity limit (friction_solver.cc), by the path's
    // curvature test on the Hessian otherwise, or where that cannot tell by
    // the capacitance test. Returns the verdict.
    Curvature test_second_order(const unsigned int      m,
                                const NodalLaw         &law,
                                const CurvatureTest    &curvature,
                                const TrescaNewtonStep &newton_step,
                                const Vector<double>   &c,
                                const Vector<double>   &eta,
                                const Vector<double>   &v,
                                FrictionNewtonResult   &result)
    {
      const double certified     = weakening_cap_fraction * law.convexity_limit;
      const auto   linearisation = linearise_law(m, eta, v, law, c, false);
      for (unsigned int p = 0; p < linearisation.size(); ++p)
        {
          const double weakening = -linearisation[p].slope;
          if (linearisation[p].state == NodeState::slip && weakening > 0 &&
              !(weakening < certified * law.weights[p]))
            result.beyond_convexity_limit = true;
        }
      Curvature verdict = Curvature::positive;
      try
        {
          if (result.beyond_convexity_limit)
            verdict = curvature(linearisation);
          if (verdict == Curvature::unknown && certified > 0)
            verdict = capacitance_test(
              newton_step, m, law, certified, linearisation, eta, v);
        }
      catch (const ExcIndefiniteNewtonMatrix &)
        {
          // The capped model's matrix was refused: nothing is certified.
          verdict = Curvature::unknown;
        }
      result.converged             = (verdict == Curvature::positive);
      result.minimum_not_certified = !result.converged;
      return verdict;
    }

    // One convexification step from (eta, v): the Tresca problem with the
    // bounds of the slip rates of v, which lowers E because j is concave
    // along |v| (a majorisation), its forces and velocities in
    // (new_eta, new_v). False if the active set method did not converge to
    // `tolerance` (relative to the largest bound).
    bool
    convexification_step(const TrescaNewtonStep &newton_step,
                         const unsigned int      m,
                         const NodalLaw         &law,
                         const Vector<double>   &c,
                         const unsigned int      max_active_set_iterations,
                         const Vector<double>   &eta,
                         const Vector<double>   &v,
                         Vector<double>         &new_eta,
                         Vector<double>         &new_v,
                         FrictionNewtonResult   &result,
                         const double tolerance = friction_residual_tolerance)
    {
      Vector<double> bound(c.size());
      for (unsigned int p = 0; p < c.size(); ++p)
        bound[p] = law.bound(p, node_norm(v, p, m));
      new_eta = eta;
      new_v   = v;
      // No velocity function: the active set method's first sets are those
      // of (eta, v), which costs no solve even where v is not the velocity
      // of eta this step (the previous step's state at the start of a
      // step).
      std::vector<NodeState> state;
      const TrescaResult     tresca = solve_tresca(TrescaVelocity(),
                                               newton_step,
                                               m,
                                               bound,
                                               c,
                                               max_active_set_iterations,
                                               new_eta,
                                               new_v,
                                               state,
                                               tolerance);
      result.active_set_iterations += tresca.iterations;
      return tresca.converged;
    }

    // Where the capped model creeps (solve_friction_newton()), the slip
    // nodes that weaken faster than the cap and slowed down in the last
    // step are proposed to stick: one Newton step with them held at
    // v_p = 0, taken if it lowers E. Returns whether it was taken.
    bool propose_stick(const TrescaNewtonStep        &newton_step,
                       const unsigned int             m,
                       const NodalLaw                &law,
                       const StepEnergy              &energy_of,
                       const Vector<double>          &previous_v,
                       std::vector<NodeLinearisation> proposal,
                       double                        &energy,
                       Vector<double>                &eta,
                       Vector<double>                &v)
    {
      bool any = false;
      for (unsigned int p = 0; p < proposal.size(); ++p)
        {
          const double s = node_norm(v, p, m);
          if (proposal[p].state == NodeState::slip && proposal[p].bound > 0 &&
              law.slope(p, s) < proposal[p].definite_slope &&
              s < node_norm(previous_v, p, m))
            {
              proposal[p].state = NodeState::stick;
              any               = true;
            }
        }
      if (!any)
        return false;
      Vector<double> trial_eta(eta), trial_v(v);
      try
        {
          newton_step(proposal, trial_eta, trial_v);
        }
      catch (const ExcIndefiniteNewtonMatrix &)
        {
          return false;
        }
      double       scale        = 0;
      const double trial_energy = energy_of(trial_eta, trial_v, scale);
      if (!(trial_energy < energy - law.energy_accuracy * scale))
        return false;
      eta.swap(trial_eta);
      v.swap(trial_v);
      energy = trial_energy;
      return true;
    }

    // The complementarity residual with the bounds of the slip rates at
    // which the law was linearised.
    double law_residual(const unsigned int                    m,
                        const std::vector<NodeLinearisation> &linearisation,
                        const Vector<double>                 &eta,
                        const Vector<double>                 &v,
                        const Vector<double>                 &c)
    {
      Vector<double> bound(c.size());
      for (unsigned int p = 0; p < c.size(); ++p)
        bound[p] = linearisation[p].bound;
      return complementarity_residual(m, eta, v, bound, c);
    }
  } // namespace


  FrictionNewtonResult
  solve_friction_newton(const TrescaNewtonStep &newton_step,
                        const CurvatureTest    &curvature,
                        const unsigned int      m,
                        const NodalLaw         &law,
                        const Vector<double>   &c,
                        const unsigned int      max_iterations,
                        const unsigned int      max_active_set_iterations,
                        Vector<double>         &eta,
                        Vector<double>         &v,
                        std::vector<NodeState> &state)
  {
    const unsigned int n = c.size();
    AssertDimension(eta.size(), n * m);
    FrictionNewtonResult result;
    double               largest_bound = std::numeric_limits<double>::min();
    for (unsigned int p = 0; p < n; ++p)
      largest_bound = std::max(largest_bound, law.bound(p, 0.));
    const double tolerance = friction_residual_tolerance * largest_bound;
    // Whether the model caps the weakening, and may switch to the true
    // slope.
    const bool may_uncap = std::isfinite(law.weakening_cap);
    bool       capped    = may_uncap;

    // Where E may be nonconvex the first iterate is the convexification's
    // (friction.h); elsewhere the first step is taken from the
    // linearisation at the previous step's state. The energy is only
    // formed when a line search needs it, so that a step solved by its
    // start or its first full Newton step never forms it. It is measured
    // from the first iterate where it is needed (NodalLaw::energy()), a
    // solution of the step's equations with v = v_free - D eta: the
    // start's where E may be nonconvex, a Newton step's otherwise.
    double     energy = std::numeric_limits<double>::quiet_NaN();
    StepEnergy energy_of{law, {}, {}};
    // Whether (eta, v) solve the step's equations: not the previous step's
    // state on entry.
    bool       solves_step = false;
    const auto energy_from = [&](const Vector<double> &reference_eta,
                                 const Vector<double> &reference_v) {
      Assert(std::isnan(energy), ExcInternalError());
      energy_of.reference_eta = reference_eta;
      energy_of.reference_v   = reference_v;
      double scale            = 0;
      return energy_of(reference_eta, reference_v, scale);
    };
    // E at the current iterate, where it is first needed.
    const auto energy_here = [&]() {
      Assert(solves_step, ExcInternalError());
      return energy_from(eta, v);
    };
    const bool nonconvex = law.may_be_nonconvex();
    if (nonconvex)
      {
        Vector<double> start_eta, start_v(v);
        ++result.convexification_steps;
        if (!convexification_step(newton_step,
                                  m,
                                  law,
                                  c,
                                  max_active_set_iterations,
                                  eta,
                                  v,
                                  start_eta,
                                  start_v,
                                  result,
                                  start_residual_tolerance))
          {
            result.tresca_failed = true;
            return result;
          }
        eta.swap(start_eta);
        v.swap(start_v);
        solves_step = true;
      }
    auto           linearisation = linearise_law(m, eta, v, law, c, capped);
    Vector<double> new_eta(eta), new_v(v);
    // The model switches to the true slope once the sets repeat after a
    // full step and the residual is below uncap_below. Where neither model
    // descends from an iterate, the other one is tried before the
    // convexification step; a failed true step halves uncap_below, so that
    // the two models do not take turns at the same residual.
    double residual      = std::numeric_limits<double>::infinity();
    double uncap_below   = 0.1 * largest_bound;
    bool   capped_failed = false, uncapped_failed = false;
    // Full capped steps on repeating sets whose residual grew: where a
    // node's true weakening is much steeper than the cap, the capped model
    // creeps towards its stick state (the residual grows by 10 to 40 % per
    // step while E falls by little, until the node sticks), so after
    // creep_limit such steps the nodes that slow down are proposed to
    // stick (propose_stick()).
    unsigned int       creeping    = 0;
    const unsigned int creep_limit = 3;
    // Full capped steps on repeating sets whose residual fell by less than
    // 30 % (or grew, so creeping steps count too): where E is nearly flat along
    // the step (near a fold of the slip solutions, at slip onset) the model's
    // curvature is far above E's, and its steps are far too short. After
    // slow_limit such steps in a row, a full capped step is extrapolated
    // (extrapolate()).
    unsigned int       slow_steps       = 0;
    const unsigned int slow_limit       = 2;
    const double       slow_contraction = 0.7;
    // At a solution of the law: whether it ends the step, i.e. is a
    // certified local minimum, or a saddle that could not be left. A saddle
    // is left along its negative curvature (leave_saddle()) up to
    // max_saddle_exits times per step; E is then below the saddle's, which
    // no later step returns to (every one lowers E), and the method goes
    // on from there with the capped model (where the law has a cap), its
    // counters of slow and creeping steps reset.
    const unsigned int max_saddle_exits = 3;
    const auto         ends_step        = [&]() {
      const Curvature verdict =
        test_second_order(m, law, curvature, newton_step, c, eta, v, result);
      if (verdict != Curvature::not_positive ||
          result.saddle_exits == max_saddle_exits)
        return true;
      if (std::isnan(energy))
        energy = energy_here();
      // The true slopes: the iterate may have converged with the capped
      // model, whose slopes are all at the cap.
      if (!leave_saddle(newton_step,
                        m,
                        law,
                        energy_of,
                        linearise_law(m, eta, v, law, c, false),
                        energy,
                        eta,
                        v))
        return true;
      ++result.saddle_exits;
      // The next end point is judged on its own.
      result.minimum_not_certified  = false;
      result.beyond_convexity_limit = false;
      capped                        = may_uncap;
      capped_failed = uncapped_failed = false;
      creeping = slow_steps = 0;
      residual              = std::numeric_limits<double>::infinity();
      linearisation         = linearise_law(m, eta, v, law, c, capped);
      return false;
    };
    // The start may already solve the step (a sticking step after a
    // sticking one does).
    const bool solved =
      nonconvex && law_residual(m, linearisation, eta, v, c) <= tolerance &&
      ends_step();
    // The full step with the true slopes from the current iterate, kept
    // while it failed there (see below).
    Vector<double> true_step_eta, true_step_v;
    while (!solved && result.iterations < max_iterations)
      {
        ++result.iterations;
        new_eta      = eta;
        new_v        = v;
        double scale = 0, new_energy = energy, length = 1.;
        bool   refused = false;
        // The model whose step is taken (the longer search below takes the
        // true one).
        bool capped_step = capped;
        try
          {
            newton_step(linearisation, new_eta, new_v);
          }
        catch (const ExcIndefiniteNewtonMatrix &)
          {
            // Both models give the solver the same capped matrix: straight
            // to the convexification step.
            refused = true;
            length  = 0.;
          }
        if (!refused && (result.iterations > 1 || nonconvex))
          {
            if (std::isnan(energy))
              energy = energy_here();
            if (!capped)
              {
                true_step_eta = new_eta;
                true_step_v   = new_v;
              }
            length = backtrack(
              law, energy_of, eta, v, energy, new_eta, new_v, new_energy);
          }
        if (length == 0. && !refused)
          {
            (capped ? capped_failed : uncapped_failed) = true;
            if (may_uncap &&
                (capped ? !uncapped_failed && residual < uncap_below :
                          !capped_failed))
              {
                if (!capped)
                  uncap_below = 0.5 * residual;
                capped        = !capped;
                linearisation = linearise_law(m, eta, v, law, c, capped);
                continue;
              }
          }
        if (length == 0. && uncapped_failed)
          {
            // Neither model's step lowered E within three halvings (or the
            // true one, where no cap makes it the only model). Where
            // the Hessian on the slip set is nearly singular the true step
            // is far too long, and a short step along it may still lower E
            // (the line search decides, as for every step): it is
            // searched down to 1/64 of its length, which costs no solve,
            // before the convexification step, which costs several (on the
            // 3D scene at h = k = 1/16 with CG-AMG, 10.7 instead of 11.2
            // solves with K per step, the same solutions:
            // doc/algorithm.md).
            new_eta     = true_step_eta;
            new_v       = true_step_v;
            capped_step = false;
            length      = backtrack(law,
                               energy_of,
                               eta,
                               v,
                               energy,
                               new_eta,
                               new_v,
                               new_energy,
                               shortest_true_step);
          }
        capped_failed = uncapped_failed = false;
        if (length == 0.)
          {
            // No descent along the Newton direction: one convexification
            // step instead, solved like the start (its sets decide where
            // Newton goes on from). Should that rough solution not lower E
            // (the exact one does), it is solved to the full tolerance and
            // taken (converged, its residual and so its E are finite).
            // Where the solver refused the first Newton step of a convex
            // problem, the iterate is still the previous step's state,
            // which does not solve this step's equations: E is not known
            // there, and the rough solution is taken.
            if (std::isnan(energy) && solves_step)
              energy = energy_here();
            bool solved_step = false;
            ++result.convexification_steps;
            for (const double step_tolerance :
                 {start_residual_tolerance, friction_residual_tolerance})
              {
                solved_step = convexification_step(newton_step,
                                                   m,
                                                   law,
                                                   c,
                                                   max_active_set_iterations,
                                                   eta,
                                                   v,
                                                   new_eta,
                                                   new_v,
                                                   result,
                                                   step_tolerance);
                if (!solved_step)
                  break;
                if (!solves_step)
                  {
                    new_energy = energy_from(new_eta, new_v);
                    break;
                  }
                new_energy = energy_of(new_eta, new_v, scale);
                if (new_energy <= energy + law.energy_accuracy * scale)
                  break;
              }
            if (!solved_step)
              {
                result.tresca_failed = true;
                break;
              }
          }
        else if (length < 1.)
          ++result.damped_steps;
        else if (capped_step && slow_steps >= slow_limit)
          extrapolate(law, energy_of, eta, v, new_eta, new_v, new_energy);

        const std::vector<int> previous_sets = set_signature(linearisation);
        eta.swap(new_eta);
        v.swap(new_v);
        solves_step                = true;
        energy                     = new_energy;
        linearisation              = linearise_law(m, eta, v, law, c, capped);
        const double last_residual = residual;
        residual                   = law_residual(m, linearisation, eta, v, c);
        const bool sets_repeat = set_signature(linearisation) == previous_sets;
        if (sets_repeat && residual <= tolerance)
          {
            if (ends_step())
              break;
            continue;
          }
        const bool full_capped_step =
          capped_step && sets_repeat && length == 1.;
        creeping =
          (full_capped_step && residual > last_residual ? creeping + 1 : 0);
        slow_steps =
          (full_capped_step && residual > slow_contraction * last_residual ?
             slow_steps + 1 :
             0);
        if (creeping >= creep_limit && result.iterations < max_iterations)
          {
            // new_v holds the iterate before the last step.
            creeping = 0;
            ++result.iterations;
            if (propose_stick(newton_step,
                              m,
                              law,
                              energy_of,
                              new_v,
                              linearisation,
                              energy,
                              eta,
                              v))
              {
                slow_steps    = 0;
                linearisation = linearise_law(m, eta, v, law, c, capped);
                residual      = law_residual(m, linearisation, eta, v, c);
                continue;
              }
          }
        if (may_uncap && full_capped_step && residual < uncap_below)
          {
            capped        = false;
            linearisation = linearise_law(m, eta, v, law, c, capped);
          }
      }
    state.resize(n);
    for (unsigned int p = 0; p < n; ++p)
      state[p] = linearisation[p].state;
    return result;
  }

} // namespace Contact
