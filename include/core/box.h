/**
 * The box of 'Lower corner' and 'Upper corner' divided into cells of the
 * 'Cell size' (the paper's domain), of hypercubes or simplices; its
 * faces carry the boundary ids 0 (x = x0), 1 (x = x1), 2 (y = y0),
 * 3 (y = y1), 4, 5 (z). box.cc declares and parses those three entries
 * (BoxParameters) and registers the box as the geometry 'box' of
 * 'Geometry/Domain'. Its h is the 'Cell size': the entry that a scene
 * variant halves.
 */
#ifndef contact_box_h
#define contact_box_h

#include <core/geometry.h>

#include <vector>

namespace Contact
{
  /** The entries of the box, as box.cc parses them. */
  struct BoxParameters
  {
    std::vector<double> lower_corner;
    std::vector<double> upper_corner;
    /** The edge length h of the cells. */
    double cell_size;
  };


  template <int dim>
  class Box : public Geometry<dim>
  {
  public:
    Box(const Parameters &run_parameters, const MPI_Comm mpi_communicator);

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

    std::map<std::string, std::string>
                entries_with_h_halved(const int h_halvings) const override;
    std::string mesh_size_text() const override;
    void        check_coarse_runs(const std::string &mode) const override;
    std::string
         coarsening_obstacle(const unsigned int doublings) const override;
    void check_manufactured_scene() const override;

    /** The largest of the cell sizes edge / round(edge / h) of its edges,
     *  whatever `mesh` and `mapping`. */
    double cell_size(const Triangulation<dim> &mesh,
                     const Mapping<dim>       &mapping) const override;

  private:
    /** The number of cells along the edge `d` with cells of `size`:
     *  round(edge / size), at least 1. */
    long n_cells(const unsigned int d, const double size) const;

    /** A copy: the geometry may outlive the parameters. */
    const BoxParameters box;
  };
} // namespace Contact

#endif
