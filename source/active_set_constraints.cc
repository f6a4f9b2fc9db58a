/* The straightforward path of 'Solver/Contact solver = constraints': every
   Newton step of the active set method for the Tresca problem is a solve on
   the whole body, with the sticking nodes held fixed as constraints and the
   matrix refactorised. It needs neither Z = K^{-1} C^T nor the Delassus
   operator, so its memory is that of K and one factor; it is the reference
   the Delassus path is tested against (tests/verification/
   contact_solver_paths) and the path for meshes where Z does not fit. */

#include <contact_problem.h>

#include <Epetra_CrsMatrix.h>

namespace Contact
{
  // @sect4{ContactProblem::velocity_for_friction_force}

  // The velocity of the step for given nodal friction forces: (5.2) with
  // the friction term C^T eta moved to the right-hand side,
  //   K w = step_rhs - C^T eta,
  // or the velocity a recent Newton step found for these forces.
  template <int dim>
  void
  ContactProblem<dim>::velocity_for_friction_force(const Vector<double> &eta,
                                                   VectorType           &w)
  {
    for (const auto &[newton_force, newton_velocity] : recent_newton_solves)
      if (newton_force == eta)
        {
          w = newton_velocity;
          return;
        }
    VectorType rhs(step_rhs);
    rhs.add(-1., friction_load(eta));
    w.reinit(locally_owned_dofs, mpi_communicator);
    solve_with_K(w, rhs);
    constraints.distribute(w);
  }


  // @sect4{zero_rows_and_columns}

  // The sticking dofs held at zero, symmetrically: their rows and columns
  // of the matrix are zeroed except the diagonal, their right-hand side
  // entries too. Each process edits the rows it owns (the columns of a
  // sticking dof lie in other processes' rows as well).
  namespace
  {
    void zero_rows_and_columns(const std::vector<bool> &fixed,
                               MatrixType              &matrix,
                               VectorType              &rhs)
    {
      // Epetra's views of the local rows: deal.II's entry iterator copies
      // a row per access and is far too slow for a pass over all rows.
      auto &epetra = const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
      for (int local_row = 0; local_row < epetra.NumMyRows(); ++local_row)
        {
          const auto row =
            static_cast<types::global_dof_index>(epetra.GRID64(local_row));
          int     length;
          double *values;
          int    *columns;
          epetra.ExtractMyRowView(local_row, length, values, columns);
          for (int k = 0; k < length; ++k)
            {
              const auto column = static_cast<types::global_dof_index>(
                epetra.ColMap().GID64(columns[k]));
              if (column != row && (fixed[row] || fixed[column]))
                values[k] = 0.;
            }
          if (fixed[row])
            rhs[row] = 0.;
        }
      rhs.compress(VectorOperation::insert);
    }
  } // namespace


  // @sect4{ContactProblem::newton_step_with_constraints}

  // One Newton step of the method of friction.h on the whole body, for the
  // linearisation of every node:
  // - a sticking node has v_p = 0; with w.n = 0 from the bilateral
  //   constraint that is w_p = 0, imposed by zeroing the rows and columns
  //   of the node's free dofs (keeping the diagonal, so K stays SPD);
  // - a slipping node carries the force (force_p + slope_p zhat.v) zhat
  //   (force_p = g_p, slope_p = 0 for the Tresca problem; the tangent of
  //   g_p(|v_p|) for the full law): a load force_p zhat and a spring
  //   slope_p zhat zhat^T added to K at the node; in 3D also the condition
  //   v.t = beta eta.t along the other tangent t = zhat turned by 90
  //   degrees, i.e. eta.t = (v.t) / beta: a spring (1 / beta) t t^T.
  // This is the system (D + beta)_FF eta_F = ... of the Delassus path
  // before the body's unknowns are eliminated, so both give the same
  // iterates. The friction force of a sticking node is then its reaction,
  // the residual of the unconstrained equations at the node projected on
  // its tangents (the residual is C^T eta there and nothing else, since
  // only the node's own column of C^T has support at it).
  template <int dim>
  void ContactProblem<dim>::newton_step_with_constraints(
    const std::vector<NodeLinearisation> &linearisation,
    Vector<double>                       &eta,
    Vector<double>                       &v)
  {
    const unsigned int n = contact_nodes.size(), m = dim - 1;
    MatrixType         matrix;
    matrix.copy_from(system_matrix);
    Vector<double>                       slip_force(n * m);
    std::vector<bool>                    stick_dof(dof_handler.n_dofs());
    std::vector<types::global_dof_index> node_dofs(dim);
    for (unsigned int p = 0; p < n; ++p)
      {
        const ContactNode<dim> &node = contact_nodes[p];
        if (linearisation[p].state == NodeState::stick)
          {
            // Its constrained (normal) dof has a trivial row and column in
            // the condensed K already, so all its dofs can be marked.
            for (const types::global_dof_index dof : node.dofs)
              stick_dof[dof] = true;
            continue;
          }
        const NodeLinearisation &slip  = linearisation[p];
        const FullMatrix<double> basis = local_basis(slip);
        for (unsigned int i = 0; i < m; ++i)
          slip_force[p * m + i] = slip.force * basis(i, 0);
        if (slip.bound == 0. || !node.locally_owned)
          continue;
        // The springs: slope zhat zhat^T (the full law; negative for a
        // weakening law) and (1 / beta) t t^T along the other tangent.
        std::array<Tensor<1, dim>, dim - 1> directions;
        for (unsigned int j = 0; j < m; ++j)
          for (unsigned int i = 0; i < m; ++i)
            directions[j] += basis(i, j) * node.tangents[i];
        FullMatrix<double> spring(dim, dim);
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            {
              spring(a, b) = slip.slope * directions[0][a] * directions[0][b];
              if (m == 2)
                spring(a, b) += directions[1][a] * directions[1][b] / slip.beta;
            }
        std::copy(node.dofs.begin(), node.dofs.end(), node_dofs.begin());
        constraints.distribute_local_to_global(spring, node_dofs, matrix);
      }
    matrix.compress(VectorOperation::add);

    VectorType rhs(step_rhs);
    rhs.add(-1., friction_load(slip_force));
    zero_rows_and_columns(stick_dof, matrix, rhs);

    // CG starts from the velocity of the last Newton step, the first one
    // from the free velocity.
    VectorType w(recent_newton_solves.empty() ?
                   velocity :
                   recent_newton_solves.back().second);
    ++solves_in_step;
    factorization->for_variant(matrix)->solve(w, rhs);
    constraints.distribute(w);
    v = tangential_velocities(w);

    VectorType residual(step_rhs);
    VectorType product(locally_owned_dofs, mpi_communicator);
    system_matrix.vmult(product, w);
    residual -= product;
    constraints.set_zero(residual);
    eta = tangential_velocities(residual);

    // On slip nodes eta is set from the linearisation, exactly as on the
    // Delassus path, rather than read back from the residual.
    for (unsigned int p = 0; p < n; ++p)
      if (linearisation[p].state == NodeState::slip)
        {
          const NodeLinearisation &slip  = linearisation[p];
          const FullMatrix<double> basis = local_basis(slip);
          // v in the local basis (zhat, t).
          std::array<double, dim - 1> local_v{};
          for (unsigned int j = 0; j < m; ++j)
            for (unsigned int i = 0; i < m; ++i)
              local_v[j] += basis(i, j) * v[p * m + i];
          for (unsigned int i = 0; i < m; ++i)
            {
              eta[p * m + i] = slip_force[p * m + i];
              if (slip.bound == 0.)
                continue;
              eta[p * m + i] += basis(i, 0) * slip.slope * local_v[0];
              if (m == 2)
                eta[p * m + i] += basis(i, 1) * local_v[1] / slip.beta;
            }
        }
      else
        for (unsigned int i = 0; i < m; ++i)
          v[p * m + i] = 0.;

    // Three: a convexification step inside the Newton method starts from
    // the iterate before a failed step and a failed step of the other
    // model.
    recent_newton_solves.emplace_back(eta, std::move(w));
    if (recent_newton_solves.size() > 3)
      recent_newton_solves.pop_front();
  }


#define INSTANTIATE(dim)                                           \
  template void ContactProblem<dim>::velocity_for_friction_force(  \
    const Vector<double> &, VectorType &);                         \
  template void ContactProblem<dim>::newton_step_with_constraints( \
    const std::vector<NodeLinearisation> &,                        \
    Vector<double> &,                                              \
    Vector<double> &);

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace Contact
