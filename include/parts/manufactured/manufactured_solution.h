/**
 * An exact solution of the frictional contact problem, for verification
 * (doc/verification.md). On the box with Gamma_1 = {x = 0} and
 * Gamma_3 = {y = 0}:
 *
 *   u(x, t) = theta(t) U(x),   theta(t) = A (t + t^2/2),
 *   U_x = (x - 1/2)_+^3 + x y,   U_y = x y / 2   (U_z = 0 in 3D),
 *
 * so u = 0 on Gamma_1 and u.n = 0 on Gamma_3, and on Gamma_3 the slip rate
 * w_tau = theta'(t) (x - 1/2)_+^3 vanishes on x < 1/2 (stick) and grows
 * smoothly beyond (slip, at rates where the coefficient (6.1) varies when
 * A alpha / 8 is of order 1). The data that make it exact:
 *
 *   f_0 = rho u_tt - div sigma,  f_2 = sigma n on the other sides,
 *   f_3 = sigma_tau + S mu(|w_tau|) sign(w_tau) on Gamma_3 where it slips,
 *   f_3 = sigma_tau + xi(x) S mu(0) e_x where it sticks, xi = 1/2 + x:
 *         a friction force strictly inside the bound (0 < xi < 1 on
 *         x < 1/2), so that the stick condition binds,
 *
 * with sigma = A eps(w) + B eps(u) of (3.1); f_3 is a tangential load on
 * Gamma_3, applied with the nodal weights of the friction term. The front
 * x = 1/2 is a mesh line when 1/(2h) is an integer.
 */
#ifndef contact_manufactured_solution_h
#define contact_manufactured_solution_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <core/friction.h>
#include <core/loads.h>
#include <core/parameters.h>

namespace Contact
{
  using namespace dealii;

  template <int dim>
  class ManufacturedSolution : public ExactSolution<dim>
  {
  public:
    explicit ManufacturedSolution(const Parameters &parameters);

    Tensor<1, dim> displacement(const Point<dim> &p,
                                const double      t) const override;
    Tensor<1, dim> velocity(const Point<dim> &p, const double t) const override;
    SymmetricTensor<2, dim> displacement_strain(const Point<dim> &p,
                                                const double t) const override;
    SymmetricTensor<2, dim> stress(const Point<dim> &p,
                                   const double      t) const override;
    Tensor<1, dim>          body_force(const Point<dim> &p,
                                       const double      t) const override;
    Tensor<1, dim>          contact_load(const Point<dim>     &p,
                                         const Tensor<1, dim> &normal,
                                         const double          t) const override;

    /** The box, with its stick/slip front on a mesh line
     *  (GeometryBase::check_manufactured_scene()). */
    void check_scene(const GeometryBase &geometry) const override
    {
      geometry.check_manufactured_scene();
    }

    /** xi(p) in (0, 1): the friction force in the stick zone x < 1/2 as a
     *  fraction of the bound S mu(0). */
    static double stick_fraction(const Point<dim> &p);

  private:
    double                  theta(const double t) const;
    double                  theta_dot(const double t) const;
    Tensor<1, dim>          shape(const Point<dim> &p) const;
    SymmetricTensor<2, dim> shape_strain(const Point<dim> &p) const;

    const double      amplitude;
    const double      rho;
    const double      mu1;
    const double      mu2;
    const double      lambda;
    const double      two_G;
    const FrictionLaw friction_law;
  };
} // namespace Contact

#endif
