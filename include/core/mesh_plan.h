/**
 * MeshPlan: how a mesh adaptation (ContactProblem::adapt_mesh() and
 * adapt_mesh_during_run()) changed the scene's mesh, cycle by cycle: the cells
 * it refined and those it coarsened, by their CellId. The scene's mesh is built
 * as always and the cycles are then replayed (mesh_plan.cc), on one process or
 * on several: a CellId names the same cell of p4est's forest on any number of
 * processes, so every run of the plan has the same mesh.
 */
#ifndef contact_mesh_plan_h
#define contact_mesh_plan_h

#include <deal.II/grid/tria.h>

#include <functional>
#include <string>
#include <vector>

namespace Contact
{
  using namespace dealii;

  struct MeshPlan
  {
    /** Per cycle, the cells flagged for refinement and for coarsening (as
     *  CellId::to_string()), on every process. */
    std::vector<std::vector<std::string>> refined, coarsened;

    unsigned int n_cycles() const
    {
      return refined.size();
    }

    /** Flags the cells of `mesh` (each process its own) that the plan names
     *  for its cycle `cycle` and refines and coarsens them (collective). */
    template <int dim>
    void replay_cycle(const unsigned int cycle, Triangulation<dim> &mesh) const;

    /** Replays every cycle (collective). */
    template <int dim>
    void replay(Triangulation<dim> &mesh) const;

    /** The cells now flagged on `mesh`, gathered from every process, as
     *  a new cycle (collective). */
    template <int dim>
    void add_cycle_from_flags(const Triangulation<dim> &mesh);

    /** As text, one line per cycle and kind ("refine <ids>" or "coarsen
     *  <ids>"); from_text() reads it back. */
    std::string text() const;
    /** The plan for the scene's mesh with `levels` fewer global
     *  refinements (cell size times 2^levels): each cell named by its
     *  ancestor `levels` generations up, so that the mesh is this plan's
     *  mesh coarsened by `levels` levels (where a family is split between
     *  levels, the finer part is coarsened). */
    MeshPlan coarser(const unsigned int levels) const;

    /** The plan of text(); throws naming `file_name`, where the text came
     *  from, on a line it cannot read. */
    static MeshPlan from_text(const std::string &text,
                              const std::string &file_name);
  };


  /**
   * The adaptation of a run's mesh: the plan of the cycles that changed
   * the scene's mesh so far, and during the run every how many steps the
   * mesh adapts and what flags its cells (0 and empty: the mesh stays;
   * ContactProblem::adapt_mesh_during_run()).
   */
  struct MeshAdaptation
  {
    MeshPlan              plan;
    unsigned int          interval = 0;
    std::function<void()> choose_cells;
    /** A resumed run whose checkpoint was written at the end of a run, at
     *  a step after which the mesh adapts: the adaptation comes first. */
    bool due = false;
  };
} // namespace Contact

#endif
