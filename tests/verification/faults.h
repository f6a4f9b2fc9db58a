/* Faults made on purpose, so that a test sees the self-checks of a run
   (self_checks.cc) catch them. The faults live here, not in the program:
   FaultyProblem derives from ContactProblem and overrides its private
   seams (the loads, the nodes of Gamma_3 and the friction solver made on
   them, the matrices after their assembly, the energies after a mesh
   transfer); FaultySolver derives from FrictionSolver, with a scale of
   the law's bound and wrappers of its path. Each fault breaks one thing
   that the checks verify on their own. */
#ifndef contact_tests_faults_h
#define contact_tests_faults_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <core/contact_nodes.h>
#include <core/contact_problem.h>
#include <core/loads.h>
#include <core/delassus_operator.h>
#include <core/friction_solver.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace Contact
{
  /**
   * The faults of a run; the defaults make none. The friction solver
   * solves with the bound S mu(s) times `bound_factor(x_p)` at node p (a
   * wrong coefficient; 0 removes the friction there) while the checks use
   * the true law, and with `reversed_friction_force` it applies and
   * reports -eta instead of eta. The loads (ScaledLoads, made by the
   * problem's create_loads()) are multiplied by `load_factor`. The errors in
   * the solver's map of Gamma_3, which the checks do not share (Gamma3Map): a
   * wrong compliance
   * (`compliance_factor` times D on the Delassus paths, times the step's
   * velocity on the constraints path), the Delassus operator of the old k
   * kept after a step cut, the nodes' weights times `weight_factor`, the
   * first tangent of the node in the middle of the list turned towards its
   * normal by `tangent_turn` radians, and after each step the first
   * sticking node moved along its tangent by `stick_node_velocity` times
   * max |w_n|, or (an error in the constraints of V_h, not in the law)
   * along its normal by `normal_velocity` times max |w_n|, the constraints
   * not applied. The assembly multiplies B by `stiffness_factor`. With
   * `unshared_hanging_weights` the hanging nodes of Gamma_3 keep their
   * weights and their parts of the normals (lost with them) instead of
   * sharing them. With
   * `stale_energies_after_mesh_change` a transfer to an adapted mesh keeps
   * the kinetic and elastic energy of the old mesh.
   */
  template <int dim>
  struct Faults
  {
    std::function<double(const Point<dim> &)> bound_factor;
    bool                                      reversed_friction_force = false;
    double                                    load_factor             = 1.;
    double                                    compliance_factor       = 1.;
    bool   stale_delassus_after_step_cut                              = false;
    double weight_factor                                              = 1.;
    double tangent_turn                                               = 0.;
    double stick_node_velocity                                        = 0.;
    double normal_velocity                                            = 0.;
    double stiffness_factor                                           = 1.;
    bool   unshared_hanging_weights                                   = false;
    bool   stale_energies_after_mesh_change                           = false;
  };


  // A path that passes every operation to the solver's own path, for the
  // wrappers below to change one of them. The solver reads the count of
  // solves of the path it holds: the inner path's, copied after each call.
  template <int dim>
  class PathWrapper : public ContactPath<dim>
  {
  public:
    explicit PathWrapper(std::unique_ptr<ContactPath<dim>> path)
      : inner(std::move(path))
    {}

    void begin_step(const VectorType &step_rhs,
                    const VectorType &last_velocity) override
    {
      inner->begin_step(step_rhs, last_velocity);
      copy_counts();
    }
    const Vector<double> &free_slip_velocity() override
    {
      const Vector<double> &v_free = inner->free_slip_velocity();
      copy_counts();
      return v_free;
    }
    void velocity_of_force(const Vector<double> &eta,
                           Vector<double>       &v) override
    {
      inner->velocity_of_force(eta, v);
      copy_counts();
    }
    void newton_step(const std::vector<NodeLinearisation> &linearisation,
                     Vector<double>                       &eta,
                     Vector<double>                       &v) override
    {
      inner->newton_step(linearisation, eta, v);
      copy_counts();
    }
    void velocity(const Vector<double> &eta, VectorType &w) override
    {
      inner->velocity(eta, w);
      copy_counts();
    }
    void apply_delassus(const Vector<double> &x, Vector<double> &y) override
    {
      inner->apply_delassus(x, y);
      copy_counts();
    }
    std::string description() const override
    {
      return inner->description();
    }
    double free_slip_speed() const override
    {
      return inner->free_slip_speed();
    }
    Curvature curvature_on_slip_set(
      const std::vector<NodeLinearisation> &linearisation) override
    {
      const Curvature curvature = inner->curvature_on_slip_set(linearisation);
      copy_counts();
      return curvature;
    }
    double energy_accuracy() const override
    {
      return inner->energy_accuracy();
    }

  protected:
    void copy_counts()
    {
      this->solves               = inner->solves;
      this->substitution_seconds = inner->substitution_seconds;
    }

    std::unique_ptr<ContactPath<dim>> inner;
  };


  // A Delassus path with D times c: v = v_free - D (c eta). In the forces
  // c eta of the inner path the law has c times the bound and the slope
  // and beta / c (v . t = beta eta . t), so its Newton steps are those of
  // c D. The body's velocity keeps the true K.
  template <int dim>
  class ScaledDelassusPath : public PathWrapper<dim>
  {
  public:
    ScaledDelassusPath(std::unique_ptr<ContactPath<dim>> path,
                       const double                      factor)
      : PathWrapper<dim>(std::move(path))
      , c(factor)
    {}

    void velocity_of_force(const Vector<double> &eta,
                           Vector<double>       &v) override
    {
      Vector<double> scaled(eta);
      scaled *= c;
      PathWrapper<dim>::velocity_of_force(scaled, v);
    }
    void newton_step(const std::vector<NodeLinearisation> &linearisation,
                     Vector<double>                       &eta,
                     Vector<double>                       &v) override
    {
      eta *= c;
      PathWrapper<dim>::newton_step(scaled(linearisation), eta, v);
      eta /= c;
    }
    void apply_delassus(const Vector<double> &x, Vector<double> &y) override
    {
      PathWrapper<dim>::apply_delassus(x, y);
      y *= c;
    }
    Curvature curvature_on_slip_set(
      const std::vector<NodeLinearisation> &linearisation) override
    {
      return PathWrapper<dim>::curvature_on_slip_set(scaled(linearisation));
    }

  private:
    std::vector<NodeLinearisation>
    scaled(std::vector<NodeLinearisation> linearisation) const
    {
      for (NodeLinearisation &node : linearisation)
        {
          node.bound *= c;
          node.force *= c;
          node.slope *= c;
          node.definite_slope *= c;
          node.beta /= c;
        }
      return linearisation;
    }

    const double c;
  };


  // The constraints path with the step's velocity times c.
  template <int dim>
  class ScaledVelocityPath : public PathWrapper<dim>
  {
  public:
    ScaledVelocityPath(std::unique_ptr<ContactPath<dim>> path,
                       const double                      factor)
      : PathWrapper<dim>(std::move(path))
      , c(factor)
    {}

    void velocity(const Vector<double> &eta, VectorType &w) override
    {
      PathWrapper<dim>::velocity(eta, w);
      w *= c;
    }

  private:
    const double c;
  };


  // The body's velocity for -eta.
  template <int dim>
  class ReversedForcePath : public PathWrapper<dim>
  {
  public:
    using PathWrapper<dim>::PathWrapper;

    void velocity(const Vector<double> &eta, VectorType &w) override
    {
      Vector<double> reversed(eta);
      reversed *= -1.;
      PathWrapper<dim>::velocity(reversed, w);
    }
  };


  // A Delassus path that works on Gamma_3 with the operator D of the path
  // `old` (read column by column) instead of its own: v_free and the
  // body's velocity are the new path's.
  template <int dim>
  class StaleDelassusPath : public PathWrapper<dim>
  {
  public:
    StaleDelassusPath(std::unique_ptr<ContactPath<dim>> path,
                      ContactPath<dim>                 &old,
                      const unsigned int                n_unknowns)
      : PathWrapper<dim>(std::move(path))
    {
      FullMatrix<double> D(n_unknowns, n_unknowns);
      Vector<double>     unit(n_unknowns), column(n_unknowns);
      for (unsigned int s = 0; s < n_unknowns; ++s)
        {
          unit[s] = 1.;
          old.apply_delassus(unit, column);
          unit[s] = 0.;
          for (unsigned int r = 0; r < n_unknowns; ++r)
            D(r, s) = column[r];
        }
      delassus = DelassusOperator(D, dim - 1);
    }

    void velocity_of_force(const Vector<double> &eta,
                           Vector<double>       &v) override
    {
      delassus.vmult(v, eta);
      v.sadd(-1., 1., this->free_slip_velocity());
    }
    void newton_step(const std::vector<NodeLinearisation> &linearisation,
                     Vector<double>                       &eta,
                     Vector<double>                       &v) override
    {
      delassus.newton_step(linearisation, this->free_slip_velocity(), eta, v);
    }
    void apply_delassus(const Vector<double> &x, Vector<double> &y) override
    {
      delassus.vmult(y, x);
    }
    Curvature curvature_on_slip_set(
      const std::vector<NodeLinearisation> &linearisation) override
    {
      return delassus.curvature_on_slip_set(linearisation);
    }

  private:
    DelassusOperator delassus;
  };


  // The friction solver with the faults of its map of Gamma_3, of its law
  // and of its path.
  template <int dim>
  class FaultySolver : public FrictionSolver<dim>
  {
  public:
    FaultySolver(const Faults<dim>               &faults_to_make,
                 const FrictionSolverEnvironment &environment,
                 std::vector<ContactNode<dim>>    nodes)
      : FrictionSolver<dim>(environment,
                            std::move(nodes),
                            faults_to_make.bound_factor)
      , faults(faults_to_make)
    {}

    StepStatistics solve_step(const VectorType &step_rhs,
                              VectorType       &velocity,
                              const StepLabel  &label) override
    {
      const StepStatistics statistics =
        FrictionSolver<dim>::solve_step(step_rhs, velocity, label);
      if (faults.reversed_friction_force)
        {
          FrictionState reported = this->state();
          reported.friction_force *= -1.;
          this->set_state(reported);
        }
      if (faults.stick_node_velocity != 0. || faults.normal_velocity != 0.)
        move_first_sticking_node(velocity);
      return statistics;
    }

  protected:
    std::unique_ptr<ContactPath<dim>>
    make_path(const MatrixType  &system_matrix,
              Factorization     &factorization,
              const std::string &name) override
    {
      const bool                        delassus = (name == delassus_path_name);
      std::unique_ptr<ContactPath<dim>> path =
        FrictionSolver<dim>::make_path(system_matrix, factorization, name);
      const double c = faults.compliance_factor;
      if (c != 1. && delassus)
        path = std::make_unique<ScaledDelassusPath<dim>>(std::move(path), c);
      else if (c != 1.)
        path = std::make_unique<ScaledVelocityPath<dim>>(std::move(path), c);
      if (faults.reversed_friction_force)
        path = std::make_unique<ReversedForcePath<dim>>(std::move(path));
      if (faults.stale_delassus_after_step_cut && delassus && last_path)
        path = std::make_unique<StaleDelassusPath<dim>>(
          std::move(path), *last_path, this->boundary().n_unknowns());
      // The solver holds it until the next call replaces it.
      last_path = path.get();
      return path;
    }

  private:
    // The first sticking node moved along its first tangent, or along its
    // normal without the constraints applied.
    void move_first_sticking_node(VectorType &velocity) const
    {
      const ContactBoundary<dim> &gamma3 = this->boundary();
      const bool                  normal = (faults.normal_velocity != 0.);
      const double                speed =
        (normal ? faults.normal_velocity : faults.stick_node_velocity) *
        velocity.linfty_norm();
      for (unsigned int p = 0; p < gamma3.nodes.size(); ++p)
        if (this->state().node_state[p] == NodeState::stick)
          {
            const ContactNode<dim> &node = gamma3.nodes[p];
            if (node.locally_owned)
              for (unsigned int d = 0; d < dim; ++d)
                if (normal || !gamma3.constraints.is_constrained(node.dofs[d]))
                  velocity[node.dofs[d]] +=
                    speed * (normal ? node.normal[d] : node.tangents[0][d]);
            break;
          }
      velocity.compress(VectorOperation::add);
      if (!normal)
        gamma3.constraints.distribute(velocity);
    }

    const Faults<dim> faults;
    ContactPath<dim> *last_path = nullptr;
  };


  // The loads with the load vector times a factor.
  template <int dim>
  class ScaledLoads : public Loads<dim>
  {
  public:
    template <typename... Arguments>
    ScaledLoads(const double load_factor, Arguments &&...arguments)
      : Loads<dim>(std::forward<Arguments>(arguments)...)
      , factor(load_factor)
    {}

    void assemble(const double load_time,
                  VectorType  &load_vector) const override
    {
      Loads<dim>::assemble(load_time, load_vector);
      load_vector *= factor;
    }

  private:
    const double factor;
  };


  // The weight m_p = int_Gamma3 phi_p ds and the normal of node p
  // integrated like the nodes' (the outward normal weighted with
  // |phi_p|), but without the shares of the hanging nodes that follow
  // node p: both are lost with the hanging nodes. (The integration is the
  // test's own, on the faces of hypercubes.)
  template <int dim>
  void drop_hanging_shares(const DoFHandler<dim>                 &dof_handler,
                           const Mapping<dim>                    &mapping,
                           const std::vector<types::boundary_id> &contact_ids,
                           std::vector<ContactNode<dim>>         &nodes)
  {
    std::map<types::global_dof_index, unsigned int> node_of_dof;
    for (unsigned int p = 0; p < nodes.size(); ++p)
      node_of_dof[nodes[p].dofs[0]] = p;
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    FEFaceValues<dim>                    face_values(mapping,
                                  fe,
                                  QGauss<dim - 1>(fe.degree + 1),
                                  update_values | update_normal_vectors |
                                    update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    // Per node its weight, then its normal.
    std::vector<double> integrals(nodes.size() * (dim + 1));
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              std::count(contact_ids.begin(),
                         contact_ids.end(),
                         cell->face(f)->boundary_id()) != 0)
            {
              face_values.reinit(cell, f);
              cell->get_dof_indices(dofs);
              for (unsigned int j = 0; j < fe.n_dofs_per_face(f); ++j)
                {
                  const unsigned int i    = fe.face_to_cell_index(j, f);
                  const auto         node = node_of_dof.find(dofs[i]);
                  if (fe.system_to_component_index(i).first != 0 ||
                      node == node_of_dof.end())
                    continue;
                  double *const node_integrals =
                    &integrals[node->second * (dim + 1)];
                  for (const unsigned int q :
                       face_values.quadrature_point_indices())
                    {
                      const double phi_JxW =
                        face_values.shape_value_component(i, q, 0) *
                        face_values.JxW(q);
                      node_integrals[0] += phi_JxW;
                      for (unsigned int d = 0; d < dim; ++d)
                        node_integrals[1 + d] +=
                          face_values.normal_vector(q)[d] * std::abs(phi_JxW);
                    }
                }
            }
    MPI_Allreduce(MPI_IN_PLACE,
                  integrals.data(),
                  integrals.size(),
                  MPI_DOUBLE,
                  MPI_SUM,
                  dof_handler.get_communicator());
    for (unsigned int p = 0; p < nodes.size(); ++p)
      {
        nodes[p].weight = integrals[p * (dim + 1)];
        for (unsigned int d = 0; d < dim; ++d)
          nodes[p].normal[d] = integrals[p * (dim + 1) + 1 + d];
        nodes[p].normal /= nodes[p].normal.norm();
      }
  }


  // The problem with the faults of its assembly, of its mesh transfer, of
  // its loads and of its friction solver.
  template <int dim>
  class FaultyProblem : public ContactProblem<dim>
  {
  public:
    FaultyProblem(const Parameters  &run_parameters,
                  const Faults<dim> &faults_to_make)
      : ContactProblem<dim>(run_parameters)
      , faults(faults_to_make)
    {}

  private:
    std::unique_ptr<Loads<dim>>
    create_loads(const Parameters         &run_parameters,
                 const DiscreteSpace<dim> &discrete_space,
                 TimerOutput              &timer) const override
    {
      return std::make_unique<ScaledLoads<dim>>(faults.load_factor,
                                                run_parameters,
                                                discrete_space,
                                                timer);
    }

    std::unique_ptr<FrictionSolver<dim>> create_friction_solver(
      std::vector<ContactNode<dim>>    nodes,
      const FrictionSolverEnvironment &environment) const override
    {
      if (faults.unshared_hanging_weights)
        drop_hanging_shares(this->get_dof_handler(),
                            this->get_mapping(),
                            environment.parameters.boundary.contact_ids,
                            nodes);
      for (ContactNode<dim> &node : nodes)
        node.weight *= faults.weight_factor;
      if (faults.tangent_turn != 0. && !nodes.empty())
        {
          ContactNode<dim> &node    = nodes[nodes.size() / 2];
          Tensor<1, dim>   &tangent = node.tangents[0];
          tangent                   = std::cos(faults.tangent_turn) * tangent +
                    std::sin(faults.tangent_turn) * node.normal;
        }
      return std::make_unique<FaultySolver<dim>>(faults,
                                                 environment,
                                                 std::move(nodes));
    }

    void after_assembly(SystemMatrices<dim> &assembled) const override
    {
      if (faults.stiffness_factor != 1.)
        assembled.elasticity *= faults.stiffness_factor;
    }

    // The energies before the transfer, kept on the new mesh.
    void after_mesh_transfer(EnergyBalance       &energy,
                             const EnergyBalance &before) const override
    {
      if (faults.stale_energies_after_mesh_change)
        energy = before;
    }

    const Faults<dim> faults;
  };
} // namespace Contact

#endif
