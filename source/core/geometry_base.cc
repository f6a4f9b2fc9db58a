/* What a geometry answers without a mesh, by default, and the geometry of
   the parameters (include/core/geometry_base.h). */

#include <deal.II/base/exceptions.h>

#include <core/geometry_base.h>

namespace Contact
{
  // @sect3{What a geometry answers without a mesh}

  GeometryBase::GeometryBase(const Parameters &run_parameters)
    : parameters{run_parameters.geometry, run_parameters.boundary}
  {}


  // The defaults are those of a geometry whose mesh is its coarse mesh
  // refined 'Mesh refinements' times: one refinement more halves h, and
  // the meshes of 2h and 4h exist where it is refined at least twice.
  std::map<std::string, std::string>
  GeometryBase::entries_with_h_halved(const int h_halvings) const
  {
    return {
      {Entry::mesh_refinements,
       std::to_string(static_cast<int>(parameters.geometry.mesh_refinements) +
                      h_halvings)}};
  }


  std::string GeometryBase::mesh_size_text() const
  {
    return "mesh refinements = " +
           std::to_string(parameters.geometry.mesh_refinements);
  }


  void GeometryBase::check_coarse_runs(const std::string &mode) const
  {
    check_entry(parameters.geometry.mesh_refinements >= 2,
                Entry::mesh_refinements,
                parameters.geometry.mesh_refinements,
                "at least 2 with " + mode +
                  " (the coarse runs use one and two refinements "
                  "fewer)");
  }


  std::string
  GeometryBase::coarsening_obstacle(const unsigned int doublings) const
  {
    if (parameters.geometry.mesh_refinements >= doublings)
      return "";
    return "'" + Entry::mesh_refinements + "' needs to be at least " +
           std::to_string(doublings);
  }


  void GeometryBase::check_manufactured_scene() const
  {
    AssertThrow(false,
                ExcMessage("'" + Entry::manufactured_solution +
                           "' needs the box: '" + Entry::domain +
                           " = box' and no '" + Entry::mesh_file + "'."));
  }


  // @sect3{The geometry of the parameters}

  std::unique_ptr<const GeometryBase>
  create_geometry(const Parameters &parameters)
  {
    return GeometryBaseRegistry::create(Entry::domain,
                                        parameters.geometry.domain,
                                        parameters);
  }
} // namespace Contact
