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

// Welded composites of the converging step's down pass (btShockPredictor.h).
//
// Fixation gives a lower body no inertia from what rests on it, which is exact only while the
// lower body's own supports hold it. Where they do not (a base sliding on ice or pushed along the
// ground, a column tipping over a ledge), the exact elimination of the contact problem gives the
// lower body the Schur complement of what sticks to it: for a pair whose rows fix all six relative
// degrees of freedom and all push, the body above moves rigidly with the one below. So:
//
//   weld      body m is welded to its parent p when all of m's support rows go to the one
//             dynamic body p, one of its points pushes after the up pass, and its rows have full
//             rank 6 (three or more points not on a line);
//   composite in the down pass, a free body b of the layer carries C(b): b and every body welded
//             to it, recursively, with mass M, centre x_C and inertia I_C (parallel axes);
//   solve     b's support rows are swept as rows of C(b): Jacobian (n, c + (x_b - x_C) x n),
//             effective mass n.n / M + a.I_C^-1 a, the change kept as C's rigid motion (dv, dw);
//   transfer  afterwards b gets its support rows' impulses, and each member m, children first,
//             gets through its weld rows the impulse that gives it the rigid motion: the wrench
//               F_m = M_m (dv + dw x (x_m - x_C)) + sum_children F_c,
//               T_m = I_m dw + sum_children (T_c + (x_c - x_m) x F_c)      (about x_m),
//             spread over its weld rows by least norm (J A^-1 J^T with A = sum J_r J_r^T) and
//             applied to both bodies of each row; a row the transfer would pull or push past
//             Coulomb is clamped to its bound (applied to both bodies too): that weld lets go;
//   settle    the weld rows are then swept with both bodies free until converged, so that what a
//             clamped row could not carry is spread over the rows that can (settleWelds).
// Every impulse acts on both bodies of its row, so momentum is kept whatever the welds do.

#include "btShockPredictor.h"

#include "btCholesky6.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

namespace
{
bool unitFactors(const btSolverBody& body)
{
	return body.m_linearFactor == btVector3(1, 1, 1) && body.m_angularFactor == btVector3(1, 1, 1);
}
}  // namespace

void btShockPredictor::applyToBoth(Row& r, btScalar impulse, btAlignedObjectArray<btSolverBody>& bodies)
{
	r.m_row->m_appliedImpulse += impulse;
	applyToSide(*r.m_row, true, impulse, bodies);
	applyToSide(*r.m_row, false, impulse, bodies);
}

const btCholesky6* btShockPredictor::weldFactor(int body) const
{
	// A pair in contact (one point pushing) whose points span the six directions
	// (supportFactor). Which of its points push is the load's business (a resting box may carry
	// its load on two of four corners).
	int pushing = 0, points = 0;
	for (int k = m_supportStart[body]; k < m_supportStart[body + 1]; ++k)
	{
		const Row& r = m_rows[m_supportRows[k]];
		if (r.m_normal) continue;
		++points;
		if (r.m_row->m_appliedImpulse > btScalar(0)) ++pushing;
	}
	return pushing >= 1 && points >= 3 ? supportFactor(body) : 0;
}

void btShockPredictor::findWelds(const Pools& pools)
{
	btAlignedObjectArray<btSolverBody>& bodies = pools.m_bodies;
	const int numBodies = bodies.size();
	m_parent.resize(numBodies);
	m_compositeOf.resize(numBodies);
	m_weldForce.resize(numBodies);
	m_weldMoment.resize(numBodies);
	for (int i = 0; i < numBodies; ++i)
	{
		m_parent[i] = -1;
		m_compositeOf[i] = -1;
		const int begin = m_supportStart[i], end = m_supportStart[i + 1];
		if (begin == end || !bodies[i].m_originalBody || !unitFactors(bodies[i])) continue;
		int parent = -1;
		bool single = true;
		for (int k = begin; k < end && single; ++k)
		{
			const Row& r = m_rows[m_supportRows[k]];
			const int other = r.m_fixed == 1 ? r.m_bodyA : r.m_bodyB;
			if (parent < 0) parent = other;
			single = other == parent;
		}
		if (!single || parent < 0 || !bodies[parent].m_originalBody || !unitFactors(bodies[parent])) continue;
		if (weldFactor(i)) m_parent[i] = parent;
	}
	// Children of each body.
	m_childStart.resize(numBodies + 1);
	for (int i = 0; i <= numBodies; ++i) m_childStart[i] = 0;
	for (int i = 0; i < numBodies; ++i)
		if (m_parent[i] >= 0) ++m_childStart[m_parent[i] + 1];
	for (int i = 0; i < numBodies; ++i) m_childStart[i + 1] += m_childStart[i];
	m_children.resize(m_childStart[numBodies]);
	for (int i = 0; i < numBodies; ++i) m_count[i] = m_childStart[i];
	for (int i = 0; i < numBodies; ++i)
		if (m_parent[i] >= 0) m_children[m_count[m_parent[i]]++] = i;
}

void btShockPredictor::formComposites(int layer, const Pools& pools, btScalar heldSpeed)
{
	btAlignedObjectArray<btSolverBody>& bodies = pools.m_bodies;
	for (int i = 0; i < m_composites.size(); ++i) m_compositeOf[m_composites[i].m_root] = -1;
	m_composites.resize(0);
	m_members.resize(0);
	for (int i = m_layerFreeStart[layer]; i < m_layerFreeStart[layer + 1]; ++i)
	{
		const int root = m_layerFree[i];
		if (m_childStart[root] == m_childStart[root + 1] || heldBySupports(root, bodies, heldSpeed)) continue;
		Composite comp;
		comp.m_root = root;
		comp.m_first = m_members.size();
		m_members.push_back(root);
		for (int k = comp.m_first; k < m_members.size(); ++k)  // breadth first: parents before children
			for (int j = m_childStart[m_members[k]]; j < m_childStart[m_members[k] + 1]; ++j) m_members.push_back(m_children[j]);
		comp.m_end = m_members.size();
		btScalar mass = 0;
		btVector3 center(0, 0, 0);
		bool ok = true;
		for (int k = comp.m_first; k < comp.m_end; ++k)
		{
			const btRigidBody* rb = bodies[m_members[k]].m_originalBody;
			const btScalar m = btScalar(1) / rb->getInvMass();
			mass += m;
			center += bodies[m_members[k]].getWorldTransform().getOrigin() * m;
			ok = ok && worldInertia(m_members[k], *rb) != 0;
		}
		if (!ok || !(mass > btScalar(0)))
		{
			m_members.resize(comp.m_first);
			continue;
		}
		center /= mass;
		btMatrix3x3 inertia(0, 0, 0, 0, 0, 0, 0, 0, 0);
		for (int k = comp.m_first; k < comp.m_end; ++k)
		{
			const btRigidBody* rb = bodies[m_members[k]].m_originalBody;
			const btScalar m = btScalar(1) / rb->getInvMass();
			const btVector3 d = bodies[m_members[k]].getWorldTransform().getOrigin() - center;
			const btMatrix3x3& own = *worldInertia(m_members[k], *rb);
			const btScalar d2 = d.length2();
			for (int a = 0; a < 3; ++a)
				for (int b = 0; b < 3; ++b) inertia[a][b] += own[a][b] + m * ((a == b ? d2 : btScalar(0)) - d[a] * d[b]);
		}
		comp.m_center = center;
		comp.m_invMass = btScalar(1) / mass;
		comp.m_invInertia = inertia.inverse();
		// The rigid motion with the members' momentum and angular momentum (about the centre).
		btVector3 momentum(0, 0, 0), spin(0, 0, 0);
		for (int k = comp.m_first; k < comp.m_end; ++k)
		{
			btSolverBody& body = bodies[m_members[k]];
			const btRigidBody* rb = body.m_originalBody;
			const btVector3 p = wholeLinear(body) / rb->getInvMass();
			momentum += p;
			spin += *worldInertia(m_members[k], *rb) * wholeAngular(body) + (body.getWorldTransform().getOrigin() - center).cross(p);
		}
		comp.m_v0 = momentum * comp.m_invMass;
		comp.m_w0 = comp.m_invInertia * spin;
		btSolverBody& rootBody = bodies[root];
		comp.m_rootDv0 = comp.m_v0 + comp.m_w0.cross(rootBody.getWorldTransform().getOrigin() - center) - rootBody.m_linearVelocity - rootBody.m_externalForceImpulse;
		comp.m_rootDw0 = comp.m_w0 - rootBody.m_angularVelocity - rootBody.m_externalTorqueImpulse;
		comp.m_dv.setZero();
		comp.m_dw.setZero();
		comp.m_sweepDv.setZero();
		comp.m_sweepDw.setZero();
		m_compositeOf[root] = m_composites.size();
		m_composites.push_back(comp);
	}
}

btScalar btShockPredictor::solveCompositeRow(Row& r, Composite& comp, btAlignedObjectArray<btSolverBody>& bodies)
{
	btSolverConstraint& c = *r.m_row;
	boundByNormal(r);
	if (r.m_scale == btScalar(0)) return 0;
	btVector3 n, cr;
	freeSide(r, n, cr);
	const btVector3 arm = cr + (bodies[r.m_free].getWorldTransform().getOrigin() - comp.m_center).cross(n);
	// The free side moves with the composite (its rigid motion at the root, in Bullet's delta
	// form); the fixated side with its own velocity.
	const btScalar velocity = sideVelocity(c, r.m_fixed == 1, bodies) + n.dot(comp.m_rootDv0) + cr.dot(comp.m_rootDw0) + n.dot(comp.m_dv) + arm.dot(comp.m_dw);
	const btScalar cfm = c.m_cfm / c.m_jacDiagABInv;
	const btScalar effective = n.length2() * comp.m_invMass + arm.dot(comp.m_invInertia * arm) + cfm + r.m_fixedTerm;
	if (!(effective > btScalar(0))) return 0;
	btScalar delta = (r.m_total / effective) * (c.m_rhs + r.m_restTarget - c.m_appliedImpulse * c.m_cfm - velocity * c.m_jacDiagABInv);
	const btScalar clamped = btMax(c.m_lowerLimit, btMin(c.m_upperLimit, c.m_appliedImpulse + delta));
	delta = clamped - c.m_appliedImpulse;
	c.m_appliedImpulse = clamped;
	comp.m_dv += n * (delta * comp.m_invMass);
	comp.m_dw += comp.m_invInertia * (arm * delta);
	r.m_withheld += delta;
	r.m_layerDelta += delta;
	moveFixated(r, delta, btScalar(1), bodies);
	return btFabs(delta) * effective;
}

btScalar btShockPredictor::compositeMotion(int layer, const btAlignedObjectArray<btSolverBody>& bodies) const
{
	// The composites' rigid motion in the last sweep, along their rows (m/s).
	btScalar largest = 0;
	for (int i = m_layerStart[layer]; i < m_layerStart[layer + 1]; ++i)
	{
		const Row& r = m_rows[i];
		if (r.m_free < 0 || m_compositeOf[r.m_free] < 0) continue;
		const Composite& comp = m_composites[m_compositeOf[r.m_free]];
		btVector3 n, cr;
		freeSide(r, n, cr);
		const btVector3 arm = cr + (bodies[r.m_free].getWorldTransform().getOrigin() - comp.m_center).cross(n);
		largest = btMax(largest, btFabs(n.dot(comp.m_dv - comp.m_sweepDv) + arm.dot(comp.m_dw - comp.m_sweepDw)));
	}
	return largest;
}

void btShockPredictor::finishComposites(int layer, const Pools& pools, int sweeps, btScalar convergedSpeed)
{
	btAlignedObjectArray<btSolverBody>& bodies = pools.m_bodies;
	// The roots take their support rows' impulses (the fixated sides keep them withheld).
	for (int i = m_layerStart[layer]; i < m_layerStart[layer + 1]; ++i)
	{
		Row& r = m_rows[i];
		if (r.m_layerDelta == btScalar(0)) continue;
		applyToSide(*r.m_row, r.m_fixed == 2, r.m_layerDelta, bodies);
		r.m_layerDelta = 0;
	}
	for (int ci = 0; ci < m_composites.size(); ++ci)
	{
		const Composite& comp = m_composites[ci];
		const btVector3 v = comp.m_v0 + comp.m_dv, w = comp.m_w0 + comp.m_dw;
		// Children first: each member's weld carries what brings it to the rigid motion and what
		// its children's welds take from it (velocities as the layer left them).
		for (int k = comp.m_end - 1; k > comp.m_first; --k)
		{
			const int m = m_members[k];
			btSolverBody& body = bodies[m];
			const btRigidBody* rb = body.m_originalBody;
			const btVector3 x = body.getWorldTransform().getOrigin();
			btVector3 force = (v + w.cross(x - comp.m_center) - wholeLinear(body)) / rb->getInvMass();
			// Every member's inverse inertia is regular (formComposites).
			btVector3 moment = *worldInertia(m, *rb) * (w - wholeAngular(body));
			for (int j = m_childStart[m]; j < m_childStart[m + 1]; ++j)
			{
				const int child = m_children[j];
				force += m_weldForce[child];
				moment += m_weldMoment[child] + (bodies[child].getWorldTransform().getOrigin() - x).cross(m_weldForce[child]);
			}
			m_weldForce[m] = force;
			m_weldMoment[m] = moment;
		}
		for (int k = comp.m_end - 1; k > comp.m_first; --k)
		{
			const int m = m_members[k];
			// Least-norm impulses of the weld rows with that force and moment on m.
			const btCholesky6* factor = weldFactor(m);
			if (!factor) continue;
			const btScalar wrench[6] = {m_weldForce[m].x(), m_weldForce[m].y(), m_weldForce[m].z(), m_weldMoment[m].x(), m_weldMoment[m].y(), m_weldMoment[m].z()};
			btScalar y[6];
			factor->solve(wrench, y);
			const btVector3 yl(y[0], y[1], y[2]), ya(y[3], y[4], y[5]);
			for (int s = m_supportStart[m]; s < m_supportStart[m + 1]; ++s)
			{
				Row& r = m_rows[m_supportRows[s]];
				btVector3 n, cr;
				freeSide(r, n, cr);
				const btScalar impulse = n.dot(yl) + cr.dot(ya);
				if (impulse == impulse) applyToBoth(r, impulse, bodies);
			}
		}
		// A row the transfer pulls, or pushes past Coulomb, lets go at its bound.
		for (int k = comp.m_first + 1; k < comp.m_end; ++k)
		{
			const int m = m_members[k];
			for (int pass = 0; pass < 2; ++pass)
				for (int s = m_supportStart[m]; s < m_supportStart[m + 1]; ++s)
				{
					Row& r = m_rows[m_supportRows[s]];
					btSolverConstraint& c = *r.m_row;
					if ((pass == 0) != (r.m_normal == 0)) continue;
					boundByNormal(r);
					const btScalar clamped = btMax(r.m_normal ? c.m_lowerLimit : btScalar(0), btMin(c.m_upperLimit, btScalar(c.m_appliedImpulse)));
					if (clamped != c.m_appliedImpulse) applyToBoth(r, clamped - c.m_appliedImpulse, bodies);
				}
		}
	}
	settleWelds(sweeps, convergedSpeed, bodies);
	for (int i = 0; i < m_composites.size(); ++i) m_compositeOf[m_composites[i].m_root] = -1;
	m_composites.resize(0);
}

void btShockPredictor::settleWelds(int sweeps, btScalar convergedSpeed, btAlignedObjectArray<btSolverBody>& bodies)
{
	// The transfer's least-norm impulses, clamped where a row would pull or slip, leave a member
	// off its composite's motion wherever a row was clamped. The weld rows are then swept, members
	// children first, each row Bullet's own update with both bodies free (a projected Gauss-Seidel
	// step of the coupled problem: it keeps momentum and lowers the solve's objective), until a
	// sweep changes no row by more than the convergence speed or the sweeps cannot get there
	// (cannotConverge, as a layer's: in piles most weld sweeps stall at a fixed change). Without:
	// the pushed stack's members stayed 0.2-0.3 m/s off their composite's motion whenever a corner
	// let go, the cycles stalled there and its boxes parted by 0.8-8.6 mm in 2 s; with: 0.015 mm
	// (docs/design.md, section 4.6).
	for (int s = 0; s < sweeps; ++s)
	{
		btScalar largest = 0;
		for (int ci = 0; ci < m_composites.size(); ++ci)
		{
			const Composite& comp = m_composites[ci];
			for (int k = comp.m_end - 1; k > comp.m_first; --k)
			{
				const int m = m_members[k];
				for (int j = m_supportStart[m]; j < m_supportStart[m + 1]; ++j)
				{
					Row row = m_rows[m_supportRows[j]];
					freeBothSides(row);
					row.m_restTarget = 0;
					largest = btMax(largest, solveRow(row, bodies));
				}
			}
		}
		if (!(largest > convergedSpeed)) break;
		if (cannotConverge(m_weldChange, s, largest, convergedSpeed, sweeps)) break;
	}
}
