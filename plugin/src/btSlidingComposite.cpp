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

#include "btSlidingComposite.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

btScalar btRowVelocityError(const btSolverConstraint& row, btAlignedObjectArray<btSolverBody>& bodies)
{
	if (row.m_jacDiagABInv == btScalar(0)) return btScalar(0);
	btSolverBody& a = bodies[row.m_solverBodyIdA];
	btSolverBody& b = bodies[row.m_solverBodyIdB];
	return (row.m_rhs - row.m_appliedImpulse * row.m_cfm) / row.m_jacDiagABInv - row.m_contactNormal1.dot(a.internalGetDeltaLinearVelocity()) -
		   row.m_relpos1CrossNormal.dot(a.internalGetDeltaAngularVelocity()) - row.m_contactNormal2.dot(b.internalGetDeltaLinearVelocity()) -
		   row.m_relpos2CrossNormal.dot(b.internalGetDeltaAngularVelocity());
}

btScalar btRowSlipAtSetup(const btSolverConstraint& row, const btAlignedObjectArray<btSolverBody>& bodies)
{
	const btSolverBody& a = bodies[row.m_solverBodyIdA];
	const btSolverBody& b = bodies[row.m_solverBodyIdB];
	return row.m_contactNormal1.dot(a.m_linearVelocity + a.m_externalForceImpulse) + row.m_relpos1CrossNormal.dot(a.m_angularVelocity) +
		   row.m_contactNormal2.dot(b.m_linearVelocity + b.m_externalForceImpulse) + row.m_relpos2CrossNormal.dot(b.m_angularVelocity);
}

void btEqualizeAcross(btAlignedObjectArray<btSolverBody>& bodies, const int* members, int count, const btVector3& normal)
{
	btVector3 momentum(0, 0, 0);
	btScalar mass = 0;
	for (int i = 0; i < count; ++i)
	{
		btSolverBody& m = bodies[members[i]];
		const btScalar inverse = m.m_originalBody ? m.m_originalBody->getInvMass() : btScalar(0);
		if (!(inverse > btScalar(0))) return;  // members are dynamic bodies (btLayeredPasses checks)
		momentum += (m.m_linearVelocity + m.m_externalForceImpulse + m.internalGetDeltaLinearVelocity()) / inverse;
		mass += btScalar(1) / inverse;
	}
	if (!(mass > btScalar(0))) return;
	const btVector3 common = momentum / mass;
	for (int i = 0; i < count; ++i)
	{
		btSolverBody& m = bodies[members[i]];
		btVector3 change = common - (m.m_linearVelocity + m.m_externalForceImpulse + m.internalGetDeltaLinearVelocity());
		change -= normal * change.dot(normal);
		m.internalGetDeltaLinearVelocity() += change;
	}
}

void btSetDeltaAcross(btSolverBody& body, const btVector3& delta, const btVector3& normal)
{
	btVector3 change = delta - body.internalGetDeltaLinearVelocity();
	change -= normal * change.dot(normal);
	body.internalGetDeltaLinearVelocity() += change;
}

void btCompositeFrictionRow(btSolverConstraint& row, const btSolverBody& bodyA, const btSolverBody& bodyB, btScalar ratioA, btScalar ratioB,
							btScalar sor)
{
	// Bullet's friction row: m_jacDiagABInv = sor / (J W J^T), m_rhs = error * m_jacDiagABInv.
	const btScalar jacOld = row.m_jacDiagABInv;
	if (jacOld == btScalar(0)) return;
	const btScalar error = row.m_rhs / jacOld;
	btScalar denominator = sor / jacOld;
	const btScalar ratios[2] = {ratioA, ratioB};
	const btSolverBody* ends[2] = {&bodyA, &bodyB};
	const btVector3* axes[2] = {&row.m_contactNormal1, &row.m_contactNormal2};
	for (int side = 0; side < 2; ++side)
	{
		if (!(ratios[side] > btScalar(1)) || !ends[side]->m_originalBody) continue;
		denominator -= ends[side]->m_originalBody->getInvMass() * (btScalar(1) - btScalar(1) / ratios[side]) * axes[side]->length2();
	}
	if (!(denominator > SIMD_EPSILON)) return;
	row.m_jacDiagABInv = sor / denominator;
	row.m_rhs = error * row.m_jacDiagABInv;
}
