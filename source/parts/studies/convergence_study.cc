/* ---------------------------------------------------------------------
 * A convergence study ('Convergence study/Levels' > 0).
 *
 * The scene runs Levels + 1 times, halving h, k or both from one level to
 * the next (each run in its own subdirectory, with its own parameters.prm;
 * the time steps are T/(N 2^l), so that the time grids are nested), and
 * the errors are printed with their rates log2(e_{l-1}/e_l). Corollary
 * 5.3, (5.26): O(h + k) in the V-norm.
 *
 * With a manufactured solution the errors are exact. Otherwise the finest
 * level is the reference (run first and kept, so that the coarser
 * solutions can be interpolated onto its mesh), the errors are taken at
 * t = T and over the common time grid (the coarsest level's), and the
 * differences of successive levels give an estimate that needs no
 * reference (a reference only twice as fine flatters the last rate).
 * --------------------------------------------------------------------- */

#include <deal.II/base/mpi.h>
#include <deal.II/base/table_handler.h>

#include <base/dimensions.h>
#include <core/geometry_base.h>
#include <base/version.h>
#include <core/contact_problem.h>
#include <core/output_directory.h>
#include <core/postprocessor.h>
#include <parts/studies/convergence_study.h>
#include <parts/studies/reference_interpolation.h>
#include <parts/studies/scene_variant.h>
#include <parts/studies/study_parameters.h>
#include <parts/studies/sub_run.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace Contact
{
  namespace
  {
    // What a convergence study writes into its output directory: its table
    // and the runs of its levels.
    const ResultFiles       study_table("convergence\\.txt");
    const ResultDirectories level_runs("level-[0-9]+");

    using Refine = ConvergenceStudyParameters::Refine;

    // @sect4{The levels}

    // Level l: h and/or k of the scene times 2^-l, the reference's degree
    // on the reference level (the finest, without an exact solution).
    SceneVariant level_variant(const Parameters  &scene,
                               const unsigned int level)
    {
      const ConvergenceStudyParameters &study =
        ConvergenceStudyParameters::of(scene);
      const bool reference = level == study.levels &&
                             study.reference_degree > 0 &&
                             !scene.verification.manufactured();
      return {study.refine == Refine::time ? 0 : static_cast<int>(level),
              scene.time.n_steps()
                << (study.refine == Refine::space ? 0 : level),
              reference ? study.reference_degree : scene.geometry.fe_degree,
              scene.output.directory + "/level-" + std::to_string(level),
              false};
    }

    void announce(const Parameters &level_parameters, const unsigned int level)
    {
      std::ostringstream line;
      line << std::setprecision(17) << "Convergence study, level " << level
           << ": " << create_geometry(level_parameters)->mesh_size_text()
           << ", k = " << level_parameters.time.time_step;
      study_console() << line.str() << std::endl;
    }

    // One level's run, and (without an exact solution) its displacements
    // at the times of the coarsest level's grid, interpolated onto the
    // finest mesh.
    struct LevelResult
    {
      RunSummary              run;
      std::vector<VectorType> displacements;
    };

    // Runs the levels; without an exact solution the reference first, kept
    // in `reference`. The displacement at the common times (every 2^l-th
    // step of level l when k is refined) is interpolated onto the
    // reference mesh, whose nodes are gathered at its first step and
    // located in a level's mesh at the level's first step.
    template <int dim>
    std::vector<LevelResult>
    run_levels(const std::vector<Parameters>        &levels,
               std::unique_ptr<ContactProblem<dim>> &reference)
    {
      const unsigned int L     = levels.size() - 1;
      const bool         exact = levels[0].verification.manufactured();
      const Refine refine = ConvergenceStudyParameters::of(levels[0]).refine;
      std::vector<LevelResult>                     results(L + 1);
      std::unique_ptr<ReferenceInterpolation<dim>> interpolate;
      using NodesInCells =
        std::vector<typename ReferenceInterpolation<dim>::NodeInCell>;
      const auto collect = [&](const unsigned int level) {
        const unsigned int stride = (refine == Refine::space ? 1 : 1u << level);
        return [&, stride, level, located = std::optional<NodesInCells>()](
                 const ContactProblem<dim> &problem) mutable {
          if (problem.get_step_number() % stride != 0)
            return;
          if (!interpolate)
            interpolate =
              std::make_unique<ReferenceInterpolation<dim>>(*reference);
          if (!located)
            located = interpolate->locate(problem);
          results[level].displacements.push_back(
            (*interpolate)(*located, problem, problem.get_displacement()));
        };
      };
      if (!exact)
        {
          announce(levels[L], L);
          reference = std::make_unique<ContactProblem<dim>>(levels[L]);
          reference->add_postprocessor(
            std::make_unique<StepObserver<dim>>(collect(L)));
          results[L].run = reference->run();
        }
      for (unsigned int level = 0; level < (exact ? L + 1 : L); ++level)
        {
          announce(levels[level], level);
          ContactProblem<dim> problem(levels[level]);
          if (!exact)
            problem.add_postprocessor(
              std::make_unique<StepObserver<dim>>(collect(level)));
          results[level].run = problem.run();
        }
      return results;
    }


    // @sect4{The errors}

    // An error of a level, with the name of its column and of its rate
    // column (log2 of the ratio to the level before).
    struct Error
    {
      std::string name;
      std::string rate_name;
      double      value;
    };

    std::vector<Error> exact_errors(const LevelResult &result)
    {
      const ErrorNorms &e = result.run.max_errors;
      return {{"max V-error", "V rate", e.displacement_V},
              {"max L2 velocity error", "velocity rate", e.velocity_L2},
              {"max L2 displacement error",
               "displacement rate",
               e.displacement_L2}};
    }

    // Against the reference: at T and the largest over the common times,
    // and the difference to the next level at T.
    template <int dim>
    std::vector<Error> reference_errors(const ContactProblem<dim> &reference,
                                        const LevelResult         &result,
                                        const LevelResult         &next,
                                        const LevelResult         &finest)
    {
      const auto &u       = result.displacements;
      const auto &u_ref   = finest.displacements;
      double      largest = 0;
      for (unsigned int n = 0; n < u.size(); ++n)
        largest = std::max(largest, strain_distance(reference, u[n], u_ref[n]));
      return {
        {"V-error at T",
         "rate at T",
         strain_distance(reference, u.back(), u_ref.back())},
        {"max V-error", "max rate", largest},
        {"V-difference to next level at T",
         "difference rate",
         strain_distance(reference, u.back(), next.displacements.back())}};
    }


    // @sect4{The table}

    // A row per level with its errors and their rates; the relative
    // V-error is the first error over ||eps(u_h(T))|| of the finest level.
    TableHandler table_of(const std::vector<LevelResult>        &results,
                          const std::vector<std::vector<Error>> &errors,
                          const bool                             timings)
    {
      const double solution_norm = results.back().run.displacement_V_norm;
      TableHandler table;
      for (unsigned int level = 0; level < errors.size(); ++level)
        {
          const RunSummary &run = results[level].run;
          table.add_value("level", level);
          table.add_value("h", run.cell_size);
          table.add_value("k", run.time_step);
          table.add_value("unknowns", run.n_dofs);
          table.add_value("steps", run.n_steps);
          for (unsigned int i = 0; i < errors[level].size(); ++i)
            {
              const Error &e = errors[level][i];
              table.add_value(e.name, e.value);
              table.set_precision(e.name, 4);
              table.set_scientific(e.name, true);
              if (level == 0)
                table.add_value(e.rate_name, std::string("-"));
              else
                table.add_value(e.rate_name,
                                std::log2(errors[level - 1][i].value /
                                          e.value));
              table.set_precision(e.rate_name, 2);
            }
          table.add_value("relative V-error",
                          errors[level][0].value /
                            std::max(solution_norm,
                                     std::numeric_limits<double>::min()));
          table.set_precision("relative V-error", 2);
          table.set_scientific("relative V-error", true);
          if (timings)
            table.add_value("wall time [s]", run.wall_time);
        }
      for (const std::string column : {"h", "k"})
        table.set_scientific(column, true);
      return table;
    }

    // The table's title, the table (also to convergence.txt) and, with an
    // exact solution, the rates between the two finest levels.
    void print_study(const Parameters               &scene,
                     const std::vector<LevelResult> &results,
                     const TableHandler             &table)
    {
      const bool        exact  = scene.verification.manufactured();
      const Refine      refine = ConvergenceStudyParameters::of(scene).refine;
      const RunSummary &finest = results.back().run;
      study_console()
        << std::endl
        << "Convergence study (refining "
        << (refine == Refine::space ? "h" :
            refine == Refine::time  ? "k" :
                                      "h and k")
        << "; rates log2(e_{l-1}/e_l); relative V-error: the first "
        << "error column over ||eps(u_h(T))|| = " << std::setprecision(4)
        << finest.displacement_V_norm << " of the finest level";
      if (!exact)
        study_console() << "; reference: level " << results.size() - 1
                        << std::setprecision(6) << ", h = " << finest.cell_size
                        << ", k = " << finest.time_step << ", " << finest.n_dofs
                        << " unknowns";
      std::ostringstream text;
      table.write_text(text, TableHandler::TextOutputFormat::org_mode_table);
      study_console() << "):" << std::endl << text.str();
      write_study_file(scene.output.directory + "/convergence.txt", text.str());
      if (!exact || results.size() < 2)
        return;
      const ErrorNorms &coarse = results[results.size() - 2].run.max_errors;
      const ErrorNorms &fine   = finest.max_errors;
      study_console() << "Rates between the two finest levels: V-norm "
                      << std::fixed << std::setprecision(2)
                      << std::log2(coarse.displacement_V / fine.displacement_V)
                      << ", velocity L2 "
                      << std::log2(coarse.velocity_L2 / fine.velocity_L2)
                      << ", displacement L2 "
                      << std::log2(coarse.displacement_L2 /
                                   fine.displacement_L2)
                      << std::defaultfloat << std::endl;
    }
  } // namespace


  // @sect4{The study}

  template <int dim>
  RunResult ConvergenceStudy<dim>::run(const Parameters &scene,
                                       // The levels refine the scene's own
                                       // mesh: no study wraps this one.
                                       const StudyInput<dim> &)
  {
    const unsigned int L     = ConvergenceStudyParameters::of(scene).levels;
    const bool         exact = scene.verification.manufactured();
    // Every level's entries are checked before the first level runs, so
    // that a study does not fail at its finest level (e.g. over 'Time/Max
    // steps' or the number of VTU files).
    std::vector<Parameters> levels;
    for (unsigned int level = 0; level <= L; ++level)
      try
        {
          levels.push_back(parameters_of(scene, level_variant(scene, level)));
        }
      catch (const ExceptionBase &error)
        {
          // The reference's degree is the study's entry, not the scene's:
          // named where the level runs with the scene's own degree.
          std::ostringstream text;
          error.print_info(text);
          SceneVariant own_degree  = level_variant(scene, level);
          own_degree.degree        = scene.geometry.fe_degree;
          bool runs_without_degree = true;
          try
            {
              parameters_of(scene, own_degree);
            }
          catch (const ExceptionBase &)
            {
              runs_without_degree = false;
            }
          AssertThrow(
            !(level == L && runs_without_degree &&
              ConvergenceStudyParameters::of(scene).reference_degree > 0 &&
              !scene.verification.manufactured()),
            ExcMessage(
              "Entry '" + Entry::reference_degree + "' = " +
              std::to_string(
                ConvergenceStudyParameters::of(scene).reference_degree) +
              ": the reference level cannot run with "
              "this degree, for this reason: " +
              Utilities::trim(text.str())));
          throw;
        }
    // The study owns its directory while it runs (a plain run there would
    // clean away its levels), and starts it afresh: a study with fewer
    // levels than the last one leaves none of that one's levels or table
    // behind.
    const auto lock =
      lock_output_directory(scene.output.directory, MPI_COMM_WORLD);
    remove_results(scene.output.directory, false, MPI_COMM_WORLD);
    // The study's parameters run it again (each level's run is in its
    // directory's).
    write_study_file(scene.output.directory + "/parameters.prm",
                     parameter_file_header() + scene.used_parameters);

    std::unique_ptr<ContactProblem<dim>> reference;
    const std::vector<LevelResult>  results = run_levels(levels, reference);
    std::vector<std::vector<Error>> errors(exact ? L + 1 : L);
    for (unsigned int level = 0; level < errors.size(); ++level)
      errors[level] = exact ? exact_errors(results[level]) :
                              reference_errors(*reference,
                                               results[level],
                                               results[level + 1],
                                               results[L]);
    print_study(scene,
                results,
                table_of(results, errors, scene.output.print_timings));
    return {};
  }


#define INSTANTIATE(dim) template class ConvergenceStudy<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
