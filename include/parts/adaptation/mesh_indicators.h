/**
 * The error indicators of a mesh adaptation, and the choice of cells from
 * them (mesh_indicators.cc): shared by the pilots that adapt a mesh to the
 * whole run (mesh_adaptation.cc) and by the adaptation during a run
 * (adapt_during_run.cc). Up to three indicators per cell ('Mesh
 * adaptation/Indicators'):
 *   - Kelly's indicator of the displacement u_n: the V-norm of u at T is
 *     the error a user reads;
 *   - Kelly's indicator of the velocity w_n, the scheme's unknown, in which
 *     the waves and the slip front move;
 *   - at Gamma_3, the variation of the slip rate over the cell's face,
 *     times the square root of the face's size: the slip rate changes
 *     fastest at the slip front.
 * Each is divided by its largest value over the cells: the three have
 * different units and are compared as shares of their worst cell; a
 * cell's indicator is the largest of its shares. The default is Kelly's of
 * u alone: on the paper's scene the other two spent unknowns on the slip
 * zone that did not lower the V-error at T (bench/adapted_mesh.md).
 */
#ifndef contact_mesh_indicators_h
#define contact_mesh_indicators_h

#include <deal.II/lac/vector.h>

#include <core/parameters.h>
#include <core/postprocessor.h>
#include <parts/adaptation/mesh_adaptation_parameters.h>

#include <array>
#include <map>

namespace Contact
{
  /** The indicators of a mesh adaptation (above) at the state of one
   *  step, as shares, and the choice of cells from them: a postprocessor
   *  of the run whose mesh is adapted. A pilot takes them at many steps
   *  (mesh_adaptation.cc), a run that adapts during itself at the step of
   *  each adaptation (adapt_during_run.cc). */
  template <int dim>
  class MeshIndicators : public Postprocessor<dim>
  {
  public:
    /** `coarsest_level`: the level of the scene's coarsest cells, which
     *  bounds the coarsening and 'Max levels'; set by the run on the
     *  scene's mesh (coarsest_is_scene_mesh()) and kept by the caller for
     *  the runs after it. */
    MeshIndicators(const MeshAdaptationParameters &parameters,
                   unsigned int                   &coarsest_level);

    /** At the start of the run: the friction nodes, and the scene's
     *  coarsest level where the run starts from the scene's mesh. */
    void mesh_event(const MeshEvent event) override;

  protected:
    /** Whether this run starts from the scene's mesh (the first pilot, a
     *  run adapting during itself). */
    virtual bool coarsest_is_scene_mesh() const = 0;

    /** The friction node of each first unknown of a node of Gamma_3 (the
     *  slip rate's variation); again after each change of the mesh. */
    void index_friction_nodes();

    /** The chosen indicators of the state now, per active cell, into
     *  `fields` as the largest of what they hold and the new values. */
    void take_indicators(std::array<Vector<float>, 3> &fields) const;

    static void keep_largest(const Vector<float> &estimate,
                             Vector<float>       &field);

    /** sqrt(size of the face) (max - min of the slip rates of its friction
     *  nodes), on the cells with a face on Gamma_3; 0 elsewhere. */
    void slip_rate_variation(Vector<float> &estimate) const;

    /** Each indicator as a share of its largest value over the cells,
     *  rounded to share_resolution; a cell's is the largest of its
     *  three. */
    Vector<float> shares(const std::array<Vector<float>, 3> &fields) const;

    /** Flags the cells with the largest and the smallest indicators,
     *  within the levels allowed. */
    void flag_cells(const Vector<float> &indicator,
                    const double         refine_fraction) const;

    /** The indicators, their shares and the cells chosen (1 refined, -1
     *  coarsened), as indicators_<number>.pvtu. */
    void write_indicators(const std::array<Vector<float>, 3> &fields,
                          const Vector<float>                &indicator,
                          const unsigned int                  number,
                          const unsigned int n_digits = 5) const;

    const MeshAdaptationParameters                 &adaptation;
    unsigned int                                   &base_level;
    std::map<types::global_dof_index, unsigned int> node_of_dof;
  };
} // namespace Contact

#endif
