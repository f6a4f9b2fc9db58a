/**
 * A gmsh mesh read from the 'Mesh file' (whose physical ids become the
 * boundary ids), refined 'Mesh refinements' times. Its entries are shared
 * with the other geometries: the file is what chooses it.
 */
#ifndef contact_mesh_file_h
#define contact_mesh_file_h

#include <geometry/geometry.h>

namespace Contact
{
  template <int dim>
  class MeshFile : public Geometry<dim>
  {
  public:
    using Geometry<dim>::Geometry;

    unsigned int create_coarse_mesh(Triangulation<dim> &mesh) const override;

  private:
    /** Reads the file into `mesh`; errors name the entry. */
    void read(Triangulation<dim> &mesh) const;
  };
} // namespace Contact

#endif
