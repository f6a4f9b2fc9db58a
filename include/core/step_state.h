/**
 * What a time step of ContactProblem<dim> reads from the past and writes
 * for the next one, in one struct: a checkpoint stores it (one serialize),
 * and a step that is cut is retaken from a copy of it (one rollback).
 */
#ifndef contact_step_state_h
#define contact_step_state_h

#include <deal.II/lac/trilinos_vector.h>

#include <boost/serialization/version.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace Contact
{
  using namespace dealii;

  /**
   * The terms of the discrete energy identity of backward Euler, (5.7)
   * summed over the steps: kinetic + elastic energy now, plus everything
   * dissipated so far (viscous, frictional and the numerical dissipation
   * rho/2 |w_n - w_{n-1}|^2 + k^2/2 <B w_n, w_n> of the scheme) equals the
   * initial energy plus the work of the loads, plus what the transfers of
   * u and w to adapted meshes changed of the kinetic and elastic energy
   * (ContactProblem::transfer_to_adapted_mesh()).
   */
  struct EnergyBalance
  {
    double kinetic               = 0;
    double elastic               = 0;
    double initial               = 0;
    double external_work         = 0;
    double viscous_dissipation   = 0;
    double friction_dissipation  = 0;
    double numerical_dissipation = 0;
    double mesh_transfer         = 0;

    double residual() const
    {
      return kinetic + elastic + viscous_dissipation + friction_dissipation +
             numerical_dissipation - initial - external_work - mesh_transfer;
    }
    double scale() const
    {
      return std::max(
        {kinetic + elastic,
         initial + std::abs(external_work) + std::abs(mesh_transfer),
         viscous_dissipation + std::abs(friction_dissipation) +
           numerical_dissipation});
    }

    template <class Archive>
    void serialize(Archive &archive, const unsigned int version)
    {
      archive &kinetic &elastic &initial &external_work &viscous_dissipation
        &friction_dissipation &numerical_dissipation;
      // (A checkpoint of version 0 was written before meshes changed
      // during a run.)
      if (version > 0)
        archive &mesh_transfer;
    }
  };


  /**
   * The state of the discrete problem at t_n: u_n, w_n, their predecessors,
   * the load F_n, what the next step's right-hand side needs of this one
   * (M w_n and B u_n, condensed, updated by the step), and the energy
   * balance. The nodal state of Gamma_3 is the friction solver's
   * (FrictionState).
   */
  struct StepState
  {
    double       time        = 0;
    unsigned int step_number = 0;
    /** The time step k: constant, except while a step is cut ('Solver/Step
     *  cuts'); not saved (the .prm gives it). */
    double                        time_step = 0;
    TrilinosWrappers::MPI::Vector displacement;
    TrilinosWrappers::MPI::Vector velocity;
    TrilinosWrappers::MPI::Vector old_displacement;
    TrilinosWrappers::MPI::Vector old_velocity;
    TrilinosWrappers::MPI::Vector load;
    TrilinosWrappers::MPI::Vector mass_times_velocity;
    TrilinosWrappers::MPI::Vector elasticity_times_displacement;
    /** What the step solved for, F_n + (1/k) M w_{n-1} - B u_{n-1}, and
     *  ((1/k) M + A + k B) w_n from the step's products of w_n with the
     *  three matrices (condensed), for the self-checks; set by the step,
     *  not saved. */
    TrilinosWrappers::MPI::Vector step_rhs;
    TrilinosWrappers::MPI::Vector system_times_velocity;
    /** |M w_n| / k + |A w_n| + k |B w_n|: the size of the terms of
     *  system_times_velocity, the scale of its round-off. */
    double system_times_velocity_terms = 0;
    /** The last step's terms of the energy identity: the energies after
     *  it and what it dissipated and what the loads did in it (set by the
     *  step, not saved). */
    EnergyBalance step_energy;
    EnergyBalance energy;

    /** What a checkpoint keeps: what the next step reads (u, w, M w, B u)
     *  and the balance. u_{n-1}, w_{n-1} and F_n are set by the step. */
    template <class Archive>
    void serialize(Archive &archive, const unsigned int /*version*/)
    {
      archive &step_number &time;
      for (TrilinosWrappers::MPI::Vector *vector :
           {&displacement,
            &velocity,
            &mass_times_velocity,
            &elasticity_times_displacement})
        {
          std::vector<double> values(vector->begin(), vector->end());
          archive            &values;
          AssertThrow(values.size() == vector->locally_owned_size(),
                      ExcInternalError());
          std::copy(values.begin(), values.end(), vector->begin());
        }
      archive &energy;
    }
  };
} // namespace Contact

BOOST_CLASS_VERSION(Contact::EnergyBalance, 1)

#endif
