/**
 * What the rest of the program asks of the domain without a mesh, the same
 * in 2D and 3D (GeometryBase), and the one way to get it from the
 * parameters (create_geometry()). The answers are the geometry's
 * (core/geometry.h): its classes derive from GeometryBase, and each
 * registers itself as a part of the kind GeometryBaseRegistry too, so that
 * base/ (the checks of the parameters, the Selection 'Geometry/Domain')
 * knows the geometries without including them.
 *
 * A run asks the geometry of its problem (ContactProblem::get_geometry());
 * the checks of the parameters and the drivers before a run, which have no
 * problem, make one with create_geometry().
 */
#ifndef contact_geometry_base_h
#define contact_geometry_base_h

#include <core/parameters.h>
#include <base/parts.h>

#include <map>
#include <memory>
#include <string>

namespace Contact
{
  /**
   * What a geometry answers from its entries alone, the same in 2D and 3D
   * and before any mesh exists: the kind of its domain (the questions that
   * the postprocessors, the self-checks and the report of the mesh ask)
   * and how its mesh size h is set and halved (the questions of the
   * drivers and of the checks of the parameters). The answers about h have
   * defaults for a geometry whose mesh is its coarse mesh refined 'Mesh
   * refinements' times (the shell, a mesh file); the box overrides them.
   */
  class GeometryBase
  {
  public:
    explicit GeometryBase(const Parameters &run_parameters);
    virtual ~GeometryBase() = default;

    /** Whether the cells only approximate a curved boundary: then the
     *  mapping's degree decides how well (the report of the mesh warns
     *  below the element's degree), and a point of the body may lie
     *  outside every cell (Geometry::contains()). */
    virtual bool has_curved_boundary() const = 0;

    /** Whether Gamma_3 is closed around the z-axis: its slip zone is then
     *  an arc about the axis, and it has no start x (slip_zone()). */
    virtual bool gamma3_is_closed() const = 0;

    /** Whether the body is symmetric about the z-axis, so that the rigid
     *  rotation about it keeps the body and its boundary: without a clamp
     *  the body may turn, and the balance of moments about the axis is a
     *  self-check (SelfChecks). */
    virtual bool is_symmetric_about_z_axis() const = 0;

    /** The entries ('Section/Entry' -> value) that give this geometry's
     *  mesh with h times 2^-h_halvings (negative: coarser), nested in or
     *  around the scene's: a scene variant's mesh. */
    virtual std::map<std::string, std::string>
    entries_with_h_halved(const int h_halvings) const;

    /** The mesh size as a convergence study's level names it, e.g.
     *  "mesh refinements = 2". */
    virtual std::string mesh_size_text() const;

    /** Refuses, naming the entry, a mesh without the nested meshes of 2h
     *  and 4h that the coarse runs of an error estimate need; `mode` names
     *  the entry that asks for the estimate. */
    virtual void check_coarse_runs(const std::string &mode) const;

    /** What keeps the mesh of 2^doublings h from being nested around this
     *  one, as a reason in a sentence, e.g. "'Geometry/Mesh refinements'
     *  needs to be at least 3"; empty where nothing does. */
    virtual std::string coarsening_obstacle(const unsigned int doublings) const;

    /** Refuses a scene on which the manufactured solution (the exact
     *  solution of 'Verification/Manufactured solution') does not solve
     *  the continuous problem or is not resolved; the manufactured
     *  solution asks it (ExactSolution::check_scene()). By default every
     *  scene: the solution is defined on the box. */
    virtual void check_manufactured_scene() const;

  protected:
    /** The subsections of the parameters that a geometry reads. */
    struct Entries
    {
      GeometryParameters geometry;
      BoundaryParameters boundary;
    };

    /** A copy, not a reference: a geometry may outlive the Parameters it
     *  was made from (the problem keeps its own). */
    const Entries parameters;
  };


  /** The geometries as base/ knows them (base/parts.h): the Selection
   *  'Geometry/Domain' and its help text are made of their names and
   *  descriptions, by rank; each is made from the parameters in their
   *  dimension, on one process. a geometry's GeometryRegistration
   *  registers every geometry here. */
  using GeometryBaseRegistry =
    PartRegistry<const GeometryBase, const Parameters &>;

  /** The geometry of `parameters`, in their dimension, for the answers
   *  that need no mesh. */
  std::unique_ptr<const GeometryBase>
  create_geometry(const Parameters &parameters);


  /** The messages name a part of this kind a geometry. */
  template <>
  inline std::string
  PartRegistry<const GeometryBase, const Parameters &>::noun()
  {
    return "geometry";
  }
} // namespace Contact

#endif
