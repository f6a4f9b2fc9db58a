/* The entries of the subsection Mesh adaptation
   (include/parts/adaptation/mesh_adaptation_parameters.h): declared, parsed
   and checked against the scene here; the studies register the subsection
   among theirs and check it against their own entries. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <parts/adaptation/mesh_adaptation_parameters.h>

#include <algorithm>
#include <any>
#include <vector>

namespace Contact
{
  const std::array<std::string, 3> &MeshAdaptationParameters::indicator_names()
  {
    static const std::array<std::string, 3> names = {
      {"displacement", "velocity", "slip rate"}};
    return names;
  }

  void MeshAdaptationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh adaptation");
    {
      prm.declare_entry(
        "Cycles",
        "0",
        Patterns::Integer(0, 20),
        "0: the mesh of the Geometry. n > 0: n pilot runs of the whole scene "
        "(each in its own directory adaptation-cycle-c), each on the mesh its "
        "predecessor refined and coarsened from the 'Indicators', taken at "
        "at most 20 steps spread over the run and kept as their largest; "
        "then the scene runs on the adapted mesh. The pilots write "
        "indicators_0.pvtu; adapted_mesh.txt holds the mesh's cycles (every "
        "checkpoint stores them too: --resume runs on them without the "
        "pilots).");
      prm.declare_entry(
        "Interval",
        "0",
        Patterns::Integer(0),
        "0: the mesh does not change during the run. n > 0: after every n-th "
        "step the mesh is refined and coarsened from the 'Indicators' of that "
        "step, u and w are carried over to the new mesh, K is assembled and "
        "factorised again, and the change of the kinetic and elastic energy "
        "that the transfer makes enters the energy balance. adaptation.csv "
        "lists the adaptations (with the energy before and after each), "
        "adapted_mesh.txt the mesh's cycles, and with 'Output/VTU interval' "
        "> 0 indicators_<step>.pvtu the indicators and the cells chosen; a "
        "checkpoint stores the mesh.");
      prm.declare_entry("Refine fraction",
                        "0.3",
                        Patterns::Double(0, 1),
                        "The share of the cells, those with the largest "
                        "indicators, refined per cycle (or per adaptation "
                        "during the run).");
      prm.declare_entry("Coarsen fraction",
                        "0",
                        Patterns::Double(0, 1),
                        "The share of the cells, those with the smallest "
                        "indicators, coarsened per cycle (never coarser than "
                        "the Geometry's coarsest cells).");
      prm.declare_entry(
        "Target unknowns",
        "0",
        Patterns::Integer(0),
        "0: refine by 'Refine fraction'. n > 0: refine as many cells per "
        "cycle as multiply the unknowns by equal factors to about n at the "
        "last cycle. During the run ('Interval' > 0, which then needs "
        "'Coarsen fraction' > 0): refine by 'Refine fraction' up to about n "
        "unknowns, and from there only as many cells as the coarsening frees, "
        "so that the mesh keeps about n unknowns and still follows the "
        "solution. Without a target, each adaptation during the run refines "
        "'Refine fraction' of the cells, up to 'Max levels'.");
      prm.declare_entry(
        "Indicators",
        "displacement",
        Patterns::MultipleSelection("displacement|velocity|slip rate"),
        "What chooses the cells: Kelly's indicator of the displacement, of "
        "the velocity, and the variation of the slip rate over the faces of "
        "Gamma_3 (each as a share of its worst cell; a cell's indicator is "
        "the largest of its shares). The default gave the smallest V-error "
        "at T per unknown on the paper's scene (bench/adapted_mesh.md).");
      prm.declare_entry("Max levels",
                        "4",
                        Patterns::Integer(0, 12),
                        "Cells are refined at most this many times beyond "
                        "the Geometry's coarsest cells.");
    }
    prm.leave_subsection();
  }

  void MeshAdaptationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh adaptation");
    {
      cycles           = prm.get_integer("Cycles");
      interval         = prm.get_integer("Interval");
      refine_fraction  = prm.get_double("Refine fraction");
      coarsen_fraction = prm.get_double("Coarsen fraction");
      target_unknowns  = prm.get_integer("Target unknowns");
      max_levels       = prm.get_integer("Max levels");
      const std::vector<std::string> chosen =
        Utilities::split_string_list(prm.get("Indicators"));
      for (unsigned int i = 0; i < indicators.size(); ++i)
        indicators[i] =
          std::find(chosen.begin(), chosen.end(), indicator_names()[i]) !=
          chosen.end();
    }
    prm.leave_subsection();
    AssertThrow((cycles == 0 && interval == 0) || indicators[0] ||
                  indicators[1] || indicators[2],
                ExcMessage("Entry '" + Entry::indicators +
                           "' is empty: allowed is one or more of "
                           "displacement, velocity, slip rate."));
    AssertThrow(refine_fraction + coarsen_fraction <= 1,
                ExcMessage("Entries '" + Entry::refine_fraction +
                           "' = " + number_text(refine_fraction) + " and '" +
                           Entry::coarsen_fraction +
                           "' = " + number_text(coarsen_fraction) +
                           ": allowed is a sum of at most 1."));
  }


  std::string MeshAdaptationParameters::what_adapts() const
  {
    if (cycles == 0 && interval == 0)
      return "";
    return cycles > 0 ?
             "Entry '" + Entry::adaptation_cycles +
               "' = " + std::to_string(cycles) + " adapts the mesh: " :
             "Entry '" + Entry::adaptation_interval +
               "' = " + std::to_string(interval) +
               " adapts the mesh during the run: ";
  }


  // The checks of the subsection against the scene: those against the
  // studies' entries are the studies' (study_parameters.cc).
  void MeshAdaptationParameters::check(const Parameters &parameters) const
  {
    if (cycles == 0 && interval == 0)
      {
        AssertThrow(target_unknowns == 0,
                    ExcMessage("Entry '" + Entry::target_unknowns +
                               "' = " + std::to_string(target_unknowns) +
                               " is the size of an adapted mesh, but nothing "
                               "adapts the mesh: allowed with it is '" +
                               Entry::adaptation_cycles + "' > 0 or '" +
                               Entry::adaptation_interval + "' > 0 (or " +
                               Entry::target_unknowns + " = 0)."));
        return;
      }
    const std::string adapting = what_adapts();
    AssertThrow(cycles == 0 || interval == 0,
                ExcMessage(adapting + "it cannot be combined with '" +
                           Entry::adaptation_interval +
                           "' = " + std::to_string(interval) +
                           " yet; allowed is one of the two, the other 0."));
    // Settings under which the mesh cannot change at all.
    check_entry(max_levels > 0,
                Entry::max_levels,
                max_levels,
                "at least 1 where the mesh adapts (with 0 no cell may be "
                "refined, and none coarser than the Geometry's)");
    if (interval > 0)
      check_entry(interval < parameters.time.n_steps(),
                  Entry::adaptation_interval,
                  interval,
                  "0 or below the run's " +
                    std::to_string(parameters.time.n_steps()) +
                    " steps (the mesh adapts after every n-th step but "
                    "the last)");
    AssertThrow(parameters.geometry.cell_shape !=
                  GeometryParameters::CellShape::simplex,
                ExcMessage(adapting +
                           "it refines quadrilaterals and "
                           "hexahedra only; allowed with it is '" +
                           Entry::cell_shape + "' = hypercube."));
  }


  const MeshAdaptationParameters &
  MeshAdaptationParameters::of(const Parameters &parameters)
  {
    return parameters.part<MeshAdaptationParameters>(part_name);
  }

  MeshAdaptationParameters &MeshAdaptationParameters::of(Parameters &parameters)
  {
    return std::any_cast<MeshAdaptationParameters &>(
      parameters.part_values.at(part_name));
  }
} // namespace Contact
