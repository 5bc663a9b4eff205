/*
BulletShockPropagation - velocity-based shock propagation for Bullet
Copyright (c) 2026 the BulletShockPropagation authors

This software is provided 'as-is', without any express or implied warranty.
In no event will the authors be held liable for any damages arising from the use of this software.
Permission is granted to anyone to use this software for any purpose,
including commercial applications, and to alter it and redistribute it freely,
subject to the following restrictions:
1. The origin of this software must not be misrepresented; you must not claim that you wrote the original software. If you use this software in a product, an acknowledgment in the product documentation would be appreciated but is not required.
2. Altered source versions must be plainly marked as such, and must not be misrepresented as being the original software.
3. This notice may not be removed or altered from any source distribution.
*/

#ifndef BT_SHOCK_PROPAGATION_SLIDING_COMPOSITE_H
#define BT_SHOCK_PROPAGATION_SLIDING_COMPOSITE_H

#include "BulletDynamics/ConstraintSolver/btSolverBody.h"
#include "BulletDynamics/ConstraintSolver/btSolverConstraint.h"
#include "LinearMath/btAlignedObjectArray.h"

/// D23: a base that slides carries the inertia of what rests on it. Private to the plugin.
///
/// The layer passes fixate a layer's lower bodies: each body is solved as if what it carries
/// were not there, and the weight pass hands that back top-down. For a body at rest on its
/// support that is exact (its support's friction holds it still whatever it carries). For a
/// body whose support slides it is not: its friction is saturated, so everything resting on it
/// moves with it, and a top-down pass settles the bodies above at the base's velocity before the
/// base has felt their inertia (docs/design.md, section 4h).
///
/// The composite: the base B and the sub-stack S resting on it (everything above B through
/// contacts, no joints) with mass M = sum of m_i. Where the layer pass reaches B:
///  1. S's velocities along the support plane (across the contact normal n) are set to their
///     common momentum velocity, sum(m_i v_i) / M (momentum kept: the sub-stack sticks);
///  2. B's friction rows against its support are swept with B's linear inverse mass 1 / M (its
///     normal rows keep m_B: the composite only changes sliding, not support);
///  3. after B's layer, S moves across n by B's change dv: the rows' impulse M dv is the
///     composite's momentum, and the bodies above have nothing left to drag (no reaction to
///     hand down for it);
///  4. the weight pass sweeps B's friction rows with 1 / M again, unless the load handed to B
///     across n shows that S did not move with it (then B is solved alone), and moves S by the
///     velocity change that impulse gives the composite; at the end S is equalized once more.
struct btSlidingComposite
{
	int m_base = -1;                 ///< solver body of B
	int m_node = -1;                 ///< graph node of B
	int m_layer = -1;                ///< B's layer (B is one of its free bodies)
	int m_local = -1;                ///< weight pass: B's index among its layer's free bodies
	btScalar m_massRatio = 1;        ///< M / m_B (unitless, >= 1)
	btVector3 m_normal;              ///< unit normal of the sliding support contact
	btVector3 m_velocityBefore;      ///< m/s: B's velocity when its layer pass began (after step 1)
	btVector3 m_shift;               ///< m/s: weight pass, the composite's velocity change across n
	btVector3 m_savedInvMass;        ///< B's solver-body inverse mass (per axis) while active
	int m_firstMember = 0;           ///< S (B first) in btLayeredPasses' member array
	int m_numMembers = 0;
	bool m_held = true;              ///< the weight pass found S moving with B (else B is solved alone)
};

/// The row's remaining velocity error as Bullet's kernel sees it (m/s): what one more kernel call
/// would change the row's velocity by, before clamping.
btScalar btRowVelocityError(const btSolverConstraint& row, btAlignedObjectArray<btSolverBody>& bodies);

/// How fast the row's two ends slide along it when the step begins (m/s): J (v + external force
/// impulse), with last step's velocities and this step's forces, before any impulse.
btScalar btRowSlipAtSetup(const btSolverConstraint& row, const btAlignedObjectArray<btSolverBody>& bodies);

/// Velocities of `count` solver bodies across `normal` set to their common momentum velocity
/// (momentum kept; the parts along `normal` untouched).
void btEqualizeAcross(btAlignedObjectArray<btSolverBody>& bodies, const int* members, int count, const btVector3& normal);

/// The body's velocity change so far (its solver body's delta) set to `delta` across `normal`; the
/// part along `normal` untouched.
void btSetDeltaAcross(btSolverBody& body, const btVector3& delta, const btVector3& normal);

/// Re-derive a friction row whose end A (ratioA > 1) or B carries a composite: that end's linear
/// inverse mass becomes m^-1 / ratio in the row's effective mass; its velocity error is kept.
/// sor: the row's relaxation (btContactSolverInfo::m_sor).
void btCompositeFrictionRow(btSolverConstraint& row, const btSolverBody& bodyA, const btSolverBody& bodyB, btScalar ratioA, btScalar ratioB,
							btScalar sor);

#endif  // BT_SHOCK_PROPAGATION_SLIDING_COMPOSITE_H
