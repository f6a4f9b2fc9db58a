/* Errors against the manufactured solution. */

#include <deal.II/base/exceptions.h>

#include <deal.II/fe/fe_values.h>

#include <core/contact_problem.h>

#include <algorithm>
#include <cmath>

namespace Contact
{
  // @sect4{ContactProblem::check_manufactured_setup}

  // The exact solution vanishes on x = 0, has u.n = 0 on y = 0 and its
  // stick/slip front at x = 1/2: the scene must clamp the first, put the
  // contact on the second and have a mesh line on the third, or the
  // "exact" solution would not solve the discrete problem's continuous
  // counterpart, or not be resolved.
  template <int dim>
  void ContactProblem<dim>::check_manufactured_setup() const
  {
    const auto &geometry = parameters.geometry;
    const auto &boundary = parameters.boundary;
    AssertThrow(geometry.is_box(),
                ExcMessage("'" + Entry::manufactured_solution +
                           "' needs the box: '" + Entry::domain +
                           " = box' and no '" + Entry::mesh_file + "'."));
    AssertThrow(geometry.lower_corner[0] == 0. &&
                  geometry.lower_corner[1] == 0.,
                ExcMessage("'" + Entry::manufactured_solution +
                           "' needs "
                           "'" +
                           Entry::lower_corner +
                           "' to start at x = 0, y = 0."));
    AssertThrow(boundary.clamped_ids == std::vector<types::boundary_id>{0} &&
                  boundary.contact_ids == std::vector<types::boundary_id>{2},
                ExcMessage("'" + Entry::manufactured_solution +
                           "' needs "
                           "'" +
                           Entry::clamped_boundary_ids +
                           " = 0' "
                           "(x = 0) and 'Contact boundary ids = 2' (y = 0)."));
    const double length = geometry.upper_corner[0] - geometry.lower_corner[0];
    const double cells_to_front =
      0.5 / (length / std::max(1., std::round(length / geometry.cell_size)));
    AssertThrow(std::abs(cells_to_front - std::round(cells_to_front)) < 1e-8,
                ExcMessage("'" + Entry::manufactured_solution +
                           "': the "
                           "stick/slip front x = 1/2 must be a mesh line; "
                           "choose '" +
                           Entry::cell_size +
                           "' so that 1/(2h) cells "
                           "fit in [0, 1/2]."));
  }


  // @sect4{ContactProblem::compute_errors}

  // ||eps(u - u_h)||, ||w - w_h|| and ||u - u_h|| at the current time, with
  // a Gauss rule three orders above the one of the assembly so that the
  // quadrature error does not pollute the rates.
  template <int dim>
  ErrorNorms ContactProblem<dim>::compute_errors() const
  {
    const Quadrature<dim> error_quadrature = gauss_rule(fe.degree + 3);
    FEValues<dim>         fe_values(*mapping,
                            fe,
                            error_quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector     displacements(0);
    const unsigned int                   n_q = error_quadrature.size();
    std::vector<Tensor<1, dim>>          u_h(n_q), w_h(n_q);
    std::vector<SymmetricTensor<2, dim>> eps_h(n_q);

    const VectorType u = ghosted(displacement), w = ghosted(velocity);
    double           e_V = 0, e_w = 0, e_u = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacements].get_function_values(u, u_h);
          fe_values[displacements].get_function_values(w, w_h);
          fe_values[displacements].get_function_symmetric_gradients(u, eps_h);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const Point<dim>             &p   = fe_values.quadrature_point(q);
              const double                  JxW = fe_values.JxW(q);
              const SymmetricTensor<2, dim> strain_error =
                exact_solution->displacement_strain(p, time) - eps_h[q];
              e_V += strain_error * strain_error * JxW;
              e_w +=
                (exact_solution->velocity(p, time) - w_h[q]).norm_square() *
                JxW;
              e_u +=
                (exact_solution->displacement(p, time) - u_h[q]).norm_square() *
                JxW;
            }
        }
    ErrorNorms errors;
    errors.displacement_V =
      std::sqrt(Utilities::MPI::sum(e_V, mpi_communicator));
    errors.velocity_L2 = std::sqrt(Utilities::MPI::sum(e_w, mpi_communicator));
    errors.displacement_L2 =
      std::sqrt(Utilities::MPI::sum(e_u, mpi_communicator));
    return errors;
  }


  // @sect4{ContactProblem::strain_norm}

  // Norms of a field of this problem's finite element space, such as the
  // difference of two solutions interpolated onto this mesh; the Gauss rule
  // of the assembly integrates them exactly on affine cells. The cells of
  // this process need the field's ghost entries too.
  template <int dim>
  double ContactProblem<dim>::strain_norm(const VectorType &field) const
  {
    const VectorType                     v = ghosted(field);
    FEValues<dim>                        fe_values(*mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacements(0);
    std::vector<SymmetricTensor<2, dim>> eps(quadrature.size());
    double                               sum = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacements].get_function_symmetric_gradients(v, eps);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            sum += eps[q] * eps[q] * fe_values.JxW(q);
        }
    return std::sqrt(Utilities::MPI::sum(sum, mpi_communicator));
  }


#define INSTANTIATE(dim)                                                     \
  template void       ContactProblem<dim>::check_manufactured_setup() const; \
  template ErrorNorms ContactProblem<dim>::compute_errors() const;           \
  template double ContactProblem<dim>::strain_norm(const VectorType &) const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace Contact
