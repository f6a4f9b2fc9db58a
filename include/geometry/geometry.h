/**
 * The domain of a run behind one interface: Geometry<dim> builds the mesh
 * of the run on a Triangulation that the caller owns, and answers what the
 * rest of the program asks of the domain (GeometryBase,
 * base/geometry_base.h): whether Gamma_3 is closed, whether the body may
 * turn into itself, what h is and how it is halved, whether a point lies
 * in the body. Each geometry (the box, the shell, a gmsh mesh file) is one
 * class in its own file, which also declares, parses and checks the
 * entries of the subsection Geometry that describe it alone
 * (GeometryParameters::register_entries()). create_geometry() picks one by
 * 'Geometry/Domain' and 'Geometry/Mesh file'; geometry.cc registers it as
 * the factory of base/'s create_geometry(parameters) too. No code outside
 * source/geometry/ asks which geometry it is.
 *
 * A new geometry (doc/tutorial.md, "Adding a geometry"): its class (a
 * header and a .cc file here, with its entries; CMakeLists.txt compiles
 * every .cc file of source/geometry/), which answers the pure virtual
 * functions of GeometryBase and create_coarse_mesh() below, its enumerator and
 * name in GeometryParameters::Domain and GeometryParameters::domains(), its
 * line in create_geometry(), and, if it has entries of its own, their fields in
 * GeometryParameters.
 */
#ifndef contact_geometry_h
#define contact_geometry_h

#include <deal.II/base/mpi.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/grid/tria.h>

#include <base/geometry_base.h>
#include <base/parameters.h>

#include <memory>
#include <string>

namespace Contact
{
  using namespace dealii;

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
   *  'Geometry/Domain': made once by the problem of a run, which keeps it
   *  (ContactProblem::get_geometry()). */
  template <int dim>
  std::unique_ptr<const Geometry<dim>>
  create_geometry(const Parameters &parameters, const MPI_Comm communicator);
} // namespace Contact

#endif
