/**
 * The complementarity function of the nodal friction condition,
 * eta_p = P_{B(g_p)}(eta_p + c_p v_p), that the Tresca problem
 * (tresca_active_set.cc) and Newton's method on the full law
 * (friction_newton.cc) both solve: its linearisation at an iterate, the
 * stick/slip sets it selects, and its residual.
 */
#ifndef contact_complementarity_h
#define contact_complementarity_h

#include <deal.II/lac/vector.h>

#include <core/friction.h>

#include <vector>

namespace Contact
{
  namespace Complementarity
  {
    /** |x_p|, the Euclidean norm of node p's m components of x. */
    double node_norm(const Vector<double> &x,
                     const unsigned int    p,
                     const unsigned int    m);

    /** The linearisation at (eta, v) for the bounds g (NodeLinearisation):
     *  force = bound = g_p and slope = 0 on every node. */
    std::vector<NodeLinearisation> linearise(const unsigned int    m,
                                             const Vector<double> &eta,
                                             const Vector<double> &v,
                                             const Vector<double> &g,
                                             const Vector<double> &c);

    /** The sets that the cycle detection and the convergence tests
     *  compare: stick, or slip with (in 2D) its sign. */
    std::vector<int>
    set_signature(const std::vector<NodeLinearisation> &linearisation);

    /** max_p |eta_p - P_{B(g_p)}(eta_p + c_p v_p)|; zero at a solution. */
    double residual(const unsigned int    m,
                    const Vector<double> &eta,
                    const Vector<double> &v,
                    const Vector<double> &g,
                    const Vector<double> &c);
  } // namespace Complementarity
} // namespace Contact

#endif
