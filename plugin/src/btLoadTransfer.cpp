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

#include "btLoadTransfer.h"

#include "btCholesky6.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

namespace
{
/// Row i's velocity change per unit impulse on its body, as Bullet's kernels apply it
/// (btSolverBody::internalApplyImpulse with the row's W J^T and the body's factors).
void velocityPerImpulse(const btSolverBody& body, const btLoadTransferRow& r, btScalar out[6])
{
	const btSolverConstraint& c = *r.m_row;
	const btVector3 linear = (r.m_sideA ? c.m_contactNormal1 : c.m_contactNormal2) * body.internalGetInvMass() * body.m_linearFactor;
	const btVector3 angular = (r.m_sideA ? c.m_angularComponentA : c.m_angularComponentB) * body.m_angularFactor;
	for (int j = 0; j < 3; ++j)
	{
		out[j] = linear[j];
		out[3 + j] = angular[j];
	}
}

/// Solves (A + eps I) x = b for a symmetric positive semi-definite 6 x 6 A (Cholesky).
/// Returns false if A is zero.
bool solveRegularized(btScalar A[6][6], const btScalar b[6], btScalar x[6])
{
	btScalar trace = 0;
	for (int i = 0; i < 6; ++i) trace += A[i][i];
	if (!(trace > btScalar(0))) return false;
	// Directions the rows cannot reach keep their velocity; a small relative regularisation
	// keeps the factorisation defined there (float: 1e-6 of the mean diagonal).
	const btScalar eps = trace * btScalar(1e-6) / btScalar(6);
	btCholesky6 cholesky;
	if (!cholesky.factor(A, eps, btScalar(0), false)) return false;
	cholesky.solve(b, x);
	return true;
}

/// Projects each row's change (changeOf(i), its impulse change before projection) onto the
/// row's limits and applies it to the body: contact normals first, so the friction bounds follow
/// their new normal impulses. Returns the total impulse magnitude moved onto the rows.
template <class ChangeOf>
btScalar applyTransfer(btSolverBody& body, const btLoadTransferRow* rows, int numRows, const btConstraintArray& contacts, ChangeOf changeOf)
{
	btScalar moved = 0;
	for (int pass = 0; pass < 2; ++pass)
		for (int i = 0; i < numRows; ++i)
		{
			const btLoadTransferRow& r = rows[i];
			if (r.m_contact != (pass == 0)) continue;
			btSolverConstraint& c = *r.m_row;
			btScalar change = changeOf(i);
			const btScalar before = c.m_appliedImpulse;
			btScalar after = before + change;
			if (r.m_contact)
				after = btMax(btScalar(0), after);
			else
			{
				const btScalar bound = btFrictionBound(c, contacts);
				after = btMax(-bound, btMin(bound, after));
			}
			if (!(after == after)) continue;  // NaN: the row is left to the sweeps
			change = after - before;
			if (change == btScalar(0)) continue;
			c.m_appliedImpulse = after;
			body.internalApplyImpulse((r.m_sideA ? c.m_contactNormal1 : c.m_contactNormal2) * body.internalGetInvMass(),
									  r.m_sideA ? c.m_angularComponentA : c.m_angularComponentB, change);
			moved += btFabs(change);
		}
	return moved;
}
}  // namespace

btScalar btTransferLoad(btSolverBody& body, const btVector3& beforeLinear, const btVector3& beforeAngular, const btLoadTransferRow* rows,
						int numRows, const btConstraintArray& contacts)
{
	if (!body.m_originalBody || numRows == 0) return btScalar(0);
	const btVector3 dv = body.internalGetDeltaLinearVelocity() - beforeLinear;
	const btVector3 dw = body.internalGetDeltaAngularVelocity() - beforeAngular;
	const btScalar target[6] = {-dv[0], -dv[1], -dv[2], -dw[0], -dw[1], -dw[2]};
	// Normal equations of min |d_lambda|^2 subject to H d_lambda = target, H = [h_1 ... h_m]:
	// d_lambda = H^T (H H^T)^-1 target, H H^T = sum of h_i h_i^T (6 x 6).
	// Each row's h_i once (kept for the impulse changes below); the rows' products summed into the
	// lower triangle, which is all the factorisation reads.
	const int kCachedRows = 64;
	btScalar cached[kCachedRows][6];
	btScalar A[6][6] = {};
	btScalar h[6];
	for (int i = 0; i < numRows; ++i)
	{
		btScalar* hi = i < kCachedRows ? cached[i] : h;
		velocityPerImpulse(body, rows[i], hi);
		for (int a = 0; a < 6; ++a)
			for (int b = 0; b <= a; ++b) A[a][b] += hi[a] * hi[b];
	}
	btScalar y[6];
	if (!solveRegularized(A, target, y)) return btScalar(0);

	return applyTransfer(body, rows, numRows, contacts, [&](int i) {
		const btScalar* hi = i < kCachedRows ? cached[i] : h;
		if (i >= kCachedRows) velocityPerImpulse(body, rows[i], h);
		btScalar change = 0;
		for (int a = 0; a < 6; ++a) change += hi[a] * y[a];
		return change;
	});
}

btScalar btTransferLoad(btSolverBody& body, const btVector3& beforeLinear, const btVector3& beforeAngular, const btLoadTransferRow* rows,
						int numRows, const btConstraintArray& contacts, const btCholesky6& blockFactor)
{
	const btRigidBody* rb = body.m_originalBody;
	if (!rb || numRows == 0) return btScalar(0);
	// M target: the momentum that undoes the load.
	btScalar p[6], z[6];
	btMomentumOf(rb->getInvMass(), rb->getInvInertiaTensorWorld(), beforeLinear - body.internalGetDeltaLinearVelocity(),
				 beforeAngular - body.internalGetDeltaAngularVelocity(), p);
	blockFactor.solve(p, z);
	const btVector3 zLinear(z[0], z[1], z[2]), zAngular(z[3], z[4], z[5]);
	return applyTransfer(body, rows, numRows, contacts, [&](int i) {
		const btRowSides s = btSidesOf(rows[i]);
		return s.m_linear.dot(zLinear) + s.m_angular.dot(zAngular);
	});
}
