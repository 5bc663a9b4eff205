// Accuracy reference on Eigen: the contact problem of one step (harness/ContactProblem.h) solved to
// high accuracy, and how far a solver's impulses are from solving it. Not part of the shipped plugin.
//
// Method: proximal point around a semismooth Newton method on the minimum map.
//   outer:  lambda_{k+1} solves the problem with A + eps I and b - eps lambda_k (eps = 1e-8 of the
//           mean diagonal of A). A is singular whenever four coplanar points carry one face (the
//           split of the load among them is statically indeterminate); the regularized problem
//           has a unique solution and the outer loop converges to a solution of the original one.
//   inner:  phi_i(lambda) = lambda_i - mid(lo_i, lambda_i - w_i / A_ii, hi_i) = 0 with the Newton
//           matrix of the active bounds, solved by Eigen's SparseLU (COLAMD), Armijo line search on
//           |phi|^2, projected Gauss-Seidel sweeps when the line search fails.
// Stops when the natural residual of the original problem (below) is <= tolerance * |lambda|.
//
// Measures, for impulses x (N s per row) against the reference lambda*:
//  - complementarity residual: |r(x)|_2 / |lambda*|_2 with r_i = x_i - mid(lo_i(x), x_i - w_i / A_ii,
//    hi_i(x)), w = A x + b. In impulse units: the change one Jacobi projection would make to row i.
//    0 exactly when x solves the problem.
//  - distance: |x - lambda*|_A / |lambda*|_A with |y|_A^2 = y^T A y = |W^1/2 J^T y|^2: the
//    difference of the impulses each body receives, in the kinetic-energy norm. Blind to the
//    indeterminate split among coplanar points, which no solver can be blamed for.
// Both are computed with the full Jacobian, both bodies of every row free: a solver that fixates
// bodies (the plugin) is measured on what its impulses would do to the real bodies.
#pragma once

#include <harness/ContactProblem.h>

#include <vector>

namespace reference
{
struct Options
{
	double tolerance = 1e-10;    ///< relative natural residual to reach
	double regularization = 1e-8;  ///< eps relative to the mean diagonal of A
	int maxOuterIterations = 200;
	int maxNewtonIterations = 60;  ///< per outer iteration
};

struct Solution
{
	std::vector<double> impulse;  ///< N s per row
	double residual = 0;          ///< relative natural residual of `impulse`
	bool converged = false;
	int outerIterations = 0;
	int newtonIterations = 0;     ///< summed over outer iterations
};

/// Solves the problem to `options.tolerance` (or as far as the iteration limits allow).
Solution solve(const harness::ContactProblem& problem, const Options& options = Options());

/// |r(x)|_2 (N s), the natural residual of impulses x (see above).
double naturalResidual(const harness::ContactProblem& problem, const std::vector<double>& x);

/// |x - y|_A (sqrt of kg m^2/s^2, i.e. sqrt(2 x kinetic energy) of the impulse difference).
double energyDistance(const harness::ContactProblem& problem, const std::vector<double>& x, const std::vector<double>& y);

/// The solver impulses recorded in the problem's rows.
std::vector<double> solverImpulses(const harness::ContactProblem& problem);

/// What the sweep reports per step sample.
struct Accuracy
{
	int rows = 0;
	double residual = 0;           ///< solver: |r(x)| / |lambda*|
	double distance = 0;           ///< solver: |x - lambda*|_A / |lambda*|_A
	double referenceResidual = 0;  ///< the reference's own relative residual
	bool referenceConverged = false;
	double referenceMs = 0;        ///< wall time of the reference solve
};

/// Solves the reference and measures the recorded solver impulses against it. Rows = 0 (and the
/// measures NaN) when the problem has no rows or carries no load.
Accuracy measure(const harness::ContactProblem& problem, const Options& options = Options());

/// The same against a reference already solved for this problem (referenceMs stays 0).
Accuracy measureAgainst(const harness::ContactProblem& problem, const Solution& reference);
}  // namespace reference
