/* The factorisation of K by CHOLMOD, the core's linear solver, and the
   choice among the registered linear solvers. */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <core/factorization.h>
#include <core/parameters.h>
#include <suitesparse/cholmod.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cstring>
#include <iomanip>
#include <sstream>

namespace Contact
{
  void Factorization::forward_substitution(
    std::vector<Vector<double>> &,
    const std::vector<TrilinosWrappers::MPI::Vector> &)
  {
    AssertThrow(false,
                ExcMessage("This factorisation does not expose its "
                           "triangular factor."));
  }

  void Factorization::backward_substitution(TrilinosWrappers::MPI::Vector &,
                                            const Vector<double> &)
  {
    AssertThrow(false,
                ExcMessage("This factorisation does not expose its "
                           "triangular factor."));
  }

  std::unique_ptr<Factorization> Factorization::for_indefinite_variant(
    const TrilinosWrappers::SparseMatrix &) const
  {
    AssertThrow(false,
                ExcMessage("This solver needs a positive definite matrix."));
    return nullptr;
  }


  namespace
  {
    // @sect3{CHOLMOD}

    // K is handed to CHOLMOD as its upper triangle in compressed columns;
    // since K is symmetric, row i of the (row-wise) Epetra matrix holds
    // column i. The factor is supernodal (CHOLMOD's default for matrices
    // like this one) and its solves run on blocks of right-hand sides.
    class CholmodFactorization : public Factorization
    {
    public:
      // CHOLMOD's objects are freed if the factorisation fails (the
      // destructor does not run for a constructor that throws), and the
      // class is not copied (the copies would free them twice).
      explicit CholmodFactorization(const TrilinosWrappers::SparseMatrix &K)
      {
        cholmod_start(&common);
        // Errors only: a matrix that is not positive definite is reported
        // by the program (a Newton matrix of the constraints path is then
        // refused on purpose), not by CHOLMOD's warning on stderr.
        common.print = 0;
        try
          {
            factorise(K);
          }
        catch (...)
          {
            release();
            throw;
          }
      }

      CholmodFactorization(const CholmodFactorization &)            = delete;
      CholmodFactorization &operator=(const CholmodFactorization &) = delete;

      ~CholmodFactorization() override
      {
        release();
      }

    private:
      void factorise(const TrilinosWrappers::SparseMatrix &K)
      {
        const Epetra_CrsMatrix &matrix = K.trilinos_matrix();
        AssertThrow(matrix.Comm().NumProc() == 1,
                    ExcMessage("'" + Entry::linear_solver +
                               " = CHOLMOD' runs on one "
                               "process; choose an Amesos solver for more."));
        cholmod_sparse *A = upper_triangle(matrix);
        // L L^T also where CHOLMOD chooses a simplicial factor, whose
        // default is L D L^T: the forward and backward substitutions are
        // then the two halves of a solve.
        common.final_ll = 1;
        factor          = cholmod_analyze(A, &common);
        cholmod_factorize(A, factor, &common);
        cholmod_free_sparse(&A, &common);
        check_factor(matrix.NumMyRows());
      }

      // K's upper triangle in CHOLMOD's sorted compressed columns (its
      // symmetric storage, stype 1): K being symmetric, the entries of row
      // i in the columns up to i are column i of that triangle.
      cholmod_sparse *upper_triangle(const Epetra_CrsMatrix &matrix)
      {
        const int   n       = matrix.NumMyRows();
        std::size_t n_upper = 0;
        for (int i = 0; i < n; ++i)
          {
            int     length;
            double *values;
            int    *columns;
            matrix.ExtractMyRowView(i, length, values, columns);
            for (int k = 0; k < length; ++k)
              n_upper += (columns[k] <= i ? 1 : 0);
          }
        cholmod_sparse *A            = cholmod_allocate_sparse(n,
                                                    n,
                                                    n_upper,
                                                    /*sorted=*/true,
                                                    /*packed=*/true,
                                                    /*stype=*/1,
                                                    CHOLMOD_REAL,
                                                    &common);
        auto           *column_start = static_cast<int *>(A->p);
        auto           *row_index    = static_cast<int *>(A->i);
        auto           *entries      = static_cast<double *>(A->x);
        std::size_t     position     = 0;
        for (int i = 0; i < n; ++i)
          {
            column_start[i] = position;
            int     length;
            double *values;
            int    *columns;
            matrix.ExtractMyRowView(i, length, values, columns);
            std::vector<std::pair<int, double>> upper;
            for (int k = 0; k < length; ++k)
              if (columns[k] <= i)
                upper.emplace_back(columns[k], values[k]);
            std::sort(upper.begin(), upper.end());
            for (const auto &[row, value] : upper)
              {
                row_index[position] = row;
                entries[position]   = value;
                ++position;
              }
          }
        column_start[n] = position;
        return A;
      }

      // That the factorisation succeeded and K is not singular to working
      // precision; n is K's size.
      void check_factor(const int n)
      {
        AssertThrow(common.status == CHOLMOD_OK &&
                      factor->minor == static_cast<std::size_t>(n) &&
                      factor->is_ll,
                    ExcMessage("CHOLMOD could not factorise K = (1/k) M + A + "
                               "k B: it is not positive definite (status " +
                               std::to_string(common.status) +
                               "). Its entries overflow or span more than "
                               "the range of double precision if "
                               "'" +
                               Entry::youngs_modulus + "', '" + Entry::density +
                               "', the viscosities or '" + Entry::time_step +
                               "' are extreme (e.g. E = 1e308, k = "
                               "1e-300)."));
        // A matrix that is singular in exact arithmetic (a body free to
        // move rigidly) may still factorise in floating point; CHOLMOD's
        // estimate of the reciprocal condition number tells.
        const double       rcond = cholmod_rcond(factor, &common);
        std::ostringstream rcond_text;
        rcond_text << std::setprecision(2) << rcond;
        AssertThrow(rcond > 1e-14,
                    ExcMessage("K = (1/k) M + A + k B is singular to working "
                               "precision (CHOLMOD's reciprocal condition "
                               "estimate " +
                               rcond_text.str() +
                               "): either the body is not fixed against a "
                               "rigid motion (clamp a boundary, '" +
                               Entry::clamped_boundary_ids +
                               "', or give it "
                               "mass, '" +
                               Entry::density +
                               "' > 0), or its terms "
                               "differ by more than 14 orders of magnitude "
                               "(extreme '" +
                               Entry::youngs_modulus +
                               "', "
                               "'" +
                               Entry::density + "', viscosities or '" +
                               Entry::time_step +
                               "'), or a cell of the mesh is degenerate "
                               "(zero area)."));
      }

    public:
      std::unique_ptr<Factorization>
      for_variant(const TrilinosWrappers::SparseMatrix &variant) const override
      {
        return std::make_unique<CholmodFactorization>(variant);
      }

      double factor_size() const override
      {
        return common.lnz;
      }

      void release()
      {
        cholmod_free_dense(&solution, &common);
        cholmod_free_dense(&workspace_y, &common);
        cholmod_free_dense(&workspace_e, &common);
        cholmod_free_factor(&factor, &common);
        cholmod_finish(&common);
      }

      void solve(TrilinosWrappers::MPI::Vector       &x,
                 const TrilinosWrappers::MPI::Vector &b) override
      {
        solve_block(
          CHOLMOD_A,
          1,
          [&](double *column, unsigned int) {
            std::memcpy(column, b.begin(), sizeof(double) * b.size());
          },
          [&](const double *column, unsigned int) {
            std::memcpy(x.begin(), column, sizeof(double) * x.size());
          });
      }

      bool has_triangular_factor() const override
      {
        return true;
      }

      // CHOLMOD's CHOLMOD_L and CHOLMOD_Lt systems do not permute; P b is
      // (P b)_k = b_{Perm[k]}.
      void forward_substitution(
        std::vector<Vector<double>>                      &y,
        const std::vector<TrilinosWrappers::MPI::Vector> &b) override
      {
        const auto       *permutation = static_cast<const int *>(factor->Perm);
        const std::size_t n           = factor->n;
        y.resize(b.size());
        solve_block(
          CHOLMOD_L,
          b.size(),
          [&](double *column, unsigned int j) {
            const double *values = b[j].begin();
            for (std::size_t k = 0; k < n; ++k)
              column[k] = values[permutation[k]];
          },
          [&](const double *column, unsigned int j) {
            y[j].reinit(n, true);
            std::copy(column, column + n, y[j].begin());
          });
      }

      void backward_substitution(TrilinosWrappers::MPI::Vector &x,
                                 const Vector<double>          &y) override
      {
        const auto       *permutation = static_cast<const int *>(factor->Perm);
        const std::size_t n           = factor->n;
        solve_block(
          CHOLMOD_Lt,
          1,
          [&](double *column, unsigned int) {
            std::copy(y.begin(), y.end(), column);
          },
          [&](const double *column, unsigned int) {
            double *values = x.begin();
            for (std::size_t k = 0; k < n; ++k)
              values[permutation[k]] = column[k];
          });
      }

    private:
      template <typename Fill, typename Take>
      void solve_block(const int          system,
                       const unsigned int n_columns,
                       const Fill        &fill,
                       const Take        &take)
      {
        const std::size_t n = factor->n;
        cholmod_dense    *B =
          cholmod_allocate_dense(n, n_columns, n, CHOLMOD_REAL, &common);
        for (unsigned int j = 0; j < n_columns; ++j)
          fill(static_cast<double *>(B->x) + j * n, j);
        cholmod_solve2(system,
                       factor,
                       B,
                       nullptr,
                       &solution,
                       nullptr,
                       &workspace_y,
                       &workspace_e,
                       &common);
        cholmod_free_dense(&B, &common);
        AssertThrow(common.status == CHOLMOD_OK,
                    ExcMessage("CHOLMOD's solve failed (status " +
                               std::to_string(common.status) + ")."));
        for (unsigned int j = 0; j < n_columns; ++j)
          take(static_cast<const double *>(solution->x) + j * n, j);
      }

      cholmod_common  common;
      cholmod_factor *factor      = nullptr;
      cholmod_dense  *solution    = nullptr;
      cholmod_dense  *workspace_y = nullptr;
      cholmod_dense  *workspace_e = nullptr;
    };
  } // namespace


  std::unique_ptr<Factorization>
  Factorization::create(const std::string                    &solver,
                        const TrilinosWrappers::SparseMatrix &K,
                        const std::vector<std::vector<bool>> &constant_modes)
  {
    return LinearSolverRegistry::create(Entry::linear_solver,
                                        solver,
                                        K,
                                        constant_modes);
  }


  namespace
  {
    // CHOLMOD is the core's linear solver; the others are parts
    // (parts/linear_solvers). Rank 10: the first of the help text.
    const bool cholmod_registered = LinearSolverRegistry::add(
      {cholmod_name,
       "CHOLMOD (SuiteSparse's supernodal Cholesky, one process)",
       10,
       {},
       [](const TrilinosWrappers::SparseMatrix &K,
          const std::vector<std::vector<bool>> &)
         -> std::unique_ptr<Factorization> {
         return std::make_unique<CholmodFactorization>(K);
       }});
  } // namespace
} // namespace Contact
