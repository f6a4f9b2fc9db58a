/* A geometry added from outside the program, as doc/tutorial.md's
   checklist "Adding a geometry" describes: a class defined in this file
   alone, registered as a part with an entry of its own, with no file of
   base/ or core/ changed. The strip [0, 1] x [0, 1/4] (x
   [0, 1/4] in 3D) of 'Strip cells' cells along x and a quarter of them
   across, with boundary ids of its own: 5 at x = 0, 7 at y = 0, 6 at
   y = 1/4 (0 elsewhere).

   Checked: the Selection 'Geometry/Domain' lists it after the box and the
   shell (and takes it; its default stays the box), and its entry is declared in
   Geometry right after 'Rotation axis' (the place it asked for); a value
   outside its pattern, and one that its own check refuses, are refused naming
   the entry; base/'s geometry of the parameters (the answers without a mesh) is
   the strip's; a run of the paper's scene on it ('Geometry/Domain = strip' and
   its boundary ids) builds its mesh: 8 x 2 cells, 8 free nodes on Gamma_3 (9 on
   y = 0, the one at x = 0 clamped), and runs its steps. */

#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_generator.h>

#include <app/run.h>
#include <core/geometry_base.h>
#include <core/contact_problem.h>
#include <core/geometry.h>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace Contact;

namespace
{
  // @sect3{The geometry}

  const std::string cells_entry = "Strip cells";

  // Its entry, declared after the last entry of Geometry; checked where
  // the strip is the domain.
  const PartEntries strip_entries{
    "Geometry",
    "Rotation axis",
    cells_entry,
    [](ParameterHandler &prm) {
      prm.declare_entry(cells_entry,
                        "8",
                        Patterns::Integer(4, 1000),
                        "Cells of the strip along x, a multiple of 4 (a "
                        "quarter of them across).");
    },
    [](ParameterHandler &prm, const Parameters &parameters) -> std::any {
      const unsigned int cells = prm.get_integer(cells_entry);
      if (parameters.geometry.domain == "strip")
        check_entry(cells % 4 == 0,
                    "Geometry/" + cells_entry,
                    cells,
                    "a multiple of 4");
      return cells;
    }};

  template <int dim>
  class Strip : public Geometry<dim>
  {
  public:
    Strip(const Parameters &run_parameters, const MPI_Comm mpi_communicator)
      : Geometry<dim>(run_parameters, mpi_communicator)
      , cells(run_parameters.part<unsigned int>("strip"))
    {}

    unsigned int create_coarse_mesh(Triangulation<dim> &mesh) const override
    {
      std::vector<unsigned int> subdivisions(dim, cells / 4);
      subdivisions[0] = cells;
      Point<dim> upper;
      for (unsigned int d = 0; d < dim; ++d)
        upper[d] = (d == 0 ? 1. : 0.25);
      GridGenerator::subdivided_hyper_rectangle(mesh,
                                                subdivisions,
                                                Point<dim>(),
                                                upper);
      for (const auto &face : mesh.active_face_iterators())
        if (face->at_boundary())
          {
            const Point<dim> center = face->center();
            face->set_boundary_id(center[0] < 1e-10        ? 5 :
                                  center[1] < 1e-10        ? 7 :
                                  center[1] > 0.25 - 1e-10 ? 6 :
                                                             0);
          }
      return this->parameters.geometry.mesh_refinements;
    }

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
    const unsigned int cells;
  };

  // The one statement that adds it: third in 'Domain'.
  const GeometryRegistration<Strip>
    registration("strip",
                 30,
                 "[0, 1] x [0, 1/4] of Strip cells along x",
                 strip_entries);


  // @sect3{Helpers}

  // The printed parameters, in the order of declaration.
  std::string printed_parameters()
  {
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    std::ostringstream printed;
    prm.print_parameters(printed,
                         ParameterHandler::ShortPRM |
                           ParameterHandler::KeepDeclarationOrder);
    return printed.str();
  }

  // The name of the entry declared right after `entry` in Geometry.
  std::string entry_after(const std::string &entry)
  {
    std::istringstream lines(printed_parameters());
    bool               in_geometry = false, found = false;
    for (std::string line; std::getline(lines, line);)
      {
        line = Utilities::trim(line);
        if (line == "subsection Geometry")
          in_geometry = true;
        else if (in_geometry && found && line.rfind("set ", 0) == 0)
          return Utilities::trim(line.substr(4, line.find('=') - 4));
        else if (in_geometry && line.rfind("set " + entry + " ", 0) == 0)
          found = true;
      }
    return "(none)";
  }

  // The paper's scene on the strip, with `overrides` on top.
  Parameters strip_scene(const std::vector<std::string> &overrides = {})
  {
    std::vector<std::string> entries = {
      "Geometry/Domain=strip",
      "Boundary conditions/Clamped boundary ids=5",
      "Boundary conditions/Contact boundary ids=7",
      "Boundary conditions/Tractions=6: 0; -600*t",
      "Time/End time=0.25",
      "Time/Time step=0.0625",
      "Output/VTU interval=0",
      "Output/Progress interval=0",
      "Output/Print timings=false",
      "Output/Report times=",
      "Output/Output directory=run"};
    entries.insert(entries.end(), overrides.begin(), overrides.end());
    return read_parameters(CONTACT_PRM_DIR "/barboteu2015.prm", entries);
  }

  void print_refusal(const std::string &value)
  {
    try
      {
        strip_scene({"Geometry/" + cells_entry + "=" + value});
        std::cout << "'" << value << "' accepted (wrong)" << std::endl;
      }
    catch (const ExceptionBase &error)
      {
        const std::string what = error.what();
        std::cout << "'" << value << "' refused, the message names the entry: "
                  << (what.find("Geometry/" + cells_entry) !=
                          std::string::npos ?
                        "yes" :
                        "no")
                  << std::endl;
      }
  }

  std::string line_with(const std::string &text, const std::string &word)
  {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      if (line.find(word) != std::string::npos)
        return line;
    return "(none)";
  }
} // namespace


int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // The declared entry: set() refuses a value outside its pattern.
  ParameterHandler prm;
  Parameters::declare_parameters(prm);
  prm.enter_subsection("Geometry");
  const std::string default_domain = prm.get("Domain");
  prm.set("Domain", "strip");
  std::cout
    << "'Geometry/Domain' takes '" << prm.get("Domain")
    << "', its default stays '" << default_domain << "'; pattern "
    << Patterns::Selection(GeometryBaseRegistry::selection()).description()
    << std::endl
    << "entry after 'Rotation axis': " << entry_after("Rotation axis")
    << std::endl;
  print_refusal("many");
  print_refusal("6");

  const Parameters parameters = strip_scene();
  std::cout << "base/'s geometry of the parameters: "
            << create_geometry(parameters)->mesh_size_text()
            << ", Gamma_3 closed: "
            << create_geometry(parameters)->gamma3_is_closed() << std::endl;

  ContactProblem<2>  problem(parameters);
  std::ostringstream console;
  auto *const        saved = std::cout.rdbuf(console.rdbuf());
  problem.run();
  std::cout.rdbuf(saved);
  std::cout << "the run's geometry is the strip: "
            << (dynamic_cast<const Strip<2> *>(&problem.get_geometry()) !=
                    nullptr ?
                  "yes" :
                  "no")
            << std::endl
            << line_with(console.str(), "Mesh:") << std::endl
            << "steps: " << problem.get_step_number() << std::endl;
}
