/**
 * The domain of a run behind one interface: Geometry<dim> builds the mesh
 * of the run on a Triangulation that the caller owns. Each geometry (the
 * box, the shell, a gmsh mesh file) is one class in its own file, which
 * also declares and parses the entries of the subsection Geometry that
 * describe it alone (GeometryParameters::register_entries()).
 * create_geometry() picks one by 'Geometry/Domain' and 'Geometry/Mesh
 * file'.
 *
 * A new geometry: its class (a header and a .cc file here, with its
 * entries; CMakeLists.txt compiles every .cc file of source/geometry/), its
 * enumerator and name in GeometryParameters::Domain and
 * GeometryParameters::domains(), its line in create_geometry(), and, if it
 * has entries of its own, their fields in GeometryParameters (where the
 * rest of the program reads them).
 */
#ifndef contact_geometry_h
#define contact_geometry_h

#include <deal.II/base/mpi.h>

#include <deal.II/grid/tria.h>

#include <base/parameters.h>

#include <memory>
#include <string>

namespace Contact
{
  using namespace dealii;

  template <int dim>
  class Geometry
  {
  public:
    Geometry(const Parameters &run_parameters, const MPI_Comm communicator);
    virtual ~Geometry() = default;

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

  protected:
    /** Refuses a mesh of `cells` cells and `unknowns` unknowns that needs
     *  more memory per process than the machine has, naming `entry`. */
    void check_memory(const double       cells,
                      const double       unknowns,
                      const std::string &entry) const;

    const Parameters &parameters;
    const MPI_Comm    communicator;
  };


  /** The geometry of 'Geometry/Mesh file' if it is set, else that of
   *  'Geometry/Domain'. */
  template <int dim>
  std::unique_ptr<const Geometry<dim>>
  create_geometry(const Parameters &parameters, const MPI_Comm communicator);
} // namespace Contact

#endif
