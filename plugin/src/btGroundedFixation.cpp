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

// Grounded fixation of the converging step's predictor (btShockPredictor.h).
//
// Fixation stands for the ground holding a body through the bodies under it, and the one-sided
// update hands the fixated body the free one's load: s = (D_A + D_B + c) / (D_A + c) times the
// free side's velocity change, to be passed on to its own supports once delivered. That is exact
// only where the fixated body can pass it on:
//
//   grounded  a body is grounded if it is static or kinematic, or its one-sided support rows to
//             grounded bodies fix all six of its degrees of freedom: sum_r J_r J_r^T has full
//             rank (its side of each row). A row whose fixated side is not grounded (a body on one
//             point or one edge, hanging on a joint, leaning on a side contact) is solved with both
//             bodies free, as Bullet's own update: fixating that body would hand it a load it
//             cannot pass on (hostile worlds: a 3 g body under a 0.67 kg one flung at 1.7 km/s).
//   held      in the down pass a free body is held if its support rows fix all six degrees of
//             freedom and every one's relative velocity is within the convergence speed. One that
//             is not (it slides, tips or lifts under what was delivered to it) carries what is
//             welded to it (btWeldedComposites.cpp).
//   precision s is the free body's mass over the fixated one's along the row, plus one; the
//             fixated body's velocity carries s times the load until its supports take it back,
//             so the rounding of that cancellation grows with s. Rows with s > 1 / sqrt(epsilon)
//             (2.9e3 in float, 6.7e7 in double) are solved with both bodies free (addRow).

#include "btShockPredictor.h"

#include "btCholesky6.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

namespace
{
const btScalar kSpanMinPivot = btScalar(1e-3);  // Jacobi-scaled pivot: a body's support rows span six directions (welds too)
}  // namespace

void btShockPredictor::groundRows(const btAlignedObjectArray<btSolverBody>& bodies, const btAlignedObjectArray<int>& heightOfSolverBody)
{
	// Fixation stands for the ground holding a body through the bodies under it. A body is
	// grounded if it is static or kinematic, or its one-sided support rows to grounded bodies fix
	// all six of its degrees of freedom; layer k's fixated sides lie below it, so one pass up the
	// layers decides every body. A row whose fixated side is not grounded (a body on one point, on
	// an edge, hanging on a joint, leaning on a side contact) is solved with both bodies free:
	// fixating such a body would hand it a load it cannot pass on.
	m_grounded.resize(bodies.size());
	for (int i = 0; i < bodies.size(); ++i)
	{
		const btRigidBody* rb = bodies[i].m_originalBody;
		m_grounded[i] = !rb || !(rb->getInvMass() > btScalar(0)) || heightOfSolverBody[i] == 0;
	}
	for (int k = 0; k < m_numLayers; ++k)
		for (int i = m_layerStart[k]; i < m_layerStart[k + 1]; ++i)
		{
			const int b = m_rows[i].m_free;
			if (b < 0 || m_grounded[b]) continue;
			for (int j = m_supportStart[b]; j < m_supportStart[b + 1]; ++j)
			{
				Row& r = m_rows[m_supportRows[j]];
				if (r.m_fixed && m_grounded[fixedSide(r)] != 1) freeBothSides(r);
			}
			btCholesky6 span;
			const bool grounded = supportFactor(b, span);
			if (!grounded)  // not held: its rows to the bodies under it are free on both sides
				for (int j = m_supportStart[b]; j < m_supportStart[b + 1]; ++j) freeBothSides(m_rows[m_supportRows[j]]);
			m_grounded[b] = grounded ? 1 : 2;  // 2: decided, not grounded
		}
}

bool btShockPredictor::supportFactor(int body, btCholesky6& factor) const
{
	// A = sum over the body's one-sided support rows of J_r J_r^T (its side), factored: it has
	// full rank where the rows fix all six degrees of freedom.
	btScalar A[6][6] = {};
	for (int k = m_supportStart[body]; k < m_supportStart[body + 1]; ++k)
	{
		const Row& r = m_rows[m_supportRows[k]];
		if (!r.m_fixed) continue;
		btVector3 n, cr;
		freeSide(r, n, cr);
		const btScalar J[6] = {n.x(), n.y(), n.z(), cr.x(), cr.y(), cr.z()};
		for (int i = 0; i < 6; ++i)
			for (int j = 0; j <= i; ++j) A[i][j] += J[i] * J[j];
	}
	return factor.factor(A, btScalar(0), kSpanMinPivot, true);
}

bool btShockPredictor::heldBySupports(int body, btAlignedObjectArray<btSolverBody>& bodies, btScalar speed)
{
	// Held: the support rows fix all six of the body's degrees of freedom (a body on one point or
	// one edge can still turn about it) and every one's relative velocity (whole velocities, not
	// Bullet's deltas) is within the convergence speed.
	btCholesky6 span;
	if (!supportFactor(body, span)) return false;
	for (int k = m_supportStart[body]; k < m_supportStart[body + 1]; ++k)
	{
		const btSolverConstraint& c = *m_rows[m_supportRows[k]].m_row;
		btSolverBody& a = bodies[c.m_solverBodyIdA];
		btSolverBody& b = bodies[c.m_solverBodyIdB];
		const btScalar v = c.m_contactNormal1.dot(wholeLinear(a)) + c.m_relpos1CrossNormal.dot(wholeAngular(a)) +
						   c.m_contactNormal2.dot(wholeLinear(b)) + c.m_relpos2CrossNormal.dot(wholeAngular(b));
		if (btFabs(v) > speed) return false;
	}
	return true;
}
