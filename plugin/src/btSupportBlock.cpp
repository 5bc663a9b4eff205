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

#include "btSupportBlock.h"

#include "btCholesky6.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

namespace
{
const int kMaxBlockRows = 64;  // a body with more support rows keeps PGS alone
}  // namespace

bool btSolveSupportBlock(btSolverBody& body, const btAlignedObjectArray<btSolverBody>& bodies, const btLoadTransferRow* rows, int numRows,
						 const btConstraintArray& contacts, btCholesky6* factorOut, char* factorValid)
{
	if (factorValid) *factorValid = 0;
	const btRigidBody* rb = body.m_originalBody;
	if (!rb || numRows < 6 || numRows > kMaxBlockRows || !(rb->getInvMass() > btScalar(0))) return false;
	// Bullet's W J^T carries the factors; the momentum formula below assumes none.
	if (body.m_linearFactor != btVector3(1, 1, 1) || body.m_angularFactor != btVector3(1, 1, 1)) return false;
	const btMatrix3x3& invInertia = rb->getInvInertiaTensorWorld();
	if (!(btFabs(invInertia.determinant()) > SIMD_EPSILON)) return false;

	// The resting rows, their errors e (m/s) and the normal equations A = J^T J, J^T e.
	btVector3 linearLinear[3], angularLinear[3], angularAngular[3];
	for (int r = 0; r < 3; ++r) linearLinear[r] = angularLinear[r] = angularAngular[r] = btVector3(0, 0, 0);
	btVector3 JeLinear(0, 0, 0), JeAngular(0, 0, 0);
	bool use[kMaxBlockRows];
	btScalar error[kMaxBlockRows];
	int used = 0;
	for (int i = 0; i < numRows; ++i)
	{
		use[i] = false;
		const btSolverConstraint& c = *rows[i].m_row;
		if (c.m_jacDiagABInv == btScalar(0)) continue;
		const btSolverConstraint* contact = &c;
		if (!rows[i].m_contact)
		{
			if (c.m_frictionIndex < 0 || c.m_frictionIndex >= contacts.size()) continue;
			contact = &contacts[c.m_frictionIndex];
		}
		if (!(contact->m_appliedImpulse > btScalar(0))) continue;  // not in contact
		// A contact pushing now that carried nothing last step is an impact or a new load: the
		// body is not at rest, and its block is PGS's.
		if (!rows[i].m_carried) return false;
		const btRowSides s = btSidesOf(rows[i]);
		const btSolverBody& other = bodies[rows[i].m_sideA ? c.m_solverBodyIdB : c.m_solverBodyIdA];
		// What Bullet's kernel would turn into an impulse, in velocity units (Bullet's delta
		// accessors are not const).
		const btScalar e = btSupportRowError(rows[i], body, const_cast<btSolverBody&>(other));
		if (!(e == e)) continue;
		// J^T e and the lower triangle of J^T J by 3 x 3 blocks (btCholesky6 reads no more; each
		// entry sums the same products in the same order as entry by entry would).
		const btVector3& l = s.m_linear;
		const btVector3& w = s.m_angular;
		JeLinear += l * e;
		JeAngular += w * e;
		for (int r = 0; r < 3; ++r)
		{
			for (int c = 0; c <= r; ++c)
			{
				linearLinear[r][c] += l[c] * l[r];
				angularAngular[r][c] += w[c] * w[r];
			}
			angularLinear[r] += l * w[r];
		}
		use[i] = true;
		error[i] = e;
		++used;
	}
	if (used < 6) return false;
	btScalar A[6][6];  // lower triangle only: btCholesky6::factor reads no more
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 3; ++c)
		{
			A[3 + r][c] = angularLinear[r][c];
			if (c > r) continue;
			A[r][c] = linearLinear[r][c];
			A[3 + r][3 + c] = angularAngular[r][c];
		}
	const btScalar Je[6] = {JeLinear[0], JeLinear[1], JeLinear[2], JeAngular[0], JeAngular[1], JeAngular[2]};
	btCholesky6 cholesky;  // Jacobi-scaled: metres and radians weigh alike
	if (!cholesky.factor(A, btScalar(0), btScalar(1e-3), true)) return false;
	// D24: kept for the weight pass's load transfer when it covers the transfer's rows (all of them).
	if (factorOut && used == numRows)
	{
		*factorOut = cholesky;
		*factorValid = 1;
	}

	// Velocity change (least squares), its momentum, and the impulses that deliver it.
	btScalar du[6], p[6], z[6];
	cholesky.solve(Je, du);
	btMomentumOf(rb->getInvMass(), invInertia, btVector3(du[0], du[1], du[2]), btVector3(du[3], du[4], du[5]), p);
	cholesky.solve(p, z);
	const btVector3 zLinear(z[0], z[1], z[2]), zAngular(z[3], z[4], z[5]);

	// Projected onto the limits: normals first, friction bounded by its normal's new impulse. The
	// new impulses are written into the rows (the old ones kept) so friction reads its normal's.
	btScalar old[kMaxBlockRows];
	for (int pass = 0; pass < 2; ++pass)
		for (int i = 0; i < numRows; ++i)
		{
			if (!use[i] || rows[i].m_contact != (pass == 0)) continue;
			btSolverConstraint& c = *rows[i].m_row;
			const btRowSides s = btSidesOf(rows[i]);
			old[i] = c.m_appliedImpulse;
			btScalar after = old[i] + s.m_linear.dot(zLinear) + s.m_angular.dot(zAngular);
			if (rows[i].m_contact)
				after = btMax(btScalar(0), after);
			else
			{
				const btScalar bound = btFrictionBound(c, contacts);
				after = btMax(-bound, btMin(bound, after));
			}
			if (after == after) c.m_appliedImpulse = after;
		}

	// Kept only if it lowers 1/2 d^T J W J^T d - d . e (W: the body's inverse mass and inertia).
	btVector3 impulseLinear(0, 0, 0), impulseAngular(0, 0, 0);
	btScalar work = 0;
	for (int i = 0; i < numRows; ++i)
	{
		if (!use[i]) continue;
		const btRowSides s = btSidesOf(rows[i]);
		const btScalar d = btScalar(rows[i].m_row->m_appliedImpulse) - old[i];
		impulseLinear += s.m_linear * d;
		impulseAngular += s.m_angular * d;
		work += d * error[i];
	}
	const btScalar objective =
		btScalar(0.5) * (impulseLinear.length2() * rb->getInvMass() + impulseAngular.dot(invInertia * impulseAngular)) - work;
	const bool descent = objective < btScalar(0);
	for (int i = 0; i < numRows; ++i)
	{
		if (!use[i]) continue;
		btSolverConstraint& c = *rows[i].m_row;
		if (!descent)
		{
			c.m_appliedImpulse = old[i];
			continue;
		}
		const btScalar change = btScalar(c.m_appliedImpulse) - old[i];
		if (change == btScalar(0)) continue;
		body.internalApplyImpulse((rows[i].m_sideA ? c.m_contactNormal1 : c.m_contactNormal2) * body.internalGetInvMass(),
								  rows[i].m_sideA ? c.m_angularComponentA : c.m_angularComponentB, change);
	}
	return descent;
}
