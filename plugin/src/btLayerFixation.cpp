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

#include "btLayerFixation.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

namespace
{
/// J W J^T of one side of a row: m^-1 |n|^2 + (r x n) . I^-1 (r x n).
btScalar sideInverseMass(const btSolverBody& body, const btVector3& linearAxis, const btVector3& angularAxis,
						 const btVector3& angularComponent)
{
	const btRigidBody* rb = body.m_originalBody;
	if (!rb) return btScalar(0);  // Bullet's shared fixed body: static
	return rb->getInvMass() * linearAxis.length2() + angularAxis.dot(angularComponent);
}

/// A rigid motion of a solver body: linear and angular velocity.
struct btBodyMotion
{
	btVector3 m_linear;
	btVector3 m_angular;
};

/// J u of a motion of one side of a row.
btScalar along(const btBodyMotion& motion, const btVector3& linearAxis, const btVector3& angularAxis)
{
	return linearAxis.dot(motion.m_linear) + angularAxis.dot(motion.m_angular);
}

/// J u of the part of a fixated side's motion u that the mode hides from the layer above (D1).
btScalar modeHidden(const btBodyMotion& motion, const btVector3& linearAxis, const btVector3& angularAxis, btSolverRowKind kind,
					const btVector3& contactNormal, btShockPropagationFixationMode mode)
{
	if (mode == BT_FIXATION_KEEP_VELOCITY) return btScalar(0);
	if (mode == BT_FIXATION_KEEP_LINEAR_AND_TWIST && kind == BT_ROW_JOINT) return btScalar(0);
	btVector3 omega = motion.m_angular;
	if (mode == BT_FIXATION_KEEP_LINEAR_AND_TWIST)
	{
		// Keep the spin about the contact normal (it moves the upper body along, as a turntable
		// does); hide the tilt, which is what moves the contact points along the normal.
		const btScalar length2 = contactNormal.length2();
		if (length2 > SIMD_EPSILON) omega -= contactNormal * (omega.dot(contactNormal) / length2);
		return angularAxis.dot(omega);
	}
	const btScalar angular = angularAxis.dot(omega);
	if (mode == BT_FIXATION_KEEP_LINEAR_VELOCITY) return angular;
	return linearAxis.dot(motion.m_linear) + angular;
}

/// J u of what the layer above does not see of a fixated side. Bullet set the row up with
/// u + u_ext (external impulse: gravity; friction rows leave out the torque); the sweeps add
/// delta u from the solver body. The mode hides its part (D1). D32: along a contact, friction or
/// rolling row, a support that nothing drives (no joint or moving kinematic body, directly or
/// through contacts) and whose shown motion is slower than the rest speed shows none: that motion
/// is the solve's error.
btScalar hiddenVelocity(const btSolverBody& body, const btVector3& linearAxis, const btVector3& angularAxis, btSolverRowKind kind,
						const btVector3& contactNormal, const btLayerFixationParams& params, bool driven)
{
	if (!body.m_originalBody) return btScalar(0);  // Bullet's shared fixed body: static
	btSolverBody& state = const_cast<btSolverBody&>(body);  // Bullet's delta accessors are not const
	btBodyMotion motion{body.m_linearVelocity + body.m_externalForceImpulse + state.internalGetDeltaLinearVelocity(),
						body.m_angularVelocity + state.internalGetDeltaAngularVelocity()};
	if (kind == BT_ROW_CONTACT || kind == BT_ROW_JOINT) motion.m_angular += body.m_externalTorqueImpulse;
	const btScalar hidden = modeHidden(motion, linearAxis, angularAxis, kind, contactNormal, params.m_mode);
	if (driven || !(params.m_restSpeed > btScalar(0)) || kind == BT_ROW_JOINT || params.m_mode == BT_FIXATION_ZERO_VELOCITY) return hidden;
	const btScalar full = along(motion, linearAxis, angularAxis);
	return btFabs(full - hidden) < params.m_restSpeed ? full : hidden;
}

/// J u of one end of a contact row as the sweeps see it: velocity, this step's external impulse
/// (gravity, torque) and the deltas of the solve so far.
btScalar velocityAlong(const btSolverBody& body, const btVector3& linearAxis, const btVector3& angularAxis)
{
	btSolverBody& state = const_cast<btSolverBody&>(body);  // Bullet's delta accessors are not const
	return linearAxis.dot(body.m_linearVelocity + body.m_externalForceImpulse + state.internalGetDeltaLinearVelocity()) +
		   angularAxis.dot(body.m_angularVelocity + body.m_externalTorqueImpulse + state.internalGetDeltaAngularVelocity());
}

/// D14 for a contact row with fixated side F and free side R: how much of F's approach speed
/// a_F = -J_F u_F (> 0: F moves towards R) to take out of the row's velocity error, so that F
/// pushes R at most at the common normal velocity of an inelastic collision of the two,
/// (a_F w_R + a_R w_F) / (w_F + w_R) with w = J W J^T of each side. A support heavier than its
/// load is unaffected; a light fixated body no longer throws a heavy one at its own speed.
/// hidden: the fixated end's hiddenVelocity for this row.
btScalar inelasticExcess(const btSolverBody& fixated, const btVector3& fixatedLinear, const btVector3& fixatedAngular,
						 const btVector3& fixatedAngularComponent, const btSolverBody& free, const btVector3& freeLinear,
						 const btVector3& freeAngular, const btVector3& freeAngularComponent, btScalar hidden,
						 btShockPropagationFixationMode mode)
{
	if (!fixated.m_originalBody || !free.m_originalBody || mode == BT_FIXATION_ZERO_VELOCITY) return btScalar(0);
	// Velocities as the row sees them: set up with u + u_ext (gravity), swept with the deltas;
	// the fixated end as its mode shows it.
	const btScalar approach = -(velocityAlong(fixated, fixatedLinear, fixatedAngular) - hidden);
	const btScalar away = velocityAlong(free, freeLinear, freeAngular);
	const btScalar wF = sideInverseMass(fixated, fixatedLinear, fixatedAngular, fixatedAngularComponent);
	const btScalar wR = sideInverseMass(free, freeLinear, freeAngular, freeAngularComponent);
	if (!(approach > away) || !(approach > btScalar(0)) || !(wF + wR > SIMD_EPSILON)) return btScalar(0);
	const btScalar common = btMax((approach * wR + away * wF) / (wF + wR), btScalar(0));
	return approach - common;
}
}  // namespace

void btFixateSolverRow(btSolverConstraint& row, btSolverRowKind kind, const btSolverBody& bodyA, const btSolverBody& bodyB,
					   bool fixA, bool fixB, const btLayerFixationParams& params, const btVector3& contactNormal, bool drivenA, bool drivenB)
{
	if (!fixA && !fixB) return;
	const btScalar jacOld = row.m_jacDiagABInv;
	// The row's right-hand side is (velocity error) * effective mass; recover the error.
	btScalar error = jacOld != btScalar(0) ? row.m_rhs / jacOld : btScalar(0);
	// Contact rows carry cfm * effective mass; the others an absolute cfm.
	const btScalar cfm = (kind == BT_ROW_CONTACT && jacOld != btScalar(0)) ? row.m_cfm / jacOld : btScalar(0);
	// rel_vel = J_A u_A + J_B u_B enters the error with a minus sign (joints weighted by damping).
	const btScalar weight = kind == BT_ROW_JOINT ? params.m_jointDamping : btScalar(1);

	// What each fixated end's mode hides (D1, D32), computed once: D14 reads it too.
	const btScalar hiddenA = fixA ? hiddenVelocity(bodyA, row.m_contactNormal1, row.m_relpos1CrossNormal, kind, contactNormal, params, drivenA) : btScalar(0);
	const btScalar hiddenB = fixB ? hiddenVelocity(bodyB, row.m_contactNormal2, row.m_relpos2CrossNormal, kind, contactNormal, params, drivenB) : btScalar(0);
	if (params.m_inelasticFixation && kind == BT_ROW_CONTACT && fixA != fixB)
	{
		// D14, before the fixated side's angular component is zeroed below (it holds W_F J_F^T).
		error -= fixA ? inelasticExcess(bodyA, row.m_contactNormal1, row.m_relpos1CrossNormal, row.m_angularComponentA, bodyB,
										row.m_contactNormal2, row.m_relpos2CrossNormal, row.m_angularComponentB, hiddenA, params.m_mode)
					  : inelasticExcess(bodyB, row.m_contactNormal2, row.m_relpos2CrossNormal, row.m_angularComponentB, bodyA,
										row.m_contactNormal1, row.m_relpos1CrossNormal, row.m_angularComponentA, hiddenB, params.m_mode);
	}

	btScalar denominator = cfm;
	if (fixA)
	{
		error += weight * hiddenA;
		row.m_angularComponentA.setZero();
	}
	else
	{
		denominator += sideInverseMass(bodyA, row.m_contactNormal1, row.m_relpos1CrossNormal, row.m_angularComponentA);
	}
	if (fixB)
	{
		error += weight * hiddenB;
		row.m_angularComponentB.setZero();
	}
	else
	{
		denominator += sideInverseMass(bodyB, row.m_contactNormal2, row.m_relpos2CrossNormal, row.m_angularComponentB);
	}

	if (!(denominator > SIMD_EPSILON))
	{
		// Both ends immovable (or a degenerate Jacobian): the row can do nothing this layer.
		row.m_jacDiagABInv = btScalar(0);
		row.m_rhs = btScalar(0);
		row.m_cfm = btScalar(0);
		return;
	}
	const btScalar relaxation = (kind == BT_ROW_CONTACT || kind == BT_ROW_FRICTION) ? params.m_sor : btScalar(1);
	const btScalar jacNew = relaxation / denominator;
	row.m_jacDiagABInv = jacNew;
	row.m_rhs = error * jacNew;
	if (kind == BT_ROW_CONTACT) row.m_cfm = cfm * jacNew;
}
