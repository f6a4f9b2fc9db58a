/* The self-checks of a run (doc/verification.md): what they compare, the
   values they keep and the class that makes them, a postprocessor
   (self_checks.cc makes the checks, self_check_summary.cc reports them). */

#ifndef contact_self_checks_h
#define contact_self_checks_h

#include <core/postprocessor.h>
#include <parts/self_checks/gamma3_map.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace Contact
{
  /**
   * The self-checks of a run, each a relative violation that round-off
   * keeps far below SelfChecks::tolerance. What each compares, relative to
   * what, and what it catches is the table of doc/verification.md; each is
   * computed by the member of SelfChecks (self_checks.cc) named here:
   *   - matrices: M, A and B against the integrals of their forms, once
   *     before the first step (check_matrices()).
   *   - algebraic_energy: the step's part of the energy identity (5.7);
   *     load_power: the load vector against the loads' integral
   *     (check_energy_and_loads()).
   *   - constraints: how far w_n is from V_h (check_constraints()).
   *   - equation_residual: (5.2) at t_n from the stored fields
   *     (equation_residual()).
   *   - friction_law: the friction law (5.3)-(5.4) at the stored
   *     velocities; it fails where it exceeds the tolerance and twice what
   *     the convexification's own tolerance allows (friction_law_allowance,
   *     FrictionSolver::law_residual_allowance). stick_motion: the speed of
   *     the nodes the solver says stick; negative_friction_power: the
   *     friction power on the slipping nodes (check_friction_law()).
   *   - moment_balance: the balance of moments about the z-axis, where it
   *     can be stated (update_moments(), MomentBalance).
   */
  struct SelfCheckValues
  {
    double matrices                = 0;
    double algebraic_energy        = 0;
    double load_power              = 0;
    double constraints             = 0;
    double equation_residual       = 0;
    double friction_law            = 0;
    double friction_law_allowance  = 0;
    double friction_law_excess     = 0;
    double stick_motion            = 0;
    double negative_friction_power = 0;
    double moment_balance          = 0;

    void take_largest(const SelfCheckValues &other)
    {
      matrices          = std::max(matrices, other.matrices);
      algebraic_energy  = std::max(algebraic_energy, other.algebraic_energy);
      load_power        = std::max(load_power, other.load_power);
      constraints       = std::max(constraints, other.constraints);
      equation_residual = std::max(equation_residual, other.equation_residual);
      friction_law      = std::max(friction_law, other.friction_law);
      stick_motion      = std::max(stick_motion, other.stick_motion);
      friction_law_allowance =
        std::max(friction_law_allowance, other.friction_law_allowance);
      friction_law_excess =
        std::max(friction_law_excess, other.friction_law_excess);
      negative_friction_power =
        std::max(negative_friction_power, other.negative_friction_power);
      moment_balance = std::max(moment_balance, other.moment_balance);
    }

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &matrices &algebraic_energy &load_power &constraints
        &equation_residual &friction_law &friction_law_allowance
          &friction_law_excess &stick_motion &negative_friction_power
            &moment_balance;
    }
  };


  /** The integrals of the forms of the matrices on two fields in V_h, by
   *  which the check of the matrices compares them (self_checks.cc). */
  struct FieldIntegrals
  {
    double kinetic       = 0; // 1/2 int rho |w|^2
    double elastic       = 0; // 1/2 int B eps(u) : eps(u)
    double viscous_power = 0; // int A eps(w) : eps(w)
    double elastic_power = 0; // int B eps(w) : eps(w)
  };


  /**
   * The moments about the z-axis through the origin (the axis normal to
   * the plane in 2D) at t_n: the angular momentum L_n = int rho (x x w_n)_z
   * (with the mass matrix's quadrature), the moment of the loads F_n, that
   * of the friction forces -C^T eta_n on the body, and what is left of
   * (L_n - L_{n-1}) / k: the moment of the reactions of the constraints
   * (clamp, normal reactions of Gamma_3 and of symmetry planes). (5.2)
   * tested with the rotation r = e_z x x gives
   *   (L_n - L_{n-1}) / k = applied + friction + reaction
   * where r lies in V_h, with reaction = 0: no clamp, and every normal
   * constraint normal to r, as on a Gamma_3 that is a circle or a cylinder
   * around the z-axis; and the mapping's degree at most the element's, so
   * that r is its own interpolant.
   */
  struct MomentBalance
  {
    double angular_momentum = 0;
    double applied          = 0;
    double friction         = 0;
    double reaction         = 0;
  };


  template <int dim>
  class SelfChecks : public Postprocessor<dim>
  {
  public:
    /** Above it a self-check has failed, and the run ends with an error
     *  (the summary prints which). */
    static constexpr double tolerance = 1e-8;
    /** Below it a check's value is printed as "below 1e-10". */
    static constexpr double round_off_bound = 1e-10;
    /** The most of a violation of the friction law that a loose
     *  'Solver/Convexification tolerance' excuses, relative to
     *  max_p g_p(0): beyond it the check fails whatever the tolerance. */
    static constexpr double largest_friction_law_allowance = 1e-3;

    // The map of Gamma_3 and the rotation of the mesh at the start, and
    // after a change of the mesh also the new matrices checked; the next
    // step's energy identity starts from the energies after the transfer.
    void mesh_event(const MeshEvent event) override
    {
      if (event == MeshEvent::before_change)
        return;
      if (event == MeshEvent::after_change)
        {
          residual_work = VectorType();
          friction_work = VectorType();
        }
      setup_gamma3_map();
      setup_moment_balance();
      if (event == MeshEvent::after_change)
        start_self_checks();
    }

    // A resumed run has the checks' largest values from the checkpoint;
    // the matrices are checked by every run.
    void start(const bool resumed) override
    {
      if (!resumed)
        largest_checks = SelfCheckValues();
      start_self_checks();
      warn_of_loose_tolerance();
    }

    // Each solve of a step: both halves of a cut step are checked.
    void after_step(const StepStatistics &, const StepEnd end) override
    {
      if (end == StepEnd::solve)
        check_step();
    }

    void add_columns(TimeSeriesRow &row) const override;

    void checkpoint(CheckpointArchive &archive) override;

    /** The summary's lines of the checks. */
    void finish(RunSummary &) override;

    void require_success() const override;

  private:
    FieldIntegrals              field_integrals(const FastVector &u,
                                                const FastVector &w) const;
    void                        setup_gamma3_map();
    void                        setup_moment_balance();
    void                        start_self_checks();
    double                      check_matrices() const;
    void                        warn_of_loose_tolerance() const;
    void                        check_step();
    void                        check_energy_and_loads(const FastVector                  &w,
                                                       const std::vector<Tensor<1, dim>> &forces);
    double                      check_constraints(const FastVector &w) const;
    std::vector<Tensor<1, dim>> friction_forces_on_map() const;
    double equation_residual(const std::vector<Tensor<1, dim>> &forces) const;
    void   check_friction_law(const FastVector                  &w,
                              const std::vector<Tensor<1, dim>> &forces);
    double update_moments(const LoadPower                   &applied,
                          const std::vector<Tensor<1, dim>> &forces);
    void   print_why_moments_are_not_checked() const;

    // The energy balance after the last step checked and the sum of the
    // magnitudes of that step's terms in it, and the checks' values of that
    // step and their largest over the steps.
    EnergyBalance   last_energy;
    double          step_energy_scale = 0;
    SelfCheckValues step_checks;
    SelfCheckValues largest_checks;
    // Gamma_3 as the checks see it, and for each node of the friction
    // solver's list the node of the map at its place.
    std::unique_ptr<Gamma3Map<dim>> gamma3_map;
    std::vector<unsigned int>       map_node_of_solver_node;
    // The vectors of equation_residual().
    mutable VectorType residual_work, friction_work;
    // The rotation r = e_z x x (interpolated), its values at the nodes of
    // the map of Gamma_3, whether the balance of moments is a self-check,
    // and the moments of the last step.
    FastVector                  rotation;
    std::vector<Tensor<1, dim>> rotation_at_nodes;
    bool                        moment_balance_is_checked = false;
    MomentBalance               moments;
    // |density of the angular momentum| and |w| of the last step checked.
    double momentum_density_norm = 0, last_velocity_norm = 0;
  };
} // namespace Contact

#endif
