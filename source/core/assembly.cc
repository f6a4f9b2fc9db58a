/* Matrices of the scheme (5.2)-(5.5), the factor of K, and the products
   of the state with the matrices. */

#include <deal.II/base/exceptions.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <base/dimensions.h>
#include <core/contact_problem.h>

#include <vector>

namespace Contact
{
  // @sect4{SystemMatrices::reinit}

  // The factor of K refers to K, which is reinitialised here (MUMPS frees
  // its factor through the matrix's map): it goes first.
  template <int dim>
  void SystemMatrices<dim>::reinit(const DiscreteSpace<dim> &space)
  {
    factorization.reset();
    const IndexSet        &owned    = space.locally_owned_dofs;
    const IndexSet        &relevant = space.locally_relevant_dofs;
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(space.dof_handler,
                                    dsp,
                                    space.constraints,
                                    false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               owned,
                                               space.mpi_communicator,
                                               relevant);
    for (MatrixType *matrix : {&mass, &viscosity, &elasticity, &system})
      matrix->reinit(owned, owned, dsp, space.mpi_communicator);
    for (VectorType &vector : momentum_density)
      vector.reinit(owned, space.mpi_communicator);
    angular_momentum_density.reinit(owned, space.mpi_communicator);
  }


  namespace
  {
    // The matrices and the momentum densities of one cell.
    template <int dim>
    struct CellMatrices
    {
      explicit CellMatrices(const unsigned int n_dofs)
        : mass(n_dofs, n_dofs)
        , viscosity(n_dofs, n_dofs)
        , elasticity(n_dofs, n_dofs)
        , momentum(dim, Vector<double>(n_dofs))
        , angular_momentum(n_dofs)
      {}

      void clear()
      {
        mass       = 0;
        viscosity  = 0;
        elasticity = 0;
        for (Vector<double> &vector : momentum)
          vector = 0;
        angular_momentum = 0;
      }

      FullMatrix<double>          mass;
      FullMatrix<double>          viscosity;
      FullMatrix<double>          elasticity;
      std::vector<Vector<double>> momentum;
      Vector<double>              angular_momentum;
    };


    // The mass (rho w, v) and the momentum densities of a cell, with the
    // values of `mass_values` (whose rule may be the lumping one).
    template <int dim>
    void add_cell_mass(const FEValues<dim> &mass_values,
                       const double         rho,
                       CellMatrices<dim>   &cell)
    {
      const FEValuesExtractors::Vector displacements(0);
      const unsigned int               n_dofs = mass_values.dofs_per_cell;
      std::vector<Tensor<1, dim>>      phi(n_dofs);
      for (const unsigned int q : mass_values.quadrature_point_indices())
        {
          for (unsigned int i = 0; i < n_dofs; ++i)
            phi[i] = mass_values[displacements].value(i, q);
          const double      JxW = mass_values.JxW(q);
          const Point<dim> &x   = mass_values.quadrature_point(q);
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              for (unsigned int d = 0; d < dim; ++d)
                cell.momentum[d](i) += rho * phi[i][d] * JxW;
              cell.angular_momentum(i) +=
                rho * (x[0] * phi[i][1] - x[1] * phi[i][0]) * JxW;
              for (unsigned int j = 0; j < n_dofs; ++j)
                cell.mass(i, j) += rho * phi[i] * phi[j] * JxW;
            }
        }
    }


    // The viscosity (A eps(w), eps(v)) and the elasticity (B eps(u),
    // eps(v)) of a cell.
    template <int dim>
    void add_cell_stiffness(const FEValues<dim>      &fe_values,
                            const MaterialParameters &material,
                            CellMatrices<dim>        &cell)
    {
      const FEValuesExtractors::Vector     displacements(0);
      const double                         two_G  = material.two_G();
      const double                         lambda = material.lambda(dim);
      const unsigned int                   n_dofs = fe_values.dofs_per_cell;
      std::vector<SymmetricTensor<2, dim>> eps(n_dofs);
      std::vector<double>                  div(n_dofs);
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              eps[i] = fe_values[displacements].symmetric_gradient(i, q);
              div[i] = trace(eps[i]);
            }
          const double JxW = fe_values.JxW(q);
          for (unsigned int i = 0; i < n_dofs; ++i)
            for (unsigned int j = 0; j < n_dofs; ++j)
              {
                const double div_div = div[i] * div[j];
                const double eps_eps = eps[i] * eps[j];
                cell.viscosity(i, j) += (material.viscosity_mu1 * div_div +
                                         material.viscosity_mu2 * eps_eps) *
                                        JxW;
                cell.elasticity(i, j) +=
                  (lambda * div_div + two_G * eps_eps) * JxW;
              }
        }
    }


    // M x for x in V_h, with M condensed: the rows of constrained dofs
    // carry only a diagonal entry that has nothing to do with the form, so
    // they are zeroed. (For the unconstrained rows, condensed M times x is
    // P^T M x, and y . P^T M x = y^T M x for y, x in V_h because
    // x = P x_free.)
    void condensed_product(const MatrixType                &matrix,
                           const VectorType                &x,
                           const AffineConstraints<double> &constraints,
                           VectorType                      &product)
    {
      matrix.vmult(product, x);
      constraints.set_zero(product);
    }
  } // namespace


  // @sect4{SystemMatrices::assemble}

  // The three bilinear forms of (5.2) on V_h: the mass (rho w, v), the
  // viscosity (A eps(w), eps(v)) with A tau = mu_1 tr(tau) I + mu_2 tau and
  // the elasticity (B eps(u), eps(v)) with
  // B tau = lambda tr(tau) I + 2G tau, lambda = E kappa/((1+kappa)(1-2kappa)),
  // 2G = E/(1+kappa) (the paper's formula, plane strain in 2D; plane
  // stress replaces lambda by 2 lambda G/(lambda + 2G)). A lumped mass
  // matrix comes from the Gauss-Lobatto rule, whose points are the nodes of
  // Q_p: M is then diagonal.
  template <int dim>
  void SystemMatrices<dim>::assemble(const DiscreteSpace<dim> &space,
                                     const MaterialParameters &material)
  {
    FEValues<dim>                        fe_values(*space.mapping,
                            space.fe,
                            space.quadrature,
                            update_gradients | update_JxW_values);
    FEValues<dim>                        mass_values(*space.mapping,
                              space.fe,
                              space.mass_quadrature,
                              update_values | update_quadrature_points |
                                update_JxW_values);
    const unsigned int                   n_dofs = space.fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dof_indices(n_dofs);
    const AffineConstraints<double>     &constraints = space.constraints;
    CellMatrices<dim>                    local(n_dofs);
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          mass_values.reinit(cell);
          local.clear();
          add_cell_mass(mass_values, material.density, local);
          add_cell_stiffness(fe_values, material, local);
          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(local.mass, dof_indices, mass);
          constraints.distribute_local_to_global(local.viscosity,
                                                 dof_indices,
                                                 viscosity);
          constraints.distribute_local_to_global(local.elasticity,
                                                 dof_indices,
                                                 elasticity);
          for (unsigned int d = 0; d < dim; ++d)
            momentum_density[d].add(dof_indices, local.momentum[d]);
          angular_momentum_density.add(dof_indices, local.angular_momentum);
        }
    for (VectorType &vector : momentum_density)
      vector.compress(VectorOperation::add);
    angular_momentum_density.compress(VectorOperation::add);
    for (MatrixType *matrix : {&mass, &viscosity, &elasticity})
      matrix->compress(VectorOperation::add);
  }


  // @sect4{SystemMatrices::factorize}

  // The constant matrix of a step follows from backward Euler, (5.2) with
  // (5.5):
  //   K w_n = F_n + (1/k) M w_{n-1} - B u_{n-1} - C^T eta_n,
  //   K = (1/k) M + A + k B.
  // K does not change while k is constant, so it is factorised once per
  // mesh and every later solve is a forward/back substitution.
  template <int dim>
  void SystemMatrices<dim>::factorize(const double              k,
                                      const SolverParameters   &solver,
                                      const DiscreteSpace<dim> &space,
                                      TimerOutput              &timer)
  {
    system.copy_from(mass);
    system *= 1. / k;
    system.add(1., viscosity);
    system.add(k, elasticity);

    TimerOutput::Scope t(timer, "Factorization");
    // The near null space for a solver that needs it (an algebraic
    // multigrid); a direct solver ignores it.
    std::vector<std::vector<bool>> constant_modes;
    DoFTools::extract_constant_modes(space.dof_handler,
                                     ComponentMask(),
                                     constant_modes);
    factorization =
      Factorization::create(solver.linear_solver, system, constant_modes);
  }


  // @sect4{SystemMatrices::velocity_products}

  // M w_n, A w_n and B w_n: what the energy balance and the next step's
  // right-hand side need of the new velocity. (The program runs one thread
  // per process, main.cc, so the three products are taken one after the
  // other.)
  template <int dim>
  VelocityProducts SystemMatrices<dim>::velocity_products(
    const VectorType                &w,
    const AffineConstraints<double> &constraints) const
  {
    VelocityProducts products{w, w, w};
    condensed_product(mass, w, constraints, products.mass);
    condensed_product(viscosity, w, constraints, products.viscosity);
    condensed_product(elasticity, w, constraints, products.elasticity);
    return products;
  }


  // @sect4{SystemMatrices::update_state_products}

  // Of the initial values, and of the fields carried to a new mesh.
  template <int dim>
  void SystemMatrices<dim>::update_state_products(
    StepState                       &state,
    const AffineConstraints<double> &constraints) const
  {
    state.mass_times_velocity.reinit(state.velocity);
    state.elasticity_times_displacement.reinit(state.displacement);
    condensed_product(mass,
                      state.velocity,
                      constraints,
                      state.mass_times_velocity);
    condensed_product(elasticity,
                      state.displacement,
                      constraints,
                      state.elasticity_times_displacement);
    state.energy.kinetic = 0.5 * (state.mass_times_velocity * state.velocity);
    state.energy.elastic =
      0.5 * (state.elasticity_times_displacement * state.displacement);
  }


#define INSTANTIATE(dim) template struct SystemMatrices<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
