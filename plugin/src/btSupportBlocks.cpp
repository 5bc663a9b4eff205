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

// Support blocks of the converging step's predictor (btShockPredictor.h).
//
// In a layer each free body (or the composite it carries) moves against fixated supports alone:
// its support rows form one block of a body with six degrees of freedom. Row sweeps solve the
// block at a rate set by how the rows couple through the body's turn: a brick loaded at one end
// by the layers above needs tens to hundreds of sweeps to reach the predictor's convergence
// speed, each leaving an error the next layer inherits. The block's pushing rows are solved at
// once first: with e_r the rows' velocity errors and J_r their Jacobians on the body,
//   du = A^-1 sum_r J_r e_r,   A = sum_r J_r J_r^T        (the least-squares velocity change),
//   dlambda_r = J_r . A^-1 M du                            (the least-norm impulses giving it),
// M the body's (or the composite's) mass and inertia. The impulses are projected on the rows'
// bounds (pushing normals, friction within mu of the normal) and applied as the row sweeps apply
// theirs (to the free side, the fixated side's share withheld); the sweeps then finish the block.

#include "btShockPredictor.h"

#include "btCholesky6.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

void btShockPredictor::solveBlocks(int layer, const Pools& pools)
{
	for (int i = m_layerFreeStart[layer]; i < m_layerFreeStart[layer + 1]; ++i) solveBlock(m_layerFree[i], pools.m_bodies);
}

void btShockPredictor::solveBlock(int b, btAlignedObjectArray<btSolverBody>& bodies)
{
	btSolverBody& body = bodies[b];
	const btRigidBody* rb = body.m_originalBody;
	if (!rb || !(rb->getInvMass() > btScalar(0))) return;
	if (!(body.m_linearFactor == btVector3(1, 1, 1) && body.m_angularFactor == btVector3(1, 1, 1))) return;
	Composite* comp = (m_compositeOf.size() > b && m_compositeOf[b] >= 0) ? &m_composites[m_compositeOf[b]] : 0;
	const btVector3 offset = comp ? body.getWorldTransform().getOrigin() - comp->m_center : btVector3(0, 0, 0);
	const btScalar invMass = comp ? comp->m_invMass : rb->getInvMass();
	// The inertia I (the inverse of the inverse inertia): a body's is formed once per step.
	const btMatrix3x3* inertia = comp ? 0 : worldInertia(b, *rb);
	if (comp ? !(btFabs(comp->m_invInertia.determinant()) > SIMD_EPSILON) : !inertia) return;

	// The rows that push or would push (and the friction rows of those): their Jacobians on the
	// body (or composite) and velocity errors. A point Bullet just added starts from no impulse.
	btScalar g[6] = {};
	m_blockRows.resize(0);
	m_blockContacts.resize(0);
	// A body's block matrix depends only on which of its support rows it holds: its factor is kept
	// for the step and formed again only when that set changes (not for a composite, whose
	// Jacobians depend on its members).
	const bool cache = !comp;
	bool same = cache && (m_blockState[b] == 1 || m_blockState[b] == 3);
	for (int k = m_supportStart[b]; k < m_supportStart[b + 1]; ++k)
	{
		const int ri = m_supportRows[k];
		const Row& r = m_rows[ri];
		const btSolverConstraint& c = *r.m_row;
		bool included = false;
		if (c.m_jacDiagABInv != btScalar(0) && r.m_scale != btScalar(0))
		{
			btVector3 n, cr;
			freeSide(r, n, cr);
			const btVector3 arm = cr + offset.cross(n);
			bool take = true;
			if (r.m_normal)
			{
				take = false;
				for (int j = 0; j < m_blockContacts.size() && !take; ++j) take = m_blockContacts[j] == r.m_normal;
			}
			if (take)
			{
				const btScalar fixedVelocity = sideVelocity(c, r.m_fixed == 1, bodies);
				const btScalar freeVelocity = comp ? n.dot(comp->m_rootDv0 + comp->m_dv) + cr.dot(comp->m_rootDw0) + arm.dot(comp->m_dw) : sideVelocity(c, r.m_fixed == 2, bodies);
				const btScalar error = (c.m_rhs + r.m_restTarget - c.m_appliedImpulse * c.m_cfm) / c.m_jacDiagABInv - fixedVelocity - freeVelocity;
				if (!r.m_normal)
				{
					take = c.m_appliedImpulse > btScalar(0) || error > btScalar(0);
					if (take) m_blockContacts.push_back(&c);
				}
				if (take)
				{
					const btScalar J[6] = {n.x(), n.y(), n.z(), arm.x(), arm.y(), arm.z()};
					for (int i = 0; i < 6; ++i) g[i] += J[i] * error;
					m_blockRows.push_back(ri);
					included = true;
				}
			}
		}
		if (cache)
		{
			same = same && m_blockIncluded[k] == char(included);
			m_blockIncluded[k] = included;
		}
	}
	if (m_blockRows.size() < 6)
	{
		if (cache) m_blockState[b] = 2;
		return;
	}
	// The factor is read where it is kept (no copy of it per call). A block holding every one-sided
	// support row of the body is the matrix its span factor was formed from (supportFactor: the same
	// Jacobians, summed in the same order; the arm is the row's own cr here, offset.cross(n) adding
	// only zeros, and the pivots are the same), so a body whose rows span takes that factor.
	const btCholesky6* factor = 0;
	if (same)
		factor = m_blockState[b] == 3 ? &m_spanFactors[b] : &m_blockFactors[b];
	else if (cache && m_blockRows.size() == m_supportStart[b + 1] - m_supportStart[b] && b < m_spanState.size() && m_spanState[b] == 1 &&
			 m_spanRowCount[b] == m_blockRows.size() && btShockPropagationNumerics::blockMinPivot() == spanMinPivot())
	{
		factor = &m_spanFactors[b];
		m_blockState[b] = 3;
	}
	else
	{
		btScalar A[6][6] = {};
		for (int k = 0; k < m_blockRows.size(); ++k)
		{
			btVector3 n, cr;
			freeSide(m_rows[m_blockRows[k]], n, cr);
			const btVector3 arm = cr + offset.cross(n);
			const btScalar J[6] = {n.x(), n.y(), n.z(), arm.x(), arm.y(), arm.z()};
			for (int i = 0; i < 6; ++i)
				for (int j = 0; j <= i; ++j) A[i][j] += J[i] * J[j];
		}
		// Factored in place: factor() writes all that solve() reads (the lower triangle, the scales).
		btCholesky6& formed = cache ? m_blockFactors[b] : m_blockScratch;
		const bool factored = formed.factor(A, btScalar(0), btShockPropagationNumerics::blockMinPivot(), true);
		if (cache) m_blockState[b] = factored ? 1 : 2;
		if (!factored) return;
		factor = &formed;
	}
	btScalar du[6], y[6];
	factor->solve(g, du);
	const btVector3 dv(du[0], du[1], du[2]), dw(du[3], du[4], du[5]);
	const btVector3 p = dv / invMass, L = (comp ? comp->m_invInertia.inverse() : *inertia) * dw;
	const btScalar momentum[6] = {p.x(), p.y(), p.z(), L.x(), L.y(), L.z()};
	factor->solve(momentum, y);
	const btVector3 yl(y[0], y[1], y[2]), ya(y[3], y[4], y[5]);

	// Projected: normals first (they bound the friction rows), then friction.
	for (int pass = 0; pass < 2; ++pass)
		for (int k = 0; k < m_blockRows.size(); ++k)
		{
			Row& r = m_rows[m_blockRows[k]];
			if ((pass == 0) != (r.m_normal == 0)) continue;
			btSolverConstraint& c = *r.m_row;
			btVector3 n, cr;
			freeSide(r, n, cr);
			const btVector3 arm = cr + offset.cross(n);
			boundByNormal(r);
			const btScalar target = c.m_appliedImpulse + n.dot(yl) + arm.dot(ya);
			if (!(target == target)) continue;
			const btScalar delta = btMax(c.m_lowerLimit, btMin(c.m_upperLimit, target)) - c.m_appliedImpulse;
			if (delta == btScalar(0)) continue;
			c.m_appliedImpulse += delta;
			r.m_withheld += delta;
			moveFixated(r, delta, btScalar(1), bodies);
			if (comp)
			{
				comp->m_dv += n * (delta * comp->m_invMass);
				comp->m_dw += comp->m_invInertia * (arm * delta);
				r.m_layerDelta += delta;
			}
			else
				applyToSide(c, r.m_fixed == 2, delta, bodies);
		}
}
