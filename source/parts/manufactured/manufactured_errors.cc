/* The errors against a manufactured solution ('Verification/Manufactured
   solution'): at every step, the largest over the steps, and columns of
   time_series.csv. */

#include <deal.II/fe/fe_values.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <core/postprocessor.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace Contact
{
  template <int dim>
  class ManufacturedErrors : public Postprocessor<dim>
  {
  public:
    void start(const bool resumed) override
    {
      if (this->exact_solution() && !resumed)
        current_errors = compute_errors();
    }

    void after_step(const StepStatistics &, const StepEnd end) override
    {
      if (end != StepEnd::whole_step || !this->exact_solution())
        return;
      current_errors = compute_errors();
      max_errors.displacement_V =
        std::max(max_errors.displacement_V, current_errors.displacement_V);
      max_errors.velocity_L2 =
        std::max(max_errors.velocity_L2, current_errors.velocity_L2);
      max_errors.displacement_L2 =
        std::max(max_errors.displacement_L2, current_errors.displacement_L2);
    }

    void add_columns(TimeSeriesRow &row) const override
    {
      if (!this->exact_solution())
        return;
      row.add("error_V", current_errors.displacement_V);
      row.add("error_w_L2", current_errors.velocity_L2);
      row.add("error_u_L2", current_errors.displacement_L2);
    }

    void checkpoint(CheckpointArchive &archive) override
    {
      archive &current_errors &max_errors;
    }

    void finish(RunSummary &summary) override
    {
      if (this->exact_solution())
        this->pcout() << "Errors, largest over the steps: ||eps(u - u_h)|| "
                      << std::setprecision(6) << max_errors.displacement_V
                      << ", ||w - w_h|| " << max_errors.velocity_L2
                      << ", ||u - u_h|| " << max_errors.displacement_L2
                      << std::endl;
      summary.max_errors   = max_errors;
      summary.final_errors = current_errors;
    }

  private:
    ErrorNorms compute_errors() const;

    // The errors at t_n and their largest over the steps 1..n.
    ErrorNorms current_errors;
    ErrorNorms max_errors;
  };


  // @sect4{ManufacturedErrors::compute_errors}

  // ||eps(u - u_h)||, ||w - w_h|| and ||u - u_h|| at the current time, with
  // a Gauss rule three orders above the one of the assembly so that the
  // quadrature error does not pollute the rates.
  template <int dim>
  ErrorNorms ManufacturedErrors<dim>::compute_errors() const
  {
    const DiscreteSpace<dim> &space = this->space();
    const ExactSolution<dim> &exact = *this->exact_solution();
    const double              time  = this->state().time;
    const Quadrature<dim>     error_quadrature =
      space.gauss_rule(space.fe.degree + 3);
    FEValues<dim>                        fe_values(*space.mapping,
                            space.fe,
                            error_quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector     displacements(0);
    const unsigned int                   n_q = error_quadrature.size();
    std::vector<Tensor<1, dim>>          u_h(n_q), w_h(n_q);
    std::vector<SymmetricTensor<2, dim>> eps_h(n_q);

    const VectorType u = space.ghosted(this->state().displacement),
                     w = space.ghosted(this->state().velocity);
    double e_V = 0, e_w = 0, e_u = 0;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
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
                exact.displacement_strain(p, time) - eps_h[q];
              e_V += strain_error * strain_error * JxW;
              e_w += (exact.velocity(p, time) - w_h[q]).norm_square() * JxW;
              e_u += (exact.displacement(p, time) - u_h[q]).norm_square() * JxW;
            }
        }
    ErrorNorms errors;
    errors.displacement_V =
      std::sqrt(Utilities::MPI::sum(e_V, this->mpi_communicator()));
    errors.velocity_L2 =
      std::sqrt(Utilities::MPI::sum(e_w, this->mpi_communicator()));
    errors.displacement_L2 =
      std::sqrt(Utilities::MPI::sum(e_u, this->mpi_communicator()));
    return errors;
  }



  namespace
  {
    const PostprocessorRegistration<ManufacturedErrors>
      registration("manufactured errors", 50);
  }
} // namespace Contact
