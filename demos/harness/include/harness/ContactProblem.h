// The contact problem of one simulation step, as plain numbers: the rows Bullet builds for the
// step's contacts, the bodies' inverse masses and free velocities, and the impulse a solver applied
// to each row. Filled by ContactRecorder (harness/ContactRecorder.h); solved to high accuracy by
// the Eigen reference (demos/reference). Not part of the shipped plugin.
//
// The problem (velocity level, one step of dt, inelastic, box friction as in Bullet's rows):
//   w = A lambda + b,   A = J W J^T,   b_i = J_i u_free + max(0, gap_i) / dt
//   normal row:   0 <= lambda_i  _|_  w_i >= 0
//   friction row: -mu lambda_n <= lambda_i <= mu lambda_n, w_i >= 0 at the lower bound, w_i <= 0
//                 at the upper bound, w_i = 0 between (lambda_n: the row's normal row)
// u_free is each body's velocity at the start of the step plus the external (gravity) impulse;
// W = diag(1/m I3, I^-1 world). A speculative contact (gap > 0) may close by gap / dt. No
// Baumgarte or split-impulse bias: stabilization is not part of the physical problem.
#pragma once

#include <vector>

class btCollisionObject;

namespace harness
{
struct ContactProblem
{
	/// A body with finite mass; static and kinematic bodies are not unknowns (their velocity is in b).
	struct Body
	{
		double invMass = 0;          ///< 1/kg
		double invInertia[9] = {};   ///< world inverse inertia, row major (1/(kg m^2))
	};

	enum RowKind
	{
		kNormal = 0,
		kFriction = 1
	};

	struct Row
	{
		RowKind kind = kNormal;
		int bodyA = -1, bodyB = -1;  ///< indices into bodies, -1 for a static or kinematic body
		double jacobianA[6] = {};    ///< linear (3) then angular (3) part for body A
		double jacobianB[6] = {};
		double b = 0;                ///< m/s: J u_free + max(0, gap) / dt
		int normalRow = -1;          ///< friction rows: index of their normal row
		double mu = 0;               ///< friction rows: coefficient
		double solverImpulse = 0;    ///< N s: what the solver under test applied over the step
		const btCollisionObject* objectA = nullptr;  ///< for grouping rows by body pair
		const btCollisionObject* objectB = nullptr;
	};

	double timeStep = 0;  ///< s
	std::vector<Body> bodies;
	std::vector<Row> rows;
};
}  // namespace harness
