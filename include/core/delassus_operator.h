/**
 * The Delassus operator D = C K^{-1} C^T on the tangential unknowns of
 * Gamma_3 and the Newton step of the friction solvers on it.
 */
#ifndef contact_delassus_operator_h
#define contact_delassus_operator_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <core/friction.h>

#include <memory>
#include <vector>

namespace Contact
{
  using namespace dealii;

  /**
   * D, dense, symmetric positive semidefinite, with m = dim - 1 tangential
   * unknowns per node (node-major), and its inverse W = D^{-1} where D is
   * definite with cond(D) <= 1e4. Both are formed once per time step size;
   * products with them and every Newton step's dense factorisation go
   * through BLAS/LAPACK.
   *
   * A Newton step (the linearisation of friction.h) fixes, in every node's
   * local basis, either the velocity (v' = 0: stick, or a slip direction
   * with beta = 0), or the force (eta' = force: the frozen bound along
   * zhat), or a Robin relation between them (eta' = force + sigma v', with
   * sigma = 1/beta across zhat and sigma = g'(s) along zhat for the full
   * law). With v = v_free - D eta it can be solved for the forces on the
   * unknowns that do not fix the force,
   *   (D'_FF + diag(1/sigma)) eta'_F = ...            (force form),
   * or, through eta = W (v_free - v), for the velocities on the unknowns
   * that do not fix the velocity,
   *   (W'_UU + diag(sigma)) v'_U = ...                (velocity form),
   * where D' = Q^T D Q and W' = Q^T W Q in the local bases Q. Both give the
   * same step; the force form's block is the stick set (and the Robin
   * rows), the velocity form's the slip set. The step takes the smaller
   * one: while most of Gamma_3 sticks a step costs a product with W and a
   * small factorisation, and no step factorises more than the whole of D.
   */
  class DelassusOperator
  {
  public:
    enum class Form
    {
      force,
      velocity,
      smaller
    };

    DelassusOperator() = default;

    /** Takes D with m = n_components unknowns per node; forms W if D is
     *  positive definite with cond(D) <= 1e4. */
    DelassusOperator(const FullMatrix<double> &D,
                     const unsigned int        n_components);

    unsigned int size() const;

    /** y = D x. */
    void vmult(Vector<double> &y, const Vector<double> &x) const;

    /** The forces eta and velocities v = v_free - D eta of one Newton step
     *  for the given linearisation; v_p = 0 on stick nodes. On entry
     *  (eta, v) is the current iterate, the first guess where a block is
     *  solved by GMRES. The form is chosen by size unless given (the tests
     *  compare them). */
    void newton_step(const std::vector<NodeLinearisation> &linearisation,
                     const Vector<double>                 &v_free,
                     Vector<double>                       &eta,
                     Vector<double>                       &v,
                     const Form form = Form::smaller) const;

    /** The curvature test of friction.h: whether the Hessian of E on the
     *  slip set of this linearisation (with the true slopes) is positive
     *  definite, from W (the velocity form, where W is formed) or from D
     *  alone (the force form; the tests compare them). */
    Curvature
    curvature_on_slip_set(const std::vector<NodeLinearisation> &linearisation,
                          const Form form = Form::smaller) const;

    /** How many Newton steps' blocks were solved by GMRES preconditioned
     *  with the factor of an earlier block. */
    unsigned int preconditioned_solves() const;

  private:
    /** The block of a Newton step: of W (velocity form) or D, rotated by
     *  the nodes' bases Q, on these unknowns, plus the diagonal shift;
     *  `weakening` where a row has a weakening slope. */
    struct StepBlock
    {
      bool                                   velocity_form;
      const std::vector<FullMatrix<double>> &Q;
      const std::vector<unsigned int>       &unknowns;
      const Vector<double>                  &shift;
      bool                                   weakening;
    };

    void solve_block(const StepBlock      &block,
                     const Vector<double> &rhs,
                     Vector<double>       &x) const;
    /** GMRES on a Newton step's block preconditioned with the factor of
     *  the last factorised one; false where it did not converge. */
    bool solve_block_by_gmres(const StepBlock      &block,
                              const Vector<double> &rhs,
                              Vector<double>       &x) const;
    /** A Newton step's block formed, factorised (the factor kept as the
     *  last one) and solved. */
    void factorise_and_solve_block(const StepBlock      &block,
                                   const Vector<double> &rhs,
                                   Vector<double>       &x) const;

    /** W = D^{-1} is formed only while cond(D) <= 1 / this: eta = W (v_free
     *  - v) leaves a velocity residual cond(D) times that of a solve. */
    static constexpr double min_reciprocal_condition = 1e-4;
    /** A Newton block of at least this many unknowns that differs from the
     *  last factorised one in at most max_changed_unknowns is solved by
     *  GMRES preconditioned with that factor, to the relative residual
     *  gmres_reduction in at most gmres_max_iterations (else factorised). */
    static constexpr unsigned int min_unknowns_for_gmres = 400;
    static constexpr unsigned int max_changed_unknowns   = 10;
    static constexpr unsigned int gmres_max_iterations   = 10;
    static constexpr double       gmres_reduction        = 1e-4;

    unsigned int             n_components = 1;
    LAPACKFullMatrix<double> D;
    /** D^{-1}, empty where D is singular (a tangent that cannot move) or
     *  its condition number is above 1 / min_reciprocal_condition. */
    LAPACKFullMatrix<double> W;

    /** The last factorised block of a Newton step and the form and
     *  unknowns it belongs to (a cache: the steps stay const). */
    struct FactorisedBlock
    {
      bool                                      velocity_form = false;
      std::vector<unsigned int>                 unknowns;
      std::unique_ptr<LAPACKFullMatrix<double>> factor;
      // Whether the factor is Cholesky's (else LU's).
      bool cholesky = false;
    };
    mutable FactorisedBlock last_factorised_block;
    /** W v_free of the velocity form, for the last v_free. */
    mutable Vector<double> last_v_free;
    mutable Vector<double> W_v_free;
    mutable unsigned int   n_preconditioned_solves = 0;
  };


  /** The Tresca problem on a dense Delassus operator (friction.h). */
  TrescaResult solve_tresca(const DelassusOperator &D,
                            const Vector<double>   &v_free,
                            const Vector<double>   &g,
                            const Vector<double>   &c,
                            const unsigned int      max_iterations,
                            Vector<double>         &eta,
                            Vector<double>         &v,
                            std::vector<NodeState> &state);
} // namespace Contact

#endif
