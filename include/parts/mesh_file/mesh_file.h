/**
 * A gmsh mesh read from the 'Mesh file' (whose physical ids become the
 * boundary ids), refined 'Mesh refinements' times. Its entries are shared
 * with the other geometries: the file is what chooses it, in place of
 * 'Geometry/Domain' (a ReplacingGeometry, registered in mesh_file.cc). Its
 * cells are its body, and nothing is known of its shape beyond them: its
 * boundary is taken as straight, its Gamma_3 as open, the body as not
 * symmetric.
 */
#ifndef contact_mesh_file_h
#define contact_mesh_file_h

#include <core/geometry.h>

namespace Contact
{
  template <int dim>
  class MeshFile : public ReplacingGeometry<dim>
  {
  public:
    using ReplacingGeometry<dim>::ReplacingGeometry;

    unsigned int create_coarse_mesh(Triangulation<dim> &mesh) const override;

    bool has_curved_boundary() const override
    {
      return false;
    }
    bool gamma3_is_closed() const override
    {
      return false;
    }
    bool is_symmetric_about_z_axis() const override
    {
      return false;
    }

  private:
    /** Reads the file into `mesh`; errors name the entry. */
    void read(Triangulation<dim> &mesh) const;
  };
} // namespace Contact

#endif
