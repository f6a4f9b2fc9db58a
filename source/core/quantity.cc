/* The names of the quantities that an error estimate compares. */

#include <deal.II/base/exceptions.h>

#include <core/parameters.h>
#include <core/quantity.h>

#include <regex>
#include <utility>

namespace Contact
{
  namespace
  {
    using Kind = Quantity::Kind;

    // The names of all kinds but the probes', in the order in which the
    // message of an unknown name lists them.
    const std::vector<std::pair<std::string, Kind>> &fixed_names()
    {
      static const std::vector<std::pair<std::string, Kind>> names = {
        {"V-norm of u, max over t", Kind::worst_V_error},
        {"V-norm of u", Kind::V_norm},
        {"friction dissipation", Kind::friction_dissipation},
        {"slipping share of Gamma_3", Kind::slipping_share},
        {"slip zone starts at x", Kind::slip_zone_start},
        {"time of the first slip", Kind::first_slip_time}};
      return names;
    }
  } // namespace


  // @sect4{Quantity::name}

  // A probe's displacement is 'probe <i> u_<x|y|z>', i counted from 1.
  // The V-norm ||eps(u)|| is the L2 norm of a strain over the body:
  // m^(dim/2); the friction dissipation an energy, per metre of thickness
  // in 2D.
  std::string Quantity::unit(const unsigned int dim) const
  {
    switch (kind)
      {
        case Kind::worst_V_error:
        case Kind::V_norm:
          return dim == 2 ? "m" : "m^1.5";
        case Kind::friction_dissipation:
          return dim == 2 ? "J/m" : "J";
        case Kind::slipping_share:
          return "1";
        case Kind::first_slip_time:
          return "s";
        case Kind::slip_zone_start:
        case Kind::probe_displacement:
          return "m";
      }
    return "";
  }


  std::string Quantity::name() const
  {
    if (kind == Kind::probe_displacement)
      return "probe " + std::to_string(probe + 1) + " u_" +
             std::string(1, "xyz"[component]);
    for (const auto &[text, named_kind] : fixed_names())
      if (named_kind == kind)
        return text;
    AssertThrow(false, ExcInternalError("A quantity without a name."));
    return "";
  }


  // @sect4{Quantity::parse}

  Quantity Quantity::parse(const std::string &text, const std::string &entry)
  {
    for (const auto &[name, kind] : fixed_names())
      if (name == text)
        return {kind};
    std::smatch probe;
    if (std::regex_match(text,
                         probe,
                         std::regex("probe ([1-9][0-9]{0,5}) u_([xyz])")))
      return {Kind::probe_displacement,
              static_cast<unsigned int>(std::stoul(probe[1].str()) - 1),
              static_cast<unsigned int>(probe[2].str()[0] - 'x')};
    std::string allowed;
    for (const auto &[name, kind] : fixed_names())
      allowed += "'" + name + "', ";
    AssertThrow(false,
                ExcMessage("Entry '" + entry + "' = '" + text +
                           "' is not a quantity; allowed: " + allowed +
                           "or 'probe <i> u_x' (u_y, u_z) of the i-th '" +
                           Entry::probe_points + "' point."));
    return {};
  }


  // @sect4{Quantity::of_scene}

  std::vector<Quantity> Quantity::of_scene(const unsigned int n_probes,
                                           const unsigned int dim)
  {
    std::vector<Quantity> quantities;
    for (const auto &[name, kind] : fixed_names())
      quantities.push_back({kind});
    for (unsigned int i = 0; i < n_probes; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        quantities.push_back({Kind::probe_displacement, i, d});
    return quantities;
  }
} // namespace Contact
