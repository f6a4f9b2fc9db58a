/* What several verification tests do with files: read one whole, and copy
   the mesh-file scene (with the scene it includes) into a folder of its
   own, so that it is read through a relative path. */
#ifndef contact_tests_scene_files_h
#define contact_tests_scene_files_h

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

inline std::string contents(const std::string &path)
{
  std::ifstream      file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

inline void copy_mesh_file_scene(const std::string &folder)
{
  std::filesystem::create_directories(folder);
  for (const std::string name : {"barboteu2015.prm",
                                 "inclined_foundation.prm",
                                 "inclined_foundation.msh"})
    std::filesystem::copy_file(
      std::string(CONTACT_PRM_DIR) + "/" + name,
      folder + "/" + name,
      std::filesystem::copy_options::overwrite_existing);
}

#endif
