/**
 * The space dimensions the program is compiled for: those of the CMake
 * option CONTACT_DIMENSIONS ("2;3" by default, or "2" or "3" alone), which
 * defines CONTACT_WITH_2D and CONTACT_WITH_3D. Every explicit
 * instantiation of a class or function templated on dim goes through
 * CONTACT_INSTANTIATE, so that the option is the one list of them:
 *
 *   #define INSTANTIATE(dim) template class Foo<dim>;
 *   CONTACT_INSTANTIATE(INSTANTIATE)
 *   #undef INSTANTIATE
 *
 * A build of one dimension compiles each template once instead of twice,
 * yet the build measured no shorter (README, "Building for one dimension").
 */
#ifndef contact_dimensions_h
#define contact_dimensions_h

#include <string>

#if !defined(CONTACT_WITH_2D) && !defined(CONTACT_WITH_3D)
#  error "Neither CONTACT_WITH_2D nor CONTACT_WITH_3D: configure with CMake."
#endif

#ifdef CONTACT_WITH_2D
#  define CONTACT_INSTANTIATE_2D(INSTANTIATE) INSTANTIATE(2)
#else
#  define CONTACT_INSTANTIATE_2D(INSTANTIATE)
#endif

#ifdef CONTACT_WITH_3D
#  define CONTACT_INSTANTIATE_3D(INSTANTIATE) INSTANTIATE(3)
#else
#  define CONTACT_INSTANTIATE_3D(INSTANTIATE)
#endif

#define CONTACT_INSTANTIATE(INSTANTIATE) \
  CONTACT_INSTANTIATE_2D(INSTANTIATE) CONTACT_INSTANTIATE_3D(INSTANTIATE)

namespace Contact
{
  /** Whether ContactProblem<dim> is compiled. */
  constexpr bool is_compiled_dimension(const unsigned int dim)
  {
#ifdef CONTACT_WITH_2D
    if (dim == 2)
      return true;
#endif
#ifdef CONTACT_WITH_3D
    if (dim == 3)
      return true;
#endif
    return false;
  }

  /** The compiled dimensions as CONTACT_DIMENSIONS spells them, e.g.
   *  "2;3". */
  inline std::string compiled_dimensions()
  {
    std::string list;
    for (const unsigned int dim : {2u, 3u})
      if (is_compiled_dimension(dim))
        list += (list.empty() ? "" : ";") + std::to_string(dim);
    return list;
  }
} // namespace Contact

#endif
