#include "reference/ContactReference.h"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace reference
{
namespace
{
using SparseMatrix = Eigen::SparseMatrix<double>;
using Vector = Eigen::VectorXd;
using Problem = harness::ContactProblem;

/// Where a row's projection lands: between its bounds, or on one of them.
enum Bound
{
	kFree,
	kLower,
	kUpper
};

/// A = J W J^T (symmetric positive semi-definite), assembled once per problem.
struct Assembled
{
	SparseMatrix A;
	Vector b;
	Vector diagonal;
	std::vector<int> normalRow;  // -1 for normal rows
	std::vector<double> mu;
};

Assembled assemble(const Problem& problem)
{
	const int n = int(problem.rows.size());
	const int unknowns = 6 * int(problem.bodies.size());
	std::vector<Eigen::Triplet<double>> jt, wt;
	for (int i = 0; i < n; ++i)
	{
		const Problem::Row& row = problem.rows[i];
		for (int k = 0; k < 6; ++k)
		{
			if (row.bodyA >= 0 && row.jacobianA[k] != 0) jt.emplace_back(i, 6 * row.bodyA + k, row.jacobianA[k]);
			if (row.bodyB >= 0 && row.jacobianB[k] != 0) jt.emplace_back(i, 6 * row.bodyB + k, row.jacobianB[k]);
		}
	}
	for (size_t body = 0; body < problem.bodies.size(); ++body)
	{
		const int base = 6 * int(body);
		for (int k = 0; k < 3; ++k) wt.emplace_back(base + k, base + k, problem.bodies[body].invMass);
		for (int r = 0; r < 3; ++r)
			for (int c = 0; c < 3; ++c)
				if (problem.bodies[body].invInertia[3 * r + c] != 0) wt.emplace_back(base + 3 + r, base + 3 + c, problem.bodies[body].invInertia[3 * r + c]);
	}
	SparseMatrix J(n, unknowns), W(unknowns, unknowns);
	J.setFromTriplets(jt.begin(), jt.end());
	W.setFromTriplets(wt.begin(), wt.end());
	Assembled out;
	out.A = SparseMatrix(J * W * J.transpose());
	out.A.makeCompressed();
	out.b.resize(n);
	out.diagonal = out.A.diagonal();
	out.normalRow.resize(n);
	out.mu.resize(n);
	for (int i = 0; i < n; ++i)
	{
		out.b[i] = problem.rows[i].b;
		out.normalRow[i] = problem.rows[i].kind == Problem::kFriction ? problem.rows[i].normalRow : -1;
		out.mu[i] = problem.rows[i].mu;
	}
	return out;
}

/// The problem lambda -> w = (A + eps I) lambda + q with its bounds; eps = 0, q = b is the original.
struct Shifted
{
	const Assembled& sys;
	double eps;
	Vector q;

	double scale(int i) const
	{
		const double d = sys.diagonal[i] + eps;
		return d > 0 ? 1.0 / d : 0.0;
	}
	void bounds(const Vector& x, int i, double& lo, double& hi) const
	{
		if (sys.normalRow[i] < 0)
		{
			lo = 0;
			hi = std::numeric_limits<double>::infinity();
			return;
		}
		const double limit = sys.mu[i] * std::max(0.0, x[sys.normalRow[i]]);
		lo = -limit;
		hi = limit;
	}
	/// phi(x) and which bound each row's projection sits on.
	Vector phi(const Vector& x, std::vector<Bound>* where) const
	{
		const Vector w = sys.A * x + eps * x + q;
		Vector out(x.size());
		if (where) where->resize(x.size());
		for (int i = 0; i < x.size(); ++i)
		{
			double lo, hi;
			bounds(x, i, lo, hi);
			const double trial = x[i] - scale(i) * w[i];
			Bound at = kFree;
			double projected = trial;
			if (trial <= lo) { projected = lo; at = kLower; }
			else if (trial >= hi) { projected = hi; at = kUpper; }
			if (scale(i) == 0) { projected = x[i]; at = kFree; }  // a row that moves nothing
			out[i] = x[i] - projected;
			if (where) (*where)[i] = at;
		}
		return out;
	}
	/// Projected Gauss-Seidel sweeps (the fallback when Newton's line search fails).
	void sweeps(Vector& x, int count) const
	{
		for (int s = 0; s < count; ++s)
		{
			for (int i = 0; i < x.size(); ++i)
			{
				if (scale(i) == 0) continue;
				double w = q[i] + eps * x[i];
				for (SparseMatrix::InnerIterator it(sys.A, i); it; ++it) w += it.value() * x[it.row()];  // column i = row i
				double lo, hi;
				bounds(x, i, lo, hi);
				x[i] = std::min(hi, std::max(lo, x[i] - scale(i) * w));
			}
		}
	}
};

/// Semismooth Newton on phi for one regularized problem, from x.
int newton(const Shifted& p, Vector& x, double tolerance, int maxIterations)
{
	const int n = int(x.size());
	std::vector<Bound> where;
	Vector f = p.phi(x, &where);
	double merit = 0.5 * f.squaredNorm();
	int iteration = 0;
	int failures = 0;
	Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
	for (; iteration < maxIterations && f.lpNorm<Eigen::Infinity>() > tolerance; ++iteration)
	{
		// Generalized Jacobian of phi: free rows c_i (A + eps I)_i; rows on a bound e_i -/+ d bound.
		std::vector<Eigen::Triplet<double>> ht;
		ht.reserve(p.sys.A.nonZeros() + 2 * n);
		for (int i = 0; i < n; ++i)
		{
			const double c = p.scale(i);
			if (where[i] == kFree && c != 0)
			{
				for (SparseMatrix::InnerIterator it(p.sys.A, i); it; ++it) ht.emplace_back(i, int(it.row()), c * it.value());
				ht.emplace_back(i, i, c * p.eps);
			}
			else
			{
				ht.emplace_back(i, i, 1.0);
				const int normal = p.sys.normalRow[i];
				if (normal >= 0 && x[normal] > 0 && where[i] != kFree)
					ht.emplace_back(i, normal, where[i] == kLower ? p.sys.mu[i] : -p.sys.mu[i]);
			}
		}
		SparseMatrix H(n, n);
		H.setFromTriplets(ht.begin(), ht.end());
		H.makeCompressed();
		lu.compute(H);
		bool stepped = false;
		if (lu.info() == Eigen::Success)
		{
			const Vector dx = lu.solve(-f);
			if (lu.info() == Eigen::Success && dx.allFinite())
			{
				for (double t = 1; t > 1e-6; t *= 0.5)
				{
					const Vector trial = x + t * dx;
					std::vector<Bound> trialWhere;
					const Vector trialF = p.phi(trial, &trialWhere);
					const double trialMerit = 0.5 * trialF.squaredNorm();
					if (trialMerit <= (1 - 1e-4 * t) * merit)
					{
						x = trial;
						f = trialF;
						where = trialWhere;
						merit = trialMerit;
						stepped = true;
						break;
					}
				}
			}
		}
		if (stepped)
		{
			failures = 0;
		}
		else
		{
			// No descent: a wrong active set far from the solution, or the rounding floor near it.
			if (++failures > 2) break;
			p.sweeps(x, 20);
			f = p.phi(x, &where);
			merit = 0.5 * f.squaredNorm();
		}
	}
	return iteration;
}
}  // namespace

double naturalResidual(const Problem& problem, const std::vector<double>& x)
{
	if (problem.rows.empty()) return 0;
	const Assembled sys = assemble(problem);
	const Shifted original{sys, 0.0, sys.b};
	return original.phi(Eigen::Map<const Vector>(x.data(), Eigen::Index(x.size())), nullptr).norm();
}

double energyDistance(const Problem& problem, const std::vector<double>& x, const std::vector<double>& y)
{
	if (problem.rows.empty()) return 0;
	const Assembled sys = assemble(problem);
	const Vector d = Eigen::Map<const Vector>(x.data(), Eigen::Index(x.size())) - Eigen::Map<const Vector>(y.data(), Eigen::Index(y.size()));
	return std::sqrt(std::max(0.0, d.dot(sys.A * d)));
}

std::vector<double> solverImpulses(const Problem& problem)
{
	std::vector<double> x;
	x.reserve(problem.rows.size());
	for (const Problem::Row& row : problem.rows) x.push_back(row.solverImpulse);
	return x;
}

Solution solve(const Problem& problem, const Options& options)
{
	Solution out;
	const int n = int(problem.rows.size());
	out.impulse.assign(n, 0.0);
	if (n == 0)
	{
		out.converged = true;
		return out;
	}
	const Assembled sys = assemble(problem);
	const double meanDiagonal = sys.diagonal.sum() / n;
	const double eps = options.regularization * std::max(meanDiagonal, 1e-300);
	const Shifted original{sys, 0.0, sys.b};

	Vector x = Vector::Zero(n);
	Shifted regularized{sys, eps, sys.b};
	regularized.sweeps(x, 50);  // a start inside the bounds, near the active set
	double best = std::numeric_limits<double>::infinity();
	int stalled = 0;
	for (; out.outerIterations < options.maxOuterIterations; ++out.outerIterations)
	{
		const double residual = original.phi(x, nullptr).norm();
		const double size = x.norm();
		if (residual <= options.tolerance * size || (size == 0 && residual == 0))
		{
			out.converged = true;
			break;
		}
		// Stop at the rounding floor: no 10% gain in five outer iterations.
		if (residual < 0.9 * best) { best = residual; stalled = 0; }
		else if (++stalled >= 5) break;
		regularized.q = sys.b - eps * x;
		out.newtonIterations += newton(regularized, x, 1e-3 * options.tolerance * std::max(size, 1e-300), options.maxNewtonIterations);
	}
	for (int i = 0; i < n; ++i) out.impulse[i] = x[i];
	const double size = x.norm();
	out.residual = size > 0 ? original.phi(x, nullptr).norm() / size : 0;
	return out;
}

Accuracy measureAgainst(const Problem& problem, const Solution& ref)
{
	Accuracy a;
	const double nan = std::numeric_limits<double>::quiet_NaN();
	a.residual = a.distance = nan;
	a.rows = int(problem.rows.size());
	a.referenceResidual = ref.residual;
	a.referenceConverged = ref.converged;
	if (a.rows == 0) return a;
	const Assembled sys = assemble(problem);
	const Shifted original{sys, 0.0, sys.b};
	const std::vector<double> solver = solverImpulses(problem);
	const Eigen::Map<const Vector> x(solver.data(), Eigen::Index(solver.size()));
	const Eigen::Map<const Vector> star(ref.impulse.data(), Eigen::Index(ref.impulse.size()));
	const double size = star.norm();
	const double energy = std::sqrt(std::max(0.0, star.dot(sys.A * star)));
	const Vector d = x - star;
	if (size > 0) a.residual = original.phi(x, nullptr).norm() / size;
	if (energy > 0) a.distance = std::sqrt(std::max(0.0, d.dot(sys.A * d))) / energy;
	return a;
}

Accuracy measure(const Problem& problem, const Options& options)
{
	if (problem.rows.empty()) return measureAgainst(problem, Solution());
	const auto start = std::chrono::steady_clock::now();
	const Solution ref = solve(problem, options);
	const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
	Accuracy a = measureAgainst(problem, ref);
	a.referenceMs = ms;
	return a;
}
}  // namespace reference
