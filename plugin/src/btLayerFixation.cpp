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

#include "BulletShockPropagation/btLayerFixation.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

namespace
{
/// J W J^T of one side of a row: m^-1 |n|^2 + (r x n) . I^-1 (r x n).
btScalar sideInverseMass(const btSolverBody& body, const btVector3& linearAxis, const btVector3& angularAxis,
						 const btVector3& angularComponent)
{
	const btRigidBody* rb = body.m_originalBody;
	if (!rb)
	{
		return btScalar(0);  // Bullet's shared fixed body: static
	}
	return rb->getInvMass() * linearAxis.length2() + angularAxis.dot(angularComponent);
}

/// J u_ext: the part of one side's external impulse (gravity, gyroscopic torque) that Bullet
/// put into the row's velocity error (friction rows leave out the torque).
btScalar externalVelocity(const btSolverBody& body, const btVector3& linearAxis, const btVector3& angularAxis, btSolverRowKind kind)
{
	if (!body.m_originalBody)
	{
		return btScalar(0);
	}
	btScalar u = linearAxis.dot(body.m_externalForceImpulse);
	if (kind == BT_ROW_CONTACT || kind == BT_ROW_JOINT)
	{
		u += angularAxis.dot(body.m_externalTorqueImpulse);
	}
	return u;
}

/// J u of the motion the row assumed for one side that is now fixated and should not count.
btScalar removedVelocity(const btSolverBody& body, const btVector3& linearAxis, const btVector3& angularAxis,
						 btSolverRowKind kind, btShockPropagationFixationMode mode)
{
	if (!body.m_originalBody)
	{
		return btScalar(0);
	}
	// The external impulse (gravity) of this sub-step: a fixated body does not accelerate.
	btScalar u = externalVelocity(body, linearAxis, angularAxis, kind);
	// Zero-velocity mode: the fixated body is at rest for the layer (OpenTissue's set_fixed).
	if (mode == BT_FIXATION_ZERO_VELOCITY)
	{
		u += linearAxis.dot(body.m_linearVelocity) + angularAxis.dot(body.m_angularVelocity);
	}
	else if (mode == BT_FIXATION_KEEP_LINEAR_VELOCITY)
	{
		u += angularAxis.dot(body.m_angularVelocity);
	}
	return u;
}
/// D14 for a contact row with fixated side F and free side R: how much of F's approach speed
/// a_F = -J_F u_F (> 0: F moves towards R) to take out of the row's velocity error
/// (btInelasticApproach). A heavy support (w_F << w_R) keeps its speed and carries the stack; a
/// light fixated body thrown into a heavy one (by a joint or a correction) no longer throws it at
/// its own speed.
btScalar inelasticExcess(const btSolverBody& fixated, const btVector3& fixatedLinear, const btVector3& fixatedAngular,
						 const btVector3& fixatedAngularComponent, const btSolverBody& free, const btVector3& freeLinear,
						 const btVector3& freeAngular, const btVector3& freeAngularComponent, btShockPropagationFixationMode mode)
{
	if (mode == BT_FIXATION_ZERO_VELOCITY || !fixated.m_originalBody || !free.m_originalBody)
	{
		return btScalar(0);  // at rest, or a static end: nothing to limit
	}
	const btScalar approach = -btFixatedEndVelocity(fixated, fixatedLinear, fixatedAngular, mode);
	const btScalar away = freeLinear.dot(free.m_linearVelocity) + freeAngular.dot(free.m_angularVelocity);
	const btScalar wF = sideInverseMass(fixated, fixatedLinear, fixatedAngular, fixatedAngularComponent);
	const btScalar wR = sideInverseMass(free, freeLinear, freeAngular, freeAngularComponent);
	return approach - btInelasticApproach(approach, away, wF, wR);
}
}  // namespace

btScalar btFixatedEndVelocity(const btSolverBody& body, const btVector3& linearAxis, const btVector3& angularAxis,
							  btShockPropagationFixationMode mode)
{
	if (mode == BT_FIXATION_ZERO_VELOCITY)
	{
		return btScalar(0);
	}
	btScalar u = linearAxis.dot(body.m_linearVelocity);
	if (mode == BT_FIXATION_KEEP_VELOCITY)
	{
		u += angularAxis.dot(body.m_angularVelocity);
	}
	return u;
}

btScalar btInelasticApproach(btScalar approach, btScalar away, btScalar wFixated, btScalar wFree)
{
	if (!(approach > away) || !(approach > btScalar(0)) || !(wFixated + wFree > SIMD_EPSILON))
	{
		return approach;
	}
	const btScalar common = (approach * wFree + away * wFixated) / (wFixated + wFree);
	return btMax(common, btScalar(0));
}

void btFixateSolverRow(btSolverConstraint& row, btSolverRowKind kind, const btSolverBody& bodyA, const btSolverBody& bodyB,
					   bool fixA, bool fixB, const btLayerFixationParams& params)
{
	if (!fixA && !fixB)
	{
		return;
	}
	const btScalar jacOld = row.m_jacDiagABInv;
	// The row's right-hand side is (velocity error) * effective mass; recover the error.
	btScalar error = jacOld != btScalar(0) ? row.m_rhs / jacOld : btScalar(0);
	// Contact rows carry cfm * effective mass; the others an absolute cfm.
	const btScalar cfm = (kind == BT_ROW_CONTACT && jacOld != btScalar(0)) ? row.m_cfm / jacOld : btScalar(0);
	// rel_vel = J_A u_A + J_B u_B enters the error with a minus sign (joints weighted by damping).
	const btScalar weight = kind == BT_ROW_JOINT ? params.m_jointDamping : btScalar(1);

	if (params.m_inelasticFixation && kind == BT_ROW_CONTACT && fixA != fixB)
	{
		// Before the fixated side's angular component is zeroed below: it holds W_F J_F^T.
		error -= fixA ? inelasticExcess(bodyA, row.m_contactNormal1, row.m_relpos1CrossNormal, row.m_angularComponentA, bodyB,
										row.m_contactNormal2, row.m_relpos2CrossNormal, row.m_angularComponentB, params.m_mode)
					  : inelasticExcess(bodyB, row.m_contactNormal2, row.m_relpos2CrossNormal, row.m_angularComponentB, bodyA,
										row.m_contactNormal1, row.m_relpos1CrossNormal, row.m_angularComponentA, params.m_mode);
	}

	btScalar denominator = cfm;
	if (fixA)
	{
		error += weight * removedVelocity(bodyA, row.m_contactNormal1, row.m_relpos1CrossNormal, kind, params.m_mode);
		row.m_angularComponentA.setZero();
	}
	else
	{
		denominator += sideInverseMass(bodyA, row.m_contactNormal1, row.m_relpos1CrossNormal, row.m_angularComponentA);
	}
	if (fixB)
	{
		error += weight * removedVelocity(bodyB, row.m_contactNormal2, row.m_relpos2CrossNormal, kind, params.m_mode);
		row.m_angularComponentB.setZero();
	}
	else
	{
		denominator += sideInverseMass(bodyB, row.m_contactNormal2, row.m_relpos2CrossNormal, row.m_angularComponentB);
	}

	if (!(denominator > SIMD_EPSILON))
	{
		// Both ends immovable (or a degenerate Jacobian): the row can do nothing.
		row.m_jacDiagABInv = btScalar(0);
		row.m_rhs = btScalar(0);
		row.m_rhsPenetration = btScalar(0);
		row.m_lowerLimit = btScalar(0);
		row.m_upperLimit = btScalar(0);
		return;
	}
	const btScalar relaxation = (kind == BT_ROW_CONTACT || kind == BT_ROW_FRICTION) ? params.m_sor : btScalar(1);
	const btScalar jacNew = relaxation / denominator;
	row.m_jacDiagABInv = jacNew;
	row.m_rhs = error * jacNew;
	if (kind == BT_ROW_CONTACT)
	{
		row.m_cfm = cfm * jacNew;
	}
}

void btRemoveExternalImpulse(btSolverConstraint& row, btSolverRowKind kind, const btSolverBody& bodyA, const btSolverBody& bodyB,
							 bool sideA, bool sideB, btScalar jointDamping)
{
	// rhs = (b - J_A (u_A + u_A^ext) - J_B (u_B + u_B^ext)) * m_jacDiagABInv: add the external terms back.
	const btScalar weight = kind == BT_ROW_JOINT ? jointDamping : btScalar(1);
	btScalar u = btScalar(0);
	if (sideA) u += externalVelocity(bodyA, row.m_contactNormal1, row.m_relpos1CrossNormal, kind);
	if (sideB) u += externalVelocity(bodyB, row.m_contactNormal2, row.m_relpos2CrossNormal, kind);
	row.m_rhs += weight * u * row.m_jacDiagABInv;
}

btRigidBody* btFixateSolverBody(btSolverBody& body, btShockPropagationFixationMode mode)
{
	btRigidBody* original = body.m_originalBody;
	body.internalSetInvMass(btVector3(0, 0, 0));
	body.m_externalForceImpulse.setZero();
	body.m_externalTorqueImpulse.setZero();
	body.internalGetDeltaLinearVelocity().setZero();  // drop warm-start impulses applied at setup
	body.internalGetDeltaAngularVelocity().setZero();
	body.internalGetPushVelocity().setZero();
	body.internalGetTurnVelocity().setZero();
	if (mode == BT_FIXATION_ZERO_VELOCITY)
	{
		body.m_linearVelocity.setZero();
		body.m_angularVelocity.setZero();
	}
	body.m_originalBody = 0;  // write-back skips it: the btRigidBody stays exactly as it was
	return original;
}
