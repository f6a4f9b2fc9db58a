/* The constructor and the time loop of ContactProblem<dim>. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/grid/grid_tools.h>

#include <core/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace Contact
{
  namespace
  {
    template <int dim>
    std::unique_ptr<Triangulation<dim>>
    make_triangulation(const GeometryParameters &geometry,
                       const MPI_Comm            communicator)
    {
      if (geometry.simplex_cells &&
          Utilities::MPI::n_mpi_processes(communicator) > 1)
        return std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
          communicator);
      if (geometry.simplex_cells)
        return std::make_unique<Triangulation<dim>>();
      return std::make_unique<parallel::distributed::Triangulation<dim>>(
        communicator);
    }

    template <int dim>
    std::unique_ptr<const FiniteElement<dim>>
    make_scalar_element(const GeometryParameters &geometry)
    {
      if (geometry.simplex_cells)
        return std::make_unique<FE_SimplexP<dim>>(geometry.fe_degree);
      return std::make_unique<FE_Q<dim>>(geometry.fe_degree);
    }

    // The map of the reference cell: linear (straight edges), or of the
    // 'Mapping degree', whose points between the vertices lie on the
    // manifold of a curved boundary. Assembly, the normals of Gamma_3 and
    // its nodal weights all use this one.
    template <int dim>
    std::unique_ptr<const Mapping<dim>>
    make_mapping(const GeometryParameters &geometry)
    {
      if (geometry.simplex_cells)
        return std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
      return std::make_unique<MappingQ<dim>>(geometry.mapping_degree);
    }
  } // namespace


  // @sect4{ContactProblem::gauss_rule}

  // QGaussSimplex has rules of up to 4 points per direction in this deal.II
  // (exact for degree 7); more are not needed for the degrees offered.
  template <int dim>
  Quadrature<dim>
  ContactProblem<dim>::gauss_rule(const unsigned int n_points) const
  {
    if (parameters.geometry.simplex_cells)
      return QGaussSimplex<dim>(std::min(n_points, 4u));
    return QGauss<dim>(n_points);
  }

  template <int dim>
  Quadrature<dim - 1>
  ContactProblem<dim>::face_gauss_rule(const unsigned int n_points) const
  {
    if (parameters.geometry.simplex_cells)
      return QGaussSimplex<dim - 1>(std::min(n_points, 4u));
    return QGauss<dim - 1>(n_points);
  }


  // @sect4{ContactProblem::ContactProblem}

  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters &run_parameters)
    : parameters(run_parameters)
    , friction_law(parameters.friction)
    , n_time_steps(parameters.time.n_steps())
    , time_step(parameters.time.end_time / n_time_steps)
    , mpi_communicator(MPI_COMM_WORLD)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , computing_timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , body_force_is_constant(
        !parameters.verification.manufactured_solution &&
        !expression_uses_variable(parameters.loads.body_force, "t"))
    , triangulation(
        make_triangulation<dim>(parameters.geometry, mpi_communicator))
    , scalar_fe(make_scalar_element<dim>(parameters.geometry))
    , fe(*scalar_fe, dim)
    , mapping(make_mapping<dim>(parameters.geometry))
    , quadrature(gauss_rule(parameters.geometry.fe_degree + 1))
    , mass_quadrature(parameters.geometry.lumped_mass ?
                        Quadrature<dim>(QGaussLobatto<dim>(
                          parameters.geometry.fe_degree + 1)) :
                        quadrature)
    , face_quadrature(face_gauss_rule(parameters.geometry.fe_degree + 1))
    , dof_handler(*triangulation)
    , scalar_dof_handler(*triangulation)
    , time(0)
    , step_number(0)
    , pending_report_times(parameters.output.report_times)
  {
    AssertThrow(parameters.dimension == dim, ExcInternalError());
    body_force = parse_vector_function<dim>(Entry::body_force,
                                            parameters.loads.body_force,
                                            true);
    initial_displacement =
      parse_vector_function<dim>(Entry::initial_displacement,
                                 parameters.loads.initial_displacement,
                                 false);
    initial_velocity =
      parse_vector_function<dim>(Entry::initial_velocity,
                                 parameters.loads.initial_velocity,
                                 false);
    for (const auto &[id, expression] : parameters.boundary.tractions)
      tractions[id] =
        parse_vector_function<dim>(Entry::tractions + " (boundary id " +
                                     std::to_string(id) + ")",
                                   expression,
                                   true);
    if (parameters.verification.manufactured_solution)
      exact_solution = std::make_unique<ManufacturedSolution<dim>>(parameters);
  }


  // @sect4{ContactProblem::run}

  template <int dim>
  RunSummary ContactProblem<dim>::run()
  {
    run_timer.restart();
    claim_output_directory();
    if (parameters.output.resume)
      require_checkpoint();
    make_grid();
    if (exact_solution)
      check_manufactured_setup();
    setup_system();
    assemble_matrices();
    if (body_force_is_constant)
      assemble_constant_body_load();
    set_initial_values();
    start_self_checks();
    factorize_system_matrix();
    friction_solver->reinit(system_matrix, *factorization);
    friction_solver->set_initial_velocity(velocity);

    step_number = 0;
    if (parameters.output.resume)
      load_checkpoint();
    prepare_output_directory();
    if (!parameters.output.resume)
      {
        if (exact_solution)
          current_errors = compute_errors();
        write_time_series_row(StepStatistics());
        write_gamma3_history_rows();
        if (parameters.output.vtu_interval > 0)
          write_vtu();
      }
    time_loop();
    finish_vtu();
    step_number = n_time_steps;
    print_summary();
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        // Removed only if empty: what a killed run left there stays.
        std::error_code error;
        std::filesystem::remove(parameters.output.directory + "/.partial",
                                error);
      }
    // The lock on the output directory is kept until the problem is
    // destroyed: an error estimate's coarse runs still write under it.
    require_self_checks();

    RunSummary summary;
    // A box has round(edge / h) cells along each edge: the largest of
    // their sizes is the h it has.
    summary.cell_size = 0;
    if (parameters.geometry.is_box())
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double edge = parameters.geometry.upper_corner[d] -
                              parameters.geometry.lower_corner[d];
          summary.cell_size = std::max(
            summary.cell_size,
            edge /
              std::max(1., std::round(edge / parameters.geometry.cell_size)));
        }
    else
      summary.cell_size =
        GridTools::maximal_cell_diameter(*triangulation, *mapping);
    summary.time_step           = time_step;
    summary.n_steps             = n_time_steps;
    summary.n_dofs              = dof_handler.n_dofs();
    summary.wall_time           = run_timer.wall_time();
    summary.max_errors          = max_errors;
    summary.displacement_V_norm = strain_norm(displacement);
    summary.final_errors        = current_errors;
    summary.final_quantities    = final_quantities();
    return summary;
  }


  // @sect4{ContactProblem::time_loop}

  // The steps t_1, ..., t_N (from the checkpoint's step on a resumed run),
  // and after each what the user asked to see of it.
  template <int dim>
  void ContactProblem<dim>::time_loop()
  {
    const unsigned int vtu_interval = parameters.output.vtu_interval;
    time_loop_timer.restart();
    for (++step_number; step_number <= n_time_steps; ++step_number)
      {
        time                            = step_number * time_step;
        const StepStatistics statistics = advance(parameters.solver.step_cuts);
        ++steps_timed;
        AssertThrow(std::isfinite(velocity.linfty_norm()) &&
                      std::isfinite(energy.residual()),
                    ExcMessage("Step " + std::to_string(step_number) +
                               " (t = " + std::to_string(time) +
                               ") produced a velocity or energy that is not "
                               "a finite number; the results up to step " +
                               std::to_string(step_number - 1) +
                               " are written. Check the loads and material "
                               "data for values that overflow."));

        if (exact_solution)
          {
            current_errors            = compute_errors();
            max_errors.displacement_V = std::max(max_errors.displacement_V,
                                                 current_errors.displacement_V);
            max_errors.velocity_L2 =
              std::max(max_errors.velocity_L2, current_errors.velocity_L2);
            max_errors.displacement_L2 =
              std::max(max_errors.displacement_L2,
                       current_errors.displacement_L2);
          }

        totals.add_counts(statistics);

        track_slip_onset();
        write_time_series_row(statistics);
        write_gamma3_history_rows();
        if (vtu_interval > 0 && (step_number % vtu_interval == 0 ||
                                 step_number == n_time_steps || report_due()))
          write_vtu();
        print_progress(statistics);
        report_contact_state();
        if (step_observer)
          step_observer(*this);
        if (checkpoint_due())
          save_checkpoint();
      }
  }


  // A run that ends with an error completes the VTU output of the last
  // written step; on several processes the others may not get here, and
  // its pieces stay in .partial/ (the PVD does not list them).
  template <int dim>
  ContactProblem<dim>::~ContactProblem()
  {
    if (pending_vtu && Utilities::MPI::n_mpi_processes(mpi_communicator) == 1)
      try
        {
          finish_vtu();
        }
      catch (...)
        {
          // An output error while another error ends the run: the first
          // one is reported.
        }
  }


  template <int dim>
  void ContactProblem<dim>::set_step_observer(
    const std::function<void(const ContactProblem<dim> &)> &observer)
  {
    step_observer = observer;
  }

  template <int dim>
  unsigned int ContactProblem<dim>::get_step_number() const
  {
    return step_number;
  }

  template <int dim>
  const DoFHandler<dim> &ContactProblem<dim>::get_dof_handler() const
  {
    return dof_handler;
  }

  template <int dim>
  const Mapping<dim> &ContactProblem<dim>::get_mapping() const
  {
    return *mapping;
  }

  template <int dim>
  const VectorType &ContactProblem<dim>::get_displacement() const
  {
    return displacement;
  }


  template <int dim>
  const VectorType &ContactProblem<dim>::get_velocity() const
  {
    return velocity;
  }

  template <int dim>
  const Vector<double> &ContactProblem<dim>::get_friction_force() const
  {
    return friction_solver->state().friction_force;
  }


  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace Contact
