/* The checks every run makes of its own results (doc/verification.md;
   the list: include/parts/self_checks/self_checks.h). Their report at the
   end of the run is in self_check_summary.cc. */

#include <deal.II/base/array_view.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/la_parallel_vector.h>

#include <deal.II/numerics/vector_tools.h>

#include <base/dimensions.h>
#include <core/geometry.h>
#include <parts/self_checks/self_checks.h>

#include <array>
#include <limits>

namespace Contact
{
  // @sect4{SelfChecks::field_integrals}

  // The integrals of the forms of M, A and B on fields u_h, w_h, with the
  // quadrature rules of the assembly (the mass rule for rho |w|^2, which is
  // the nodal one for a lumped mass: the discrete kinetic energy is defined
  // by it), but from the values and strains of the fields on the cells,
  // not from the matrices. Each cell's dof values are read once, and the
  // fields are summed from the scalar shape functions (each shape function
  // of the vector element is a scalar one in one component) instead of
  // through FEValues' vector functions, which allocate at every call.
  template <int dim>
  FieldIntegrals SelfChecks<dim>::field_integrals(const FastVector &u,
                                                  const FastVector &w) const
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
    Vector<double>     u_cell(n_dofs), w_cell(n_dofs);
    std::vector<unsigned int> component(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      component[i] = space.fe.system_to_component_index(i).first;

    std::vector<double> sums(4, 0.);
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_values(u, u_cell);
          cell->get_dof_values(w, w_cell);
          strain_values.reinit(cell);
          if (lumped)
            lumped_values.reinit(cell);
          for (const unsigned int q : mass_values.quadrature_point_indices())
            {
              Tensor<1, dim> w_q;
              for (unsigned int i = 0; i < n_dofs; ++i)
                w_q[component[i]] += w_cell[i] * mass_values.shape_value(i, q);
              sums[0] += 0.5 * rho * (w_q * w_q) * mass_values.JxW(q);
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
              sums[1] += 0.5 * form(lambda, two_G, eps_u) * JxW;
              sums[2] += form(mu1, mu2, eps_w) * JxW;
              sums[3] += form(lambda, two_G, eps_w) * JxW;
            }
        }
    Utilities::MPI::sum(sums, this->mpi_communicator(), sums);
    return {sums[0], sums[1], sums[2], sums[3]};
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
  // solver has no node (where V_h fixes the node in every direction).
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
  // the stored w_n (K w_n = ((1/k) M + A + k B) w_n from the step's products
  // of w_n with the three matrices, not from K or its factorisation) and the
  // step's right-hand side, with C^T eta_n put on the dofs of the map's
  // nodes and condensed. Relative to the largest of |M w_n| / k + |A w_n| +
  // k |B w_n|, |step_rhs| and |C^T eta_n|: a step's own scale, which an
  // error in one step cannot hide in.
  template <int dim>
  double SelfChecks<dim>::equation_residual(
    const std::vector<Tensor<1, dim>> &forces) const
  {
    const DiscreteSpace<dim> &space = this->space();
    // Kept between the steps: a distributed vector is costly to make.
    VectorType &residual = residual_work, &friction = friction_work;
    if (residual.size() == 0)
      {
        residual.reinit(space.locally_owned_dofs, this->mpi_communicator());
        friction.reinit(residual);
      }
    friction = 0;
    residual = this->state().system_times_velocity;
    gamma3_map->add_nodal_forces(forces, friction);
    const VectorType &step_rhs = this->state().step_rhs;
    const double scale = std::max({this->state().system_times_velocity_terms,
                                   step_rhs.l2_norm(),
                                   friction.l2_norm()});
    residual -= step_rhs;
    residual += friction;
    return residual.l2_norm() /
           std::max(scale, std::numeric_limits<double>::min());
  }


  // @sect4{SelfChecks::check_friction_law}

  // The friction law (5.3)-(5.4) at the stored velocities, through the
  // map: at each node the parts of the solver's force f_p and of w_n in
  // which V_h lets the node move, and the bound g_p = m_p S mu(|v_p|) with
  // the map's weight and the true law, in the complementarity form
  //   f_p = P_{B(g_p)}(f_p + c_p v_p),
  // P the projection onto the ball of radius g_p: within the ball where
  // v_p = 0, g_p v_p / |v_p| where v_p != 0. Its residual |f_p - P(...)|
  // is relative to max_p g_p(0). c_p = m_p S mu(0) / (the step's speed
  // scale) makes a velocity of round-off size give a force of round-off
  // size, so that a node slipping by round-off, or at a slip front, gives
  // no spurious direction. The nodes the solver says stick must be at
  // rest, and the friction power sum f_p . v_p of those it says slip must
  // not be negative.
  template <int dim>
  void
  SelfChecks<dim>::check_friction_law(const FastVector                  &w,
                                      const std::vector<Tensor<1, dim>> &forces)
  {
    const auto       &solver_nodes = this->friction_solver().boundary().nodes;
    const auto       &claimed      = this->friction_solver().state().node_state;
    std::vector<bool> slips(gamma3_map->nodes.size(), false);
    for (unsigned int p = 0; p < solver_nodes.size(); ++p)
      slips[map_node_of_solver_node[p]] = (claimed[p] != NodeState::stick);

    const FrictionLaw &law        = this->friction_law();
    const auto         velocities = gamma3_map->values_at_nodes(w);
    const double       speed_scale =
      std::max(this->state().velocity.linfty_norm(),
               this->friction_solver().free_slip_speed());
    double largest_bound = std::numeric_limits<double>::min(), violation = 0,
           largest_speed = 0, power = 0;
    for (unsigned int k = 0; k < gamma3_map->nodes.size(); ++k)
      {
        const auto          &node         = gamma3_map->nodes[k];
        const Tensor<1, dim> force        = node.tangential(forces[k]);
        const Tensor<1, dim> v            = node.tangential(velocities[k]);
        const double         static_bound = node.weight * law.bound(0.);
        const double         bound        = node.weight * law.bound(v.norm());
        largest_bound = std::max(largest_bound, static_bound);
        const Tensor<1, dim> z =
          force + (speed_scale > 0 ? static_bound / speed_scale : 0.) * v;
        const Tensor<1, dim> projection =
          (z.norm() > bound ? (bound / z.norm()) * z : z);
        violation = std::max(violation, (force - projection).norm());
        if (slips[k])
          power += force * v;
        else
          largest_speed = std::max(largest_speed, v.norm());
      }
    step_checks.friction_law = violation / largest_bound;
    step_checks.stick_motion =
      largest_speed / std::max(speed_scale, std::numeric_limits<double>::min());
    step_checks.negative_friction_power =
      std::abs(std::min(this->time_step() * power, 0.)) /
      std::max(step_energy_scale, std::numeric_limits<double>::min());
  }


  // @sect4{SelfChecks::setup_moment_balance}

  // The rigid rotation r = e_z x x, interpolated, its values at the nodes of
  // the map of Gamma_3, and whether the balance of moments is a self-check:
  // where r lies in V_h, (5.2) tested with r has no reaction term, and
  // where the mapping's degree is at most the element's, r is its own
  // interpolant, so eps(r) = 0 takes the internal forces out and the
  // angular momentum with the exact x is r^T M w. Whether r lies in V_h is
  // asked of the constraints themselves (they leave r as it is, to 1e-12 of
  // its size): a clamp, or a normal constraint not normal to r, excludes
  // it. On a body symmetric about the axis without a clamp (and without
  // hanging nodes that bend r off the circle) r must lie in V_h (a shell):
  // there the check is made in any case, and nodes' normals that are not
  // radial fail it instead of switching it off.
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
    // How far constraints move r, relative to its size.
    const auto defect = [&](const AffineConstraints<double> &constraints) {
      VectorType constrained(r);
      constraints.distribute(constrained);
      constrained -= r;
      return constrained.linfty_norm() / r.linfty_norm();
    };
    // Hanging nodes on a curved mesh (a refined shell) interpolate r along
    // the coarse cell's polynomial, not along the circle: there r is not in
    // V_h whatever the normals are.
    const AffineConstraints<double> &hanging = space.hanging_node_constraints;
    const auto                      &parameters = this->parameters();
    const auto                      &geometry   = parameters.geometry;
    const double rotation_defect                = defect(space.constraints);
    const bool   must_admit_rotation =
      this->problem().get_geometry().is_symmetric_about_z_axis() &&
      parameters.boundary.clamped_ids.empty() && defect(hanging) <= 1e-12;
    moment_balance_is_checked =
      (rotation_defect <= 1e-12 || must_admit_rotation) &&
      ((geometry.cell_shape == GeometryParameters::CellShape::simplex) ||
       geometry.mapping_degree <= space.fe.degree);
    rotation          = space.fast_ghosted(r);
    rotation_at_nodes = gamma3_map->values_at_nodes(rotation);
  }


  // @sect4{SelfChecks::start_self_checks}

  // Before the first step (of a fresh or a resumed run): the matrices, the
  // energy balance the first step's part of it starts from, and the
  // moments of the row of the step the run starts at: the angular momentum
  // and the loads' moment (no friction force acts before the first step,
  // and the reaction, a rate, is not defined there: 0).
  template <int dim>
  void SelfChecks<dim>::start_self_checks()
  {
    const StepState &state = this->state();
    step_checks            = SelfCheckValues();
    step_checks.matrices   = check_matrices();
    largest_checks.take_largest(step_checks);
    last_energy = state.energy;
    moments     = MomentBalance();
    moments.angular_momentum =
      this->matrices().angular_momentum_density * state.velocity;
    momentum_density_norm = this->matrices().angular_momentum_density.l2_norm();
    last_velocity_norm    = state.velocity.l2_norm();
    moments.applied = this->loads().power(state.time, {&rotation})[0].power;
  }


  // @sect4{SelfChecks::warn_of_loose_tolerance}

  // The check of the friction law excuses what the convexification's
  // tolerance leaves of the law (up to largest_friction_law_allowance):
  // where that tolerance is loose, the run says so before its first step.
  template <int dim>
  void SelfChecks<dim>::warn_of_loose_tolerance() const
  {
    const double convexification_tolerance =
      this->parameters().solver.convexification_tolerance;
    if (convexification_tolerance > round_off_bound &&
        !this->friction_law().is_rate_independent())
      this->pcout() << "Note: with '" << Entry::convexification_tolerance
                    << "' = " << convexification_tolerance
                    << " the self-check of the friction law is looser: it "
                       "excuses what that tolerance leaves of the law, up to "
                    << largest_friction_law_allowance << " of max g(0)."
                    << std::endl;
  }


  // @sect4{SelfChecks::check_matrices}

  // M, A and B against the integrals of their forms: x^T M x against
  // int rho |x_h|^2, y^T A y against int A eps(y_h) : eps(y_h), x^T B x
  // and y^T B y against the same with B, for two fields x, y in V_h whose
  // free entries vary from dof to dof without a pattern (a wrong entry of
  // a matrix shows in them). The largest difference relative to the
  // integral.
  template <int dim>
  double SelfChecks<dim>::check_matrices() const
  {
    const DiscreteSpace<dim> &space = this->space();
    VectorType x(space.locally_owned_dofs, this->mpi_communicator());
    VectorType y(x), product(x);
    for (const types::global_dof_index i : space.locally_owned_dofs)
      {
        x[i] = std::sin(1.3 * i + 0.7);
        y[i] = std::cos(0.9 * i + 0.2);
      }
    x.compress(VectorOperation::insert);
    y.compress(VectorOperation::insert);
    space.constraints.distribute(x);
    space.constraints.distribute(y);
    const FieldIntegrals integrals =
      field_integrals(space.fast_ghosted(x), space.fast_ghosted(y));
    const auto form = [&](const MatrixType &matrix, const VectorType &field) {
      matrix.vmult(product, field);
      space.constraints.set_zero(product);
      return product * field;
    };
    const auto difference = [](const double from_matrix,
                               const double integral) {
      return std::abs(from_matrix - integral) /
             std::max({std::abs(from_matrix),
                       std::abs(integral),
                       std::numeric_limits<double>::min()});
    };
    const SystemMatrices<dim> &matrices = this->matrices();
    return std::max(
      {difference(0.5 * form(matrices.mass, y), integrals.kinetic),
       difference(0.5 * form(matrices.elasticity, x), integrals.elastic),
       difference(form(matrices.viscosity, y), integrals.viscous_power),
       difference(form(matrices.elasticity, y), integrals.elastic_power)});
  }


  // @sect4{SelfChecks::check_step}

  // After each step (each half of a cut step), each check relative to a
  // scale of that step. The friction law fails where it exceeds twice what
  // the convexification's own tolerance allows, up to
  // largest_friction_law_allowance.
  template <int dim>
  void SelfChecks<dim>::check_step()
  {
    const DiscreteSpace<dim> &space = this->space();
    TimerOutput::Scope        t(this->computing_timer(), "Self-checks");
    const FastVector          w = space.fast_ghosted(this->state().velocity);
    step_checks                 = SelfCheckValues();
    const std::vector<Tensor<1, dim>> forces = friction_forces_on_map();
    check_energy_and_loads(w, forces);
    step_checks.constraints       = check_constraints(w);
    step_checks.equation_residual = equation_residual(forces);
    check_friction_law(w, forces);
    step_checks.friction_law_allowance =
      std::min(2. * this->friction_solver().law_residual_allowance(),
               largest_friction_law_allowance);
    step_checks.friction_law_excess =
      step_checks.friction_law <= step_checks.friction_law_allowance ?
        0. :
        step_checks.friction_law;
    largest_checks.take_largest(step_checks);
  }


  // @sect4{SelfChecks::check_energy_and_loads}

  // The step's part of the energy identity (5.7) of backward Euler, from
  // the products of the matrices with w_n (EnergyBalance), relative to the
  // sum of the magnitudes of its terms: the energies before and after the
  // step, and what it dissipated and what the loads did in it (the step's
  // own terms, StepState::step_energy, not differences of the sums over
  // the steps, whose round-off would swamp a body that has come to rest).
  // Then the load power F_n . w_n of the step with the assembled load
  // vector against the loads' integral with w_h (Loads::power()), relative
  // to |F_n| |w_n| (a bound of the magnitudes of the products F_i w_i)
  // plus the magnitudes of the integral's products; and the balance of
  // moments.
  template <int dim>
  void SelfChecks<dim>::check_energy_and_loads(
    const FastVector                  &w,
    const std::vector<Tensor<1, dim>> &forces)
  {
    const StepState     &state = this->state();
    const EnergyBalance &now = state.step_energy, &before = last_energy;
    const double         energy_terms =
      now.kinetic + before.kinetic + now.elastic + before.elastic +
      std::abs(now.viscous_dissipation) + std::abs(now.friction_dissipation) +
      std::abs(now.numerical_dissipation) + std::abs(now.external_work);
    const auto relative = [](const double value, const double scale) {
      return std::abs(value) /
             std::max(scale, std::numeric_limits<double>::min());
    };
    step_checks.algebraic_energy =
      relative(now.kinetic - before.kinetic + now.elastic - before.elastic +
                 now.viscous_dissipation + now.friction_dissipation +
                 now.numerical_dissipation - now.external_work,
               energy_terms);
    step_energy_scale = energy_terms;
    last_energy       = state.energy;

    const std::vector<LoadPower> integrals =
      this->loads().power(state.time, {&w, &rotation});
    // The magnitudes of the products F_i w_i add up to at most |F| |w|.
    const double assembled    = state.load * state.velocity;
    const double magnitude    = state.load.l2_norm() * state.velocity.l2_norm();
    step_checks.load_power    = relative(assembled - integrals[0].power,
                                      magnitude + integrals[0].magnitude);
    const double moment_scale = update_moments(integrals[1], forces);
    step_checks.moment_balance =
      moment_balance_is_checked ? relative(moments.reaction, moment_scale) : 0.;
  }


  // @sect4{SelfChecks::check_constraints}

  // How far w_n is from V_h: the largest difference between a constrained
  // entry and what its constraint makes of the others, relative to
  // max |w_n|.
  template <int dim>
  double SelfChecks<dim>::check_constraints(const FastVector &w) const
  {
    const DiscreteSpace<dim> &space   = this->space();
    double                    largest = 0;
    for (const auto &line : space.constraints.get_lines())
      if (space.locally_owned_dofs.is_element(line.index))
        {
          double value = line.inhomogeneity;
          for (const auto &[dof, weight] : line.entries)
            {
              AssertThrow(space.locally_relevant_dofs.is_element(dof),
                          ExcInternalError("A constraint of V_h refers to a "
                                           "dof this process does not see."));
              value += weight * w(dof);
            }
          largest = std::max(largest, std::abs(w(line.index) - value));
        }
    largest = Utilities::MPI::max(largest, this->mpi_communicator());
    return largest /
           std::max(w.linfty_norm(), std::numeric_limits<double>::min());
  }


  // @sect4{SelfChecks::update_moments}

  // The moments of the step (MomentBalance): L_n and L_{n-1} by the
  // angular momentum density (from w_{n-1}, so that a resumed run needs
  // nothing more of the past), the loads' moment F_n . r, and the
  // friction's
  // -sum_p f_p . r(x_p) over the nodes of the map of Gamma_3 with the
  // solver's forces f_p. Returned is the scale of the reaction's round-off:
  // the
  // sum of the magnitudes of all products that the four sums add up. The
  // moments themselves are no scale: a ring under pressure alone, or
  // spinning freely, has no moment at all.
  template <int dim>
  double
  SelfChecks<dim>::update_moments(const LoadPower                   &applied,
                                  const std::vector<Tensor<1, dim>> &forces)
  {
    const StepState &state = this->state();
    // L_n and L_{n-1} from the stored w_n, w_{n-1}. The magnitudes of the
    // products a_i w_i of a . w add up to at most |a| |w| (|w_{n-1}| is
    // that of the last step checked).
    const double old_momentum =
      this->matrices().angular_momentum_density * state.old_velocity;
    const double old_magnitude = momentum_density_norm * last_velocity_norm;
    const double momentum =
      this->matrices().angular_momentum_density * state.velocity;
    last_velocity_norm     = state.velocity.l2_norm();
    const double magnitude = momentum_density_norm * last_velocity_norm;
    // Every process has all nodes' forces and r.
    std::array<double, 2> friction{};
    for (unsigned int k = 0; k < forces.size(); ++k)
      {
        const double product = forces[k] * rotation_at_nodes[k];
        friction[0] += product;
        friction[1] += std::abs(product);
      }
    moments.angular_momentum = momentum;
    moments.applied          = applied.power;
    moments.friction         = -friction[0];
    moments.reaction         = (momentum - old_momentum) / this->time_step() -
                       moments.applied - moments.friction;
    return (magnitude + old_magnitude) / this->time_step() + applied.magnitude +
           friction[1];
  }


  // The members above are instantiated here, those of the summary in
  // self_check_summary.cc.
#define INSTANTIATE(dim) template class SelfChecks<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
