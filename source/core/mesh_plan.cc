/* Replaying and recording the cycles of a mesh adaptation by CellId. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>


#include <base/dimensions.h>
#include <core/mesh_plan.h>

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>

namespace Contact
{
  template <int dim>
  void MeshPlan::replay_cycle(const unsigned int  cycle,
                              Triangulation<dim> &mesh) const
  {
    const std::set<std::string> refine(refined[cycle].begin(),
                                       refined[cycle].end());
    const std::set<std::string> coarsen(coarsened[cycle].begin(),
                                        coarsened[cycle].end());
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const std::string id = cell->id().to_string();
          if (refine.count(id) != 0)
            cell->set_refine_flag();
          else if (coarsen.count(id) != 0)
            cell->set_coarsen_flag();
        }
    mesh.execute_coarsening_and_refinement();
  }


  template <int dim>
  void MeshPlan::replay(Triangulation<dim> &mesh) const
  {
    for (unsigned int cycle = 0; cycle < n_cycles(); ++cycle)
      replay_cycle(cycle, mesh);
  }


  // The flags as set by the choice of cells, before the mesh's own
  // smoothing (2:1 balance) adds any: replaying them gives the same
  // smoothing. Sorted, so that the text does not depend on the partition.
  template <int dim>
  void MeshPlan::add_cycle_from_flags(const Triangulation<dim> &mesh)
  {
    std::vector<std::string> refine, coarsen;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (cell->refine_flag_set())
            refine.push_back(cell->id().to_string());
          else if (cell->coarsen_flag_set())
            coarsen.push_back(cell->id().to_string());
        }
    const MPI_Comm communicator = mesh.get_communicator();
    for (auto [own, all] : {std::pair{&refine, &refined.emplace_back()},
                            std::pair{&coarsen, &coarsened.emplace_back()}})
      {
        for (const auto &part : Utilities::MPI::all_gather(communicator, *own))
          all->insert(all->end(), part.begin(), part.end());
        std::sort(all->begin(), all->end());
      }
  }


  MeshPlan MeshPlan::coarser(const unsigned int levels) const
  {
    // A CellId's text is '<coarse cell>_<number of children>:<children>',
    // one child digit per level: the ancestor drops the last digits.
    const auto ancestor = [levels](const std::string &id) {
      const std::size_t  underscore = id.find('_'), colon = id.find(':');
      const unsigned int level =
        std::stoul(id.substr(underscore + 1, colon - underscore - 1));
      AssertThrow(level >= levels,
                  ExcInternalError("A mesh adaptation's cell " + id +
                                   " has no ancestor " +
                                   std::to_string(levels) + " levels up."));
      return id.substr(0, underscore + 1) + std::to_string(level - levels) +
             ":" + id.substr(colon + 1, level - levels);
    };
    MeshPlan result;
    for (const auto &[from, to] : {std::pair{&refined, &result.refined},
                                   std::pair{&coarsened, &result.coarsened}})
      for (const std::vector<std::string> &cycle : *from)
        {
          std::set<std::string> cells;
          for (const std::string &id : cycle)
            cells.insert(ancestor(id));
          to->emplace_back(cells.begin(), cells.end());
        }
    return result;
  }


  std::string MeshPlan::text() const
  {
    std::ostringstream out;
    for (unsigned int cycle = 0; cycle < n_cycles(); ++cycle)
      for (const auto &[kind, cells] :
           {std::pair{"refine", &refined[cycle]},
            std::pair{"coarsen", &coarsened[cycle]}})
        {
          out << kind;
          for (const std::string &id : *cells)
            out << ' ' << id;
          out << '\n';
        }
    return out.str();
  }


  MeshPlan MeshPlan::from_text(const std::string &text,
                               const std::string &file_name)
  {
    std::istringstream file(text);
    MeshPlan           plan;
    unsigned int       line_number = 0;
    for (std::string line; std::getline(file, line);)
      {
        ++line_number;
        std::istringstream words(line);
        std::string        kind, id;
        words >> kind;
        const bool is_refine = (kind == "refine");
        AssertThrow((is_refine &&
                     plan.refined.size() == plan.coarsened.size()) ||
                      (kind == "coarsen" &&
                       plan.refined.size() == plan.coarsened.size() + 1),
                    ExcMessage("'" + file_name + "', line " +
                               std::to_string(line_number) +
                               ": expected 'refine' and 'coarsen' lines in "
                               "turn; the file is damaged."));
        std::vector<std::string> &cells =
          (is_refine ? plan.refined : plan.coarsened).emplace_back();
        // deal.II checks a CellId's text in debug builds only: a cell is
        // 'coarse_level:children', one child digit (0-7) per level.
        static const std::regex cell_pattern("([0-9]+)_([0-9]+):([0-7]*)");
        while (words >> id)
          {
            std::smatch parts;
            AssertThrow(std::regex_match(id, parts, cell_pattern) &&
                          parts[2].length() <= 2 &&
                          static_cast<unsigned long>(parts[3].length()) ==
                            std::stoul(parts[2].str()),
                        ExcMessage("'" + file_name + "', line " +
                                   std::to_string(line_number) + ": '" + id +
                                   "' is not a cell; the file is damaged."));
            cells.push_back(id);
          }
      }
    AssertThrow(plan.refined.size() == plan.coarsened.size(),
                ExcMessage("'" + file_name +
                           "' ends within a cycle; the file is damaged."));
    return plan;
  }


#define INSTANTIATE(dim)                                            \
  template void MeshPlan::replay_cycle(const unsigned int,          \
                                       Triangulation<dim> &) const; \
  template void MeshPlan::replay(Triangulation<dim> &) const;       \
  template void MeshPlan::add_cycle_from_flags(const Triangulation<dim> &);

  CONTACT_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace Contact
