/**
 * The annulus (2D) or the tube along z (3D) between the 'Inner radius' and
 * the 'Outer radius' around the origin, of the 'Cells around' the circle,
 * refined 'Mesh refinements' times: the bushing scene. Boundary ids 0
 * inner, 1 outer, 2 z = 0, 3 z = 'Shell length'. shell.cc declares,
 * parses and checks those four entries (ShellParameters) and registers the
 * shell as the geometry 'shell' of 'Geometry/Domain'. Its circles are
 * curved, its Gamma_3 closed about the z-axis, and the body symmetric
 * about it.
 */
#ifndef contact_shell_h
#define contact_shell_h

#include <core/geometry.h>

#include <string>

namespace Contact
{
  /** The entries of the shell, as its messages name them. */
  namespace Entry
  {
    inline const std::string inner_radius = "Geometry/Inner radius";
    inline const std::string outer_radius = "Geometry/Outer radius";
    inline const std::string shell_length = "Geometry/Shell length";
    inline const std::string cells_around = "Geometry/Cells around";
  } // namespace Entry

  /** The entries of the shell, as shell.cc parses them. */
  struct ShellParameters
  {
    double inner_radius;
    double outer_radius;
    /** The length of the tube along z (3D). */
    double       shell_length;
    unsigned int cells_around;
  };


  template <int dim>
  class Shell : public Geometry<dim>
  {
  public:
    Shell(const Parameters &run_parameters, const MPI_Comm mpi_communicator);

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

  private:
    /** A copy: the geometry may outlive the parameters. */
    const ShellParameters shell;
  };
} // namespace Contact

#endif
