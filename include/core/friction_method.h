/**
 * The methods that solve the friction problem of a step on Gamma_3, chosen
 * by 'Solver/Friction method': a kind of part (base/parts.h). The core's
 * own method is the convexification of the paper's section 6
 * (convexification.cc); other methods are parts of their own that register
 * themselves, and the entry's Selection, default and help text are made of
 * the registered methods, by rank.
 */
#ifndef contact_friction_method_h
#define contact_friction_method_h

#include <deal.II/base/mpi.h>

#include <base/dimensions.h>
#include <base/parts.h>
#include <core/friction_solver.h>

#include <string>

namespace Contact
{
  using namespace dealii;

  /**
   * What a method needs of the step it solves: the run's parameters and
   * friction law, Gamma_3 with the law's nodal weights m_p (times the
   * bound's scale) and the parameters c_p of the active set method, the
   * convexity limit of a step's problem (FrictionSolver::reinit()), the
   * path between the body and Gamma_3, and the friction state, the
   * previous step's on entry and the step's solution on return.
   */
  template <int dim>
  struct FrictionStep
  {
    const Parameters           &parameters;
    const FrictionLaw          &law;
    const ContactBoundary<dim> &gamma3;
    const Vector<double>       &law_weights;
    const Vector<double>       &active_set_parameter;
    const double                convexity_limit;
    ContactPath<dim>           &path;
    FrictionState              &state;
    const StepLabel            &label;
    /** max |w_{n-1}|: the size of the body's velocities in the step. */
    const double velocity_scale;
    /** FrictionSolver::law_residual_allowance() of the step, set by the
     *  method that solved it (0 where it solves the law itself). */
    double &law_residual_allowance;

    /** Every process solves the same problem on Gamma_3 from the same
     *  summed data, so its decisions agree; they are reduced anyway, so
     *  that no process can leave a loop that another one stays in. */
    bool all_processes(const bool condition) const
    {
      return Utilities::MPI::min(condition ? 1 : 0, gamma3.mpi_communicator) ==
             1;
    }
  };


  /**
   * A method for the friction problem of a step: given the step (its path
   * has begun the step), it sets the step's friction forces, slip
   * velocities and stick/slip states, or throws ExcStepNotConverged with a
   * diagnostic. `fallback` is the core's method, the convexification, which
   * a method may leave a step to.
   */
  template <int dim>
  class FrictionMethod
  {
  public:
    virtual ~FrictionMethod() = default;

    virtual void solve(FrictionStep<dim>   &step,
                       FrictionMethod<dim> &fallback,
                       StepStatistics      &statistics) = 0;
  };


  /** The kind of the friction methods (base/parts.h), registered once per
   *  compiled dimension. */
  template <int dim>
  using FrictionMethodRegistry = PartRegistry<FrictionMethod<dim>>;

  /** The registry whose names the entry lists: each method registers the
   *  same name in every compiled dimension. */
  using FrictionMethodNames =
    FrictionMethodRegistry<is_compiled_dimension(2) ? 2 : 3>;


  /**
   * The convexification of the paper's section 6, the core's method
   * (convexification.cc): a fixed point of Tresca problems, with Anderson
   * acceleration.
   */
  template <int dim>
  class Convexification : public FrictionMethod<dim>
  {
  public:
    void solve(FrictionStep<dim>   &step,
               FrictionMethod<dim> &fallback,
               StepStatistics      &statistics) override;
  };


  /** The messages name a part of this kind a friction method. */
  template <>
  inline std::string PartRegistry<FrictionMethod<2>>::noun()
  {
    return "friction method";
  }

  template <>
  inline std::string PartRegistry<FrictionMethod<3>>::noun()
  {
    return "friction method";
  }
} // namespace Contact

#endif
