/**
 * The domain of a run behind one interface: Geometry<dim> builds the mesh
 * of the run on a Triangulation that the caller owns, and answers what the
 * rest of the program asks of the domain (GeometryBase): whether Gamma_3 is
 * closed, whether the body may turn into itself, what h is and how it is
 * halved, whether a point lies in the body. Each geometry (the box, the
 * shell, a gmsh mesh file) is one class in its own file, which also
 * declares, parses and checks the entries of the subsection Geometry that
 * describe it alone (GeometryParameters::register_entries()).
 * create_geometry() picks one by 'Geometry/Domain' and 'Geometry/Mesh
 * file'. No code outside source/geometry/ asks which geometry it is.
 *
 * A new geometry (doc/tutorial.md, "Adding a geometry"): its class (a
 * header and a .cc file here, with its entries; CMakeLists.txt compiles
 * every .cc file of source/geometry/), which answers the pure virtual
 * functions below, its enumerator and name in GeometryParameters::Domain
 * and GeometryParameters::domains(), its line in create_geometry(), and,
 * if it has entries of its own, their fields in GeometryParameters.
 */
#ifndef contact_geometry_h
#define contact_geometry_h

#include <deal.II/base/mpi.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/grid/tria.h>

#include <base/parameters.h>

#include <map>
#include <memory>
#include <string>

namespace Contact
{
  using namespace dealii;

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

    /** Refuses a scene on which the manufactured solution
     *  (core/manufactured_solution.h) does not solve the continuous
     *  problem or is not resolved. By default every scene: the solution is
     *  defined on the box. */
    virtual void check_manufactured_scene() const;

  protected:
    const Parameters &parameters;
  };


  template <int dim>
  class Geometry : public GeometryBase
  {
  public:
    Geometry(const Parameters &run_parameters, const MPI_Comm communicator);

    /**
     * Builds the coarse mesh on the empty `mesh`, after checking that the
     * mesh of the run fits into memory (check_memory()), and returns the
     * number of global refinements that turn it into the mesh of the run.
     */
    virtual unsigned int create_coarse_mesh(Triangulation<dim> &mesh) const = 0;

    /**
     * The mesh of the run on the empty `mesh`: the coarse mesh, turned by
     * the 'Rotation angle', refined globally, graded towards the
     * 'Refinement points'; then its boundary ids are checked against the
     * entries of 'Boundary conditions'. Collective on the communicator.
     */
    void create_mesh(Triangulation<dim> &mesh) const;

    /**
     * Whether `point` lies in the body, its boundary included. By default
     * the cells of `mesh` (this geometry's mesh) decide, to 1e-10 of a
     * cell: they are the body where its boundary is straight. A geometry
     * with a curved boundary decides by its own shape, to 1e-6 of its
     * size (a point typed with a few digits). Collective on the
     * communicator.
     */
    virtual bool contains(const Point<dim>         &point,
                          const Triangulation<dim> &mesh) const;

    /**
     * The h of the run on `mesh`, as the drivers report it: by default its
     * largest cell diameter (collective).
     */
    virtual double cell_size(const Triangulation<dim> &mesh,
                             const Mapping<dim>       &mapping) const;

  protected:
    /** Refuses a mesh of `cells` cells and `unknowns` unknowns that needs
     *  more memory per process than the machine has, naming `entry`. */
    void check_memory(const double       cells,
                      const double       unknowns,
                      const std::string &entry) const;

    const MPI_Comm communicator;
  };


  /** The geometry of 'Geometry/Mesh file' if it is set, else that of
   *  'Geometry/Domain'. */
  template <int dim>
  std::unique_ptr<const Geometry<dim>>
  create_geometry(const Parameters &parameters, const MPI_Comm communicator);

  /**
   * The same geometry, for the answers that need no mesh (GeometryBase),
   * in the dimension of the parameters. A geometry holds no more than a
   * reference to the parameters, so the code that asks builds one where it
   * asks, from the parameters it has: the checks of the parameters and the
   * drivers have no problem (and no mesh) to take one from, and the
   * postprocessors get the same answers as the problem's.
   */
  std::unique_ptr<const GeometryBase>
  create_geometry(const Parameters &parameters);
} // namespace Contact

#endif
