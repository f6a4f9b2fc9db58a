/* The checks every run makes of its own results (doc/verification.md):
   the energy identity of the scheme twice, from the matrices and by
   quadrature of the fields, the equations (5.2) from the stored fields,
   the friction law and the sticking nodes' rest at the stored velocities
   (both through the checks' own map of Gamma_3), the sign of the friction
   power, and the balance of moments about the z-axis where a rigid
   rotation is admissible. A run that fails one of them ends with an error
   instead of presenting its results as good. */

#include <deal.II/base/array_view.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/la_parallel_vector.h>

#include <deal.II/numerics/vector_tools.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <core/postprocessor.h>
#include <postprocess/gamma3_map.h>

#include <array>
#include <limits>
#include <iomanip>
#include <sstream>

namespace Contact
{
  /**
   * The self-checks of a run (doc/verification.md), each a
   * relative violation that round-off keeps far below
   * SelfChecks::tolerance:
   *   - algebraic_energy: the energy identity from the products of the
   *     step's matrices with w_n. It holds whenever each step solves its
   *     linear system with the eta it reports, whatever the matrices, the
   *     loads or the friction law: it checks the solve and the bookkeeping.
   *   - quadrature_energy: the same identity with every term integrated
   *     from the fields (1/2 int rho |w_h|^2, 1/2 int B eps(u_h):eps(u_h),
   *     ...) and the loads' expressions, not from the matrices and the
   *     load vector: it catches wrong matrices, loads or constraints.
   *   - equation_residual: (5.2) at t_n from the stored fields,
   *     K w_n - (F_n + M w_{n-1} / k - B u_{n-1}) + C^T eta_n, with the
   *     solver's nodal forces applied through the checks' own map of
   *     Gamma_3 (Gamma3Map), relative to the largest of the three terms of
   *     this step: it catches a velocity that is not the solution of the
   *     step's system with the reported forces (a stale factorisation, a
   *     wrong compliance of Gamma_3 on the constraints path, a force put on
   *     the wrong dofs).
   *   - friction_law: the friction law (5.3)-(5.4) at the stored
   *     velocities, with the checks' weights and normals (Gamma3Map) and
   *     the true law: on a node the solver says slips, the distance of the
   *     tangential part of its force from g_p(|v_p|) v_p / |v_p|; on one
   *     that sticks, how far the force exceeds g_p(0); relative to
   *     max_p g_p(0). It catches a wrong coefficient, sign, weight,
   *     tangent or compliance in the solver. It fails where it exceeds the
   *     tolerance and twice what the convexification's own tolerance
   *     allows (friction_law_allowance,
   *     FrictionSolver::law_residual_allowance).
   *   - stick_motion: the speed of the nodes the solver says stick, at
   *     the stored velocity, relative to the step's speed scale, the larger
   *     of max |w_n| and max |v_free| (FrictionSolver::free_slip_speed(),
   *     the size of the terms whose difference a sticking node's velocity
   *     is, so that a body held by friction alone with little inertia, K
   *     close to singular, does not fail by round-off): a sticking node
   *     that moves.
   *   - negative_friction_power: a step whose friction power on the
   *     slipping nodes (the same forces and velocities) is negative,
   *     relative to the energies (friction only dissipates).
   *   - moment_balance: the balance of moments about the z-axis, (5.2)
   *     tested with the rigid rotation r = e_z x x, relative to the
   *     largest sum so far of the magnitudes of the products it adds up
   *     (moment_scale, update_moments()). Checked only where r lies in
   *     V_h (MomentBalance): it catches wrong loads or velocities in the
   *     balance law of the angular momentum.
   */
  struct SelfCheckValues
  {
    double algebraic_energy        = 0;
    double quadrature_energy       = 0;
    double equation_residual       = 0;
    double friction_law            = 0;
    double friction_law_allowance  = 0;
    double friction_law_excess     = 0;
    double stick_motion            = 0;
    double negative_friction_power = 0;
    double moment_balance          = 0;
    double moment_scale            = 0;

    void take_largest(const SelfCheckValues &other)
    {
      algebraic_energy  = std::max(algebraic_energy, other.algebraic_energy);
      quadrature_energy = std::max(quadrature_energy, other.quadrature_energy);
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
      moment_scale   = std::max(moment_scale, other.moment_scale);
    }

    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &algebraic_energy &quadrature_energy &equation_residual
        &friction_law &friction_law_allowance &friction_law_excess &stick_motion
          &negative_friction_power &moment_balance &moment_scale;
    }
  };


  /** The integrals of the fields that the energy identity by quadrature
   *  adds up (self_checks.cc). */
  struct FieldIntegrals
  {
    double kinetic       = 0; // 1/2 int rho |w_n|^2
    double velocity_jump = 0; // 1/2 int rho |w_n - w_{n-1}|^2
    double elastic       = 0; // 1/2 int B eps(u_n) : eps(u_n)
    double viscous_power = 0; // int A eps(w_n) : eps(w_n)
    double elastic_power = 0; // int B eps(w_n) : eps(w_n)
  };


  /** * The moments about the z-axis through the origin (the axis normal to
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

    void initialize() override
    {
      setup_gamma3_map();
      setup_moment_balance();
    }

    // A resumed run has the state of the checks from the checkpoint.
    void start(const bool resumed) override
    {
      if (!resumed)
        start_self_checks();
    }

    void after_substep() override
    {
      check_step();
    }

    void add_columns(TimeSeriesRow &row) const override;

    void save(boost::archive::binary_oarchive &archive) override
    {
      archive &energy_by_quadrature &largest_checks;
    }

    void load(boost::archive::binary_iarchive &archive) override
    {
      archive &energy_by_quadrature &largest_checks;
    }

    void print_summary() const override;

    void require_success() const override;

  private:
    FieldIntegrals              field_integrals(const FastVector &u,
                                                const FastVector &w,
                                                const FastVector &old_w) const;
    void                        setup_gamma3_map();
    void                        setup_moment_balance();
    void                        start_self_checks();
    void                        check_step();
    std::vector<Tensor<1, dim>> friction_forces_on_map() const;
    double equation_residual(const std::vector<Tensor<1, dim>> &forces) const;
    void   check_friction_law(const std::vector<Tensor<1, dim>> &forces);
    double update_moments(const LoadPower &applied);
    void   print_why_moments_are_not_checked() const;

    // The energy identity's terms by quadrature, and the checks' values of
    // the last step and their largest over the steps.
    EnergyBalance   energy_by_quadrature;
    SelfCheckValues step_checks;
    SelfCheckValues largest_checks;
    // Gamma_3 as the checks see it, and for each node of the friction
    // solver's list the node of the map at its place.
    std::unique_ptr<Gamma3Map<dim>> gamma3_map;
    std::vector<unsigned int>       map_node_of_solver_node;
    // The rotation r = e_z x x (interpolated), its tangential components on
    // Gamma_3 (C r), how much the constraints change it relative to its
    // size, whether it lies in V_h (the moment balance is then a
    // self-check), and the moments of the last step.
    FastVector     rotation;
    Vector<double> rotation_on_gamma3;
    double         rotation_defect           = 0;
    bool           moment_balance_is_checked = false;
    MomentBalance  moments;
  };


  // @sect4{SelfChecks::field_integrals}

  // The integrals of the fields that the energy identity (5.7) is made of,
  // with the quadrature rules of the assembly (the mass rule for rho |w|^2,
  // which is the nodal one for a lumped mass: the discrete kinetic energy is
  // defined by it), but from the values and strains of u_h and w_h on the
  // cells, not from the matrices. A step of the factor-once scheme costs
  // little more than two substitutions, so this loop is written for speed:
  // each cell's dof values are read once, and the fields are summed from
  // the scalar shape functions (each shape function of the vector element
  // is a scalar one in one component) instead of through FEValues' vector
  // functions, which allocate at every call.
  template <int dim>
  FieldIntegrals SelfChecks<dim>::field_integrals(const FastVector &u,
                                                  const FastVector &w,
                                                  const FastVector &old_w) const
  {
    const DiscreteSpace<dim> &space    = this->space();
    const auto               &material = this->parameters().material;
    const double rho = material.density, lambda = material.lambda(dim),
                 two_G = material.two_G(), mu1 = material.viscosity_mu1,
                 mu2 = material.viscosity_mu2;
    // (B eps) : eps = lambda tr(eps)^2 + 2G eps : eps, the same with mu_1,
    // mu_2 for A.
    const auto form = [](const double                   trace_factor,
                         const double                   deviator_factor,
                         const SymmetricTensor<2, dim> &eps) {
      return trace_factor * trace(eps) * trace(eps) +
             deviator_factor * (eps * eps);
    };

    const bool lumped = this->parameters().geometry.mass_matrix ==
                        GeometryParameters::MassMatrix::lumped;
    FEValues<dim>      strain_values(*space.mapping,
                                space.fe,
                                space.quadrature,
                                update_gradients | update_JxW_values |
                                  (lumped ? update_default : update_values));
    FEValues<dim>      lumped_values(*space.mapping,
                                space.fe,
                                space.mass_quadrature,
                                update_values | update_JxW_values);
    FEValues<dim>     &mass_values = (lumped ? lumped_values : strain_values);
    const unsigned int n_dofs      = space.fe.n_dofs_per_cell();
    Vector<double>     u_cell(n_dofs), w_cell(n_dofs), old_w_cell(n_dofs);
    std::vector<unsigned int> component(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      component[i] = space.fe.system_to_component_index(i).first;

    std::array<double, 5> sums{};
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_values(u, u_cell);
          cell->get_dof_values(w, w_cell);
          cell->get_dof_values(old_w, old_w_cell);
          strain_values.reinit(cell);
          if (lumped)
            lumped_values.reinit(cell);
          for (const unsigned int q : mass_values.quadrature_point_indices())
            {
              Tensor<1, dim> w_q, old_w_q;
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const double phi = mass_values.shape_value(i, q);
                  w_q[component[i]] += w_cell[i] * phi;
                  old_w_q[component[i]] += old_w_cell[i] * phi;
                }
              sums[0] += 0.5 * rho * (w_q * w_q) * mass_values.JxW(q);
              sums[1] +=
                0.5 * rho * (w_q - old_w_q).norm_square() * mass_values.JxW(q);
            }
          for (const unsigned int q : strain_values.quadrature_point_indices())
            {
              Tensor<2, dim> grad_u, grad_w;
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const Tensor<1, dim> &grad = strain_values.shape_grad(i, q);
                  grad_u[component[i]] += u_cell[i] * grad;
                  grad_w[component[i]] += w_cell[i] * grad;
                }
              const SymmetricTensor<2, dim> eps_u = symmetrize(grad_u),
                                            eps_w = symmetrize(grad_w);
              const double JxW                    = strain_values.JxW(q);
              sums[2] += 0.5 * form(lambda, two_G, eps_u) * JxW;
              sums[3] += form(mu1, mu2, eps_w) * JxW;
              sums[4] += form(lambda, two_G, eps_w) * JxW;
            }
        }
    Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()),
                        this->mpi_communicator(),
                        ArrayView<double>(sums.data(), sums.size()));
    return {sums[0], sums[1], sums[2], sums[3], sums[4]};
  }


  // @sect4{SelfChecks::setup_gamma3_map}

  // The checks' own map of Gamma_3, and where the friction solver's nodes
  // are on it (a solver node where the mesh has none ends the run).
  template <int dim>
  void SelfChecks<dim>::setup_gamma3_map()
  {
    gamma3_map =
      std::make_unique<Gamma3Map<dim>>(this->space(),
                                       this->parameters().boundary.contact_ids);
    std::vector<Point<dim>> locations;
    for (const ContactNode<dim> &node :
         this->friction_solver().boundary().nodes)
      locations.push_back(node.location);
    map_node_of_solver_node = gamma3_map->nodes_at(locations);
  }


  // @sect4{SelfChecks::friction_forces_on_map}

  // The force the solver reports at each node, sum_i eta_{p,i} t_{p,i}
  // with its tangents, at the node of the map at its place; zero where the
  // solver has no node (where Gamma_3 meets the clamp).
  template <int dim>
  std::vector<Tensor<1, dim>> SelfChecks<dim>::friction_forces_on_map() const
  {
    const auto &solver_nodes  = this->friction_solver().boundary().nodes;
    const Vector<double> &eta = this->friction_solver().state().friction_force;
    std::vector<Tensor<1, dim>> forces(gamma3_map->nodes.size());
    for (unsigned int p = 0; p < solver_nodes.size(); ++p)
      forces[map_node_of_solver_node[p]] =
        solver_nodes[p].tangential_vector(eta, p);
    return forces;
  }


  // @sect4{SelfChecks::equation_residual}

  // (5.2) at t_n, K w_n = F_n + M w_{n-1} / k - B u_{n-1} - C^T eta_n, from
  // the stored w_n and the step's right-hand side, with C^T eta_n put on
  // the dofs of the map's nodes and condensed. Relative to the largest of
  // the three vectors' norms: a step's own scale, which an error in one
  // step cannot hide in.
  template <int dim>
  double SelfChecks<dim>::equation_residual(
    const std::vector<Tensor<1, dim>> &forces) const
  {
    const DiscreteSpace<dim> &space = this->space();
    VectorType residual(space.locally_owned_dofs, this->mpi_communicator());
    VectorType friction(residual);
    this->matrices().system.vmult(residual, this->state().velocity);
    space.constraints.set_zero(residual);
    gamma3_map->add_nodal_forces(forces, friction);
    const VectorType &step_rhs = this->state().step_rhs;
    const double      scale =
      std::max({residual.l2_norm(), step_rhs.l2_norm(), friction.l2_norm()});
    residual -= step_rhs;
    residual += friction;
    return residual.l2_norm() /
           std::max(scale, std::numeric_limits<double>::min());
  }


  // @sect4{SelfChecks::check_friction_law}

  // The friction law (5.3)-(5.4) at the stored velocities, through the
  // map: at each node the tangential parts (to the map's normal) of the
  // solver's force f_p and of w_n, and the bound g_p = m_p S mu(|v_p|) with
  // the map's weight and the true law. Where the solver says the node
  // slips, f_p must be g_p v_p / |v_p| (or, at a rate of zero, within
  // g_p(0)); where it sticks, within g_p(0) and at rest. The friction power
  // sum f_p . v_p of the slipping nodes must not be negative.
  template <int dim>
  void
  SelfChecks<dim>::check_friction_law(const std::vector<Tensor<1, dim>> &forces)
  {
    const auto       &solver_nodes = this->friction_solver().boundary().nodes;
    const auto       &claimed      = this->friction_solver().state().node_state;
    std::vector<bool> slips(gamma3_map->nodes.size(), false);
    for (unsigned int p = 0; p < solver_nodes.size(); ++p)
      slips[map_node_of_solver_node[p]] = (claimed[p] != NodeState::stick);

    const FrictionLaw &law = this->friction_law();
    const auto velocities = gamma3_map->values_at_nodes(this->state().velocity);
    double largest_bound = std::numeric_limits<double>::min(), violation = 0,
           largest_speed = 0, power = 0;
    for (unsigned int k = 0; k < gamma3_map->nodes.size(); ++k)
      {
        const auto          &node         = gamma3_map->nodes[k];
        const Tensor<1, dim> force        = node.tangential(forces[k]);
        const Tensor<1, dim> v            = node.tangential(velocities[k]);
        const double         speed        = v.norm();
        const double         static_bound = node.weight * law.bound(0.);
        largest_bound = std::max(largest_bound, static_bound);
        if (slips[k] && speed > 0)
          {
            violation = std::max(
              violation,
              (force - node.weight * law.bound(speed) / speed * v).norm());
            power += force * v;
          }
        else
          violation = std::max(violation, force.norm() - static_bound);
        if (!slips[k])
          largest_speed = std::max(largest_speed, speed);
      }
    step_checks.friction_law = violation / largest_bound;
    step_checks.stick_motion =
      largest_speed / std::max({this->state().velocity.linfty_norm(),
                                this->friction_solver().free_slip_speed(),
                                std::numeric_limits<double>::min()});
    step_checks.negative_friction_power =
      std::abs(std::min(this->time_step() * power, 0.)) /
      std::max(this->state().energy.scale(),
               std::numeric_limits<double>::min());
  }


  // @sect4{SelfChecks::setup_moment_balance}

  // The rigid rotation r = e_z x x, interpolated, its tangential components
  // on Gamma_3, and whether the balance of moments is a self-check: where r
  // lies in V_h, (5.2) tested with r has no reaction term, and where the
  // mapping's degree is at most the element's, r is its own interpolant, so
  // eps(r) = 0 takes the internal forces out and the angular momentum with
  // the exact x is r^T M w. Whether r lies in V_h is asked of the
  // constraints themselves (they leave r as it is, to 1e-12 of its size): a
  // clamp, or a normal constraint not normal to r, excludes it; on a
  // circular Gamma_3 about the axis, so do nodes' normals that are not
  // radial, by how much the summary says (rotation_defect).
  template <int dim>
  void SelfChecks<dim>::setup_moment_balance()
  {
    const DiscreteSpace<dim> &space = this->space();
    std::vector<std::function<double(const Point<dim> &)>> components(
      dim, [](const Point<dim> &) { return 0.; });
    components[0] = [](const Point<dim> &x) { return -x[1]; };
    components[1] = [](const Point<dim> &x) { return x[0]; };
    VectorType r(space.locally_owned_dofs, this->mpi_communicator());
    VectorTools::interpolate(*space.mapping,
                             space.dof_handler,
                             FunctionFromFunctionObjects<dim>(components),
                             r);
    VectorType constrained(r);
    space.constraints.distribute(constrained);
    constrained -= r;
    const auto &geometry = this->parameters().geometry;
    rotation_defect      = constrained.linfty_norm() / r.linfty_norm();
    moment_balance_is_checked =
      rotation_defect <= 1e-12 &&
      ((geometry.cell_shape == GeometryParameters::CellShape::simplex) ||
       geometry.mapping_degree <= space.fe.degree);
    rotation = space.fast_ghosted(r);
    rotation_on_gamma3 =
      this->friction_solver().boundary().tangential_velocities(r);
  }


  // @sect4{SelfChecks::start_self_checks}

  // The initial energy by quadrature, after set_initial_values(), and the
  // moments of the row of step 0: the angular momentum and the loads'
  // moment at t = 0 (no friction force acts before the first step, and the
  // reaction, a rate, is not defined there: 0).
  template <int dim>
  void SelfChecks<dim>::start_self_checks()
  {
    const DiscreteSpace<dim> &space = this->space();
    const StepState          &state = this->state();
    moments                         = MomentBalance();
    moments.angular_momentum =
      this->matrices().angular_momentum_density * state.velocity;
    moments.applied    = this->loads().power(0., {&rotation})[0].power;
    const FastVector u = space.fast_ghosted(state.displacement),
                     w = space.fast_ghosted(state.velocity);
    const FieldIntegrals integrals = field_integrals(u, w, w);
    energy_by_quadrature           = EnergyBalance();
    energy_by_quadrature.kinetic   = integrals.kinetic;
    energy_by_quadrature.elastic   = integrals.elastic;
    energy_by_quadrature.initial   = integrals.kinetic + integrals.elastic;
    step_checks                    = SelfCheckValues();
    largest_checks                 = SelfCheckValues();
  }


  // @sect4{SelfChecks::check_step}

  // After each step (each half of a cut step): the terms of (5.7) by
  // quadrature, (5.2) tested with w_n as in update_energy_balance(),
  //   1/2|w_n|_M^2 + 1/2|u_n|_B^2 + sum k |w_j|_A^2 + sum k eta_j . C w_j
  //   + sum (1/2 |w_j - w_{j-1}|_M^2 + k^2/2 |w_j|_B^2)
  //   = 1/2|w_0|_M^2 + 1/2|u_0|_B^2 + sum k F_j . w_j,
  // the friction law at the step's slip rates, and the sign of the step's
  // friction power k eta_n . C w_n on the slipping nodes (where a node
  // sticks, C w_n is round-off, which can be amplified far beyond the
  // energies' round-off when K is ill-conditioned: the law check measures
  // it).
  template <int dim>
  void SelfChecks<dim>::check_step()
  {
    const DiscreteSpace<dim> &space = this->space();
    const StepState          &state = this->state();
    TimerOutput::Scope        t(this->computing_timer(), "Self-checks");
    const double              k    = this->time_step();
    const FastVector          u    = space.fast_ghosted(state.displacement),
                     w             = space.fast_ghosted(state.velocity),
                     old_w         = space.fast_ghosted(state.old_velocity);
    const FieldIntegrals integrals = field_integrals(u, w, old_w);
    EnergyBalance       &balance   = energy_by_quadrature;
    balance.kinetic                = integrals.kinetic;
    balance.elastic                = integrals.elastic;
    balance.viscous_dissipation += k * integrals.viscous_power;
    balance.numerical_dissipation +=
      integrals.velocity_jump + 0.5 * k * k * integrals.elastic_power;
    const std::vector<LoadPower> load_powers =
      this->loads().power(state.time, {&w, &rotation});
    balance.external_work += k * load_powers[0].power;
    balance.friction_dissipation = state.energy.friction_dissipation;
    const double moment_scale    = update_moments(load_powers[1]);

    const auto relative = [](const double value, const double scale) {
      return std::abs(value) /
             std::max(scale, std::numeric_limits<double>::min());
    };
    step_checks.algebraic_energy =
      relative(state.energy.residual(), state.energy.scale());
    step_checks.quadrature_energy =
      relative(balance.residual(), balance.scale());
    const std::vector<Tensor<1, dim>> forces = friction_forces_on_map();
    step_checks.equation_residual            = equation_residual(forces);
    check_friction_law(forces);
    step_checks.friction_law_allowance =
      2. * this->friction_solver().law_residual_allowance();
    step_checks.friction_law_excess =
      step_checks.friction_law <= step_checks.friction_law_allowance ?
        0. :
        step_checks.friction_law;
    step_checks.moment_scale = moment_scale;
    step_checks.moment_balance =
      moment_balance_is_checked ?
        relative(moments.reaction,
                 std::max(step_checks.moment_scale,
                          largest_checks.moment_scale)) :
        0.;
    largest_checks.take_largest(step_checks);
  }


  // @sect4{SelfChecks::update_moments}

  // The moments of the step (MomentBalance): L_n and L_{n-1} by the angular
  // momentum density (from w_{n-1}, so that a resumed run needs nothing
  // more of the past), the loads' moment F_n . r, and the friction's
  // -eta_n . C r. Returned is the scale of the reaction's round-off: the
  // sum of the magnitudes of all products that the four sums add up. The
  // moments themselves are no scale: a ring under pressure alone, or
  // spinning freely, has no moment at all.
  template <int dim>
  double SelfChecks<dim>::update_moments(const LoadPower &applied)
  {
    const StepState &state = this->state();
    // a . b (by the vectors' own dot product, whose summation is more
    // accurate than a plain loop's), and the sum of |a_i b_i|.
    const auto dot =
      [this](const auto &a, const auto &b, const bool distributed) {
        double magnitude = 0;
        auto   b_entry   = b.begin();
        for (auto a_entry = a.begin(); a_entry != a.end(); ++a_entry, ++b_entry)
          magnitude += std::abs(*a_entry * *b_entry);
        if (distributed)
          magnitude = Utilities::MPI::sum(magnitude, this->mpi_communicator());
        return std::array<double, 2>{{a * b, magnitude}};
      };
    const auto old_momentum =
      dot(this->matrices().angular_momentum_density, state.old_velocity, true);
    const auto momentum =
      dot(this->matrices().angular_momentum_density, state.velocity, true);
    // Every process has all of eta and C r.
    const auto friction = dot(this->friction_solver().state().friction_force,
                              rotation_on_gamma3,
                              false);
    moments.angular_momentum = momentum[0];
    moments.applied          = applied.power;
    moments.friction         = -friction[0];
    moments.reaction = (momentum[0] - old_momentum[0]) / this->time_step() -
                       moments.applied - moments.friction;
    return (momentum[1] + old_momentum[1]) / this->time_step() +
           applied.magnitude + friction[1];
  }


  // @sect4{SelfChecks::print_summary}

  template <int dim>
  void SelfChecks<dim>::print_summary() const
  {
    // A value far below the tolerance is round-off, whose digits depend
    // on the machine: only its bound is printed.
    const auto line =
      [&](const std::string &name, const double value, const double violation) {
        this->pcout() << "  " << name << ": " << std::setprecision(2);
        if (value == 0.)
          this->pcout() << 0;
        else if (value < round_off_bound)
          this->pcout() << "below " << round_off_bound;
        else
          this->pcout() << value;
        this->pcout() << (violation < tolerance ? "" : "  FAILED") << std::endl;
      };
    this->pcout()
      << "Self-checks, largest over the steps (relative; each must stay "
      << "below " << tolerance << "):" << std::endl;
    const SelfCheckValues &c = largest_checks;
    line("energy identity from the matrices (the solve)",
         c.algebraic_energy,
         c.algebraic_energy);
    line("energy identity by quadrature (matrices, loads)",
         c.quadrature_energy,
         c.quadrature_energy);
    line("equations (5.2) from the stored fields",
         c.equation_residual,
         c.equation_residual);
    line("friction law at the stored velocities",
         c.friction_law,
         c.friction_law_excess);
    if (c.friction_law >= tolerance && c.friction_law_excess < tolerance)
      this->pcout() << "    (within what '" + Entry::convexification_tolerance +
                         "' allows, "
                    << "up to " << c.friction_law_allowance << ")" << std::endl;
    line("sticking nodes at rest", c.stick_motion, c.stick_motion);
    line("negative friction power on slipping nodes",
         c.negative_friction_power,
         c.negative_friction_power);
    if (moment_balance_is_checked)
      line("balance of moments about the z-axis",
           c.moment_balance,
           c.moment_balance);
    else if (this->parameters().geometry.domain ==
             GeometryParameters::Domain::shell)
      print_why_moments_are_not_checked();
  }


  // @sect4{SelfChecks::print_why_moments_are_not_checked}

  // On a shell, where a user expects the balance of moments, the reason it
  // is not a self-check of this run (setup_moment_balance()).
  template <int dim>
  void SelfChecks<dim>::print_why_moments_are_not_checked() const
  {
    this->pcout() << "  (balance of moments about the z-axis: not checked, ";
    if (rotation_defect <= 1e-12)
      this->pcout()
        << "the mapping's degree is above the element's, so the rigid "
           "rotation is not in the finite element space; column "
           "reaction_moment of time_series.csv shows how far the "
           "balance holds)";
    else if (!this->parameters().boundary.clamped_ids.empty())
      this->pcout() << "a clamp holds the body against turning; column "
                       "reaction_moment of time_series.csv is its moment)";
    else
      this->pcout()
        << "the nodes' normals on the constraints' boundaries are not "
           "all normal to the rotation about the axis: they change it "
           "by "
        << rotation_defect << " of its size)";
    this->pcout() << std::endl;
  }


  // @sect4{SelfChecks::require_success}

  // The end of a run whose self-check failed: an error that names the
  // check and the column of time_series.csv that shows from which step on.
  template <int dim>
  void SelfChecks<dim>::require_success() const
  {
    std::ostringstream failures;
    failures << std::setprecision(2);
    const auto add = [&](const double       value,
                         const std::string &what,
                         const std::string &column) {
      if (!(value < tolerance))
        failures << "\n  " << what << " holds only to " << value << " (column "
                 << column << " of time_series.csv)";
    };
    add(largest_checks.algebraic_energy,
        "the energy identity from the matrices, i.e. the steps' linear "
        "solves,",
        "algebraic_energy_residual");
    add(largest_checks.quadrature_energy,
        "the energy identity by quadrature of the fields and loads",
        "quadrature_energy_residual");
    add(largest_checks.equation_residual,
        "the equations (5.2) of the step, from the stored fields with the "
        "friction forces put on the body by the checks' own map of Gamma_3,",
        "equation_residual");
    add(largest_checks.friction_law_excess,
        "the friction law at the stored velocities",
        "friction_law_residual");
    add(largest_checks.stick_motion,
        "the rest of the nodes the solver says stick (their speed relative "
        "to the larger of max |w_n| and max |v_free|)",
        "stick_speed");
    add(largest_checks.negative_friction_power,
        "the friction power on the slipping nodes, which must not be "
        "negative,",
        "friction_dissipation");
    add(largest_checks.moment_balance,
        "the balance of moments about the z-axis (the reactions of the "
        "constraints must have no moment)",
        "reaction_moment");
    std::ostringstream message;
    message << "Self-check failed (tolerance " << tolerance
            << "):" << failures.str() << "\nThe results in '"
            << this->parameters().output.directory
            << "' are not a solution of the scheme.";
    AssertThrow(failures.str().empty(), ExcMessage(message.str()));
  }


  // @sect4{SelfChecks::add_columns}

  // The checks' values of the step, with the momentum and the moments the
  // balance of moments adds up (columns of time_series.csv).
  template <int dim>
  void SelfChecks<dim>::add_columns(TimeSeriesRow &row) const
  {
    const StepState     &state = this->state();
    const Tensor<1, dim> p     = this->matrices().momentum(state.velocity);
    row.add("algebraic_energy_residual", state.energy.residual());
    row.add("quadrature_energy_residual", energy_by_quadrature.residual());
    row.add("equation_residual", step_checks.equation_residual);
    row.add("friction_law_residual", step_checks.friction_law);
    row.add("stick_speed", step_checks.stick_motion);
    for (unsigned int d = 0; d < dim; ++d)
      row.add(std::string("momentum_") + "xyz"[d], p[d]);
    row.add("angular_momentum", moments.angular_momentum);
    row.add("applied_moment", moments.applied);
    row.add("friction_moment", moments.friction);
    row.add("reaction_moment", moments.reaction);
  }



  namespace
  {
    const PostprocessorRegistration<SelfChecks> registration(30);
  }
} // namespace Contact
