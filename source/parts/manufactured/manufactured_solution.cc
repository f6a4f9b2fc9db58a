/* The exact solution with a stick/slip front used for verification. */

#include <deal.II/base/exceptions.h>

#include <base/dimensions.h>
#include <parts/manufactured/manufactured_solution.h>

#include <algorithm>
#include <cmath>

namespace Contact
{
  template <int dim>
  ManufacturedSolution<dim>::ManufacturedSolution(const Parameters &parameters)
    : amplitude(parameters.verification.amplitude)
    , rho(parameters.material.density)
    , mu1(parameters.material.viscosity_mu1)
    , mu2(parameters.material.viscosity_mu2)
    , lambda(parameters.material.lambda(dim))
    , two_G(parameters.material.two_G())
    , friction_law(parameters.friction)
  {}

  template <int dim>
  double ManufacturedSolution<dim>::theta(const double t) const
  {
    return amplitude * (t + 0.5 * t * t);
  }

  template <int dim>
  double ManufacturedSolution<dim>::theta_dot(const double t) const
  {
    return amplitude * (1. + t);
  }

  template <int dim>
  Tensor<1, dim> ManufacturedSolution<dim>::shape(const Point<dim> &p) const
  {
    const double   r = std::max(p[0] - 0.5, 0.);
    Tensor<1, dim> U;
    U[0] = r * r * r + p[0] * p[1];
    U[1] = 0.5 * p[0] * p[1];
    return U;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  ManufacturedSolution<dim>::shape_strain(const Point<dim> &p) const
  {
    const double            r = std::max(p[0] - 0.5, 0.);
    SymmetricTensor<2, dim> eps;
    eps[0][0] = 3. * r * r + p[1];
    eps[1][1] = 0.5 * p[0];
    eps[0][1] = 0.5 * (p[0] + 0.5 * p[1]);
    return eps;
  }

  template <int dim>
  Tensor<1, dim> ManufacturedSolution<dim>::displacement(const Point<dim> &p,
                                                         const double t) const
  {
    return theta(t) * shape(p);
  }

  template <int dim>
  Tensor<1, dim> ManufacturedSolution<dim>::velocity(const Point<dim> &p,
                                                     const double      t) const
  {
    return theta_dot(t) * shape(p);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  ManufacturedSolution<dim>::displacement_strain(const Point<dim> &p,
                                                 const double      t) const
  {
    return theta(t) * shape_strain(p);
  }

  // sigma = A eps(w) + B eps(u) = L tr(eps(U)) I + M eps(U) with
  // L = mu_1 theta' + lambda theta and M = mu_2 theta' + 2G theta, (3.1).
  template <int dim>
  SymmetricTensor<2, dim>
  ManufacturedSolution<dim>::stress(const Point<dim> &p, const double t) const
  {
    const double                  L   = mu1 * theta_dot(t) + lambda * theta(t);
    const double                  M   = mu2 * theta_dot(t) + two_G * theta(t);
    const SymmetricTensor<2, dim> eps = shape_strain(p);
    return L * trace(eps) * unit_symmetric_tensor<dim>() + M * eps;
  }

  // f_0 = rho u_tt - div sigma, (3.2), with theta'' = A and
  // div sigma = L grad tr(eps(U)) + M div eps(U), where
  // grad tr(eps(U)) = (6 r + 1/2, 1) and div eps(U) = (6 r + 1/4, 1/2).
  template <int dim>
  Tensor<1, dim> ManufacturedSolution<dim>::body_force(const Point<dim> &p,
                                                       const double t) const
  {
    const double   L = mu1 * theta_dot(t) + lambda * theta(t);
    const double   M = mu2 * theta_dot(t) + two_G * theta(t);
    const double   r = std::max(p[0] - 0.5, 0.);
    Tensor<1, dim> div_sigma;
    div_sigma[0] = L * (6. * r + 0.5) + M * (6. * r + 0.25);
    div_sigma[1] = L + 0.5 * M;
    return rho * amplitude * shape(p) - div_sigma;
  }

  // f_3 = sigma_tau + eta with the exact friction density eta: the
  // friction law (3.6) where the body slips, and where it sticks a force
  // strictly inside the bound, eta = xi(x) S mu(0) e_x with
  // xi(x) = 1/2 + x in (0, 1) on x < 1/2 (continuous with the slip side at
  // the front), so that the stick condition binds: without it the body
  // would slip there.
  template <int dim>
  double ManufacturedSolution<dim>::stick_fraction(const Point<dim> &p)
  {
    return 0.5 + p[0];
  }

  template <int dim>
  Tensor<1, dim>
  ManufacturedSolution<dim>::contact_load(const Point<dim>     &p,
                                          const Tensor<1, dim> &normal,
                                          const double          t) const
  {
    const auto tangential = [&](const Tensor<1, dim> &vector) {
      return vector - (vector * normal) * normal;
    };
    const Tensor<1, dim> sigma_tau = tangential(stress(p, t) * normal);
    const Tensor<1, dim> w_tau     = tangential(velocity(p, t));
    const double         rate      = w_tau.norm();
    if (rate > 0.)
      return sigma_tau + friction_law.bound(rate) / rate * w_tau;
    return sigma_tau + stick_fraction(p) * friction_law.bound(0.) *
                         tangential(Point<dim>::unit_vector(0));
  }


#define INSTANTIATE(dim) template class ManufacturedSolution<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE


  // The exact solution of a run with 'Verification/Manufactured solution'.
  namespace
  {
    bool register_manufactured_solution()
    {
#define INSTANTIATE(dim)                                                     \
  ExactSolutionParts<dim>::add(                                              \
    {"manufactured solution",                                                \
     "",                                                                     \
     0,                                                                      \
     {},                                                                     \
     [](const Parameters &parameters)                                        \
       -> std::unique_ptr<const ExactSolution<dim>> {                        \
       if (!parameters.verification.manufactured())                          \
         return nullptr;                                                     \
       return std::make_unique<const ManufacturedSolution<dim>>(parameters); \
     }});
      CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
      return true;
    }

    const bool registered = register_manufactured_solution();
  } // namespace
} // namespace Contact
