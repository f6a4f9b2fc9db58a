/* The indicators of a mesh adaptation and the choice of cells from them
 * (include/parts/adaptation/mesh_indicators.h).
 *
 * Each indicator is the largest over the steps at which it is taken, not
 * the sum: the error at T carries the errors of every step, so a front
 * that passes a cell once must refine it as much as one that stays, and a
 * sum would favour cells where something happens long over cells where it
 * happens briefly (and grow with the number of steps). */

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/error_estimator.h>

#include <base/dimensions.h>
#include <core/output_directory.h>
#include <parts/adaptation/mesh_indicators.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace Contact
{
  namespace
  {
    // What the indicators write into a run's output directory.
    const ResultFiles indicator_files("indicators_[0-9]+(\\.[0-9]+)?\\.p?vtu");

    // The shares of the indicators are compared after rounding to this
    // resolution, which makes it unlikely that the cells chosen depend on
    // the round-off of the solves (which differs between one and several
    // processes): it decides only where a share lies within round-off of a
    // rounding boundary. What guarantees one mesh for every run of a plan
    // is the plan (adapted_mesh.txt), not the rounding.
    constexpr double share_resolution = 1e-6;
  } // namespace


  // @sect3{The indicators of a step}

  template <int dim>
  MeshIndicators<dim>::MeshIndicators(
    const MeshAdaptationParameters &parameters,
    unsigned int                   &coarsest_level)
    : adaptation(parameters)
    , base_level(coarsest_level)
  {}


  template <int dim>
  void MeshIndicators<dim>::mesh_event(const MeshEvent event)
  {
    if (event != MeshEvent::initial)
      return;
    index_friction_nodes();
    const Triangulation<dim> &mesh = *this->space().triangulation;
    unsigned int coarsest          = std::numeric_limits<unsigned int>::max();
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        coarsest = std::min<unsigned int>(coarsest, cell->level());
    coarsest = Utilities::MPI::min(coarsest, this->space().mpi_communicator);
    // The first pilot, or a run adapting during itself, starts from the
    // scene's mesh.
    if (coarsest_is_scene_mesh())
      base_level = coarsest;
  }


  template <int dim>
  void MeshIndicators<dim>::index_friction_nodes()
  {
    node_of_dof.clear();
    const auto &nodes = this->friction_solver().boundary().nodes;
    for (unsigned int p = 0; p < nodes.size(); ++p)
      node_of_dof[nodes[p].dofs[0]] = p;
  }


  template <int dim>
  void MeshIndicators<dim>::take_indicators(
    std::array<Vector<float>, 3> &fields) const
  {
    const DiscreteSpace<dim> &space = this->space();
    const std::map<types::boundary_id, const Function<dim> *> no_neumann;
    Vector<float>     estimate(space.triangulation->n_active_cells());
    const VectorType *state_fields[] = {&this->state().displacement,
                                        &this->state().velocity};
    for (unsigned int field = 0; field < 2; ++field)
      if (adaptation.indicators[field])
        {
          KellyErrorEstimator<dim>::estimate(*space.mapping,
                                             space.dof_handler,
                                             space.face_quadrature,
                                             no_neumann,
                                             space.ghosted(
                                               *state_fields[field]),
                                             estimate);
          keep_largest(estimate, fields[field]);
        }
    if (adaptation.indicators[2])
      {
        slip_rate_variation(estimate);
        keep_largest(estimate, fields[2]);
      }
  }


  template <int dim>
  void MeshIndicators<dim>::keep_largest(const Vector<float> &estimate,
                                         Vector<float>       &field)
  {
    for (unsigned int c = 0; c < field.size(); ++c)
      field[c] = std::max(field[c], estimate[c]);
  }


  template <int dim>
  void MeshIndicators<dim>::slip_rate_variation(Vector<float> &estimate) const
  {
    estimate                         = 0;
    const DiscreteSpace<dim> &space  = this->space();
    const FiniteElement<dim> &fe     = space.fe;
    const auto               &gamma3 = this->friction_solver().boundary();
    const Vector<double>     &slip_velocity =
      this->friction_solver().state().slip_velocity;
    const std::vector<types::boundary_id> &ids =
      this->parameters().boundary.contact_ids;
    const std::set<types::boundary_id>   contact_ids(ids.begin(), ids.end());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              contact_ids.count(cell->face(f)->boundary_id()) != 0)
            {
              cell->get_dof_indices(dofs);
              double lowest  = std::numeric_limits<double>::max();
              double highest = -lowest;
              for (unsigned int j = 0; j < fe.n_dofs_per_face(f); ++j)
                {
                  // Other components, hanging nodes and clamped nodes
                  // are no friction nodes.
                  const auto node =
                    node_of_dof.find(dofs[fe.face_to_cell_index(j, f)]);
                  if (node == node_of_dof.end())
                    continue;
                  const double rate =
                    gamma3.nodes[node->second]
                      .tangential_vector(slip_velocity, node->second)
                      .norm();
                  lowest  = std::min(lowest, rate);
                  highest = std::max(highest, rate);
                }
              if (highest >= lowest)
                estimate[cell->active_cell_index()] =
                  std::max<float>(estimate[cell->active_cell_index()],
                                  std::sqrt(cell->face(f)->diameter()) *
                                    (highest - lowest));
            }
  }


  // @sect3{The choice of cells}

  template <int dim>
  Vector<float>
  MeshIndicators<dim>::shares(const std::array<Vector<float>, 3> &fields) const
  {
    Vector<float> result(fields[0].size());
    for (const Vector<float> &field : fields)
      {
        // An indicator not chosen stays 0.
        const double worst =
          Utilities::MPI::max(static_cast<double>(field.linfty_norm()),
                              this->space().mpi_communicator);
        if (!(worst > 0))
          continue;
        for (unsigned int c = 0; c < field.size(); ++c)
          result[c] =
            std::max<float>(result[c],
                            std::round(field[c] / worst / share_resolution) *
                              share_resolution);
      }
    return result;
  }


  template <int dim>
  void MeshIndicators<dim>::flag_cells(const Vector<float> &indicator,
                                       const double refine_fraction) const
  {
    Triangulation<dim> &mesh = *this->space().triangulation;
    auto               *distributed =
      dynamic_cast<parallel::distributed::Triangulation<dim> *>(&mesh);
    AssertThrow(distributed != nullptr,
                ExcInternalError("Mesh adaptation needs p4est's mesh."));
    parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
      *distributed, indicator, refine_fraction, adaptation.coarsen_fraction);
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (static_cast<unsigned int>(cell->level()) >=
              base_level + adaptation.max_levels)
            cell->clear_refine_flag();
          if (static_cast<unsigned int>(cell->level()) <= base_level)
            cell->clear_coarsen_flag();
        }
  }


  template <int dim>
  void MeshIndicators<dim>::write_indicators(
    const std::array<Vector<float>, 3> &fields,
    const Vector<float>                &indicator,
    const unsigned int                  number,
    const unsigned int                  n_digits) const
  {
    const DiscreteSpace<dim> &space = this->space();
    Vector<float>             chosen(indicator.size());
    for (const auto &cell : space.triangulation->active_cell_iterators())
      if (cell->is_locally_owned())
        chosen[cell->active_cell_index()] = cell->refine_flag_set()  ? 1 :
                                            cell->coarsen_flag_set() ? -1 :
                                                                       0;
    DataOut<dim> data_out;
    data_out.attach_dof_handler(space.dof_handler);
    const char *names[] = {"kelly_displacement",
                           "kelly_velocity",
                           "slip_rate_variation"};
    for (unsigned int i = 0; i < 3; ++i)
      data_out.add_data_vector(fields[i],
                               names[i],
                               DataOut<dim>::type_cell_data);
    data_out.add_data_vector(indicator,
                             "indicator",
                             DataOut<dim>::type_cell_data);
    data_out.add_data_vector(chosen,
                             "refine_1_coarsen_minus_1",
                             DataOut<dim>::type_cell_data);
    data_out.build_patches(*space.mapping);
    data_out.write_vtu_with_pvtu_record(this->parameters().output.directory +
                                          "/",
                                        "indicators",
                                        number,
                                        space.mpi_communicator,
                                        n_digits);
  }


#define INSTANTIATE(dim) template class MeshIndicators<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
