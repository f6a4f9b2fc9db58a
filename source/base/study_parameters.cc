/* The entries of the studies (.prm subsections Convergence study, Mesh
   adaptation and Accuracy): declaration, parsing and the checks of each
   subsection alone; those against the other entries are
   Parameters::parse_parameters()'s (parameters.cc). */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <base/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

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


  // @sect3{Mesh adaptation}

  const std::array<std::string, 3> &MeshAdaptationParameters::indicator_names()
  {
    static const std::array<std::string, 3> names = {
      {"displacement", "velocity", "slip rate"}};
    return names;
  }

  void MeshAdaptationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh adaptation");
    {
      prm.declare_entry(
        "Cycles",
        "0",
        Patterns::Integer(0, 20),
        "0: the mesh of the Geometry. n > 0: n pilot runs of the whole scene "
        "(each in its own directory adaptation-cycle-c), each on the mesh its "
        "predecessor refined and coarsened from the 'Indicators', taken at "
        "at most 20 steps spread over the run and kept as their largest; "
        "then the scene runs on the adapted mesh. The pilots write "
        "indicators_0.pvtu; adapted_mesh.txt holds the mesh's cycles (every "
        "checkpoint stores them too: --resume runs on them without the "
        "pilots).");
      prm.declare_entry(
        "Interval",
        "0",
        Patterns::Integer(0),
        "0: the mesh does not change during the run. n > 0: after every n-th "
        "step the mesh is refined and coarsened from the 'Indicators' of that "
        "step, u and w are carried over to the new mesh, K is assembled and "
        "factorised again, and the change of the kinetic and elastic energy "
        "that the transfer makes enters the energy balance. adaptation.csv "
        "lists the adaptations (with the energy before and after each), "
        "adapted_mesh.txt the mesh's cycles, and with 'Output/VTU interval' "
        "> 0 indicators_<step>.pvtu the indicators and the cells chosen; a "
        "checkpoint stores the mesh.");
      prm.declare_entry("Refine fraction",
                        "0.3",
                        Patterns::Double(0, 1),
                        "The share of the cells, those with the largest "
                        "indicators, refined per cycle (or per adaptation "
                        "during the run).");
      prm.declare_entry("Coarsen fraction",
                        "0",
                        Patterns::Double(0, 1),
                        "The share of the cells, those with the smallest "
                        "indicators, coarsened per cycle (never coarser than "
                        "the Geometry's coarsest cells).");
      prm.declare_entry(
        "Target unknowns",
        "0",
        Patterns::Integer(0),
        "0: refine by 'Refine fraction'. n > 0: refine as many cells per "
        "cycle as multiply the unknowns by equal factors to about n at the "
        "last cycle. During the run ('Interval' > 0, which then needs "
        "'Coarsen fraction' > 0): refine by 'Refine fraction' up to about n "
        "unknowns, and from there only as many cells as the coarsening frees, "
        "so that the mesh keeps about n unknowns and still follows the "
        "solution. Without a target, each adaptation during the run refines "
        "'Refine fraction' of the cells, up to 'Max levels'.");
      prm.declare_entry(
        "Indicators",
        "displacement",
        Patterns::MultipleSelection("displacement|velocity|slip rate"),
        "What chooses the cells: Kelly's indicator of the displacement, of "
        "the velocity, and the variation of the slip rate over the faces of "
        "Gamma_3 (each as a share of its worst cell; a cell's indicator is "
        "the largest of its shares). The default gave the smallest V-error "
        "at T per unknown on the paper's scene (bench/adapted_mesh.md).");
      prm.declare_entry("Max levels",
                        "4",
                        Patterns::Integer(0, 12),
                        "Cells are refined at most this many times beyond "
                        "the Geometry's coarsest cells.");
    }
    prm.leave_subsection();
  }

  void MeshAdaptationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh adaptation");
    {
      cycles           = prm.get_integer("Cycles");
      interval         = prm.get_integer("Interval");
      refine_fraction  = prm.get_double("Refine fraction");
      coarsen_fraction = prm.get_double("Coarsen fraction");
      target_unknowns  = prm.get_integer("Target unknowns");
      max_levels       = prm.get_integer("Max levels");
      const std::vector<std::string> chosen =
        Utilities::split_string_list(prm.get("Indicators"));
      for (unsigned int i = 0; i < indicators.size(); ++i)
        indicators[i] =
          std::find(chosen.begin(), chosen.end(), indicator_names()[i]) !=
          chosen.end();
    }
    prm.leave_subsection();
    AssertThrow((cycles == 0 && interval == 0) || indicators[0] ||
                  indicators[1] || indicators[2],
                ExcMessage("Entry '" + Entry::indicators +
                           "' is empty: allowed is one or more of "
                           "displacement, velocity, slip rate."));
    AssertThrow(refine_fraction + coarsen_fraction <= 1,
                ExcMessage("Entries '" + Entry::refine_fraction +
                           "' = " + number_text(refine_fraction) + " and '" +
                           Entry::coarsen_fraction +
                           "' = " + number_text(coarsen_fraction) +
                           ": allowed is a sum of at most 1."));
  }


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
      target_quantity    = Quantity::parse(prm.get("Target quantity"));
      cost_model         = cost_models().parse(prm.get("Cost model"));
      max_predicted_time = prm.get_double("Maximum predicted time");
    }
    prm.leave_subsection();
  }
} // namespace Contact
