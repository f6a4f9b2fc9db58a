/* The displacement at the 'Output/Probe points': columns of
   time_series.csv and quantities at T that an error estimate compares. */

#include <deal.II/base/exceptions.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <core/postprocessor.h>
#include <core/quantity.h>
#include <core/geometry.h>

#include <limits>
#include <memory>
#include <sstream>

namespace Contact
{
  template <int dim>
  class Probes : public Postprocessor<dim>
  {
  public:
    // At the start, and the new mesh's cells around the points after a
    // change of the mesh.
    void mesh_event(const MeshEvent event) override
    {
      if (event != MeshEvent::before_change)
        locate_probes();
    }
    void add_columns(TimeSeriesRow &row) const override;
    void finish(RunSummary &summary) override;

  private:
    void locate_probes();
    using Probe =
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>;
    unsigned int probe_near_curved_boundary(const Point<dim> &point,
                                            Probe            &probe) const;
    std::vector<Tensor<1, dim>> probe_displacements() const;

    // A probe is the cell around an 'Output/Probe points' entry and the
    // point in its reference cell; of the processes that own a cell around
    // the point, the first evaluates it, the others keep an invalid cell.
    std::vector<Probe> probes;
  };


  // @sect4{Probes::locate_probes}

  template <int dim>
  void Probes<dim>::locate_probes()
  {
    const DiscreteSpace<dim> &space        = this->space();
    const unsigned int        this_process = Utilities::MPI::this_mpi_process(
                         this->mpi_communicator()),
                       n_processes = Utilities::MPI::n_mpi_processes(
                         this->mpi_communicator());
    const Geometry<dim> &geometry = this->problem().get_geometry();
    probes.clear();
    for (const auto &coordinates : this->parameters().output.probe_points)
      {
        Point<dim> point;
        for (unsigned int d = 0; d < dim; ++d)
          point[d] = coordinates[d];
        // The cells of this process around the point (a point outside the
        // mesh gives none, or an exception, depending on the triangulation).
        Probe probe;
        try
          {
            for (const auto &candidate :
                 GridTools::find_all_active_cells_around_point(
                   *space.mapping, space.dof_handler, point))
              if (candidate.first->is_locally_owned())
                {
                  probe = candidate;
                  break;
                }
          }
        catch (const ExceptionBase &)
          {}
        unsigned int evaluating_process =
          Utilities::MPI::min(probe.first.state() == IteratorState::valid ?
                                this_process :
                                n_processes,
                              this->mpi_communicator());
        std::ostringstream text;
        text << point;
        if (evaluating_process == n_processes &&
            geometry.has_curved_boundary() &&
            geometry.contains(point, *space.triangulation))
          evaluating_process = probe_near_curved_boundary(point, probe);
        AssertThrow(evaluating_process < n_processes,
                    ExcMessage("Entry '" + Entry::probe_points +
                               "': the point " + text.str() +
                               " is not in the mesh; allowed are points of "
                               "the body."));
        if (evaluating_process != this_process)
          probe.first = typename DoFHandler<dim>::active_cell_iterator();
        probes.push_back(probe);
      }
  }


  // @sect4{Probes::probe_near_curved_boundary}

  // A point of a body with a curved boundary (Geometry::contains()) that
  // no cell contains, because the cells' boundary is a polygon or a
  // polynomial through points of the curve, not the curve itself: the
  // nearest point of the cell around it (its reference coordinates, up to
  // half a cell outside, moved onto the reference cell). Of all processes
  // the one with the nearest cell evaluates it (the lowest rank on ties);
  // the return value is that process, or the number of processes if no
  // cell is near.
  template <int dim>
  unsigned int Probes<dim>::probe_near_curved_boundary(const Point<dim> &point,
                                                       Probe &probe) const
  {
    const DiscreteSpace<dim> &space = this->space();
    const unsigned int        n_processes =
      Utilities::MPI::n_mpi_processes(this->mpi_communicator());
    double outside = std::numeric_limits<double>::max();
    try
      {
        for (const auto &candidate :
             GridTools::find_all_active_cells_around_point(
               *space.mapping, space.dof_handler, point, 0.5))
          {
            const Point<dim> inside =
              GeometryInfo<dim>::project_to_unit_cell(candidate.second);
            if (candidate.first->is_locally_owned() &&
                inside.distance(candidate.second) < outside)
              {
                outside = inside.distance(candidate.second);
                probe   = {candidate.first, inside};
              }
          }
      }
    catch (const ExceptionBase &)
      {}
    const double nearest =
      Utilities::MPI::min(outside, this->mpi_communicator());
    const unsigned int this_process =
      Utilities::MPI::this_mpi_process(this->mpi_communicator());
    return Utilities::MPI::min(nearest < std::numeric_limits<double>::max() &&
                                   outside == nearest ?
                                 this_process :
                                 n_processes,
                               this->mpi_communicator());
  }


  // @sect4{Probes::probe_displacements}

  // The displacement at each probe, on every process (collective).
  template <int dim>
  std::vector<Tensor<1, dim>> Probes<dim>::probe_displacements() const
  {
    const DiscreteSpace<dim> &space = this->space();
    const VectorType u_ghosted      = space.ghosted(this->state().displacement);
    std::vector<Tensor<1, dim>> displacements;
    for (const auto &[cell, reference_point] : probes)
      {
        Tensor<1, dim> u;
        if (cell.state() == IteratorState::valid)
          {
            FEValues<dim>               fe_values(*space.mapping,
                                    space.fe,
                                    Quadrature<dim>(reference_point),
                                    update_values);
            std::vector<Vector<double>> values(1, Vector<double>(dim));
            fe_values.reinit(cell);
            fe_values.get_function_values(u_ghosted, values);
            for (unsigned int d = 0; d < dim; ++d)
              u[d] = values[0][d];
          }
        displacements.push_back(
          Utilities::MPI::sum(u, this->mpi_communicator()));
      }
    return displacements;
  }


  // @sect4{Probes::add_columns}

  // Collective: every process takes part, the first one writes.
  template <int dim>
  void Probes<dim>::add_columns(TimeSeriesRow &row) const
  {
    if (probes.empty())
      return;
    const std::vector<Tensor<1, dim>> values = probe_displacements();
    for (unsigned int i = 0; i < probes.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        row.add("probe" + std::to_string(i + 1) + "_u_" + "xyz"[d],
                values[i][d]);
  }


  // @sect4{Probes::finish}

  // The probes' displacements at T, first among the final quantities (the
  // order of the rows of an error estimate).
  template <int dim>
  void Probes<dim>::finish(RunSummary &summary)
  {
    std::vector<std::pair<std::string, double>> quantities;
    const std::vector<Tensor<1, dim>>           values = probe_displacements();
    for (unsigned int i = 0; i < probes.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        quantities.emplace_back(
          Quantity{Quantity::Kind::probe_displacement, i, d}.name(),
          values[i][d]);
    summary.final_quantities.insert(summary.final_quantities.begin(),
                                    quantities.begin(),
                                    quantities.end());
  }


  namespace
  {
    const PostprocessorRegistration<Probes> registration("probes", 40);
  }
} // namespace Contact
