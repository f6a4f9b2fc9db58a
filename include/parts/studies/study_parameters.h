/**
 * The entries of the studies: the subsections Convergence study and
 * Accuracy of the .prm file (study_parameters.cc), and the registration of
 * the mesh adaptation's (parts/adaptation/mesh_adaptation_parameters.h)
 * after them. Each subsection is a part (base/parts.h) that
 * declares, parses and checks its own entries, printed where they always
 * were (after Verification, in this order); its value is read with of().
 * They are parts of a kind of their own, StudySubsections: their entries
 * alone are registered, nothing is created of them, and compose_study()
 * (app/) chooses the studies from their values.
 */
#ifndef contact_study_parameters_h
#define contact_study_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <base/choice_table.h>
#include <core/parameters.h>
#include <base/parts.h>
#include <core/quantity.h>
#include <parts/adaptation/mesh_adaptation_parameters.h>

#include <array>
#include <string>

namespace Contact
{
  using namespace dealii;

  /**
   * The entries of the studies that code outside study_parameters.cc
   * names, as "Subsection/Entry": in error
   * messages and in the scene variants of the drivers. unit/entry_paths
   * checks that every one of them is declared.
   */
  namespace Entry
  {
    inline const std::string levels = "Convergence study/Levels";
    inline const std::string reference_degree =
      "Convergence study/Reference degree";
    inline const std::string estimate_error = "Accuracy/Estimate error";
    inline const std::string separate_space_and_time =
      "Accuracy/Separate space and time";
    inline const std::string target_error      = "Accuracy/Target error";
    inline const std::string target_error_type = "Accuracy/Target error type";
    inline const std::string target_quantity   = "Accuracy/Target quantity";
    inline const std::string cost_model        = "Accuracy/Cost model";
    inline const std::string max_predicted_time =
      "Accuracy/Maximum predicted time";
  } // namespace Entry

  /** The kind of the studies' subsections (base/parts.h): a part of it is
   *  its entries; create() is never called. */
  struct StudySubsection
  {};
  using StudySubsections = PartRegistry<StudySubsection>;


  /** The subsection Convergence study (parts/studies/convergence_study.h). */
  struct ConvergenceStudyParameters
  {
    enum class Refine
    {
      space_and_time,
      space,
      time
    };
    /** 0: one run; n: n + 1 runs, each halving h and/or k. */
    unsigned int levels;
    Refine       refine;
    /** Element degree of the reference run; 0: that of the levels. */
    unsigned int reference_degree;

    /** The names of the choices of 'Refine'. */
    static const ChoiceTable<Refine> &refinements();

    /** The values of the scene's entries. */
    static const ConvergenceStudyParameters &of(const Parameters &parameters);

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
    /** The checks against the entries of other subsections. */
    void check(const Parameters &parameters) const;
  };


  /** The subsection Accuracy: the error estimate
   *  (parts/studies/error_estimate.h) and the target error
   *  (parts/studies/target_error.h). */
  struct AccuracyParameters
  {
    /** Also run the scene with h and k doubled and quadrupled, and report
     *  the estimated error of this run (error_estimate.cc). */
    bool estimate_error;
    /** Also run with 2h, k and with h, 2k, and split each estimate into
     *  the part that halving h removes and the part that halving k does. */
    bool separate_space_and_time;
    /** 0: off; else the error that the program picks h, k and the element
     *  degree for (target_error.cc). */
    double target_error;
    /** Relative to the size of the quantity, or absolute. */
    enum class TargetErrorType
    {
      relative,
      absolute
    };
    TargetErrorType target_error_type;
    /** A quantity of the estimate's table. */
    Quantity target_quantity;
    /** Predict the cost of a run from the pilots' measured wall times, or
     *  (reproducibly, for tests) from unknowns times steps. */
    enum class CostModel
    {
      measured,
      unknowns_times_steps
    };
    CostModel cost_model;
    /** The longest predicted wall time [s] of the run a target chooses (0:
     *  no limit); beyond it the program stops and says what it would have
     *  chosen. */
    double max_predicted_time;

    /** The names of the choices of 'Target error type' and 'Cost
     *  model'. */
    static const ChoiceTable<TargetErrorType> &target_error_types();
    static const ChoiceTable<CostModel>       &cost_models();

    /** The values of the scene's entries. */
    static const AccuracyParameters &of(const Parameters &parameters);

    static void declare_parameters(ParameterHandler &prm);
    void        parse_parameters(ParameterHandler &prm);
    /** The checks against the entries of other subsections. */
    void check(const Parameters &parameters) const;

  private:
    void check_target_quantity(const Parameters &parameters) const;
  };
} // namespace Contact

#endif
