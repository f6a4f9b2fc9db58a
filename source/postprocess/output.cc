/* What a run gives the user: VTU/PVD, time_series.csv, the used parameters
   and the console lines. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/data_out.h>

#include <core/contact_problem.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <future>
#include <iomanip>
#include <map>
#include <regex>
#include <sstream>

namespace Contact
{
  namespace
  {
    // The output directory, created, and locked with flock() on its file
    // '.lock' (which then holds the pid): the kernel releases the lock when
    // the process ends, however it ends. Returns the reason on failure.
    std::string flock_output_directory(const std::string          &directory,
                                       const bool                  created,
                                       std::shared_ptr<const int> &lock)
    {
      std::error_code error;
      std::filesystem::create_directories(directory, error);
      if (error)
        return "Cannot create the directory '" + directory +
               "' of the entry '" + Entry::output_directory +
               "': " + error.message();
      const std::string name = directory + "/.lock";
      const int         fd   = open(name.c_str(), O_RDWR | O_CREAT, 0644);
      if (fd < 0)
        return "Cannot create '" + name + "': " + std::strerror(errno);
      if (flock(fd, LOCK_EX | LOCK_NB) != 0)
        {
          if (errno != EWOULDBLOCK)
            {
              // A file system without flock (some parallel or network
              // ones): the run goes on unlocked.
              close(fd);
              return "";
            }
          std::ifstream holder(name);
          std::string   pid;
          std::getline(holder, pid);
          close(fd);
          return "The output directory '" + directory +
                 "' is in use by another run (process " +
                 (pid.empty() ? std::string("unknown") : pid) +
                 "). Wait for it to end, or give this run another "
                 "'" +
                 Entry::output_directory + "'.";
        }
      const std::string pid = std::to_string(getpid()) + "\n";
      if (ftruncate(fd, 0) != 0 || write(fd, pid.data(), pid.size()) < 0)
        {
          close(fd);
          return "Cannot write '" + name + "': " + std::strerror(errno);
        }
      // A directory this lock created and nothing but the lock went into
      // (a run refused in its setup) is removed with the lock, while it is
      // still held.
      lock = std::shared_ptr<const int>(
        new int(fd), [directory, name, created](const int *owned) {
          std::error_code error;
          if (created)
            {
              unsigned int entries = 0;
              for (const auto &entry :
                   std::filesystem::directory_iterator(directory, error))
                entries += (entry.path().filename() == ".lock" ? 0 : 1);
              if (!error && entries == 0)
                {
                  std::filesystem::remove(name, error);
                  std::filesystem::remove(directory, error);
                }
            }
          close(*owned);
          delete owned;
        });
      return "";
    }

    // Whether a file of the output directory has exactly the name of one
    // this program writes (solution_00012.3.vtu, checkpoint.1.tmp, ...):
    // a user's 'solution_notes.txt' or 'checkpoint.bak' is not one.
    bool is_result_file(const std::string &name)
    {
      static const std::regex written(
        "solution_[0-9]{5}\\.([0-9]+\\.vtu|pvtu)|solution\\.pvd(\\.tmp)?|"
        "(time_series|gamma3_history)\\.csv(\\.tmp)?|checkpoint(\\.[0-9]+)?(\\.tmp)?|"
        "parameters\\.prm|error_estimate\\.txt|target\\.txt|convergence\\.txt");
      return std::regex_match(name, written);
    }

    // The directories of an error estimate's coarse runs, of a target's
    // pilots and of a convergence study's levels: a name this program gives
    // them, and the parameters.prm that each of its runs writes (a user's own
    // 'level-1' folder is not one).
    bool is_result_directory(const std::filesystem::path &path)
    {
      static const std::regex written("coarse-(1|2|space|time)|level-[0-9]+|" +
                                      pilot_directory_pattern);
      return std::regex_match(path.filename().string(), written) &&
             std::filesystem::exists(path / "parameters.prm");
    }
  } // namespace


  // A directory this process holds already is shared rather than locked
  // again (flock would refuse a second descriptor of the same process): an
  // error estimate's or a target's runs write under the lock of the run
  // that contains them.
  std::shared_ptr<const int> lock_output_directory(const std::string &directory,
                                                   const MPI_Comm communicator)
  {
    static std::map<std::string, std::weak_ptr<const int>> held;
    std::shared_ptr<const int>                             lock;
    std::string                                            failure;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        // The key of a directory that exists: 'out/' and 'out' alike.
        std::error_code error;
        const bool      created = !std::filesystem::exists(directory, error);
        std::filesystem::create_directories(directory, error);
        const std::string key = std::filesystem::weakly_canonical(
                                  std::filesystem::absolute(directory), error)
                                  .string();
        lock = held[key].lock();
        if (!lock)
          {
            failure   = flock_output_directory(directory, created, lock);
            held[key] = lock;
          }
      }
    failure = Utilities::MPI::broadcast(communicator, failure, 0);
    AssertThrow(failure.empty(), ExcMessage(failure));
    return lock;
  }


  void remove_results(const std::string &directory,
                      const bool         keep_pilots,
                      const MPI_Comm     communicator)
  {
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    const std::regex pilot(pilot_directory_pattern);
    std::error_code  error;
    for (const auto &entry :
         std::filesystem::directory_iterator(directory, error))
      if (entry.is_regular_file() &&
          is_result_file(entry.path().filename().string()))
        std::filesystem::remove(entry.path(), error);
      else if (entry.is_directory() && is_result_directory(entry.path()) &&
               !(keep_pilots &&
                 std::regex_match(entry.path().filename().string(), pilot)))
        std::filesystem::remove_all(entry.path(), error);
    std::filesystem::remove_all(directory + "/.partial", error);
  }


  // @sect4{ContactProblem::claim_output_directory}

  // An output directory belongs to one run at a time: two runs writing the
  // same time series would interleave their rows. Collective: the first
  // process takes the lock, all throw the same error if it fails.
  template <int dim>
  void ContactProblem<dim>::claim_output_directory()
  {
    output_directory_lock =
      lock_output_directory(parameters.output.directory, mpi_communicator);
  }


  // @sect4{ContactProblem::prepare_output_directory}

  // A fresh run first removes the results an earlier run left in the
  // directory (VTU/PVD, time series, Gamma_3 history, parameters,
  // checkpoints, an error estimate and a study's table, and the coarse-*
  // and level-* directories of such runs; other files stay), so that its PVD
  // lists only its own files and a later --resume cannot resume the earlier
  // run. A resumed run keeps them, cut back to the checkpoint
  // (load_checkpoint).
  template <int dim>
  void ContactProblem<dim>::prepare_output_directory()
  {
    const std::string &directory = parameters.output.directory;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::error_code error;
    if (!parameters.output.resume)
      // The run that a target chose keeps the pilots it was chosen by.
      remove_results(directory,
                     parameters.accuracy.target_error > 0,
                     mpi_communicator);
    // VTU pieces are written here first and renamed into the directory
    // when complete (write_vtu).
    std::filesystem::create_directories(directory + "/.partial", error);
    AssertThrow(!error,
                ExcMessage("Cannot create '" + directory +
                           "/.partial': " + error.message()));
    std::ofstream used(directory + "/parameters.prm");
    used << parameters.used_parameters;
    used.flush();
    AssertThrow(used,
                ExcMessage("Cannot write '" + directory +
                           "/parameters.prm': " + std::strerror(errno) + "."));

    // On resume, load_checkpoint has cut the series back to the
    // checkpoint's step; rows are appended from there (if the file is gone,
    // a new one starts with the header at the checkpoint's step).
    const std::string series = directory + "/time_series.csv";
    if (parameters.output.write_time_series && parameters.output.resume &&
        std::filesystem::exists(series))
      time_series.open(series, std::ios::app);
    else if (parameters.output.write_time_series)
      {
        time_series.open(series);
        time_series
          << "step,time,convexification_iterations,active_set_iterations,"
             "rejected_accelerations,active_set_cycles,step_cuts,"
             "newton_iterations,newton_fallbacks,solves_with_K,cg_iterations,"
             "n_stick,n_slip,max_slip_rate,friction_force,"
             "kinetic_energy,elastic_energy,external_work,viscous_dissipation,"
             "friction_dissipation,numerical_dissipation,algebraic_energy_residual,"
             "quadrature_energy_residual,friction_law_residual,momentum_x,"
             "momentum_y"
          << (dim == 3 ? ",momentum_z" : "")
          << ",angular_momentum,applied_moment,friction_moment,"
             "reaction_moment";
        for (unsigned int i = 0; i < probes.size(); ++i)
          for (unsigned int d = 0; d < dim; ++d)
            time_series << ",probe" << i + 1 << "_u_"
                        << "xyz"[d];
        time_series << (exact_solution ? ",error_V,error_w_L2,error_u_L2\n" :
                                         "\n");
      }

    const std::string history = directory + "/gamma3_history.csv";
    if (parameters.output.write_gamma3_history && parameters.output.resume &&
        std::filesystem::exists(history))
      gamma3_history.open(history, std::ios::app);
    else if (parameters.output.write_gamma3_history)
      {
        gamma3_history.open(history);
        gamma3_history << "step,time,x,y" << (dim == 3 ? ",z" : "")
                       << ",state,slip_rate,friction_traction_t1"
                       << (dim == 3 ? ",friction_traction_t2" : "")
                       << ",friction_bound\n";
      }
  }


  // @sect4{ContactProblem::write_gamma3_history_rows}

  // The state of every node of Gamma_3 at t_n (every process has all of
  // them; the first one writes): state 1 stick, 2 slip; the friction
  // traction -eta_p / m_p in the node's tangent basis (t1 is the direction
  // of +x on the paper's Gamma_3), and the bound mu(|w_tau|) S.
  template <int dim>
  void ContactProblem<dim>::write_gamma3_history_rows()
  {
    if (!gamma3_history.is_open())
      return;
    const std::vector<ContactNode<dim>> &contact_nodes =
      friction_solver->boundary().nodes;
    const auto &[friction_force, slip_velocity, node_state] =
      friction_solver->state();
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      {
        const ContactNode<dim> &node = contact_nodes[p];
        const double rate = node.tangential_vector(slip_velocity, p).norm();
        gamma3_history << step_number << ',' << std::setprecision(12) << time;
        for (unsigned int d = 0; d < dim; ++d)
          gamma3_history << ',' << node.location[d];
        gamma3_history << ',' << (node_state[p] == NodeState::stick ? 1 : 2)
                       << ',' << rate;
        for (unsigned int i = 0; i < dim - 1; ++i)
          gamma3_history << ','
                         << (node.weight > 0 ?
                               -friction_force[p * (dim - 1) + i] /
                                 node.weight :
                               0.);
        gamma3_history << ',' << friction_law.bound(rate) << '\n';
      }
    gamma3_history.flush();
    AssertThrow(gamma3_history,
                ExcMessage("Cannot write '" + parameters.output.directory +
                           "/gamma3_history.csv': " + std::strerror(errno) +
                           "."));
  }


  // @sect4{ContactProblem::probe_displacement}

  template <int dim>
  Tensor<1, dim>
  ContactProblem<dim>::probe_displacement(const unsigned int probe,
                                          const VectorType  &u_ghosted) const
  {
    const auto &[cell, reference_point] = probes[probe];
    Tensor<1, dim> u;
    if (cell.state() == IteratorState::valid)
      {
        FEValues<dim>               fe_values(*mapping,
                                fe,
                                Quadrature<dim>(reference_point),
                                update_values);
        std::vector<Vector<double>> values(1, Vector<double>(dim));
        fe_values.reinit(cell);
        fe_values.get_function_values(u_ghosted, values);
        for (unsigned int d = 0; d < dim; ++d)
          u[d] = values[0][d];
      }
    return Utilities::MPI::sum(u, mpi_communicator);
  }


  // @sect4{ContactProblem::write_time_series_row}

  // One row per step, flushed at once: if a later step fails, the file
  // describes exactly the steps that were computed.
  template <int dim>
  void
  ContactProblem<dim>::write_time_series_row(const StepStatistics &statistics)
  {
    if (!parameters.output.write_time_series)
      return;
    // Collective: every process takes part in the momentum and the probes,
    // the first one writes.
    const Tensor<1, dim>        p = momentum();
    std::vector<Tensor<1, dim>> probe_values;
    if (!probes.empty())
      {
        const VectorType u = ghosted(displacement);
        for (unsigned int i = 0; i < probes.size(); ++i)
          probe_values.push_back(probe_displacement(i, u));
      }
    if (!time_series.is_open())
      return;
    time_series << step_number << ',' << std::setprecision(12) << time << ','
                << statistics.convexification_iterations << ','
                << statistics.active_set_iterations << ','
                << statistics.rejected_accelerations << ','
                << statistics.cycles_cured << ',' << statistics.step_cuts << ','
                << statistics.newton_iterations << ','
                << statistics.newton_fallbacks << ','
                << statistics.solves_with_K << ',' << statistics.cg_iterations
                << ',' << statistics.n_stick << ',' << statistics.n_slip << ','
                << statistics.max_slip_rate << ',' << statistics.friction_force
                << ',' << energy.kinetic << ',' << energy.elastic << ','
                << energy.external_work << ',' << energy.viscous_dissipation
                << ',' << energy.friction_dissipation << ','
                << energy.numerical_dissipation << ',' << energy.residual()
                << ',' << energy_by_quadrature.residual() << ','
                << step_checks.friction_law;
    for (unsigned int d = 0; d < dim; ++d)
      time_series << ',' << p[d];
    time_series << ',' << moments.angular_momentum << ',' << moments.applied
                << ',' << moments.friction << ',' << moments.reaction;
    for (const Tensor<1, dim> &u : probe_values)
      for (unsigned int d = 0; d < dim; ++d)
        time_series << ',' << u[d];
    if (exact_solution)
      {
        time_series << ',' << current_errors.displacement_V << ','
                    << current_errors.velocity_L2 << ','
                    << current_errors.displacement_L2;
      }
    time_series << std::endl;
    AssertThrow(time_series,
                ExcMessage("Cannot write '" + parameters.output.directory +
                           "/time_series.csv': " + std::strerror(errno) + "."));
  }


  // @sect4{ContactProblem::VtuOutput}

  // One VTU output: copies of the fields at t_n, and the thread that turns
  // them into a file. DataOut's patches and the compression take most of
  // an output's time (measured: 18 + 18 ms of 45 ms per output of the
  // paper's scene); they run in a background thread while the time loop
  // goes on, and finish_vtu() waits for them before the next output, a
  // checkpoint or the end of the run. The thread reads the mesh, the
  // DoFHandlers and the mapping, which the time loop does not change, and
  // makes no MPI calls: DataOut's ghosted copies of the fields (MPI calls)
  // are made before it starts.
  template <int dim>
  struct ContactProblem<dim>::VtuOutput
  {
    double                      time;
    unsigned int                step;
    FastVector                  displacement, velocity, friction_traction;
    Vector<double>              status, slip_rate, friction_bound;
    std::vector<Vector<double>> stress;
    Vector<double>              von_mises;
    DataOut<dim>                data_out;
    std::future<void>           written;
  };


  // @sect4{ContactProblem::vtu_piece_name}

  // deal.II's names for the pieces of a parallel VTU output and their
  // record: solution_00012.0.vtu, ..., solution_00012.pvtu.
  template <int dim>
  std::string
  ContactProblem<dim>::vtu_piece_name(const unsigned int step,
                                      const unsigned int process) const
  {
    return "solution_" + Utilities::int_to_string(step, 5) + "." +
           Utilities::int_to_string(process) + ".vtu";
  }


  // @sect4{ContactProblem::write_vtu}

  // Displacement and velocity as vectors; on Gamma_3 the status (0: off
  // Gamma_3, 1: stick, 2: slip), the slip rate |w_tau|, the friction
  // traction -eta_p/m_p t_p and the bound mu(|w_tau|) S, as nodal fields;
  // the stress of (3.1) as cell averages (cell_stress_*, cell_von_mises,
  // see cell_average_stress()). Here the fields are copied and handed to
  // DataOut; the patches and the file are made in the background
  // (VtuOutput).
  template <int dim>
  void ContactProblem<dim>::write_vtu()
  {
    finish_vtu();
    TimerOutput::Scope t(computing_timer, "Output");

    auto output          = std::make_shared<VtuOutput>();
    output->time         = time;
    output->step         = step_number;
    output->displacement = fast_ghosted(displacement);
    output->velocity     = fast_ghosted(velocity);

    const unsigned int n_scalar_dofs = scalar_dof_handler.n_dofs();
    output->status.reinit(n_scalar_dofs);
    output->slip_rate.reinit(n_scalar_dofs);
    output->friction_bound.reinit(n_scalar_dofs);
    output->friction_traction.reinit(locally_owned_dofs,
                                     locally_relevant_dofs,
                                     mpi_communicator);
    const std::vector<ContactNode<dim>> &contact_nodes =
      friction_solver->boundary().nodes;
    const auto &[friction_force, slip_velocity, node_state] =
      friction_solver->state();
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      {
        const ContactNode<dim> &node = contact_nodes[p];
        const double rate = node.tangential_vector(slip_velocity, p).norm();
        output->status[node.scalar_dof] =
          (node_state[p] == NodeState::stick ? 1 : 2);
        output->slip_rate[node.scalar_dof]      = rate;
        output->friction_bound[node.scalar_dof] = friction_law.bound(rate);
        if (node.weight > 0 && node.locally_owned)
          for (unsigned int d = 0; d < dim; ++d)
            output->friction_traction[node.dofs[d]] =
              -node.tangential_vector(friction_force, p)[d] / node.weight;
      }
    output->friction_traction.update_ghost_values();
    cell_average_stress(*output);
    add_vtu_fields(*output);

    const std::string piece =
      parameters.output.directory + "/.partial/" +
      vtu_piece_name(step_number,
                     Utilities::MPI::this_mpi_process(mpi_communicator));
    VtuOutput &fields = *output;
    output->written = std::async(std::launch::async, [this, &fields, piece]() {
      write_vtu_piece(fields, piece);
    });
    pending_vtu     = std::move(output);
  }


  // @sect4{ContactProblem::cell_average_stress}

  // The stress sigma = A eps(w) + B eps(u) of (3.1) averaged over each
  // cell, and the von Mises value of that average (in 2D plane strain
  // sigma_zz = lambda tr eps(u) + mu_1 tr eps(w) enters it).
  template <int dim>
  void ContactProblem<dim>::cell_average_stress(VtuOutput &output) const
  {
    const auto  &material     = parameters.material;
    const double two_G        = material.two_G();
    const double lambda       = material.lambda(dim);
    const bool   plane_strain = (dim == 2 && !material.plane_stress);

    const unsigned int n_cells = triangulation->n_active_cells();
    output.stress.assign(dim * (dim + 1) / 2, Vector<double>(n_cells));
    output.von_mises.reinit(n_cells);
    FEValues<dim>                        fe_values(*mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacements(0);
    std::vector<SymmetricTensor<2, dim>> eps_u(quadrature.size()),
      eps_w(quadrature.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacements].get_function_symmetric_gradients(
            output.displacement, eps_u);
          fe_values[displacements].get_function_symmetric_gradients(
            output.velocity, eps_w);
          SymmetricTensor<2, dim> sigma;
          double                  sigma_zz = 0, volume = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const double JxW = fe_values.JxW(q);
              sigma +=
                (material.viscosity_mu1 * trace(eps_w[q]) *
                   unit_symmetric_tensor<dim>() +
                 material.viscosity_mu2 * eps_w[q] +
                 lambda * trace(eps_u[q]) * unit_symmetric_tensor<dim>() +
                 two_G * eps_u[q]) *
                JxW;
              if (plane_strain)
                sigma_zz += (lambda * trace(eps_u[q]) +
                             material.viscosity_mu1 * trace(eps_w[q])) *
                            JxW;
              volume += JxW;
            }
          sigma /= volume;
          sigma_zz /= volume;
          const unsigned int c         = cell->active_cell_index();
          unsigned int       component = 0;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              output.stress[component++][c] = sigma[i][j];
          const double                  mean = (trace(sigma) + sigma_zz) / 3.;
          const SymmetricTensor<2, dim> deviator =
            sigma - mean * unit_symmetric_tensor<dim>();
          const double out_of_plane = (dim == 2 ? sigma_zz - mean : 0.);
          output.von_mises[c]       = std::sqrt(
            1.5 * (deviator * deviator + out_of_plane * out_of_plane));
        }
  }


  // @sect4{ContactProblem::add_vtu_fields}

  // DataOut makes ghosted copies of the nodal fields (an MPI call, so here,
  // before the output thread starts).
  template <int dim>
  void ContactProblem<dim>::add_vtu_fields(VtuOutput &output) const
  {
    DataOut<dim> &data_out = output.data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_field(dim,
                   DataComponentInterpretation::component_is_part_of_vector);
    const std::vector<std::pair<const FastVector *, std::string>> fields = {
      {&output.displacement, "displacement"},
      {&output.velocity, "velocity"},
      {&output.friction_traction, "friction_traction"}};
    for (const auto &[vector, name] : fields)
      data_out.add_data_vector(*vector,
                               std::vector<std::string>(dim, name),
                               DataOut<dim>::type_dof_data,
                               vector_field);
    data_out.add_data_vector(scalar_dof_handler,
                             output.status,
                             "contact_status");
    data_out.add_data_vector(scalar_dof_handler, output.slip_rate, "slip_rate");
    data_out.add_data_vector(scalar_dof_handler,
                             output.friction_bound,
                             "friction_bound");
    const char  *axes      = "xyz";
    unsigned int component = 0;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        data_out.add_data_vector(output.stress[component++],
                                 std::string("cell_stress_") + axes[i] +
                                   axes[j],
                                 DataOut<dim>::type_cell_data);
    data_out.add_data_vector(output.von_mises,
                             "cell_von_mises",
                             DataOut<dim>::type_cell_data);
  }


  // @sect4{ContactProblem::write_vtu_piece}

  // This process's piece of the output, written into .partial/: the
  // output thread's work.
  template <int dim>
  void ContactProblem<dim>::write_vtu_piece(VtuOutput         &output,
                                            const std::string &file) const
  {
    DataOut<dim> &data_out = output.data_out;
    data_out.build_patches(*mapping, fe.degree);

    DataOutBase::VtkFlags flags;
    flags.time              = output.time;
    flags.cycle             = output.step;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    std::ofstream stream(file);
    if (stream)
      data_out.write_vtu(stream);
    stream.flush();
    AssertThrow(stream,
                ExcMessage("Cannot write the VTU file '" + file +
                           "': " + std::strerror(errno) + "."));
  }


  // @sect4{ContactProblem::finish_vtu}

  // Atomic output: the pieces and the .pvtu record go to .partial/ and are
  // renamed into the output directory once all processes have written
  // them, the record last; the PVD is rewritten by rename. A run killed at
  // any point leaves only complete files, and the PVD lists only files
  // that exist.
  template <int dim>
  void ContactProblem<dim>::finish_vtu()
  {
    if (!pending_vtu)
      return;
    TimerOutput::Scope               t(computing_timer, "Output");
    const std::shared_ptr<VtuOutput> output = std::move(pending_vtu);
    output->written.get();
    const int ierr = MPI_Barrier(mpi_communicator);
    AssertThrowMPI(ierr);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;

    const std::string &directory = parameters.output.directory;
    const std::string  record =
      "solution_" + Utilities::int_to_string(output->step, 5) + ".pvtu";
    std::vector<std::string> pieces;
    for (unsigned int process = 0;
         process < Utilities::MPI::n_mpi_processes(mpi_communicator);
         ++process)
      pieces.push_back(vtu_piece_name(output->step, process));
    {
      std::ofstream stream(directory + "/.partial/" + record);
      output->data_out.write_pvtu_record(stream, pieces);
      stream.flush();
      AssertThrow(stream,
                  ExcMessage("Cannot write '" + directory + "/.partial/" +
                             record + "': " + std::strerror(errno) + "."));
    }
    for (const std::string &piece : pieces)
      std::filesystem::rename(directory + "/.partial/" + piece,
                              directory + "/" + piece);
    std::filesystem::rename(directory + "/.partial/" + record,
                            directory + "/" + record);
    pvd_records.emplace_back(output->time, record);
    write_pvd();
  }


  // @sect4{ContactProblem::write_pvd}

  template <int dim>
  void ContactProblem<dim>::write_pvd() const
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    const std::string name = parameters.output.directory + "/solution.pvd";
    {
      std::ofstream pvd(name + ".tmp");
      DataOutBase::write_pvd_record(pvd, pvd_records);
      pvd.flush();
      AssertThrow(pvd,
                  ExcMessage("Cannot write '" + name +
                             ".tmp': " + std::strerror(errno) + "."));
    }
    std::filesystem::rename(name + ".tmp", name);
  }


  // @sect4{ContactProblem::print_progress}

  template <int dim>
  void
  ContactProblem<dim>::print_progress(const StepStatistics &statistics) const
  {
    const unsigned int interval = parameters.output.progress_interval;
    if (interval == 0 ||
        (step_number % interval != 0 && step_number != n_time_steps))
      return;
    // The time left from the steps of this run alone: the setup before the
    // first step (factorisation, Delassus operator) would make the first
    // estimates several times too large.
    const double elapsed = run_timer.wall_time();
    const double left    = time_loop_timer.wall_time() /
                        std::max(steps_timed, 1u) *
                        (n_time_steps - step_number);
    pcout << "Step " << std::setw(5) << step_number << '/' << n_time_steps
          << "  t = " << std::setw(9) << std::setprecision(5) << time
          << "  iterations "
          << (statistics.newton_iterations > 0 ?
                std::to_string(statistics.newton_iterations) + " Newton" +
                  (statistics.newton_fallbacks > 0 ? " + " : "") :
                std::string())
          << (statistics.newton_iterations == 0 ||
                  statistics.newton_fallbacks > 0 ?
                std::to_string(statistics.convexification_iterations) + '/' +
                  std::to_string(statistics.active_set_iterations) :
                std::string())
          << "  solves " << statistics.solves_with_K << "  stick "
          << statistics.n_stick << "  slip " << statistics.n_slip
          << "  max slip rate " << std::setprecision(3)
          << statistics.max_slip_rate << "  [" << std::setprecision(3)
          << elapsed << " s, " << left << " s left]" << std::endl;
  }


  // @sect4{ContactProblem::report_contact_state}

  // At the step nearest to each of the 'Output/Report times': how many
  // nodes of Gamma_3 stick and slip, and where the slip zone is.
  // Whether t_n is the step nearest to t: report times are not moved onto
  // the time grid, and one after 'Time/End time' is met at the last step.
  template <int dim>
  bool ContactProblem<dim>::is_nearest_step(const double t) const
  {
    return std::abs(time - t) <= 0.5 * time_step * (1 + 1e-12) ||
           (step_number == n_time_steps && t > time);
  }


  template <int dim>
  bool ContactProblem<dim>::report_due() const
  {
    return std::any_of(pending_report_times.begin(),
                       pending_report_times.end(),
                       [this](const double t) { return is_nearest_step(t); });
  }


  // @sect4{ContactProblem::slip_zone}

  // The slipping nodes of Gamma_3 and where they are: the range of their x
  // on a box or a mesh file; on a shell, whose Gamma_3 is closed, the
  // smallest arc about the z-axis that holds them all, from `from` to `to`
  // counterclockwise in degrees: the complement of the widest gap between
  // slipping nodes.
  template <int dim>
  SlipZone ContactProblem<dim>::slip_zone() const
  {
    const std::vector<ContactNode<dim>> &contact_nodes =
      friction_solver->boundary().nodes;
    const std::vector<NodeState> &node_state =
      friction_solver->state().node_state;
    SlipZone            zone;
    std::vector<double> angles, stick_angles;
    const auto          angle = [](const Point<dim> &x) {
      return std::atan2(x[1], x[0]) * 180 / numbers::PI;
    };
    for (unsigned int p = 0; p < contact_nodes.size(); ++p)
      if (node_state[p] == NodeState::stick)
        {
          stick_angles.push_back(angle(contact_nodes[p].location));
          ++zone.n_stick;
        }
      else
        {
          const Point<dim> &x = contact_nodes[p].location;
          zone.from = (zone.n_slip == 0 ? x[0] : std::min(zone.from, x[0]));
          zone.to   = (zone.n_slip == 0 ? x[0] : std::max(zone.to, x[0]));
          angles.push_back(angle(x));
          ++zone.n_slip;
        }
    if (parameters.geometry.shell && !angles.empty())
      {
        std::sort(angles.begin(), angles.end());
        const unsigned int n = angles.size();
        // From slipping node i to the next one counterclockwise.
        const auto gap = [&](const unsigned int i) {
          return i + 1 < n ? angles[i + 1] - angles[i] :
                             angles[0] + 360 - angles[i];
        };
        unsigned int widest = n - 1;
        for (unsigned int i = 0; i < n; ++i)
          if (gap(i) > gap(widest))
            widest = i;
        zone.from = angles[(widest + 1) % n];
        zone.to   = angles[widest];
        // Counterclockwise from `from`, in [0, 360).
        const auto turn = [&](const double a) {
          return std::fmod(a - zone.from + 720, 360.);
        };
        for (const double a : stick_angles)
          if (turn(a) < turn(zone.to))
            ++zone.n_stick_inside;
      }
    return zone;
  }


  // @sect4{ContactProblem::track_slip_onset}

  // The time of the first slip. The first step with a slipping node, t_n,
  // alone would move in jumps of k as h changes; instead the friction's
  // utilisation max_p |eta_p| / (m_p S mu(0)) of the last two steps in
  // which every node stuck is extrapolated linearly to 1 (not before
  // t_{n-1}). So the onset converges in h at a fixed k where the
  // utilisation rises smoothly. Where it cannot be extrapolated the step's
  // end or start is taken, and the summary says which
  // (SlipOnset::Estimate): such a time moves in jumps of k. (A node that
  // slips in the first half of a cut step and sticks again in the second
  // is not seen: the state is that at the end of the step.)
  template <int dim>
  void ContactProblem<dim>::track_slip_onset()
  {
    if (!std::isnan(slip_onset.time) || friction_law.is_frictionless())
      return;
    const std::vector<ContactNode<dim>> &nodes =
      friction_solver->boundary().nodes;
    const auto &[friction_force, slip_velocity, node_state] =
      friction_solver->state();
    double utilisation = 0;
    for (unsigned int p = 0; p < nodes.size(); ++p)
      if (node_state[p] != NodeState::stick)
        {
          using Estimate        = SlipOnset::Estimate;
          const double previous = time - time_step;
          const double rise =
            (slip_onset.utilisation - slip_onset.previous_utilisation) /
            time_step;
          slip_onset.step = step_number;
          slip_onset.time = previous;
          if (slip_onset.stick_steps < 2)
            slip_onset.estimate = Estimate::too_few_steps;
          else if (!(rise > 0))
            slip_onset.estimate = Estimate::not_rising;
          else if (previous + (1 - slip_onset.utilisation) / rise > time)
            {
              slip_onset.estimate = Estimate::beyond_step;
              slip_onset.time     = time;
            }
          else
            {
              slip_onset.estimate = Estimate::extrapolated;
              slip_onset.time =
                std::max(previous,
                         previous + (1 - slip_onset.utilisation) / rise);
            }
          return;
        }
      else if (nodes[p].weight > 0)
        utilisation =
          std::max(utilisation,
                   nodes[p].tangential_vector(friction_force, p).norm() /
                     (nodes[p].weight * friction_law.bound(0.)));
    slip_onset.previous_utilisation = slip_onset.utilisation;
    slip_onset.utilisation          = utilisation;
    ++slip_onset.stick_steps;
  }


  // @sect4{ContactProblem::print_slip_onset}

  // The summary's line of the first slip, with how its time was found.
  template <int dim>
  void ContactProblem<dim>::print_slip_onset() const
  {
    using Estimate = SlipOnset::Estimate;
    if (std::isnan(slip_onset.time))
      return;
    pcout << "First slip at t = " << std::setprecision(8) << slip_onset.time
          << " (in step " << slip_onset.step << ", ";
    switch (slip_onset.estimate)
      {
        case Estimate::extrapolated:
          pcout << "extrapolated from the friction's utilisation at the two "
                   "steps before";
          break;
        case Estimate::beyond_step:
          pcout << "its end: the friction's utilisation at the two steps "
                   "before extrapolates to later";
          break;
        case Estimate::not_rising:
          pcout << "its start: the friction's utilisation did not rise over "
                   "the two steps before";
          break;
        case Estimate::too_few_steps:
          pcout << "its start: fewer than two steps before it in which every "
                   "node stuck, to extrapolate from";
          break;
      }
    pcout << ")" << std::endl;
  }


  // @sect4{ContactProblem::final_quantities}

  // The quantities at T that an error estimate compares between runs of
  // different h and k (collective: the probes).
  template <int dim>
  std::vector<std::pair<std::string, double>>
  ContactProblem<dim>::final_quantities() const
  {
    std::vector<std::pair<std::string, double>> quantities;
    const VectorType                            u = ghosted(displacement);
    for (unsigned int i = 0; i < probes.size(); ++i)
      {
        const Tensor<1, dim> value = probe_displacement(i, u);
        for (unsigned int d = 0; d < dim; ++d)
          quantities.emplace_back("probe " + std::to_string(i + 1) + " u_" +
                                    std::string(1, "xyz"[d]),
                                  value[d]);
      }
    quantities.emplace_back("friction dissipation",
                            energy.friction_dissipation);
    const SlipZone     zone    = slip_zone();
    const unsigned int n_nodes = zone.n_stick + zone.n_slip;
    if (n_nodes > 0)
      quantities.emplace_back("slipping share of Gamma_3",
                              double(zone.n_slip) / n_nodes);
    if (!parameters.geometry.shell)
      quantities.emplace_back("slip zone starts at x",
                              zone.n_slip > 0 ?
                                zone.from :
                                std::numeric_limits<double>::quiet_NaN());
    quantities.emplace_back("time of the first slip", slip_onset.time);
    return quantities;
  }


  template <int dim>
  void ContactProblem<dim>::report_contact_state()
  {
    for (auto t = pending_report_times.begin();
         t != pending_report_times.end();)
      if (is_nearest_step(*t))
        {
          const std::vector<ContactNode<dim>> &contact_nodes =
            friction_solver->boundary().nodes;
          const Vector<double> &friction_force =
            friction_solver->state().friction_force;
          const SlipZone zone = slip_zone();
          pcout << "Report t = " << std::setprecision(6) << *t << " (step "
                << step_number << ", t_n = " << time
                << (*t - time > 0.5 * time_step * (1 + 1e-12) ?
                      ", the last step: the report time is after "
                      "'" +
                        Entry::end_time + "'" :
                      "")
                << "): " << zone.n_stick << " stick, " << zone.n_slip
                << " slip";
          if (zone.n_slip > 0 && !parameters.geometry.shell)
            pcout << ", slip zone x in [" << zone.from << ", " << zone.to
                  << "]";
          else if (zone.n_slip > 0 && zone.n_stick > 0)
            {
              pcout << ", slip on the arc from " << zone.from << " to "
                    << zone.to << " degrees (counterclockwise)";
              if (zone.n_stick_inside > 0)
                pcout << ", which holds " << zone.n_stick_inside
                      << " sticking nodes too";
            }
          // The sum of the nodal forces: along the tangent in 2D, as a
          // vector in 3D.
          Tensor<1, dim> friction;
          for (unsigned int p = 0; p < contact_nodes.size(); ++p)
            friction += contact_nodes[p].tangential_vector(friction_force, p);
          // A scalar along the tangent where Gamma_3 is straight (all its
          // nodes share one tangent), the vector otherwise. (The slip zone
          // is given by its x range, which locates it on any open Gamma_3,
          // or on a shell's closed one by its arc.)
          bool straight = (dim == 2 && !contact_nodes.empty());
          for (const ContactNode<dim> &node : contact_nodes)
            straight =
              straight &&
              (node.tangents[0] - contact_nodes[0].tangents[0]).norm() < 1e-12;
          pcout << "; friction force ";
          if (straight)
            pcout << friction * contact_nodes[0].tangents[0];
          else
            pcout << friction;
          pcout << ", momentum " << momentum() << std::endl;
          t = pending_report_times.erase(t);
        }
      else
        ++t;
  }


  // @sect4{ContactProblem::print_summary}

  template <int dim>
  void ContactProblem<dim>::print_summary() const
  {
    pcout << "Done: " << n_time_steps
          << " steps of k = " << std::setprecision(8) << time_step << ", "
          << totals.convexification_iterations
          << " convexification iterations, " << totals.active_set_iterations
          << " active set iterations, " << totals.rejected_accelerations
          << " rejected accelerations." << std::endl;
    if (totals.newton_iterations > 0)
      pcout << "Newton on the full friction law: " << totals.newton_iterations
            << " iterations, " << std::setprecision(3)
            << static_cast<double>(totals.newton_iterations) / n_time_steps
            << " per step; the convexification took over in "
            << totals.newton_fallbacks << " steps." << std::endl;
    pcout << "Solves with K per step: " << std::setprecision(3)
          << static_cast<double>(totals.solves_with_K) / n_time_steps
          << std::endl;
    if (totals.cg_iterations > 0)
      // Rounded: the count moves by a few tenths with the round-off of the
      // AMG coarse solve (the BLAS in use).
      pcout << "CG iterations per step: "
            << std::lround(static_cast<double>(totals.cg_iterations) /
                           n_time_steps)
            << std::endl;
    pcout << "Energy at t = " << time << ": kinetic " << std::setprecision(6)
          << energy.kinetic << ", elastic " << energy.elastic
          << ", external work " << energy.external_work << ", viscous "
          << energy.viscous_dissipation << ", friction "
          << energy.friction_dissipation << ", numerical "
          << energy.numerical_dissipation << std::endl;
    print_slip_onset();
    print_self_checks();
    if (exact_solution)
      pcout << "Errors, largest over the steps: ||eps(u - u_h)|| "
            << std::setprecision(6) << max_errors.displacement_V
            << ", ||w - w_h|| " << max_errors.velocity_L2 << ", ||u - u_h|| "
            << max_errors.displacement_L2 << std::endl;
    if (parameters.output.print_timings)
      {
        pcout << "Wall time: " << std::setprecision(4) << run_timer.wall_time()
              << " s" << std::endl;
        const unsigned int steps     = std::max(steps_timed, 1u);
        const double       step_time = computing_timer.get_summary_data(
                                   TimerOutput::total_wall_time)["Time steps"] /
                                 steps;
        const double substitution = substitution_time / steps;
        if (!friction_law.is_frictionless())
          pcout << "Contact solver: " << friction_solver->description()
                << std::endl;
        if (factorization && factorization->factor_size() > 0)
          pcout << "Factor of K: "
                << static_cast<long long>(factorization->factor_size())
                << " nonzeros" << std::endl;
        if (substitution > 0)
          pcout << "Time per step " << 1e3 * step_time
                << " ms = " << step_time / substitution
                << (factorization->iterations() > 0 ?
                      " solves with K (one: " :
                      " substitutions with the factor of K (one: ")
                << 1e3 * substitution << " ms)" << std::endl;
        Utilities::System::MemoryStats memory;
        Utilities::System::get_memory_stats(memory);
        const auto peak =
          Utilities::MPI::min_max_avg(memory.VmHWM / 1024., mpi_communicator);
        pcout << "Peak memory per process: " << std::setprecision(4) << peak.max
              << " MB (smallest " << peak.min << " MB, "
              << Utilities::MPI::n_mpi_processes(mpi_communicator)
              << " processes)" << std::endl;
        computing_timer.print_summary();
      }
  }


#define INSTANTIATE(dim)                                                       \
  template void ContactProblem<dim>::claim_output_directory();                 \
  template void ContactProblem<dim>::prepare_output_directory();               \
  template void ContactProblem<dim>::write_gamma3_history_rows();              \
  template void ContactProblem<dim>::track_slip_onset();                       \
  template void ContactProblem<dim>::print_slip_onset() const;                 \
  template void ContactProblem<dim>::write_time_series_row(                    \
    const StepStatistics &);                                                   \
  template std::string ContactProblem<dim>::vtu_piece_name(const unsigned int, \
                                                           const unsigned int) \
    const;                                                                     \
  template void ContactProblem<dim>::write_vtu();                              \
  template void ContactProblem<dim>::cell_average_stress(VtuOutput &) const;   \
  template void ContactProblem<dim>::add_vtu_fields(VtuOutput &) const;        \
  template void ContactProblem<dim>::write_vtu_piece(VtuOutput &,              \
                                                     const std::string &)      \
    const;                                                                     \
  template void     ContactProblem<dim>::finish_vtu();                         \
  template bool     ContactProblem<dim>::is_nearest_step(const double) const;  \
  template bool     ContactProblem<dim>::report_due() const;                   \
  template SlipZone ContactProblem<dim>::slip_zone() const;                    \
  template std::vector<std::pair<std::string, double>>                         \
                ContactProblem<dim>::final_quantities() const;                 \
  template void ContactProblem<dim>::write_pvd() const;                        \
  template void ContactProblem<dim>::print_progress(const StepStatistics &)    \
    const;                                                                     \
  template void           ContactProblem<dim>::report_contact_state();         \
  template void           ContactProblem<dim>::print_summary() const;          \
  template Tensor<1, dim> ContactProblem<dim>::probe_displacement(             \
    const unsigned int, const VectorType &) const;

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace Contact
