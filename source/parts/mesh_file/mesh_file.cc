/* A mesh read from a gmsh file. */

#include <deal.II/base/exceptions.h>

#include <deal.II/grid/grid_in.h>

#include <base/dimensions.h>
#include <parts/mesh_file/mesh_file.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace Contact
{
  // @sect4{MeshFile::read}

  template <int dim>
  void MeshFile<dim>::read(Triangulation<dim> &mesh) const
  {
    const std::string &file = this->parameters.geometry.mesh_file;
    std::ifstream      in(file);
    AssertThrow(in,
                ExcMessage("Entry '" + Entry::mesh_file + "': cannot open '" +
                           file + "'; allowed is a readable gmsh .msh file."));
    GridIn<dim> grid_in(mesh);
    try
      {
        grid_in.read_msh(in);
      }
    catch (const ExceptionBase &exc)
      {
        std::ostringstream reason;
        exc.print_info(reason);
        AssertThrow(false,
                    ExcMessage(
                      "Entry '" + Entry::mesh_file + "': cannot read '" + file +
                      "' as a gmsh mesh of dimension " + std::to_string(dim) +
                      ": " + Utilities::trim(reason.str())));
      }
  }


  // @sect4{MeshFile::create_coarse_mesh}

  // The file is read once into a serial triangulation to check that its
  // cells have the declared 'Cell shape' (p4est would fail on simplices
  // with a less clear message), then into the triangulation of the run.
  template <int dim>
  unsigned int MeshFile<dim>::create_coarse_mesh(Triangulation<dim> &mesh) const
  {
    using CellShape             = GeometryParameters::CellShape;
    const auto        &geometry = this->parameters.geometry;
    Triangulation<dim> serial;
    read(serial);
    // From below: a refined cell has 2^dim children, and at least
    // p^dim / 6 (tetrahedra) of its own nodes.
    const double cells =
      serial.n_active_cells() * std::pow(2., dim * geometry.mesh_refinements);
    this->check_memory(cells,
                       dim * cells * std::pow(geometry.fe_degree, dim) /
                         (geometry.cell_shape == CellShape::simplex ? 6. : 1.),
                       Entry::mesh_refinements);
    const CellShape shape = serial.all_reference_cells_are_simplex() ?
                              CellShape::simplex :
                              CellShape::hypercube;
    AssertThrow(shape == geometry.cell_shape &&
                  (shape == CellShape::simplex ||
                   serial.all_reference_cells_are_hyper_cube()),
                ExcMessage("Entry '" + Entry::cell_shape + "': the mesh '" +
                           geometry.mesh_file + "' has " +
                           (shape == CellShape::simplex ?
                              "simplices" :
                              "not only simplices") +
                           "; allowed is 'Cell shape = " +
                           GeometryParameters::cell_shapes().name(shape) +
                           "' for it (meshes of one cell shape only)."));
    read(mesh);
    return geometry.mesh_refinements;
  }


#define INSTANTIATE(dim) template class MeshFile<dim>;
  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE


  // A 'Mesh file' replaces the Domain (the shell's parsing refuses a shell
  // with a mesh file).
  namespace
  {
    bool register_mesh_file()
    {
#define INSTANTIATE(dim)                                                       \
  ReplacingGeometryRegistry<dim>::add(                                         \
    {"mesh file",                                                              \
     "a gmsh mesh",                                                            \
     0,                                                                        \
     {},                                                                       \
     [](const Parameters &parameters, const MPI_Comm communicator)             \
       -> std::unique_ptr<const ReplacingGeometry<dim>> {                      \
       if (parameters.geometry.mesh_file.empty())                              \
         return nullptr;                                                       \
       return std::make_unique<const MeshFile<dim>>(parameters, communicator); \
     }});
      CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
      return true;
    }

    const bool registered = register_mesh_file();
  } // namespace
} // namespace Contact
