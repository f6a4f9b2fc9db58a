/* The entries of the studies (.prm subsections Convergence study and
   Accuracy; include/parts/studies/study_parameters.h), and the
   registration of those of the mesh adaptation among them: each subsection
   a part that declares, parses and checks its entries, those against the
   other subsections once all are parsed. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <core/geometry_base.h>
#include <parts/studies/study_parameters.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace Contact
{
  // @sect3{Convergence study}

  const ChoiceTable<ConvergenceStudyParameters::Refine> &
  ConvergenceStudyParameters::refinements()
  {
    static const ChoiceTable<Refine> table("Convergence study/Refine",
                                           {{"space and time",
                                             Refine::space_and_time},
                                            {"space", Refine::space},
                                            {"time", Refine::time}});
    return table;
  }

  void ConvergenceStudyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence study");
    {
      prm.declare_entry(
        "Levels",
        "0",
        Patterns::Integer(0, 12),
        "0: one run. n > 0: n + 1 runs, starting from Geometry/Cell size and "
        "Time/Time step and halving what 'Refine' says from one run to the "
        "next (a mesh read from a Mesh file gets one more global refinement "
        "per level instead, and h is its largest cell diameter); a table of "
        "the errors (against a manufactured solution, or else against the "
        "finest level) and their rates is printed at the end.");
      prm.declare_entry("Refine",
                        refinements().name(Refine::space_and_time),
                        refinements().pattern(),
                        "What is halved from one level to the next.");
      prm.declare_entry(
        "Reference degree",
        "0",
        Patterns::Integer(0, 4),
        "Without a manufactured solution the finest level is the reference; "
        "this is its element degree (0: the degree of the levels). A richer "
        "reference lets studies with different degrees share one reference "
        "(work-precision).");
    }
    prm.leave_subsection();
  }

  void ConvergenceStudyParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence study");
    {
      levels           = prm.get_integer("Levels");
      reference_degree = prm.get_integer("Reference degree");
      refine           = refinements().parse(prm.get("Refine"));
    }
    prm.leave_subsection();
  }


  // A convergence study runs its levels from their start, each in its own
  // directory: there is no one run to resume.
  void ConvergenceStudyParameters::check(const Parameters &parameters) const
  {
    AssertThrow(!(parameters.output.resume && levels > 0),
                ExcMessage("Entry '" + Entry::resume +
                           "' (--resume): a convergence study ('" +
                           Entry::levels +
                           "' > 0) cannot be resumed; allowed is Resume = "
                           "false there."));
  }


  // @sect3{Mesh adaptation}

  // The subsection is the adaptation's
  // (parts/adaptation/mesh_adaptation_parameters.h); the studies register
  // it among theirs, and check it against their entries here.

  namespace
  {
    // Where the mesh adapts (`adapting` names the entry that makes it do
    // so): what the other entries, the drivers' among them, must allow. A
    // mesh adaptation refines the cells of p4est's forest by their ids, and
    // runs the scene as it is several times: not as a level of a study
    // (yet), nor as a target's pilot (those adapt during the run). An error
    // estimate runs a mesh adapted by pilots coarsened, and a run adapted
    // during itself again from coarser meshes (scene_variant.cc).
    void check_adaptation_combinations(const Parameters &parameters)
    {
      const std::string adapting =
        MeshAdaptationParameters::of(parameters).what_adapts();
      if (adapting.empty())
        return;
      const MeshAdaptationParameters &adaptation =
        MeshAdaptationParameters::of(parameters);
      const AccuracyParameters &accuracy = AccuracyParameters::of(parameters);
      // An error estimate runs a mesh adapted by pilots coarsened, cell by
      // cell (MeshPlan::coarser()), which gives nested meshes for plans that
      // refine only.
      AssertThrow(!accuracy.estimate_error || adaptation.cycles == 0 ||
                    adaptation.coarsen_fraction == 0,
                  ExcMessage(
                    adapting + "with '" + Entry::estimate_error +
                    "' its coarse runs are the adapted mesh coarsened, "
                    "which is only defined for meshes that the pilots "
                    "refined; allowed with it is '" +
                    Entry::coarsen_fraction + "' = 0."));
      // During the run, a mesh that keeps its size at the target must give
      // cells back to refine others.
      AssertThrow(adaptation.interval == 0 || adaptation.target_unknowns == 0 ||
                    adaptation.coarsen_fraction > 0,
                  ExcMessage(
                    adapting + "with '" + Entry::target_unknowns +
                    "' = " + std::to_string(adaptation.target_unknowns) +
                    " the mesh keeps about that size once it has "
                    "reached it, and can then follow the solution only "
                    "by coarsening where it refines; allowed with it is "
                    "'" +
                    Entry::coarsen_fraction + "' > 0."));
      AssertThrow(ConvergenceStudyParameters::of(parameters).levels == 0,
                  ExcMessage(adapting + "it cannot be combined with '" +
                             Entry::levels + "' yet; allowed are '" +
                             Entry::adaptation_cycles + "' = 0 and '" +
                             Entry::adaptation_interval + "' = 0 there."));
      // A target's 'Target unknowns' is the size of the scene's degree's
      // adapted mesh, scaled for the other of the degrees 1 and 2 that it
      // compares.
      check_entry(accuracy.target_error == 0 ||
                    adaptation.target_unknowns == 0 ||
                    parameters.geometry.fe_degree <= 2,
                  Entry::finite_element_degree,
                  parameters.geometry.fe_degree,
                  "1 or 2 with '" + Entry::target_error + "' > 0 and '" +
                    Entry::target_unknowns +
                    "' > 0 (the target compares degrees 1 and 2, and scales "
                    "'" +
                    Entry::target_unknowns +
                    "' from the scene's degree to the other)");
      // A target compares uniform meshes with meshes adapted during the run
      // (target_error.cc); the pilots' adaptation would need its own cycles
      // at each candidate h.
      AssertThrow(accuracy.target_error == 0 || adaptation.cycles == 0,
                  ExcMessage(adapting + "it cannot be combined with '" +
                             Entry::target_error +
                             "' yet, which chooses between uniform meshes and "
                             "meshes adapted during the run; allowed are '" +
                             Entry::adaptation_cycles + "' = 0 (with '" +
                             Entry::adaptation_interval +
                             "' > 0 for the adapted ones) or '" +
                             Entry::target_error + "' = 0."));
    }
  } // namespace



  // @sect3{Accuracy}

  const ChoiceTable<AccuracyParameters::TargetErrorType> &
  AccuracyParameters::target_error_types()
  {
    static const ChoiceTable<TargetErrorType> table(
      Entry::target_error_type,
      {{"relative", TargetErrorType::relative},
       {"absolute", TargetErrorType::absolute}});
    return table;
  }

  const ChoiceTable<AccuracyParameters::CostModel> &
  AccuracyParameters::cost_models()
  {
    static const ChoiceTable<CostModel> table(
      Entry::cost_model,
      {{"measured", CostModel::measured},
       {"unknowns times steps", CostModel::unknowns_times_steps}});
    return table;
  }

  namespace
  {
    // The entries of the error estimate, in the subsection Accuracy.
    void declare_error_estimate_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Estimate error",
        "false",
        Patterns::Bool(),
        "Also run the scene with h and k doubled, quadrupled and (where "
        "the mesh allows) multiplied by 8 (into <Output directory>/coarse-1, "
        "coarse-2 and coarse-3; in 2D they cost about 1/8, 1/64 and 1/512 "
        "of the run) and report the estimated error of this run at T: in "
        "the V-norm, in the probe displacements, the friction dissipation, "
        "the slipping share of Gamma_3, where its slip zone starts and the "
        "time of the first slip, each by Richardson extrapolation with the "
        "orders measured between consecutive runs. A row without "
        "consistent orders gets no estimate and says why. The table goes to "
        "the console and to <Output directory>/error_estimate.txt. On a mesh "
        "adapted by pilots the coarse runs are that mesh coarsened cell by "
        "cell; a run adapted during itself runs again from the coarser "
        "meshes of the Geometry, adapting at about the same times (the "
        "interval scaled with k and rounded) towards 1/2^dim (1/4^dim, ...) "
        "of its 'Target unknowns', and is compared at T only.");
      prm.declare_entry(
        "Separate space and time",
        "false",
        Patterns::Bool(),
        "With 'Estimate error': also run with 2h and 4h at k and with 2k "
        "and 4k at h (coarse-space-1, -2, coarse-time-1, -2; in 2D about "
        "1/4, 1/16, 1/2 and 1/4 of the run) and split every estimate into "
        "the part that halving h removes and the part that halving k does, "
        "each extrapolated with its own order; a row's estimate is their "
        "sum where that is larger. Needed where the orders in h and k "
        "differ (degree 2).");
    }

    // The entries of the target error and of the choice of h and k that
    // meets it, in the subsection Accuracy.
    void declare_target_error_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Target error",
        "0",
        Patterns::Double(0),
        "0: off. Otherwise the error in 'Target quantity' (by default the "
        "largest V-error over time) that the program picks the element "
        "degree (1 or 2), h and k for: pilot runs "
        "on the scene's h and k and on 2h, 4h, 2k, 4k (<Output "
        "directory>/pilot-*) measure how the error falls with h and with k "
        "and what a run costs; the cheapest run predicted within half the "
        "target then runs, with its error estimate (as 'Estimate error'). "
        "A scene that adapts its mesh during the run ('Mesh "
        "adaptation/Interval' > 0) adds pilots adapted during the run from "
        "H, 2H, 4H, and chooses between uniform and adapted meshes (for "
        "every 'Target quantity' but the largest V-error over time). "
        "The choice and the predicted and estimated errors are printed and "
        "written to <Output directory>/target.txt.");
      prm.declare_entry("Target error type",
                        AccuracyParameters::target_error_types().name(
                          AccuracyParameters::TargetErrorType::relative),
                        AccuracyParameters::target_error_types().pattern(),
                        "relative: 'Target error' times the size of the "
                        "quantity on the first pilot (for the V-norm "
                        "||eps(u_h)||, at T or its largest over time); "
                        "absolute: in the quantity's units.");
      prm.declare_entry(
        "Target quantity",
        worst_V_error,
        Patterns::Anything(),
        "The quantity whose error 'Target error' bounds: '" + worst_V_error +
          "' (the largest V-error ||eps(u - u_h)|| over the times t = 4Kj), "
          "or at T: 'V-norm of u', 'friction dissipation', 'probe <i> u_x' "
          "(u_y, u_z) of the i-th 'Output/Probe points' entry, 'slipping "
          "share of Gamma_3' or 'slip zone starts at x'; or the 'time of the "
          "first slip'.");
      prm.declare_entry("Cost model",
                        AccuracyParameters::cost_models().name(
                          AccuracyParameters::CostModel::measured),
                        AccuracyParameters::cost_models().pattern(),
                        "How the target predicts what a run costs: from "
                        "the pilots' measured wall times (a + b unknowns "
                        "steps, per degree), or unknowns times steps "
                        "(the same choice on every machine).");
      prm.declare_entry("Maximum predicted time",
                        "0",
                        Patterns::Double(0),
                        "0: no limit. Otherwise the longest predicted wall "
                        "time [s] of the run that 'Target error' chooses "
                        "(with its estimate's coarse runs, from the "
                        "pilots' measured wall times: needs 'Cost model' = "
                        "measured). Beyond it the program stops before "
                        "that run and says what it would have chosen.");
    }
  } // namespace

  void AccuracyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Accuracy");
    {
      declare_error_estimate_entries(prm);
      declare_target_error_entries(prm);
    }
    prm.leave_subsection();
  }

  void AccuracyParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Accuracy");
    {
      estimate_error          = prm.get_bool("Estimate error");
      separate_space_and_time = prm.get_bool("Separate space and time");
      target_error            = prm.get_double("Target error");
      target_error_type =
        target_error_types().parse(prm.get("Target error type"));
      target_quantity =
        Quantity::parse(prm.get("Target quantity"), Entry::target_quantity);
      cost_model         = cost_models().parse(prm.get("Cost model"));
      max_predicted_time = prm.get_double("Maximum predicted time");
    }
    prm.leave_subsection();
  }


  namespace
  {
    // A target's pilots run with 2k and 4k on the time grid of k. The
    // nearest valid steps: T / N for the multiples N of 4 around the N =
    // ceil(T / k) that the entry gives.
    void check_target_time_grid(const TimeParameters &time)
    {
      const unsigned int n     = time.n_steps();
      const unsigned int below = std::max(4u, n / 4 * 4);
      check_entry(
        n % 4 == 0,
        Entry::time_step,
        time.time_step,
        "a step that divides '" + Entry::end_time +
          "' into a multiple of 4 steps with '" + Entry::target_error +
          "' > 0 (the pilots run with 2k and 4k on the same "
          "time grid); this one gives " +
          std::to_string(n) + " steps, the nearest valid ones are T/" +
          std::to_string(below) + " = " + number_text(time.end_time / below) +
          " and T/" + std::to_string(below + 4) + " = " +
          number_text(time.end_time / (below + 4)));
    }
  } // namespace


  // An error estimate runs the scene twice more, with h and k doubled and
  // quadrupled, and a target's pilots do so in h and in k separately: the
  // coarse meshes must exist, and the runs are separate (not a study, not
  // a resumed run).
  void AccuracyParameters::check(const Parameters &parameters) const
  {
    const bool target = target_error > 0;
    AssertThrow(estimate_error || target || !separate_space_and_time,
                ExcMessage("Entry '" + Entry::separate_space_and_time +
                           "' = true splits an error estimate: allowed with "
                           "it is '" +
                           Entry::estimate_error + "' = true or '" +
                           Entry::target_error + "' > 0."));
    AssertThrow(max_predicted_time == 0 ||
                  (target && cost_model == CostModel::measured),
                ExcMessage("Entry '" + Entry::max_predicted_time +
                           "' = " + number_text(max_predicted_time) +
                           " limits the run that a target chooses by its "
                           "predicted wall time: allowed with it are '" +
                           Entry::target_error + "' > 0 and '" +
                           Entry::cost_model +
                           "' = " + cost_models().name(CostModel::measured) +
                           " (or 0 for no limit)."));
    if (target)
      {
        check_target_quantity(parameters);
        check_target_time_grid(parameters.time);
      }
    if (!estimate_error && !target)
      return;
    const std::string mode = target ? "'" + Entry::target_error + "' > 0" :
                                      "'" + Entry::estimate_error + "' = true";
    AssertThrow(ConvergenceStudyParameters::of(parameters).levels == 0 &&
                  !parameters.output.resume,
                ExcMessage("Entry " + mode +
                           " runs one scene with its error estimate; "
                           "allowed with it are '" +
                           Entry::levels + "' = 0 and no --resume ('" +
                           Entry::resume + "' = false)" +
                           (target ? std::string(".") :
                                     "; a run killed before its estimate "
                                     "resumes with '" +
                                       Entry::estimate_error +
                                       "' = false, and continues without "
                                       "it.")));
    // The geometry knows how its h is set, and so which meshes of 2h and
    // 4h exist.
    create_geometry(parameters)->check_coarse_runs(mode);
  }

  // A probe's quantity needs the probe: the target must be one of this
  // scene's quantities.
  void
  AccuracyParameters::check_target_quantity(const Parameters &parameters) const
  {
    const std::string target = target_quantity.name();
    bool              found  = false;
    std::string       list;
    for (const Quantity &quantity :
         Quantity::of_scene(parameters.output.probe_points.size(),
                            parameters.dimension))
      {
        found = found || quantity.name() == target;
        list += (list.empty() ? "'" : ", '") + quantity.name() + "'";
      }
    AssertThrow(found,
                ExcMessage(
                  "Entry '" + Entry::target_quantity + "' = '" + target +
                  "' is not a quantity of this scene; allowed: " + list + "."));
    // Found out before the pilots run: a closed Gamma_3 has no start of
    // its slip zone, and its x has no scale of its own.
    if (target_quantity.kind != Quantity::Kind::slip_zone_start)
      return;
    AssertThrow(!create_geometry(parameters)->gamma3_is_closed(),
                ExcMessage("Entry '" + Entry::target_quantity + "' = '" +
                           target +
                           "' is not defined on a shell (its Gamma_3 is a "
                           "closed circle); allowed there are the others of " +
                           list + "."));
    AssertThrow(target_error_type == TargetErrorType::absolute,
                ExcMessage("Entry '" + Entry::target_error_type +
                           "': a relative target on '" + target +
                           "' would depend on where x = 0 is; allowed for "
                           "it is absolute (a length in m)."));
  }


  // @sect3{The parts}
  //
  // The subsections follow Verification in this order, and are parsed and
  // checked in it: the order of the errors of a .prm with several.

  namespace
  {
    const std::string convergence_study_part = "convergence study";
    const std::string accuracy_part          = "accuracy";

    // The entries of the subsection of `Subsection`, a part of the studies'
    // kind placed after the subsection `after`, checked by its own check()
    // and then by `check_with_studies`, if given.
    template <class Subsection>
    bool register_subsection(
      const std::string              &name,
      const std::string              &subsection,
      const std::string              &after,
      const std::vector<std::string> &free_on_resume,
      void (*check_with_studies)(const Parameters &) = nullptr)
    {
      return StudySubsections::add(
        {name,
         subsection,
         0,
         {"",
          after,
          subsection,
          &Subsection::declare_parameters,
          [](ParameterHandler &prm, const Parameters &) -> std::any {
            Subsection values;
            values.parse_parameters(prm);
            return values;
          },
          [check_with_studies](const Parameters &parameters) {
            Subsection::of(parameters).check(parameters);
            if (check_with_studies)
              check_with_studies(parameters);
          },
          free_on_resume},
         nullptr});
    }

    // A resumed run is never followed by its error estimate (the estimate
    // of a killed run is dropped): whether a run asks for one does not
    // define the discrete problem.
    const bool registered =
      register_subsection<ConvergenceStudyParameters>(convergence_study_part,
                                                      "Convergence study",
                                                      "Verification",
                                                      {}) &&
      register_subsection<AccuracyParameters>(
        accuracy_part,
        "Accuracy",
        "Convergence study",
        {Entry::estimate_error, Entry::separate_space_and_time}) &&
      register_subsection<MeshAdaptationParameters>(
        MeshAdaptationParameters::part_name,
        "Mesh adaptation",
        "Accuracy",
        {},
        &check_adaptation_combinations);
  } // namespace


  const ConvergenceStudyParameters &
  ConvergenceStudyParameters::of(const Parameters &parameters)
  {
    return parameters.part<ConvergenceStudyParameters>(convergence_study_part);
  }

  const AccuracyParameters &AccuracyParameters::of(const Parameters &parameters)
  {
    return parameters.part<AccuracyParameters>(accuracy_part);
  }
} // namespace Contact
