/**
 * Loads<dim>: the data of the problem that are functions of x and t: the
 * body force f_0, the tractions f_2 on Gamma_2 and the initial values, as
 * muparser expressions of the .prm, or those of the manufactured solution
 * (and its tangential load f_3 on Gamma_3). It assembles F_n of (5.2) and
 * tests the loads with fields without the assembled vector (the power of
 * the loads in the self-checks). loads.cc.
 */
#ifndef contact_loads_h
#define contact_loads_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/timer.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/vector.h>

#include <core/parameters.h>
#include <core/discrete_space.h>
#include <parts/manufactured/manufactured_solution.h>
#include <core/friction_solver.h>

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace Contact
{
  /** F(t) . w of a field w, and the sum of the magnitudes of the products
   *  it is the sum of: the scale of its round-off. */
  struct LoadPower
  {
    double power     = 0;
    double magnitude = 0;
  };


  template <int dim>
  class Loads
  {
  public:
    /** The expressions are parsed here, so that a syntax error is
     *  reported before anything is computed. */
    Loads(const Parameters         &run_parameters,
          const DiscreteSpace<dim> &discrete_space,
          TimerOutput              &timer);

    virtual ~Loads() = default;

    /** After the set-up of the space and of Gamma_3 (whose nodes carry the
     *  manufactured solution's f_3): a constant body force is assembled. */
    void setup(const ContactBoundary<dim> &boundary);

    /** F_n at `load_time`, condensed with the constraints like the
     *  matrices (virtual: a problem with a load vector of its own derives
     *  from Loads). */
    virtual void assemble(const double load_time,
                          VectorType  &load_vector) const;

    /** F(t) . w for fields w in V_h (ghosted), each with its scale. */
    std::vector<LoadPower>
    power(const double                           load_time,
          const std::vector<const FastVector *> &fields) const;

    /** u_0 and w_0 = u_1 of the .prm or of the manufactured solution. */
    const Function<dim> &initial_displacement() const;
    const Function<dim> &initial_velocity() const;

    /** The manufactured solution, or nullptr without one. */
    const ManufacturedSolution<dim> *exact_solution() const;

  private:
    using CellVisitor =
      std::function<void(const typename DoFHandler<dim>::active_cell_iterator &,
                         const Vector<double> &)>;
    using NodeVisitor =
      std::function<void(const ContactNode<dim> &, const Tensor<1, dim> &)>;
    void visit_loads(const double       load_time,
                     const bool         with_body_force,
                     const bool         with_surface_loads,
                     const CellVisitor &visit_cell,
                     const NodeVisitor &visit_node) const;
    bool
    add_cell_loads(const typename DoFHandler<dim>::active_cell_iterator &cell,
                   const double    load_time,
                   const bool      with_body_force,
                   const bool      with_surface_loads,
                   Vector<double> &cell_rhs) const;
    bool is_free_side(const types::boundary_id id) const;
    void assemble_load(const double load_time,
                       VectorType  &load_vector,
                       const bool   with_body_force) const;
    void assemble_constant_body_load();

    const Parameters &parameters;
    // With 'Verification/Manufactured solution', the exact solution that
    // replaces the load data of the .prm.
    const std::unique_ptr<const ManufacturedSolution<dim>> exact;
    const DiscreteSpace<dim>                              &space;
    const ContactBoundary<dim>                            *gamma3 = nullptr;
    TimerOutput                                           &computing_timer;

    std::unique_ptr<FunctionParser<dim>> body_force;
    std::unique_ptr<Function<dim>>       u0;
    std::unique_ptr<Function<dim>>       u1;
    std::map<types::boundary_id, std::unique_ptr<FunctionParser<dim>>>
      tractions;
    // A body force that does not depend on t is assembled once, condensed
    // (for F_n) and not (its cell vectors summed without the constraints:
    // its power F . w is a dot product with it).
    const bool body_force_is_constant;
    VectorType constant_body_load;
    FastVector unconstrained_body_load;
    // This process's cells, and those at the boundary, which the surface
    // loads alone visit.
    std::vector<typename DoFHandler<dim>::active_cell_iterator> owned_cells;
    std::vector<typename DoFHandler<dim>::active_cell_iterator> boundary_cells;
    // The FEValues of visit_loads().
    mutable std::unique_ptr<FEValues<dim>>     cell_values;
    mutable std::unique_ptr<FEFaceValues<dim>> face_values;
  };
} // namespace Contact

#endif
