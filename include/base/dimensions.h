/**
 * The space dimensions the program is compiled for. Every explicit
 * instantiation of a class or function templated on dim goes through
 * CONTACT_INSTANTIATE, so that this is the one list of them:
 *
 *   #define INSTANTIATE(dim) template class Foo<dim>;
 *   CONTACT_INSTANTIATE(INSTANTIATE)
 *   #undef INSTANTIATE
 */
#ifndef contact_dimensions_h
#define contact_dimensions_h

#define CONTACT_INSTANTIATE(INSTANTIATE) INSTANTIATE(2) INSTANTIATE(3)

#endif
