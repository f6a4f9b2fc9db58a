/**
 * The dense kernels of the Newton step on the Delassus operator
 * (delassus_block.cc), shared by the step (delassus_operator.cc) and the
 * solve of its block.
 */
#ifndef contact_delassus_kernels_h
#define contact_delassus_kernels_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace Contact
{
  using namespace dealii;

  namespace DelassusKernels
  {
    /** y = M x for the symmetric D or W (BLAS's symv, one triangle). */
    void symmetric_vmult(const LAPACKFullMatrix<double> &M,
                         Vector<double>                 &y,
                         const Vector<double>           &x);

    /** x = F^{-1} x for a factorised block F, Cholesky's or LU's. */
    void solve_with_factor(const LAPACKFullMatrix<double> &factor,
                           const bool                      cholesky,
                           Vector<double>                 &x);

    /** M' = Q^T M Q in the nodes' local bases Q, on the rows and columns
     *  of `unknowns`. */
    void fill_rotated_block(const LAPACKFullMatrix<double>        &M,
                            const std::vector<FullMatrix<double>> &Q,
                            const std::vector<unsigned int>       &unknowns,
                            LAPACKFullMatrix<double>              &block);

    /** y = Q x (to the nodes' tangents) or Q^T x (to the local bases). */
    void rotate(const std::vector<FullMatrix<double>> &Q,
                const Vector<double>                  &x,
                Vector<double>                        &y,
                const bool                             transpose);
  } // namespace DelassusKernels
} // namespace Contact

#endif
