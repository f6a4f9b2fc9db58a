/* The sliding slab of refined_gamma3_patch and mesh_transfer: a free slab
   (no clamp) on Gamma_3 = {y = 0}, sheared so that its friction is at the
   bound a S = 10 N/m^2 everywhere (u_0 = (gamma_0 y, 0[, 0]),
   mu_L gamma_0 = 10, the side tractions of that stress) and pushed along
   Gamma_3 by the body force f_0 = (2000, 0[, 0]). Its exact solution
   slides rigidly on the sheared state, and its discrete velocity is
   w_n = n k f_0 / rho on any mesh: every node of Gamma_3 slips at 0.02 n
   with the friction traction 10. */

#ifndef contact_tests_sliding_slab_h
#define contact_tests_sliding_slab_h

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// The slab's entries on prm/barboteu2015(_3d).prm, all but the cell size.
// mu_L = E / (2 (1 + nu)) = 2000 / 2.6, so gamma_0 = 10 / mu_L = 0.013; the
// stress is 10 in sigma_xy alone.
inline std::vector<std::string> slab_settings(const int dim)
{
  std::vector<std::string> settings = {
    "Boundary conditions/Clamped boundary ids=",
    "Friction/Friction law=constant",
    "Friction/Friction bound S=20",
    "Friction/a=0.5",
    "Time/End time=0.05",
    "Time/Time step=0.01"};
  if (dim == 2)
    settings.insert(
      settings.end(),
      {"Geometry/Upper corner=1, 0.25",
       "Boundary conditions/Tractions=3: 10; 0 | 0: 0; -10 | 1: 0; 10",
       "Loads and initial values/Body force=2000; 0",
       "Loads and initial values/Initial displacement=0.013*y; 0"});
  else
    settings.insert(
      settings.end(),
      {"Geometry/Upper corner=1, 0.25, 1",
       "Boundary conditions/Tractions=3: 10; 0; 0 | 0: 0; -10; 0 | 1: 0; 10; "
       "0",
       "Loads and initial values/Body force=2000; 0; 0",
       "Loads and initial values/Initial displacement=0.013*y; 0; 0"});
  return settings;
}

// The largest relative deviations of the slip rates from 0.02 n and of
// |friction traction| from 10 over every node and step of
// gamma3_history.csv.
inline std::pair<double, double> slab_deviations(const std::string &directory,
                                                 const int          dim)
{
  std::ifstream file(directory + "/gamma3_history.csv");
  std::string   line;
  std::getline(file, line);
  double rate_deviation = 0, traction_deviation = 0;
  while (std::getline(file, line))
    {
      std::vector<double> value;
      std::istringstream  fields(line);
      for (std::string field; std::getline(fields, field, ',');)
        value.push_back(std::stod(field));
      const unsigned int step = static_cast<unsigned int>(value[0]);
      if (step == 0)
        continue;
      const double rate = value[2 + dim + 1];
      const double traction =
        std::hypot(value[2 + dim + 2], dim == 3 ? value[2 + dim + 3] : 0.);
      const double exact = 0.02 * step;
      rate_deviation = std::max(rate_deviation, std::abs(rate - exact) / exact);
      traction_deviation =
        std::max(traction_deviation, std::abs(traction - 10.) / 10.);
    }
  return {rate_deviation, traction_deviation};
}

inline std::string bound_text(const double value)
{
  return value < 1e-10 ? "below 1e-10" : "ABOVE 1e-10";
}

#endif
