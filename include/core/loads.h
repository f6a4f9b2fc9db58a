/**
 * Loads<dim>: the data of the problem that are functions of x and t: the
 * body force f_0, the tractions f_2 on Gamma_2 and the initial values, as
 * muparser expressions of the .prm, or those of an exact solution that a
 * part provides (ExactSolution; and its tangential load f_3 on Gamma_3). It
 * assembles F_n of (5.2) and tests the loads with fields without the assembled
 * vector (the power of the loads in the self-checks). loads.cc.
 */
#ifndef contact_loads_h
#define contact_loads_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/vector.h>

#include <core/parameters.h>
#include <core/discrete_space.h>
#include <core/friction_solver.h>
#include <core/geometry_base.h>
#include <base/parts.h>

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


  /**
   * A solution of the problem known in closed form, with the data that
   * make it one: the body force f_0, the stress sigma whose traction
   * sigma n acts on every side that is neither clamped nor in contact, and
   * a tangential load f_3 on Gamma_3 (a manufactured solution,
   * doc/verification.md). Where a run has one, its data and its initial
   * values replace those of the .prm, and the postprocessors may measure
   * the errors against it (Postprocessor::exact_solution()).
   */
  template <int dim>
  class ExactSolution
  {
  public:
    virtual ~ExactSolution() = default;

    virtual Tensor<1, dim> displacement(const Point<dim> &p,
                                        const double      t) const = 0;
    virtual Tensor<1, dim> velocity(const Point<dim> &p,
                                    const double      t) const     = 0;
    virtual SymmetricTensor<2, dim>
    displacement_strain(const Point<dim> &p, const double t) const   = 0;
    virtual SymmetricTensor<2, dim> stress(const Point<dim> &p,
                                           const double      t) const     = 0;
    virtual Tensor<1, dim>          body_force(const Point<dim> &p,
                                               const double      t) const = 0;
    /** The tangential load f_3 at a point of Gamma_3 with outward
     *  normal n. */
    virtual Tensor<1, dim> contact_load(const Point<dim>     &p,
                                        const Tensor<1, dim> &normal,
                                        const double          t) const = 0;

    /** Refuses a scene on which it is not a solution, or not resolved:
     *  called once the mesh of the run is built. */
    virtual void check_scene(const GeometryBase &geometry) const = 0;

    /** u or w as a deal.II Function, for interpolating u_0 and u_1. */
    class Field : public Function<dim>
    {
    public:
      Field(const ExactSolution &exact, const bool velocity)
        : Function<dim>(dim)
        , solution(exact)
        , is_velocity(velocity)
      {}

      double value(const Point<dim>  &p,
                   const unsigned int component) const override
      {
        const double t = this->get_time();
        return (is_velocity ? solution.velocity(p, t) :
                              solution.displacement(p, t))[component];
      }

    private:
      const ExactSolution &solution;
      const bool           is_velocity;
    };
  };


  /** The kind of the exact solutions (base/parts.h), registered for every
   *  compiled dimension: each part's create() gives nullptr where the
   *  parameters do not ask for it, and the loads of a run take the first
   *  that gives one. */
  template <int dim>
  using ExactSolutionParts =
    PartRegistry<const ExactSolution<dim>, const Parameters &>;


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

    /** After the set-up of the space and of Gamma_3 (whose nodes carry an
     *  exact solution's f_3): a constant body force is assembled. */
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

    /** u_0 and w_0 = u_1 of the .prm or of the exact solution. */
    const Function<dim> &initial_displacement() const;
    const Function<dim> &initial_velocity() const;

    /** The exact solution, or nullptr without one. */
    const ExactSolution<dim> *exact_solution() const;

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
    // The exact solution that replaces the load data of the .prm, if a part
    // provides one for the parameters.
    const std::unique_ptr<const ExactSolution<dim>> exact;
    const DiscreteSpace<dim>                       &space;
    const ContactBoundary<dim>                     *gamma3 = nullptr;
    TimerOutput                                    &computing_timer;

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
