/* The constructor and the time loop of ContactProblem<dim>, and what a run
   gives back. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <base/dimensions.h>
#include <base/printed_entries.h>
#include <base/version.h>
#include <core/contact_problem.h>
#include <core/csv_file.h>
#include <core/output_directory.h>
#include <core/postprocessor.h>
#include <core/geometry.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <vector>

namespace Contact
{
  namespace
  {
    // Every run writes the parameters it used.
    const ResultFiles parameter_file("parameters\\.prm");


    // @sect4{check_step_tables}

    // On --resume every table of steps in the output directory (a .csv
    // file whose header starts with its step) is checked up to the
    // checkpoint's step before any of them is cut back.
    void check_step_tables(const std::string &directory,
                           const unsigned int step)
    {
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      for (const auto &entry : std::filesystem::directory_iterator(directory))
        {
          std::ifstream table(entry.path());
          std::string   header;
          if (entry.path().extension() == ".csv" &&
              std::getline(table, header) && header.rfind("step,", 0) == 0)
            CsvFile::rows_up_to(entry.path().string(), step);
        }
    }


    // @sect4{report_mesh}

    // The size of the problem, and a warning where the mapping costs the
    // tractions an order.
    template <int dim>
    void report_mesh(const Parameters           &parameters,
                     const Geometry<dim>        &geometry,
                     const DiscreteSpace<dim>   &space,
                     const ContactBoundary<dim> &gamma3,
                     const ConditionalOStream   &pcout)
    {
      pcout << "Mesh: " << space.triangulation->n_global_active_cells()
            << " cells, "
            << (parameters.geometry.cell_shape ==
                    GeometryParameters::CellShape::simplex ?
                  'P' :
                  'Q')
            << space.fe.degree << ", " << space.dof_handler.n_dofs()
            << " unknowns, " << gamma3.nodes.size() << " free nodes on Gamma_3"
            << std::endl;
      // Measured on the bushing (doc/verification.md, "A curved Gamma_3"):
      // Q2 nodes on the chords of a circle make the slip onset converge at
      // first order in h only, Q2 on the curved cells at second order.
      const unsigned int mapping_degree = parameters.geometry.mapping_degree;
      if (geometry.has_curved_boundary() && mapping_degree < space.fe.degree)
        pcout << "Warning: '" << Entry::mapping_degree
              << "' = " << mapping_degree << " is below '"
              << Entry::finite_element_degree << "' = " << space.fe.degree
              << ": the element's nodes on the circles lie on their chords, "
                 "which costs the tractions on Gamma_3 an order of accuracy "
                 "(doc/verification.md); set both equal."
              << std::endl;
    }


    // @sect4{warn_of_normal_component}

    // The bilateral contact holds u.n = w.n = 0 on Gamma_3, and the
    // constraints of V_h set the normal component of the initial values
    // there to zero; where the .prm gives one that is not, the user is told
    // that it was removed.
    template <int dim>
    void warn_of_normal_component(const VectorType           &values,
                                  const std::string          &entry,
                                  const ContactBoundary<dim> &gamma3,
                                  const ConditionalOStream   &pcout)
    {
      double normal = 0, largest = values.linfty_norm();
      for (const ContactNode<dim> &node : gamma3.nodes)
        if (node.locally_owned)
          {
            double component = 0;
            for (unsigned int d = 0; d < dim; ++d)
              component += node.normal[d] * values[node.dofs[d]];
            normal = std::max(normal, std::abs(component));
          }
      normal = Utilities::MPI::max(normal, gamma3.mpi_communicator);
      if (normal > 1e-12 * largest)
        pcout << "Warning: 'Loads and initial values/" << entry
              << "' has a normal component on Gamma_3 (up to " << normal
              << "), which the bilateral contact (u.n = w.n = 0 there) "
              << "does not allow; it is set to zero." << std::endl;
    }


    // Before anything is written: a NaN in the initial values would be
    // blamed on step 1.
    void require_finite(const VectorType  &values,
                        const std::string &entry,
                        const std::string &expression)
    {
      // (The maximum norm skips NaN; the sum of the entries does not.)
      AssertThrow(std::isfinite(values.linfty_norm()) &&
                    !std::isnan(values.l1_norm()),
                  ExcMessage("Entry 'Loads and initial values/" + entry +
                             "' = '" + expression +
                             "' is not a finite number at some node of the "
                             "mesh (a division by zero, or the root or "
                             "logarithm of a negative number there?); "
                             "allowed are expressions finite on the whole "
                             "body."));
    }


    // @sect4{set_initial_state}

    // u_0 and w_0 = u_1 (of the .prm or of an exact solution)
    // interpolated at the nodes, then made to satisfy the constraints of
    // V_h (the clamp and w.n = 0 on Gamma_3); M w_0 and B u_0 and the
    // initial energy.
    template <int dim>
    void set_initial_state(const Parameters           &parameters,
                           const DiscreteSpace<dim>   &space,
                           const Loads<dim>           &loads,
                           const SystemMatrices<dim>  &matrices,
                           const ContactBoundary<dim> &gamma3,
                           const ConditionalOStream   &pcout,
                           StepState                  &state)
    {
      VectorTools::interpolate(*space.mapping,
                               space.dof_handler,
                               loads.initial_displacement(),
                               state.displacement);
      VectorTools::interpolate(*space.mapping,
                               space.dof_handler,
                               loads.initial_velocity(),
                               state.velocity);
      if (!loads.exact_solution())
        {
          warn_of_normal_component(state.displacement,
                                   "Initial displacement",
                                   gamma3,
                                   pcout);
          warn_of_normal_component(state.velocity,
                                   "Initial velocity",
                                   gamma3,
                                   pcout);
        }
      space.constraints.distribute(state.displacement);
      space.constraints.distribute(state.velocity);
      require_finite(state.displacement,
                     "Initial displacement",
                     parameters.loads.initial_displacement);
      require_finite(state.velocity,
                     "Initial velocity",
                     parameters.loads.initial_velocity);
      state.old_displacement = state.displacement;
      state.old_velocity     = state.velocity;

      state.energy = EnergyBalance();
      matrices.update_state_products(state, space.constraints);
      state.energy.initial = state.energy.kinetic + state.energy.elastic;
    }


    // @sect4{print_timings}

    // With 'Output/Print timings': where the wall time of the run went
    // (`steps`: the steps this process's run computed).
    template <int dim>
    void print_timings(const unsigned int         steps,
                       const RunRecord           &run_record,
                       const FrictionSolver<dim> &friction_solver,
                       const Factorization       &factorization,
                       const TimerOutput         &computing_timer,
                       const ConditionalOStream  &pcout)
    {
      const MPI_Comm communicator = friction_solver.boundary().mpi_communicator;
      pcout << "Wall time: " << std::setprecision(4)
            << run_record.run.wall_time() << " s" << std::endl;
      const double step_time = computing_timer.get_summary_data(
                                 TimerOutput::total_wall_time)["Time steps"] /
                               std::max(steps, 1u);
      const double substitution = run_record.substitution / std::max(steps, 1u);
      if (!friction_solver.law().is_frictionless())
        pcout << "Contact solver: " << friction_solver.description()
              << std::endl;
      if (factorization.factor_size() > 0)
        pcout << "Factor of K: "
              << static_cast<long long>(factorization.factor_size())
              << " nonzeros" << std::endl;
      if (substitution > 0)
        pcout << "Time per step " << 1e3 * step_time
              << " ms = " << step_time / substitution
              << (factorization.iterations() > 0 ?
                    " solves with K (one: " :
                    " substitutions with the factor of K (one: ")
              << 1e3 * substitution << " ms)" << std::endl;
      Utilities::System::MemoryStats memory;
      Utilities::System::get_memory_stats(memory);
      const auto peak =
        Utilities::MPI::min_max_avg(memory.VmHWM / 1024., communicator);
      pcout << "Peak memory per process: " << std::setprecision(4) << peak.max
            << " MB (smallest " << peak.min << " MB, "
            << Utilities::MPI::n_mpi_processes(communicator) << " processes)"
            << std::endl;
      computing_timer.print_summary();
    }

    // @sect4{say_what_is_replaced}

    // The results of an earlier run of other parameters that a fresh run
    // replaces, with the first entries that differ.
    void say_what_is_replaced(const Parameters &parameters, std::ostream &out)
    {
      const std::string earlier_file =
        parameters.output.directory + "/parameters.prm";
      std::ifstream earlier_text(earlier_file);
      if (!earlier_text)
        return;
      std::ostringstream text;
      text << earlier_text.rdbuf();
      const auto earlier = read_printed_entries(text.str());
      const auto now     = read_printed_entries(parameters.used_parameters);
      std::map<std::string, std::string> all(earlier);
      all.insert(now.begin(), now.end());
      std::vector<std::string> differing;
      for (const auto &[entry, unused] : all)
        if (earlier.count(entry) == 0 || now.count(entry) == 0 ||
            earlier.at(entry) != now.at(entry))
          differing.push_back(entry);
      // (A run again of the same parameters replaces nothing new.)
      if (differing.empty())
        return;
      out << "Replacing the results of an earlier run in '"
          << parameters.output.directory << "'";
      constexpr unsigned int shown = 4;
      for (unsigned int i = 0;
           i < std::min<std::size_t>(shown, differing.size());
           ++i)
        {
          const std::string &entry = differing[i];
          const auto         value = [&](const auto &entries) {
            return entries.count(entry) ? "'" + entries.at(entry) + "'" :
                                                  std::string("(not set)");
          };
          out << (i == 0 ? ", whose parameters differ: " : "; ") << entry
              << " was " << value(earlier) << ", now " << value(now);
        }
      if (differing.size() > shown)
        out << "; and " << differing.size() - shown << " more entries";
      out << "." << std::endl;
    }


    // @sect4{prepare_output_directory}

    // A fresh run first removes the results an earlier run left in the
    // directory (remove_results(): every file and run directory a part of
    // the program registered; other files stay), so that its PVD lists only
    // its own files and a later --resume cannot resume the earlier run. A
    // resumed run keeps them; its postprocessors cut them back to the
    // checkpoint's step. Then the parameters of this run are written.
    void prepare_output_directory(const Parameters &parameters,
                                  const MPI_Comm    mpi_communicator)
    {
      const std::string &directory = parameters.output.directory;
      if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
        return;
      if (!parameters.output.resume)
        {
          // Said once the earlier results are gone (a running run in a
          // directory below may keep them).
          std::ostringstream replaced;
          say_what_is_replaced(parameters, replaced);
          // The run that a target chose keeps the pilots it was chosen by.
          remove_results(directory, parameters.keeps_pilots, mpi_communicator);
          std::cout << replaced.str();
        }
      // Output that is written in pieces (VTU) is written here first and
      // renamed into the directory when complete.
      std::error_code error;
      std::filesystem::create_directories(directory + "/.partial", error);
      AssertThrow(!error,
                  ExcMessage("Cannot create '" + directory +
                             "/.partial': " + error.message()));
      std::ofstream used(directory + "/parameters.prm");
      used << parameter_file_header() << parameters.used_parameters;
      used.flush();
      AssertThrow(used,
                  ExcMessage("Cannot write '" + directory +
                             "/parameters.prm': " + std::strerror(errno) +
                             "."));
    }


    // @sect4{create_run_storage}

    // The part that stores the run, the first of its kind if the program
    // has one; a resumed run needs it.
    template <int dim>
    std::unique_ptr<RunStorage<dim>>
    create_run_storage(const RunStorageView<dim> &run)
    {
      const auto &parts = RunStorageParts<dim>::parts();
      AssertThrow(!parts.empty() || !run.parameters.output.resume,
                  ExcMessage("Entry '" + Entry::resume +
                             "' = true: this program has no part that stores "
                             "runs, so none can be resumed."));
      return parts.empty() ? nullptr : parts.front().create(run);
    }
  } // namespace


  // @sect4{ContactProblem::ContactProblem}

  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters &run_parameters)
    : parameters(run_parameters)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , computing_timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , geometry(create_geometry<dim>(parameters, MPI_COMM_WORLD))
    , space(parameters.geometry, MPI_COMM_WORLD)
    , storage(create_run_storage<dim>({parameters,
                                       space,
                                       adaptation,
                                       state,
                                       friction_solver,
                                       postprocessors,
                                       pcout,
                                       computing_timer}))
    , run_view{*this,
               parameters,
               state,
               space,
               matrices,
               loads,
               friction_solver,
               pcout,
               computing_timer,
               postprocessors}
  {
    AssertThrow(parameters.dimension == dim, ExcInternalError());
    state.time_step = parameters.time.end_time / parameters.time.n_steps();
    for (const auto &part : PostprocessorParts<dim>::parts())
      add_postprocessor(part.create());
  }


  // A run that ends with an error completes what output it can (the
  // postprocessors' destructors): the members are destroyed in reverse
  // order, the postprocessors first.
  template <int dim>
  ContactProblem<dim>::~ContactProblem()
  {}


  template <int dim>
  void ContactProblem<dim>::add_postprocessor(
    std::unique_ptr<Postprocessor<dim>> postprocessor)
  {
    postprocessor->observe(run_view);
    postprocessors.push_back(std::move(postprocessor));
  }


  template <int dim>
  void ContactProblem<dim>::adapt_mesh(const MeshPlan &plan)
  {
    adaptation.plan = plan;
  }


  template <int dim>
  void
  ContactProblem<dim>::adapt_mesh_during_run(const unsigned int    interval,
                                             std::function<void()> choose_cells)
  {
    adaptation.interval     = interval;
    adaptation.choose_cells = std::move(choose_cells);
  }


  template <int dim>
  const MeshPlan &ContactProblem<dim>::get_mesh_plan() const
  {
    return adaptation.plan;
  }


  // @sect4{ContactProblem::run}

  // Set-up, the initial state, the steps, and what the run gives back. The
  // load data are parsed first, so that an expression with an error is
  // refused before anything is computed or written. The output directory
  // is locked before anything else, and kept locked until the problem is
  // destroyed: an error estimate's coarse runs still write under it.
  template <int dim>
  RunSummary ContactProblem<dim>::run()
  {
    run_record.run.restart();
    loads = create_loads(parameters, space, computing_timer);
    run_record.output_directory_lock =
      lock_output_directory(parameters.output.directory,
                            space.mpi_communicator);
    const bool resumed = parameters.output.resume;
    if (resumed)
      storage->restore_mesh_plan();
    make_grid();
    if (loads->exact_solution())
      loads->exact_solution()->check_scene(*geometry);
    setup_system();
    // The postprocessors' set-up may refuse an entry of theirs (a probe
    // outside the body): before anything is reported of the mesh.
    for (const auto &postprocessor : postprocessors)
      postprocessor->mesh_event(MeshEvent::initial);
    report_mesh(
      parameters, *geometry, space, friction_solver->boundary(), pcout);
    set_initial_state(parameters,
                      space,
                      *loads,
                      matrices,
                      friction_solver->boundary(),
                      pcout,
                      state);
    matrices.factorize(state.time_step,
                       parameters.solver,
                       space,
                       computing_timer);
    friction_solver->reinit(matrices.system, *matrices.factorization);
    friction_solver->set_initial_velocity(state.velocity);

    state.step_number = 0;
    if (resumed)
      {
        storage->load();
        check_step_tables(parameters.output.directory, state.step_number);
      }
    prepare_output_directory(parameters, space.mpi_communicator);
    for (const auto &postprocessor : postprocessors)
      postprocessor->start(resumed);
    const unsigned int first_step = state.step_number;
    time_loop();
    // What each postprocessor completes, prints and gives the summary (the
    // summary's lines in the order of the ranks), then the timings; the
    // failure of a self-check ends the run last.
    state.step_number = parameters.time.n_steps();
    RunSummary summary;
    for (const auto &postprocessor : postprocessors)
      postprocessor->finish(summary);
    if (parameters.output.print_timings)
      print_timings(state.step_number - first_step,
                    run_record,
                    *friction_solver,
                    *matrices.factorization,
                    computing_timer,
                    pcout);
    if (Utilities::MPI::this_mpi_process(space.mpi_communicator) == 0)
      {
        // Removed only if empty: what a killed run left there stays.
        std::error_code error;
        std::filesystem::remove(parameters.output.directory + "/.partial",
                                error);
      }
    for (const auto &postprocessor : postprocessors)
      postprocessor->require_success();

    // What a driver gets of the run (collective); its h is the geometry's
    // (Geometry::cell_size()).
    summary.cell_size =
      geometry->cell_size(*space.triangulation, *space.mapping);
    summary.time_step           = state.time_step;
    summary.n_steps             = parameters.time.n_steps();
    summary.n_dofs              = space.dof_handler.n_dofs();
    summary.wall_time           = run_record.run.wall_time();
    summary.displacement_V_norm = strain_norm(state.displacement);
    return summary;
  }


  // @sect4{ContactProblem::time_loop}

  // The steps t_1, ..., t_N (from the checkpoint's step on a resumed run),
  // and after each what the postprocessors make of it, then the mesh's
  // adaptation and a checkpoint if one is due (in this order: the
  // checkpoint stores the mesh the next step runs on).
  template <int dim>
  void ContactProblem<dim>::time_loop()
  {
    const unsigned int n_steps = parameters.time.n_steps();
    if (adaptation.due && state.step_number < n_steps)
      transfer_to_adapted_mesh();
    for (++state.step_number; state.step_number <= n_steps; ++state.step_number)
      {
        state.time                      = state.step_number * state.time_step;
        const StepStatistics statistics = advance(parameters.solver.step_cuts);
        AssertThrow(std::isfinite(state.velocity.linfty_norm()) &&
                      std::isfinite(state.energy.residual()),
                    ExcMessage("Step " + std::to_string(state.step_number) +
                               " (t = " + number_text(state.time) +
                               ") produced a velocity or energy that is not "
                               "a finite number; the results up to step " +
                               std::to_string(state.step_number - 1) +
                               " are written. Check the loads and material "
                               "data for values that overflow."));
        for (const auto &postprocessor : postprocessors)
          postprocessor->after_step(statistics, StepEnd::whole_step);
        if (adaptation.interval > 0 &&
            state.step_number % adaptation.interval == 0 &&
            state.step_number < n_steps)
          transfer_to_adapted_mesh();
        if (storage && storage->due())
          storage->save();
      }
  }


  // @sect4{ContactProblem::strain_norm}

  // Norms of a field of this problem's finite element space, such as the
  // difference of two solutions interpolated onto this mesh; the Gauss rule
  // of the assembly integrates them exactly on affine cells. The cells of
  // this process need the field's ghost entries too.
  template <int dim>
  double ContactProblem<dim>::strain_norm(const VectorType &field) const
  {
    const VectorType                     v = space.ghosted(field);
    FEValues<dim>                        fe_values(*space.mapping,
                            space.fe,
                            space.quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacements(0);
    std::vector<SymmetricTensor<2, dim>> eps(space.quadrature.size());
    double                               sum = 0;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacements].get_function_symmetric_gradients(v, eps);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            sum += eps[q] * eps[q] * fe_values.JxW(q);
        }
    return std::sqrt(Utilities::MPI::sum(sum, space.mpi_communicator));
  }


  template <int dim>
  unsigned int ContactProblem<dim>::get_step_number() const
  {
    return state.step_number;
  }

  template <int dim>
  const DoFHandler<dim> &ContactProblem<dim>::get_dof_handler() const
  {
    return space.dof_handler;
  }

  template <int dim>
  const Mapping<dim> &ContactProblem<dim>::get_mapping() const
  {
    return *space.mapping;
  }

  template <int dim>
  const VectorType &ContactProblem<dim>::get_displacement() const
  {
    return state.displacement;
  }

  template <int dim>
  const VectorType &ContactProblem<dim>::get_velocity() const
  {
    return state.velocity;
  }

  template <int dim>
  const Vector<double> &ContactProblem<dim>::get_friction_force() const
  {
    return friction_solver->state().friction_force;
  }

  template <int dim>
  VectorType ContactProblem<dim>::ghosted(const VectorType &v) const
  {
    return space.ghosted(v);
  }


#define INSTANTIATE(dim)                                                        \
  template ContactProblem<dim>::ContactProblem(const Parameters &);             \
  template ContactProblem<dim>::~ContactProblem();                              \
  template void ContactProblem<dim>::add_postprocessor(                         \
    std::unique_ptr<Postprocessor<dim>>);                                       \
  template RunSummary ContactProblem<dim>::run();                               \
  template void       ContactProblem<dim>::adapt_mesh(const MeshPlan &);        \
  template void       ContactProblem<dim>::adapt_mesh_during_run(               \
    const unsigned int, std::function<void()>);                           \
  template const MeshPlan &ContactProblem<dim>::get_mesh_plan() const;          \
  template void            ContactProblem<dim>::time_loop();                    \
  template double ContactProblem<dim>::strain_norm(const VectorType &) const;   \
  template unsigned int           ContactProblem<dim>::get_step_number() const; \
  template const DoFHandler<dim> &ContactProblem<dim>::get_dof_handler()        \
    const;                                                                      \
  template const Mapping<dim>   &ContactProblem<dim>::get_mapping() const;      \
  template const VectorType     &ContactProblem<dim>::get_displacement() const; \
  template const VectorType     &ContactProblem<dim>::get_velocity() const;     \
  template const Vector<double> &ContactProblem<dim>::get_friction_force()      \
    const;                                                                      \
  template VectorType ContactProblem<dim>::ghosted(const VectorType &) const;

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
