/**
 * The annulus (2D) or the tube along z (3D) between the 'Inner radius' and
 * the 'Outer radius' around the origin, of the 'Cells around' the circle,
 * refined 'Mesh refinements' times: the bushing scene. Boundary ids 0
 * inner, 1 outer, 2 z = 0, 3 z = 'Shell length'. shell.cc declares and
 * parses those four entries. Its circles are curved, its Gamma_3 closed
 * about the z-axis, and the body symmetric about it.
 */
#ifndef contact_shell_h
#define contact_shell_h

#include <geometry/geometry.h>

namespace Contact
{
  template <int dim>
  class Shell : public Geometry<dim>
  {
  public:
    using Geometry<dim>::Geometry;

    unsigned int create_coarse_mesh(Triangulation<dim> &mesh) const override;

    bool has_curved_boundary() const override
    {
      return true;
    }
    bool gamma3_is_closed() const override
    {
      return true;
    }
    bool is_symmetric_about_z_axis() const override
    {
      return true;
    }

    /** Between the radii (and in 3D the end faces), whatever `mesh`. */
    bool contains(const Point<dim>         &point,
                  const Triangulation<dim> &mesh) const override;
  };
} // namespace Contact

#endif
