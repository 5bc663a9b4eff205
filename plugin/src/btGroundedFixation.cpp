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
//             rank (its side of each row). So is a cluster of the layer's bodies that are not
//             grounded alone (bodies of one height touching each other) if its members' support
//             rows and the layer's rows among them, or from them to the layer's grounded bodies,
//             fix all 6 n of their degrees of freedom: two cards leaning on each other, each on an
//             edge that lets it turn, hold each other up, and a load on them reaches the ground
//             through the layer's own sweeps. A row whose fixated side is not grounded (a body on
//             one point or one edge with nothing to lean on, hanging on a joint) is solved with
//             both bodies free, as Bullet's own update: fixating that body would hand it a load it
//             cannot pass on (hostile worlds: a 3 g body under a 0.67 kg one flung at 1.7 km/s).
//   held      in the down pass a free body is held if its support rows fix all six degrees of
//             freedom and every one's relative velocity is within the convergence speed. One that
//             is not (it slides, tips or lifts under what was delivered to it) carries what is
//             welded to it (btWeldedComposites.cpp).
//   precision s is the free body's mass over the fixated one's along the row, plus one; the
//             fixated body's velocity carries s times the load until its supports take it back,
//             so what the free body's visit left reaches it multiplied by s. Rows with
//             s > 2.9e3 (maxFixationScale, both precisions) are solved with both bodies free (addRow).

#include "btShockPredictor.h"

#include "btCholesky6.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

void btShockPredictor::groundRows(const btAlignedObjectArray<btSolverBody>& bodies, const btAlignedObjectArray<int>& heightOfSolverBody)
{
	// Fixation stands for the ground holding a body through the bodies under it. A body is
	// grounded if it is static or kinematic, or its one-sided support rows to grounded bodies fix
	// all six of its degrees of freedom, or it belongs to a cluster of its layer that they fix as a
	// whole (clusterSpans); layer k's fixated sides lie below it, so one pass up the layers decides
	// every body. A row whose fixated side is not grounded (a body on one point or on an edge with
	// nothing to lean on, hanging on a joint) is solved with both bodies free: fixating such a
	// body would hand it a load it cannot pass on.
	m_grounded.resize(bodies.size());
	m_clusterNodes.resize(bodies.size());
	m_clusterRowNext.resizeNoInitialize(m_rows.size());  // a row's link is written as it is linked
	for (int i = 0; i < bodies.size(); ++i)
	{
		const btRigidBody* rb = bodies[i].m_originalBody;
		m_grounded[i] = !rb || !(rb->getInvMass() > btScalar(0)) || heightOfSolverBody[i] == 0;
	}
	for (int k = 0; k < m_numLayers; ++k)
	{
		const int begin = m_layerStart[k], end = m_layerStart[k + 1];
		m_loose.resize(0);
		for (int i = begin; i < end; ++i)
		{
			const int b = m_rows[i].m_free;
			if (b < 0 || m_grounded[b]) continue;
			for (int j = m_supportStart[b]; j < m_supportStart[b + 1]; ++j)
			{
				Row& r = m_rows[m_supportRows[j]];
				if (r.m_fixed && (m_grounded[fixedSide(r)] != 1 || (r.m_kind == CONTACT && !pushCarried(r, bodies)))) freeBothSides(r);
			}
			// A friction or rolling row follows its contact: one-sided only while the contact is. The
			// body's contact rows freed above are listed first (none, in a stack that stands), so
			// each friction row looks among those instead of among all the body's rows.
			m_freedContacts.resize(0);
			for (int j = m_supportStart[b]; j < m_supportStart[b + 1]; ++j)
			{
				const Row& r = m_rows[m_supportRows[j]];
				if (!r.m_normal && !r.m_fixed) m_freedContacts.push_back(r.m_row);
			}
			for (int j = m_supportStart[b]; j < m_supportStart[b + 1] && m_freedContacts.size(); ++j)
			{
				Row& r = m_rows[m_supportRows[j]];
				if (!r.m_fixed || !r.m_normal) continue;
				for (int q = 0; q < m_freedContacts.size(); ++q)
					if (m_freedContacts[q] == r.m_normal) freeBothSides(r);
			}
			m_grounded[b] = supportFactor(b) ? 1 : 2;  // 2: decided, not grounded (alone, so far)
			if (m_grounded[b] != 2) continue;
			m_loose.push_back(b);
			ClusterNode& node = m_clusterNodes[b];
			node.m_parent = b;
			node.m_firstMember = node.m_firstRow = -1;
			node.m_size = 0;
		}
		if (m_loose.size() == 0) continue;
		// Clusters: the loose bodies joined by the layer's rows between them (both free, both ends
		// of height k + 1); then each cluster's members and its rows among them or to the layer's
		// grounded bodies.
		for (int i = begin; i < end; ++i)
		{
			const btSolverConstraint& c = *m_rows[i].m_row;
			const int a = c.m_solverBodyIdA, b = c.m_solverBodyIdB;
			if (m_rows[i].m_fixed || heightOfSolverBody[a] != k + 1 || heightOfSolverBody[b] != k + 1) continue;
			if (m_grounded[a] == 2 && m_grounded[b] == 2) m_clusterNodes[findCluster(a)].m_parent = findCluster(b);
		}
		for (int i = 0; i < m_loose.size(); ++i)
		{
			ClusterNode& root = m_clusterNodes[findCluster(m_loose[i])];
			m_clusterNodes[m_loose[i]].m_index = root.m_size++;
			m_clusterNodes[m_loose[i]].m_nextMember = root.m_firstMember;
			root.m_firstMember = m_loose[i];
		}
		for (int i = begin; i < end; ++i)
		{
			const btSolverConstraint& c = *m_rows[i].m_row;
			const int a = c.m_solverBodyIdA, b = c.m_solverBodyIdB;
			if (m_rows[i].m_fixed || c.m_jacDiagABInv == btScalar(0) || heightOfSolverBody[a] != k + 1 || heightOfSolverBody[b] != k + 1) continue;
			// A member's row to a member of its cluster or to a grounded body (0: undecided, its motion not fixed).
			const int member = m_grounded[a] == 2 ? a : b;
			const int other = member == a ? b : a;
			if (m_grounded[member] != 2 || (m_grounded[other] != 1 && m_grounded[other] != 2)) continue;
			ClusterNode& root = m_clusterNodes[findCluster(member)];
			m_clusterRowNext[i] = root.m_firstRow;
			root.m_firstRow = i;
		}
		for (int i = 0; i < m_loose.size(); ++i)
			if (findCluster(m_loose[i]) == m_loose[i] && clusterSpans(m_loose[i]))
				for (int b = m_clusterNodes[m_loose[i]].m_firstMember; b >= 0; b = m_clusterNodes[b].m_nextMember) m_grounded[b] = 1;
		// Not grounded: the rows to the bodies under it are free on both sides, unless they carry
		// its own load (a ball resting on one point keeps them one-sided; still nothing is fixated
		// on it).
		for (int i = 0; i < m_loose.size(); ++i)
			if (m_grounded[m_loose[i]] == 2 && !carriesOwnLoad(m_loose[i], bodies[m_loose[i]]))
				for (int j = m_supportStart[m_loose[i]]; j < m_supportStart[m_loose[i] + 1]; ++j) freeBothSides(m_rows[m_supportRows[j]]);
	}
}

int btShockPredictor::findCluster(int body)
{
	while (m_clusterNodes[body].m_parent != body)
	{
		m_clusterNodes[body].m_parent = m_clusterNodes[m_clusterNodes[body].m_parent].m_parent;
		body = m_clusterNodes[body].m_parent;
	}
	return body;
}

bool btShockPredictor::clusterSpans(int root)
{
	// The cluster's n members have 6 n degrees of freedom, u = (u_1 .. u_n). Its rows: each
	// member's one-sided support rows (to grounded bodies: J_r u = J_r,b u_b) and the layer's
	// both-free rows from a member to a member (J_r u = J_r,a u_a + J_r,b u_b) or to a grounded
	// body of the layer (held by its own supports: J_r u = J_r,a u_a). They fix the cluster where
	// sum_r J_r^T J_r (6 n x 6 n) has full rank, factored Jacobi-scaled with a single body's
	// pivot. A cluster without such rows is one body, decided alone. The test costs (6 n)^3 / 6
	// multiply-adds: at btShockPropagationNumerics::maxClusterBodies() members 9.4e6, about what the predictor's capped sweeps
	// (6 passes of 200) over the cluster's rows cost; a larger cluster's rows stay free on both
	// sides. That is a bound on cost only: fixation orders the predictor's updates and does not
	// change the coupled problem they converge to.
	const ClusterNode& node = m_clusterNodes[root];
	if (node.m_firstRow < 0 || node.m_size > btShockPropagationNumerics::maxClusterBodies()) return false;
	const int size = 6 * node.m_size;
	m_clusterMatrix.resize(size * size);
	for (int i = 0; i < size * size; ++i) m_clusterMatrix[i] = 0;
	btScalar* A = &m_clusterMatrix[0];
	for (int b = node.m_firstMember; b >= 0; b = m_clusterNodes[b].m_nextMember) addSupportRows(b, A, size, 6 * m_clusterNodes[b].m_index);
	for (int i = node.m_firstRow; i >= 0; i = m_clusterRowNext[i])
	{
		const btSolverConstraint& c = *m_rows[i].m_row;
		btScalar J[12];
		int at[12];
		int m = 0;
		for (int side = 0; side < 2; ++side)
		{
			const int b = side ? c.m_solverBodyIdB : c.m_solverBodyIdA;
			if (m_grounded[b] != 2) continue;  // grounded: held by its own supports
			const btVector3& n = side ? c.m_contactNormal2 : c.m_contactNormal1;
			const btVector3& cr = side ? c.m_relpos2CrossNormal : c.m_relpos1CrossNormal;
			const btScalar Jb[6] = {n.x(), n.y(), n.z(), cr.x(), cr.y(), cr.z()};
			for (int p = 0; p < 6; ++p, ++m)
			{
				J[m] = Jb[p];
				at[m] = 6 * m_clusterNodes[b].m_index + p;
			}
		}
		for (int p = 0; p < m; ++p)
			for (int q = 0; q < m; ++q)
				if (at[q] <= at[p]) A[at[p] * size + at[q]] += J[p] * J[q];
	}
	// Cholesky in place (lower triangle). A pivot of D^-1/2 A D^-1/2 (D = diag A, so metres and
	// radians weigh alike) is A's pivot over its diagonal.
	for (int i = 0; i < size; ++i)
		for (int j = 0; j <= i; ++j)
		{
			btScalar sum = A[i * size + j];
			for (int k = 0; k < j; ++k) sum -= A[i * size + k] * A[j * size + k];
			if (i == j)
			{
				if (!(sum > spanMinPivot() * A[i * size + i])) return false;
				A[i * size + i] = btSqrt(sum);
			}
			else
				A[i * size + j] = sum / A[j * size + j];
		}
	return true;
}

int btShockPredictor::addSupportRows(int body, btScalar* A, int stride, int offset) const
{
	// Adds J_r J_r^T (the body's side) of each one-sided support row to the lower triangle of the
	// 6 x 6 block of A (row length stride) that starts at (offset, offset). Returns the rows added.
	int added = 0;
	for (int k = m_supportStart[body]; k < m_supportStart[body + 1]; ++k)
	{
		const Row& r = m_rows[m_supportRows[k]];
		if (!r.m_fixed) continue;
		btVector3 n, cr;
		freeSide(r, n, cr);
		const btScalar J[6] = {n.x(), n.y(), n.z(), cr.x(), cr.y(), cr.z()};
		BT_CHOLESKY6_UNROLL
		for (int i = 0; i < 6; ++i)
			BT_CHOLESKY6_UNROLL
			for (int j = 0; j <= i; ++j) A[(offset + i) * stride + offset + j] += J[i] * J[j];
		++added;
	}
	return added;
}

const btCholesky6* btShockPredictor::supportFactor(int body) const
{
	// A = sum over the body's one-sided support rows of J_r J_r^T (its side), factored: it has
	// full rank where the rows fix all six degrees of freedom. Formed once per body and step, by
	// grounding (welds, the held test, the settle and the mobility ask for it again), in its slot
	// of m_spanFactors: the callers read it there instead of each copying it.
	const bool cached = body < m_spanState.size();
	if (cached && m_spanState[body] != 0) return m_spanState[body] == 1 ? &m_spanFactors[body] : 0;
	btScalar A[6][6] = {};
	// The body's rows still one-sided: all addRow summed (m_supportSums, in the same order as
	// addSupportRows would add them) unless grounding has freed some since.
	int fixed = 0;
	for (int k = m_supportStart[body]; k < m_supportStart[body + 1]; ++k)
		if (m_rows[m_supportRows[k]].m_fixed) ++fixed;
	int rows;
	if (body < m_supportSumRows.size() && fixed == m_supportSumRows[body])
	{
		const btScalar* sums = &m_supportSums[body * 21];
		for (int i = 0; i < 6; ++i)
			for (int j = 0; j <= i; ++j) A[i][j] = sums[i * (i + 1) / 2 + j];
		rows = fixed;
	}
	else
		rows = addSupportRows(body, &A[0][0], 6, 0);
	// Factored in place: factor() writes all that solve() reads (the lower triangle, the scales).
	btCholesky6& factor = cached ? m_spanFactors[body] : m_spanScratch;
	const bool spans = factor.factor(A, btScalar(0), spanMinPivot(), true);
	if (cached)
	{
		m_spanState[body] = spans ? 1 : 2;
		m_spanRowCount[body] = rows;
	}
	return spans ? &factor : 0;
}

bool btShockPredictor::heldBySupports(int body, btAlignedObjectArray<btSolverBody>& bodies, btScalar speed)
{
	// Held: the support rows fix all six of the body's degrees of freedom (a body on one point or
	// one edge can still turn about it) and every one's relative velocity (whole velocities, not
	// Bullet's deltas) is within the convergence speed.
	if (!supportFactor(body)) return false;
	// The body is one side of each of its support rows: its whole velocity is formed once.
	const btVector3 linear = wholeLinear(bodies[body]), angular = wholeAngular(bodies[body]);
	for (int k = m_supportStart[body]; k < m_supportStart[body + 1]; ++k)
	{
		const Row& r = m_rows[m_supportRows[k]];
		const btSolverConstraint& c = *r.m_row;
		const bool isA = r.m_bodyA == body;
		btSolverBody& other = bodies[isA ? r.m_bodyB : r.m_bodyA];
		const btVector3 otherLinear = wholeLinear(other), otherAngular = wholeAngular(other);
		const btScalar v = isA ? rowVelocity(c, linear, angular, otherLinear, otherAngular) : rowVelocity(c, otherLinear, otherAngular, linear, angular);
		if (btFabs(v) > speed) return false;
	}
	return true;
}

bool btShockPredictor::carriesOwnLoad(int body, const btSolverBody& solverBody) const
{
	// The load w = (F, tau) moves the body by W w; in the W inner product <g, h> = g^T W h the
	// support rows' Jacobians (its side, Gram-Schmidt: h_k with <h_j, h_k> = delta_jk) span what
	// they can carry, and w^T W w - sum_k <h_k, w>^2 is the kinetic energy (over dt^2 / 2) of the
	// motion left to the load: along the rows' null space (a ball rolling about its point).
	const btRigidBody* rb = solverBody.m_originalBody;
	if (!rb || !(rb->getInvMass() > btScalar(0))) return false;
	const btScalar invMass = rb->getInvMass();
	const btMatrix3x3& invInertia = rb->getInvInertiaTensorWorld();
	const btVector3 force = rb->getTotalForce(), torque = rb->getTotalTorque();
	const btScalar total = invMass * force.length2() + torque.dot(invInertia * torque);
	if (!(total > btScalar(0))) return false;
	SupportDirection basis[6];
	bool oneSided = false;
	const int rank = supportBasis(body, invMass, invInertia, false, basis, oneSided);
	btScalar carried = 0;
	for (int k = 0; k < rank; ++k)
	{
		const btScalar along = invMass * force.dot(basis[k].m_linear) + torque.dot(invInertia * basis[k].m_angular);
		carried += along * along;
	}
	return rank > 0 && total - carried <= spanMinPivot() * total;
}

bool btShockPredictor::pushCarried(const Row& r, const btAlignedObjectArray<btSolverBody>& bodies) const
{
	// The contact pushes the fixated body F along p (its side's normal). F's supports pass that on
	// if p lies within the friction cone of one of them: -p . n_s = cos a > 0 and sin a <= mu_s cos a,
	// n_s the support's normal on F's side. A support without friction passes on the normal part and
	// leaves the rest to F's mobility (btFixatedMobility.cpp). Outside every cone, F would slide or
	// lift under the push, and fixating it hands it a load it cannot pass on: a 1.5 g box crushed
	// by a 188 t one through a contact 31 degrees off its supports kept s = 890 times the unbalanced
	// sideways share and was flung at 446 m/s (hostile worlds, seed 258). Bodies grounded only as a
	// cluster's members are held by their mates, not by their supports.
	const int F = fixedSide(r);
	const btRigidBody* rb = bodies[F].m_originalBody;
	if (!rb || !(rb->getInvMass() > btScalar(0))) return true;
	if (!supportFactor(F)) return true;
	const btVector3 push = r.m_fixed == 1 ? r.m_row->m_contactNormal1 : r.m_row->m_contactNormal2;
	for (int k = m_supportStart[F]; k < m_supportStart[F + 1]; ++k)
	{
		const Row& s = m_rows[m_supportRows[k]];
		if (!s.m_fixed || s.m_kind != CONTACT) continue;
		btVector3 n, cr;
		freeSide(s, n, cr);
		const btScalar c = -push.dot(n);
		if (!(c > btScalar(0))) continue;
		const btScalar mu = s.m_row->m_friction;
		if (!(mu > btScalar(0)) || btSqrt(btMax(btScalar(0), btScalar(1) - c * c)) <= mu * c) return true;
	}
	return false;
}
