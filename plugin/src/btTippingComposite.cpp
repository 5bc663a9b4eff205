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

#include "btTippingComposite.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

namespace
{
btVector3 velocityOf(btSolverBody& b) { return b.m_linearVelocity + b.m_externalForceImpulse + b.internalGetDeltaLinearVelocity(); }
btVector3 spinOf(btSolverBody& b) { return b.m_angularVelocity + b.m_externalTorqueImpulse + b.internalGetDeltaAngularVelocity(); }

/// The solver deltas that give the body the rigid motion (V, Omega) about `centre`.
void moveWith(btSolverBody& b, const btVector3& centre, const btVector3& V, const btVector3& Omega)
{
	const btVector3 r = b.m_originalBody->getCenterOfMassPosition() - centre;
	b.internalGetDeltaLinearVelocity() = V + Omega.cross(r) - (b.m_linearVelocity + b.m_externalForceImpulse);
	b.internalGetDeltaAngularVelocity() = Omega - (b.m_angularVelocity + b.m_externalTorqueImpulse);
}
}  // namespace

bool btSolveTippingComposite(btAlignedObjectArray<btSolverBody>& bodies, const int* members, int numMembers, const btLoadTransferRow* rows,
							 int numRows, const btConstraintArray& contacts, int maxSweeps, btScalar convergedSpeed, int* sweepsRun,
							 bool freeMotionBound)
{
	if (sweepsRun) *sweepsRun = 0;
	if (numMembers < 2 || numRows < 1 || numRows > btTippingCompositeMaxRows) return false;
	// Mass and centre.
	btScalar mass = 0;
	btVector3 centre(0, 0, 0);
	for (int i = 0; i < numMembers; ++i)
	{
		const btSolverBody& b = bodies[members[i]];
		const btRigidBody* rb = b.m_originalBody;
		if (!rb || !(rb->getInvMass() > btScalar(0))) return false;
		if (b.m_linearFactor != btVector3(1, 1, 1) || b.m_angularFactor != btVector3(1, 1, 1)) return false;
		if (!(btFabs(rb->getInvInertiaTensorWorld().determinant()) > SIMD_EPSILON)) return false;
		const btScalar m = btScalar(1) / rb->getInvMass();
		mass += m;
		centre += rb->getCenterOfMassPosition() * m;
	}
	centre /= mass;
	// Momentum, angular momentum about the centre, and the inertia about it (parallel axes).
	btVector3 P(0, 0, 0), L(0, 0, 0);
	btMatrix3x3 inertia(0, 0, 0, 0, 0, 0, 0, 0, 0);
	for (int i = 0; i < numMembers; ++i)
	{
		btSolverBody& b = bodies[members[i]];
		const btRigidBody* rb = b.m_originalBody;
		const btScalar m = btScalar(1) / rb->getInvMass();
		const btMatrix3x3 own = rb->getInvInertiaTensorWorld().inverse();
		const btVector3 r = rb->getCenterOfMassPosition() - centre;
		const btVector3 v = velocityOf(b);
		P += v * m;
		L += own * spinOf(b) + r.cross(v * m);
		const btScalar r2 = r.length2();
		const btMatrix3x3 offset(r2 - r.x() * r.x(), -r.x() * r.y(), -r.x() * r.z(), -r.y() * r.x(), r2 - r.y() * r.y(), -r.y() * r.z(),
								 -r.z() * r.x(), -r.z() * r.y(), r2 - r.z() * r.z());
		inertia = inertia + own + offset * m;
	}
	if (!(btFabs(inertia.determinant()) > SIMD_EPSILON)) return false;
	const btMatrix3x3 invInertia = inertia.inverse();
	btVector3 V = P / mass;
	btVector3 Omega = invInertia * L;

	// The base's rows about the composite's centre.
	btSolverBody& base = bodies[members[0]];
	const btVector3 arm = base.m_originalBody->getCenterOfMassPosition() - centre;
	btVector3 angular[btTippingCompositeMaxRows], response[btTippingCompositeMaxRows];
	btScalar inverseMass[btTippingCompositeMaxRows];
	for (int i = 0; i < numRows; ++i)
	{
		const btRowSides s = btSidesOf(rows[i]);
		angular[i] = s.m_angular + arm.cross(s.m_linear);
		response[i] = invInertia * angular[i];
		inverseMass[i] = s.m_linear.length2() / mass + angular[i].dot(response[i]);
	}

	const btScalar energyMerged = mass * V.length2() + Omega.dot(inertia * Omega);  // twice the kinetic energy
	btScalar before[btTippingCompositeMaxRows];
	for (int i = 0; i < numRows; ++i) before[i] = rows[i].m_row->m_appliedImpulse;
	const btVector3 baseLinear = base.internalGetDeltaLinearVelocity(), baseAngular = base.internalGetDeltaAngularVelocity();
	moveWith(base, centre, V, Omega);
	const btScalar converged2 = convergedSpeed * convergedSpeed;
	for (int sweep = 0; sweep < maxSweeps; ++sweep)
	{
		btScalar largest = 0;
		// Normals first, then friction bounded by its normal's impulse, as Bullet's sweep.
		for (int pass = 0; pass < 2; ++pass)
			for (int i = 0; i < numRows; ++i)
			{
				if (rows[i].m_contact != (pass == 0)) continue;
				btSolverConstraint& c = *rows[i].m_row;
				if (c.m_jacDiagABInv == btScalar(0) || !(inverseMass[i] > SIMD_EPSILON)) continue;
				btSolverBody& other = bodies[rows[i].m_sideA ? c.m_solverBodyIdB : c.m_solverBodyIdA];
				// The row's velocity error as Bullet's kernel sees it (the fixated end as fixation shows it).
				const btScalar error = btSupportRowError(rows[i], base, other);
				const btScalar old = c.m_appliedImpulse;
				btScalar after = old + error / inverseMass[i];
				if (rows[i].m_contact)
					after = btMax(btScalar(0), after);
				else
				{
					if (c.m_frictionIndex < 0 || c.m_frictionIndex >= contacts.size()) continue;
					const btScalar bound = btFrictionBound(c, contacts);
					after = btMax(-bound, btMin(bound, after));
				}
				if (!(after == after)) continue;
				const btScalar change = after - old;
				if (change == btScalar(0)) continue;
				c.m_appliedImpulse = after;
				V += btSidesOf(rows[i]).m_linear * (change / mass);
				Omega += response[i] * change;
				moveWith(base, centre, V, Omega);
				const btScalar velocityChange = change * inverseMass[i];
				largest = btMax(largest, velocityChange * velocityChange);
			}
		if (sweepsRun) ++*sweepsRun;
		if (largest <= converged2) break;
	}
	// A passive support only takes energy out of the merged body (its free motion includes this
	// step's gravity). A support that adds some is moving into it: a fixated body's motion, which
	// fixation gives only the base's own mass to push against (D14), not the composite's.
	const btScalar energySolved = mass * V.length2() + Omega.dot(inertia * Omega);
	// D29: or no more than its motion without the rows' impulses (V and Omega less what the rows
	// give): a row that lets go of an impulse it held (friction whose normal carries less now)
	// returns energy the merged state had lost to it, and a passive support's solution never
	// exceeds the free motion.
	btScalar energyFree = energyMerged;
	if (freeMotionBound)
	{
		btVector3 Vfree = V, OmegaFree = Omega;
		for (int i = 0; i < numRows; ++i)
		{
			const btScalar impulse = rows[i].m_row->m_appliedImpulse;
			Vfree -= btSidesOf(rows[i]).m_linear * (impulse / mass);
			OmegaFree -= response[i] * impulse;
		}
		energyFree = btMax(energyMerged, mass * Vfree.length2() + OmegaFree.dot(inertia * OmegaFree));
	}
	if (!(energySolved <= energyFree * btScalar(1.0001) + SIMD_EPSILON))
	{
		for (int i = 0; i < numRows; ++i) rows[i].m_row->m_appliedImpulse = before[i];
		base.internalGetDeltaLinearVelocity() = baseLinear;
		base.internalGetDeltaAngularVelocity() = baseAngular;
		return false;
	}
	for (int i = 1; i < numMembers; ++i) moveWith(bodies[members[i]], centre, V, Omega);
	return true;
}
