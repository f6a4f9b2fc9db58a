/* The variants of a scene that the drivers run
 * (include/parts/studies/scene_variant.h). */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <core/geometry_base.h>
#include <base/printed_entries.h>
#include <parts/studies/scene_variant.h>
#include <parts/studies/study_parameters.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

namespace Contact
{
  // @sect3{Variants}

  namespace
  {
    // A number as an entry's value: 17 digits, so that the variant reads
    // back the double it was given.
    std::string exact_text(const double value)
    {
      std::ostringstream text;
      text << std::setprecision(17) << value;
      return text.str();
    }

    std::string bool_text(const bool value)
    {
      return value ? "true" : "false";
    }

    // The entries that a variant sets: h, k, degree and directory, how it
    // adapts its mesh, and what a quiet variant switches off (the scene's
    // values otherwise).
    std::map<std::string, std::string>
    variant_entries(const Parameters &scene, const SceneVariant &variant)
    {
      const AccuracyParameters &accuracy = AccuracyParameters::of(scene);
      const OutputParameters   &output   = scene.output;
      const bool                quiet    = variant.quiet;
      std::map<std::string, std::string> entries;
      entries[Entry::finite_element_degree] = std::to_string(variant.degree);
      entries[Entry::time_step] =
        exact_text(scene.time.end_time / variant.n_steps);
      entries[Entry::output_directory] = variant.directory;
      entries[Entry::levels]           = "0";
      // A variant runs on the mesh its driver gives it (a pilot's, or an
      // estimate's coarsened one), and adapts none by pilots itself. Of a
      // scene that adapts its mesh during the run, a variant (a coarse run
      // of its estimate) adapts the same way from its own coarser mesh: at
      // about the same times (every n-th step scaled with its k and rounded,
      // at least every step and before its last; the same times where the
      // factor divides n and N), towards as many times fewer unknowns as its
      // cells have more volume. A variant without adaptation runs on the
      // uniform mesh, and so does one of a single step (the mesh adapts
      // after a step but the last).
      const MeshAdaptationParameters &adaptation =
        MeshAdaptationParameters::of(scene);
      entries[Entry::adaptation_cycles] = "0";
      const long interval =
        std::min(std::max(1L,
                          std::lround(double(adaptation.interval) *
                                      variant.n_steps / scene.time.n_steps())),
                 long(variant.n_steps) - 1);
      if (adaptation.interval == 0 || !variant.adapts_during_run ||
          interval < 1)
        {
          entries[Entry::adaptation_interval] = "0";
          entries[Entry::target_unknowns]     = "0";
        }
      else
        {
          entries[Entry::adaptation_interval] = std::to_string(interval);
          if (adaptation.target_unknowns > 0)
            entries[Entry::target_unknowns] = std::to_string(
              std::max(1L,
                       std::lround(std::ldexp(
                         double(adaptation.target_unknowns),
                         int(scene.dimension) * variant.h_halvings))));
        }
      // The run that a target chose runs with its error estimate.
      entries[Entry::estimate_error] = bool_text(
        !quiet && (accuracy.estimate_error || accuracy.target_error > 0));
      entries[Entry::separate_space_and_time] =
        bool_text(!quiet && accuracy.separate_space_and_time);
      // No variant chooses again: the run that a target chose writes the
      // parameters.prm that reproduces it, with its error estimate.
      entries[Entry::target_error]       = "0";
      entries[Entry::max_predicted_time] = "0";
      if (quiet)
        {
          entries[Entry::vtu_interval]   = "0";
          entries[Entry::gamma3_history] = "false";
        }
      entries[Entry::checkpoint_interval] =
        quiet ? "0" : std::to_string(output.checkpoint_interval);
      entries[Entry::checkpoint_minutes] =
        quiet ? "0" : exact_text(output.checkpoint_minutes);
      // The geometry knows which of its entries sets h.
      for (const auto &[path, value] :
           create_geometry(scene)->entries_with_h_halved(variant.h_halvings))
        entries[path] = value;
      return entries;
    }
  } // namespace


  // The scene's entries as it used them, with the variant's set, parsed and
  // checked as a scene is (a variant may be refused where the scene was
  // not, e.g. for its number of steps or refinements). The handler is this
  // function's own: no variant sees what another one set.
  Parameters parameters_of(const Parameters &scene, const SceneVariant &variant)
  {
    std::map<std::string, std::string> entries =
      read_printed_entries(scene.used_parameters);
    for (const auto &[path, value] : variant_entries(scene, variant))
      entries[path] = value;
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    for (const auto &[path, value] : entries)
      try
        {
          set_entry(prm, path, value);
        }
      catch (const ExceptionBase &exc)
        {
          std::ostringstream reason;
          exc.print_info(reason);
          AssertThrow(false,
                      ExcMessage("Entry '" + path + "' = " + value +
                                 " of the run in '" + variant.directory +
                                 "': " + Utilities::trim(reason.str())));
        }
    Parameters parameters;
    parameters.parse_parameters(prm);
    parameters.keeps_pilots =
      !variant.quiet && AccuracyParameters::of(scene).target_error > 0;
    return parameters;
  }
} // namespace Contact
