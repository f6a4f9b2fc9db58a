/**
 * The box of 'Lower corner' and 'Upper corner' divided into cells of the
 * 'Cell size' (the paper's domain), of hypercubes or simplices; its
 * faces carry the boundary ids 0 (x = x0), 1 (x = x1), 2 (y = y0),
 * 3 (y = y1), 4, 5 (z). box.cc declares and parses those three entries.
 */
#ifndef contact_box_h
#define contact_box_h

#include <geometry/geometry.h>

namespace Contact
{
  template <int dim>
  class Box : public Geometry<dim>
  {
  public:
    using Geometry<dim>::Geometry;

    unsigned int create_coarse_mesh(Triangulation<dim> &mesh) const override;
  };
} // namespace Contact

#endif
