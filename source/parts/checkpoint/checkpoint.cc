/* Checkpoint and restart, the storage of a run (core/run_storage.h) that
   this part registers: everything a time step reads from the past, in
   one binary file per process (Boost serialization), written to a temporary
   name and renamed, so a run killed at any moment leaves either the
   previous checkpoint or the new one, never half of one.

   The file is a line naming the format, a line with the size and the
   CRC-32 of the rest, and the rest: the mesh's plan (the cycles by which a
   mesh adaptation changed the Geometry's mesh, MeshPlan), the shape of the
   discrete problem, the entries of the .prm that define it, the state, and
   whether the mesh's adaptation after the checkpoint's step is still due.
   A damaged or truncated file, or one of another problem, is refused by
   name.

   The mesh itself, the matrices and the factorisation are not stored: they
   follow deterministically from the .prm and the plan and are rebuilt on
   --resume, which then continues with bitwise the same numbers as the
   uninterrupted run (tests/verification/kill_and_resume). */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/crc.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <base/dimensions.h>
#include <base/printed_entries.h>
#include <base/parts.h>
#include <core/output_directory.h>
#include <core/postprocessor.h>
#include <core/run_storage.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <map>
#include <sstream>
#include <utility>

namespace Contact
{
  namespace
  {
    // The one format this program reads and writes. A change of what a
    // checkpoint holds (its payload, or an entry that defines the problem)
    // raises the number, and a checkpoint of any other number is refused by
    // it (read_payload()): a run continued from it would silently differ.
    const unsigned int checkpoint_version = 12;
    const std::string  checkpoint_prefix  = "contact checkpoint ";
    const std::string  checkpoint_format =
      checkpoint_prefix + std::to_string(checkpoint_version);
    const ResultFiles checkpoint_files("checkpoint(\\.[0-9]+)?(\\.tmp)?");

    std::uint32_t crc32(const std::string &bytes)
    {
      boost::crc_32_type crc;
      crc.process_bytes(bytes.data(), bytes.size());
      return crc.checksum();
    }

    // What a resumed run may change without changing the discrete problem
    // (README, 'When a run fails'): the end and the solver, the output
    // except the probes, the time series and the Gamma_3 history, whose
    // rows and columns must continue, and the entries that a part says
    // a resumed run may change (whether the run is followed by an error
    // estimate: a resume is not, the estimate of a killed run is dropped).
    // k itself is part of the checkpoint's shape.
    bool may_change_on_resume(const std::string &entry)
    {
      if (entry == Entry::probe_points || entry == Entry::time_series ||
          entry == Entry::gamma3_history)
        return false;
      return entry.rfind("Output/", 0) == 0 || entry.rfind("Solver/", 0) == 0 ||
             entry == Entry::end_time || entry == Entry::time_step ||
             entry == Entry::max_steps || Parts::may_change_on_resume(entry);
    }

    // 'Section/Entry' -> value for the entries of the .prm (its ShortPRM
    // print) that define the discrete problem.
    std::map<std::string, std::string>
    problem_entries(const std::string &used_parameters)
    {
      std::map<std::string, std::string> entries;
      for (auto [entry, value] : read_printed_entries(used_parameters))
        {
          // The same mesh file however the .prm's path was typed.
          std::error_code unresolved;
          if (entry == Entry::mesh_file && !value.empty())
            {
              const auto path =
                std::filesystem::weakly_canonical(value, unresolved);
              if (!unresolved)
                value = path.string();
            }
          if (!may_change_on_resume(entry))
            entries[entry] = value;
        }
      return entries;
    }

    // The entries whose values differ, 'entry: checkpoint a, now b'.
    std::string
    differing_entries(const std::map<std::string, std::string> &stored,
                      const std::map<std::string, std::string> &now)
    {
      std::string text;
      const auto  value = [](const auto &entries, const std::string &entry) {
        const auto found = entries.find(entry);
        return found == entries.end() ? std::string("(not set)") :
                                         "'" + found->second + "'";
      };
      std::map<std::string, std::string> all(stored);
      all.insert(now.begin(), now.end());
      for (const auto &[entry, unused] : all)
        if (value(stored, entry) != value(now, entry))
          text += "\n  " + entry + ": " + value(stored, entry) +
                  " in the checkpoint, " + value(now, entry) + " now";
      return text;
    }

    // The absolute values of the mesh's vertex coordinates, summed with
    // weights over the locally owned cells, to 12 digits: a moved vertex of
    // a mesh file changes it, the same mesh on the same processes gives the
    // same sum (absolute values, so that a symmetric mesh does not sum to
    // round-off).
    template <int dim>
    std::string mesh_fingerprint(const DoFHandler<dim> &dof_handler,
                                 const MPI_Comm         communicator)
    {
      double sum = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              sum += (1 + d + 0.1 * v) * std::abs(cell->vertex(v)[d]);
      std::ostringstream text;
      text << ", mesh vertex sum " << std::setprecision(12)
           << Utilities::MPI::sum(sum, communicator);
      return text.str();
    }

    // What identifies the discrete problem a checkpoint belongs to (k to
    // all digits, and the mesh's fingerprint), as stored in it and shown
    // when it does not match. (The probes, whose columns the time series
    // continues, are compared as entries.)
    template <int dim>
    std::string shape(const DoFHandler<dim> &dof_handler,
                      const unsigned int     n_contact_nodes,
                      const double           time_step,
                      const bool             manufactured,
                      const MPI_Comm         communicator)
    {
      std::ostringstream text;
      text << dim << "D, " << dof_handler.n_dofs() << " unknowns, "
           << n_contact_nodes << " nodes on Gamma_3, "
           << Utilities::MPI::n_mpi_processes(communicator)
           << " process(es), k = " << std::setprecision(17) << time_step
           << (manufactured ? ", manufactured solution" : "");
      return text.str() + mesh_fingerprint(dof_handler, communicator);
    }

    // The shape without its k, and its k.
    std::pair<std::string, double> split_k(const std::string &shape)
    {
      const std::size_t k = shape.find(", k = ");
      if (k == std::string::npos)
        return {shape, 0};
      const std::size_t end = std::min(shape.find(',', k + 6), shape.size());
      return {shape.substr(0, k) + shape.substr(end),
              std::stod(shape.substr(k + 6, end - k - 6))};
    }

    // Whether a checkpoint of `stored` shape continues a run of `problem`
    // shape: the same but for k to round-off (k = T/N of another End time
    // that is a multiple of k differs from it in the last digits).
    bool same_problem(const std::string &stored, const std::string &problem)
    {
      const auto [stored_rest, stored_k]   = split_k(stored);
      const auto [problem_rest, problem_k] = split_k(problem);
      return stored_rest == problem_rest &&
             std::abs(stored_k - problem_k) <= 1e-12 * std::abs(stored_k);
    }

    // The refusal of a checkpoint whose shape differs from the run's; where
    // only k differs, how to keep it: k is T/N, so the End time must be a
    // multiple of the checkpoint's k and 'Time step' must give that k.
    std::string another_problem(const std::string &name,
                                const std::string &stored_shape,
                                const std::string &problem_shape,
                                const double       end_time,
                                const double       time_step)
    {
      const auto [stored_rest, stored_k] = split_k(stored_shape);
      if (stored_rest == split_k(problem_shape).first && stored_k > 0)
        {
          const double below = std::max(1., std::floor(end_time / stored_k)) *
                               stored_k,
                       above = below + stored_k;
          std::ostringstream digits;
          digits << std::setprecision(17) << stored_k << "' and an End time "
                 << "that is a multiple of it, e.g. " << below << " or "
                 << above;
          return "The checkpoint '" + name +
                 "' has the time step k = " + number_text(stored_k) +
                 ", this run k = T/N = " + number_text(time_step) + " ('" +
                 Entry::end_time + "' = " + number_text(end_time) +
                 " divided into whole steps of at most 'Time step'). Resume "
                 "with 'Time step' = '" +
                 digits.str() + ".";
        }
      return "The checkpoint '" + name +
             "' belongs to another discrete problem (" + stored_shape +
             ") than this .prm gives (" + problem_shape +
             "): resume with the scene, mesh, time step and number of "
             "processes of the checkpointed run.";
    }

    // One file per process.
    std::string checkpoint_name(const std::string &directory,
                                const MPI_Comm     communicator)
    {
      std::string name = directory + "/checkpoint";
      if (Utilities::MPI::n_mpi_processes(communicator) > 1)
        name += "." + Utilities::int_to_string(
                        Utilities::MPI::this_mpi_process(communicator));
      return name;
    }

    // @sect4{mixed_checkpoints}

    std::string mixed_checkpoints(const std::string &directory)
    {
      return "The checkpoints of the processes in '" + directory +
             "' are of different steps (the job was killed while they were "
             "written): resume from a complete set, or start the run again "
             "without --resume.";
    }

    // @sect4{require_format}

    // The first line of a checkpoint names its format. A checkpoint of
    // another version is refused by its number, anything else as not a
    // checkpoint.
    void require_format(const std::string &name, const std::string &format)
    {
      const bool other_version =
        format != checkpoint_format && format.rfind(checkpoint_prefix, 0) == 0;
      AssertThrow(!other_version,
                  ExcMessage(
                    "'" + name + "' is a checkpoint of format " +
                    format.substr(checkpoint_prefix.size()) +
                    ", written by another version of this program; this "
                    "version reads format " +
                    std::to_string(checkpoint_version) +
                    " only. Resume it with the version that wrote it, or "
                    "start the run again without --resume."));
      AssertThrow(format == checkpoint_format,
                  ExcMessage("'" + name +
                             "' is not a checkpoint this program reads: it "
                             "does not begin with the line '" +
                             checkpoint_format + "' (damaged?)."));
    }


    // @sect4{read_payload}

    // The checkpoint's bytes after its two header lines, checked against the
    // size and CRC-32 stored there.
    std::string read_payload(const std::string &name)
    {
      std::ifstream file(name, std::ios::binary);
      AssertThrow(file,
                  ExcMessage("Cannot read the checkpoint '" + name + "'."));
      std::string format;
      std::getline(file, format);
      require_format(name, format);
      std::size_t   size     = 0;
      std::uint32_t checksum = 0;
      file >> size >> checksum;
      file.get();
      std::error_code error;
      const auto      file_size = std::filesystem::file_size(name, error);
      AssertThrow(file && !error &&
                    file_size ==
                      static_cast<std::uintmax_t>(file.tellg()) + size,
                  ExcMessage("The checkpoint '" + name +
                             "' is damaged: its size does not match its header "
                             "(truncated?). Resume from another copy, or start "
                             "the run again without --resume."));
      std::string bytes(size, '\0');
      file.read(bytes.data(), size);
      AssertThrow(file && crc32(bytes) == checksum,
                  ExcMessage("The checkpoint '" + name +
                             "' is damaged: its checksum does not match its "
                             "contents. Resume from another copy, or start the "
                             "run again without --resume."));
      return bytes;
    }

    // @sect4{require_checkpoint}

    // Checked before anything is computed or written.
    void require_checkpoint(const std::string &directory,
                            const MPI_Comm     mpi_communicator)
    {
      const unsigned int n_processes =
        Utilities::MPI::n_mpi_processes(mpi_communicator);
      std::string other;
      if (n_processes > 1 && std::filesystem::exists(directory + "/checkpoint"))
        other = " There is one written by 1 process ('" + directory +
                "/checkpoint'): resume it with one process.";
      else if (n_processes == 1 &&
               std::filesystem::exists(directory + "/checkpoint.0"))
        other = " There is one written by several processes ('" + directory +
                "/checkpoint.0', ...): resume it with as many processes.";
      const std::string name = checkpoint_name(directory, mpi_communicator);
      AssertThrow(std::filesystem::exists(name),
                  ExcMessage("'" + Entry::resume +
                             "' (--resume): there is no "
                             "checkpoint '" +
                             name + "' for a run on " +
                             std::to_string(n_processes) + " process(es)." +
                             other +
                             " Checkpoints are written with "
                             "'" +
                             Entry::checkpoint_interval +
                             "' or "
                             "'" +
                             Entry::checkpoint_minutes +
                             "' into the output "
                             "directory."));
    }
  } // namespace


  // @sect3{The class Checkpoint}

  // The storage of the run (core/run_storage.h) that this part registers:
  // it holds references to the parts of the problem that a checkpoint
  // stores and restores.
  template <int dim>
  class Checkpoint : public RunStorage<dim>
  {
  public:
    explicit Checkpoint(const RunStorageView<dim> &run);

    /** On --resume, before anything is computed or written: the
     *  checkpoint of this number of processes exists, and the mesh plan
     *  stored with it becomes the run's. */
    void restore_mesh_plan() override;

    /** Whether a checkpoint is due after the current step. */
    bool due() const override;

    void save() override;

    /** On --resume, once the problem is set up on the checkpoint's mesh:
     *  the state of the run at the checkpoint's step. */
    void load() override;

  private:
    /** Refuses a checkpoint of another discrete problem than this run's
     *  (its shape, or an entry of the .prm that defines it). */
    void require_same_problem(
      const std::string                        &stored_shape,
      const std::map<std::string, std::string> &stored_entries) const;

    const Parameters                                       &parameters;
    const DiscreteSpace<dim>                               &space;
    MeshAdaptation                                         &adaptation;
    StepState                                              &state;
    const std::unique_ptr<FrictionSolver<dim>>             &friction_solver;
    const std::vector<std::unique_ptr<Postprocessor<dim>>> &postprocessors;
    const ConditionalOStream                               &pcout;
    TimerOutput                                            &computing_timer;
    // This process's file.
    const std::string name;
    // The wall time since the last checkpoint ('Checkpoint minutes').
    Timer wall_timer;
  };


  // @sect4{Checkpoint::Checkpoint}

  template <int dim>
  Checkpoint<dim>::Checkpoint(const RunStorageView<dim> &run)
    : parameters(run.parameters)
    , space(run.space)
    , adaptation(run.adaptation)
    , state(run.state)
    , friction_solver(run.friction_solver)
    , postprocessors(run.postprocessors)
    , pcout(run.pcout)
    , computing_timer(run.computing_timer)
    , name(checkpoint_name(parameters.output.directory, space.mpi_communicator))
  {}


  // @sect4{Checkpoint::restore_mesh_plan}

  // A resumed run is built on its checkpoint's mesh: the scene's mesh
  // changed by the cycles of the plan stored with it (of pilot runs, or of
  // the adaptations during the run up to the checkpoint's step).
  template <int dim>
  void Checkpoint<dim>::restore_mesh_plan()
  {
    require_checkpoint(parameters.output.directory, space.mpi_communicator);
    std::string plan_text;
    {
      std::istringstream payload(read_payload(name), std::ios::binary);
      boost::archive::binary_iarchive archive(payload);
      archive                        &plan_text;
    }
    // A set of checkpoints of different steps (a job killed while they were
    // written) may have different plans: refused here, before the processes
    // build different meshes (load() compares the steps).
    const std::size_t plan_hash = std::hash<std::string>()(plan_text);
    AssertThrow(Utilities::MPI::min(plan_hash, space.mpi_communicator) ==
                  Utilities::MPI::max(plan_hash, space.mpi_communicator),
                ExcMessage(mixed_checkpoints(parameters.output.directory)));
    adaptation.plan = MeshPlan::from_text(plan_text, name);
  }


  // @sect4{Checkpoint::due}

  // Every 'Checkpoint interval' steps, when 'Checkpoint minutes' have
  // passed, and at the end (so that a finished run can be extended). The
  // processes agree on the wall time criterion through a reduction.
  template <int dim>
  bool Checkpoint<dim>::due() const
  {
    const auto &output = parameters.output;
    if (output.checkpoint_interval == 0 && output.checkpoint_minutes == 0)
      return false;
    const bool late = output.checkpoint_minutes > 0 &&
                      wall_timer.wall_time() >= 60. * output.checkpoint_minutes;
    return state.step_number == parameters.time.n_steps() ||
           (output.checkpoint_interval > 0 &&
            state.step_number % output.checkpoint_interval == 0) ||
           Utilities::MPI::max(late ? 1 : 0, space.mpi_communicator) == 1;
  }


  // @sect4{Checkpoint::save}

  // Everything a step reads from the past: the step state, the nodal state
  // of Gamma_3, and each postprocessor's own state (its totals, the
  // records of its files, ...), in the order of their ranks.
  template <int dim>
  void Checkpoint<dim>::save()
  {
    TimerOutput::Scope t(computing_timer, "Checkpoint");
    std::ostringstream payload(std::ios::binary);
    {
      boost::archive::binary_oarchive archive(payload);
      std::string                     plan_text = adaptation.plan.text();
      std::string                     problem_shape =
        shape(space.dof_handler,
              friction_solver->boundary().nodes.size(),
              state.time_step,
              parameters.verification.manufactured(),
              space.mpi_communicator);
      std::map<std::string, std::string> entries =
        problem_entries(parameters.used_parameters);
      FrictionState friction_state = friction_solver->state();
      archive &plan_text &problem_shape &entries &state &friction_state;
      // Each postprocessor's own state, in the order of their ranks.
      CheckpointArchive parts(archive);
      for (const auto &postprocessor : postprocessors)
        postprocessor->checkpoint(parts);
      // The time loop adapts after every interval-th step but the last
      // (ContactProblem::time_loop()).
      bool due = adaptation.interval > 0 && state.step_number > 0 &&
                 state.step_number % adaptation.interval == 0 &&
                 state.step_number == parameters.time.n_steps();
      archive &due;
    }
    const std::string bytes = payload.str();
    {
      std::ofstream file(name + ".tmp", std::ios::binary);
      file << checkpoint_format << '\n'
           << bytes.size() << ' ' << crc32(bytes) << '\n';
      file.write(bytes.data(), bytes.size());
      file.flush();
      AssertThrow(file,
                  ExcMessage("Cannot write the checkpoint '" + name +
                             ".tmp': " + std::strerror(errno) + "."));
    }
    // Every process's new checkpoint is complete before any replaces its
    // old one, so a job killed in between leaves one set of checkpoints of
    // one step (of the old or the new one per process; load() refuses a
    // set of different steps).
    const int ierr = MPI_Barrier(space.mpi_communicator);
    AssertThrowMPI(ierr);
    std::filesystem::rename(name + ".tmp", name);
    wall_timer.restart();
  }


  // @sect4{Checkpoint::load}

  template <int dim>
  void Checkpoint<dim>::load()
  {
    std::istringstream payload(read_payload(name), std::ios::binary);
    boost::archive::binary_iarchive    archive(payload);
    std::string                        plan_text, stored_shape;
    std::map<std::string, std::string> stored_entries;
    // (The plan was read before the mesh was built.)
    archive &plan_text &stored_shape &stored_entries;
    require_same_problem(stored_shape, stored_entries);

    FrictionState   friction_state;
    archive &state &friction_state;
    friction_solver->set_state(friction_state);
    CheckpointArchive parts(archive);
    for (const auto &postprocessor : postprocessors)
      postprocessor->checkpoint(parts);
    archive           &adaptation.due;
    const unsigned int step_number = state.step_number;
    AssertThrow(Utilities::MPI::min(step_number, space.mpi_communicator) ==
                  Utilities::MPI::max(step_number, space.mpi_communicator),
                ExcMessage(mixed_checkpoints(parameters.output.directory)));
    const unsigned int n_steps = parameters.time.n_steps();
    AssertThrow(step_number <= n_steps,
                ExcMessage(
                  "The checkpoint is at step " + std::to_string(step_number) +
                  ", beyond the end of this run (" + std::to_string(n_steps) +
                  " steps): '" + Entry::end_time + "' is too small."));
    pcout << "Resumed from the checkpoint at step " << step_number
          << " (t = " << state.time << ")." << std::endl;
    wall_timer.restart();
  }


  // @sect4{Checkpoint::require_same_problem}

  // The checkpoint's shape and defining entries against this run's.
  template <int dim>
  void Checkpoint<dim>::require_same_problem(
    const std::string                        &stored_shape,
    const std::map<std::string, std::string> &stored_entries) const
  {
    const std::map<std::string, std::string> entries_now =
      problem_entries(parameters.used_parameters);
    const std::string problem_shape =
      shape(space.dof_handler,
            friction_solver->boundary().nodes.size(),
            state.time_step,
            parameters.verification.manufactured(),
            space.mpi_communicator);
    AssertThrow(same_problem(stored_shape, problem_shape),
                ExcMessage(another_problem(name,
                                           stored_shape,
                                           problem_shape,
                                           parameters.time.end_time,
                                           state.time_step)));
    const std::string differences =
      differing_entries(stored_entries, entries_now);
    AssertThrow(differences.empty(),
                ExcMessage("The checkpoint '" + name +
                           "' belongs to another problem: these entries "
                           "differ from the checkpointed run's, and only "
                           "'" +
                           Entry::end_time +
                           "', 'Solver/...' and most of "
                           "'Output/...' may change on --resume:" +
                           differences));
  }


  // The one storage of runs: a run has it whether or not it writes
  // checkpoints, so that every run can be resumed from those it wrote.
  namespace
  {
    bool register_checkpoint()
    {
#define INSTANTIATE(dim)                                                      \
  RunStorageParts<dim>::add(                                                  \
    {"checkpoint",                                                            \
     "",                                                                      \
     0,                                                                       \
     {},                                                                      \
     [](const RunStorageView<dim> &run) -> std::unique_ptr<RunStorage<dim>> { \
       return std::make_unique<Checkpoint<dim>>(run);                         \
     }});
      CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
      return true;
    }

    const bool registered = register_checkpoint();
  } // namespace
} // namespace Contact
