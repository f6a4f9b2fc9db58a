/**
 * The domain of a run behind one interface: Geometry<dim> builds the mesh
 * of the run on a Triangulation that the caller owns, and answers what the
 * rest of the program asks of the domain (GeometryBase,
 * core/geometry_base.h): whether Gamma_3 is closed, whether the body may
 * turn into itself, what h is and how it is halved, whether a point lies
 * in the body. Each geometry (the box, the shell, a gmsh mesh file) is one
 * class in its own file, which also declares, parses and checks the
 * entries of the subsection Geometry that describe it alone (PartEntries,
 * base/parts.h). The box and the shell are parts of the program
 * (GeometryRegistration): 'Geometry/Domain' is the Selection of their
 * names. A geometry that an entry of its own asks for (a mesh file)
 * replaces the Domain: a part of the kind ReplacingGeometryRegistry
 * (create_geometry()).
 * No code outside the geometries' own files asks which geometry it is.
 *
 * A new geometry (doc/tutorial.md, "Adding a geometry") is one file: its
 * class, which answers the pure virtual functions of GeometryBase and
 * create_coarse_mesh() below, its entries if it has any, and the one
 * statement that registers it; tests/verification/second_geometry.cc is
 * one, defined in the test alone.
 */
#ifndef contact_geometry_h
#define contact_geometry_h

#include <deal.II/base/mpi.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/grid/tria.h>

#include <base/dimensions.h>
#include <core/geometry_base.h>
#include <core/parameters.h>
#include <base/parts.h>

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


  /**
   * A geometry that an entry of its own chooses in place of
   * 'Geometry/Domain' (a mesh file): a part of the kind
   * ReplacingGeometryRegistry, whose create() gives nullptr where the
   * parameters do not ask for it.
   */
  template <int dim>
  class ReplacingGeometry : public Geometry<dim>
  {
  public:
    using Geometry<dim>::Geometry;
  };

  /** The kind of the geometries that replace the Domain (base/parts.h),
   *  registered for every compiled dimension; the first whose create()
   *  gives one is the run's. */
  template <int dim>
  using ReplacingGeometryRegistry =
    PartRegistry<const ReplacingGeometry<dim>, const Parameters &, MPI_Comm>;

  /** The geometry that replaces the Domain if a part of
   *  ReplacingGeometryRegistry makes one, else that of 'Geometry/Domain':
   *  made once by the problem of a run, which keeps it
   *  (ContactProblem::get_geometry()). */
  template <int dim>
  std::unique_ptr<const Geometry<dim>>
  create_geometry(const Parameters &parameters, const MPI_Comm communicator);

  /** The same in the dimension of `parameters`, on one process (it builds
   *  no mesh): what base/'s create_geometry(parameters) makes for the
   *  answers without a mesh. */
  std::unique_ptr<const GeometryBase>
  create_geometry_on_one_process(const Parameters &parameters);


  /** The kind of the geometries of dimension dim (base/parts.h): made
   *  from the parameters of a run on its communicator. */
  template <int dim>
  using GeometryRegistry =
    PartRegistry<const Geometry<dim>, const Parameters &, MPI_Comm>;

  /**
   * The registration of a geometry, one statement in its file:
   *   const GeometryRegistration<Class> registration(name, rank,
   *                                                  description, entries);
   * Class<dim> derives from Geometry<dim> and is made from (parameters,
   * communicator); it reads its own entries as
   * parameters.part<Value>(name). `name` is its value of
   * 'Geometry/Domain', `rank` its place in the Selection, `description`
   * what the entry's help text says of it; `entries` its own entries of
   * the subsection Geometry, if it has any. It is registered in every
   * compiled dimension, and as a geometry of base/ (GeometryBaseRegistry),
   * whose answers without a mesh are those of create_geometry().
   */
  template <template <int> class Class>
  struct GeometryRegistration
  {
    GeometryRegistration(const std::string &name,
                         const unsigned int rank,
                         const std::string &description,
                         const PartEntries &entries = {})
    {
#define INSTANTIATE(dim)                                                       \
  GeometryRegistry<dim>::add(                                                  \
    {name,                                                                     \
     description,                                                              \
     rank,                                                                     \
     entries,                                                                  \
     [](const Parameters &parameters,                                          \
        const MPI_Comm communicator) -> std::unique_ptr<const Geometry<dim>> { \
       return std::make_unique<const Class<dim>>(parameters, communicator);    \
     }});
      CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
      GeometryBaseRegistry::add(
        {name, description, rank, {}, &create_geometry_on_one_process});
    }
  };
} // namespace Contact

#endif
