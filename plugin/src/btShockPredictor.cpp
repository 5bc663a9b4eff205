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

// The predictor stage (btShockPredictor.h): layered passes whose impulses are all delivered.

#include "btShockPredictor.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

namespace
{
// J W J^T of one side of a row, as Bullet applies impulses (btSolverBody::internalApplyImpulse).
btScalar sideTerm(const btVector3& normal, const btVector3& crossNormal, const btVector3& angularComponent, const btSolverBody& body)
{
	return normal.dot(normal * body.internalGetInvMass()) + crossNormal.dot(angularComponent);
}
}  // namespace

void btShockPredictor::addRow(btSolverConstraint& c, const btSolverConstraint* normal, int kind, int layer,
							  const btAlignedObjectArray<btSolverBody>& bodies, const btAlignedObjectArray<int>& heightOfSolverBody)
{
	Row r;
	r.m_row = &c;
	r.m_normal = normal;
	r.m_kind = kind;
	r.m_withheld = 0;
	r.m_fixed = 0;
	r.m_scale = 1;
	r.m_total = 0;
	r.m_layerDelta = 0;
	r.m_restTarget = 0;
	r.m_fixedTerm = 0;
	r.m_free = -1;
	r.m_pastLimit = false;
	r.m_bodyA = c.m_solverBodyIdA;
	r.m_bodyB = c.m_solverBodyIdB;
	const int hA = heightOfSolverBody[c.m_solverBodyIdA];
	const int hB = heightOfSolverBody[c.m_solverBodyIdB];
	// A side is fixated in layer k if it is not above the layer (height <= k); a component
	// without a root (height -1) has every body free.
	const bool fixA = hA >= 0 && hA <= layer;
	const bool fixB = hB >= 0 && hB <= layer;
	if (fixA != fixB && c.m_jacDiagABInv != btScalar(0))
	{
		const btScalar dA = sideTerm(c.m_contactNormal1, c.m_relpos1CrossNormal, c.m_angularComponentA, bodies[c.m_solverBodyIdA]);
		const btScalar dB = sideTerm(c.m_contactNormal2, c.m_relpos2CrossNormal, c.m_angularComponentB, bodies[c.m_solverBodyIdB]);
		const btScalar cfm = c.m_cfm / c.m_jacDiagABInv;
		const btScalar freeTerm = (fixA ? dB : dA) + cfm;
		const btScalar total = dA + dB + cfm;
		const btScalar scale = fixationScale(freeTerm, total);
		// s is the free body's mass over the fixated one's along the row, plus one: the fixated
		// body's velocity carries s times the free one's change until its own supports take it
		// back, so what the free body's visit left reaches it multiplied by s. Up to 2.9e3
		// (maxFixationScale, both precisions) that stays small; beyond, the row is solved with
		// both bodies free, as Bullet does.
		if (scale <= maxFixationScale())
		{
			r.m_fixed = fixA ? 1 : 2;
			r.m_free = fixA ? c.m_solverBodyIdB : c.m_solverBodyIdA;
			r.m_total = total;
			r.m_scale = scale;
			// The free body's sum of J J^T over its one-sided rows (supportFactor), formed here while
			// the row is at hand. A body's rows are added in the order its support rows list them
			// (contacts, friction, rolling, each in pool order: their order in m_rows).
			btVector3 n, cr;
			freeSide(r, n, cr);
			const btScalar J[6] = {n.x(), n.y(), n.z(), cr.x(), cr.y(), cr.z()};
			btScalar* sums = &m_supportSums[r.m_free * 21];
			BT_CHOLESKY6_UNROLL
			for (int i = 0; i < 6; ++i)
				BT_CHOLESKY6_UNROLL
				for (int j = 0; j <= i; ++j) sums[i * (i + 1) / 2 + j] += J[i] * J[j];
			++m_supportSumRows[r.m_free];
		}
		else
			r.m_pastLimit = true;
	}
	m_rows[m_cursor[layer * 3 + kind]++] = r;
}

void btShockPredictor::build(const Pools& pools, int numLayers, const btAlignedObjectArray<int>& contactRowLayer,
							 const btAlignedObjectArray<int>& heightOfSolverBody, const btAlignedObjectArray<int>& componentOfSolverBody,
							 int numComponents)
{
	m_numLayers = numLayers;
	m_componentOfSolverBody = &componentOfSolverBody;
	m_slope.resize(numComponents);
	m_curvature.resize(numComponents);
	m_alpha.resize(numComponents);
	const int keys = numLayers * 3;
	m_count.resize(keys + 1);
	for (int i = 0; i <= keys; ++i) m_count[i] = 0;
	const int numContacts = pools.m_contacts.size();
	for (int i = 0; i < numContacts; ++i)
		if (contactRowLayer[i] >= 0 && contactRowLayer[i] < numLayers) ++m_count[contactRowLayer[i] * 3 + CONTACT];
	btConstraintArray* frictionPools[2] = {&pools.m_frictions, &pools.m_rollingFrictions};
	for (int p = 0; p < 2; ++p)
		for (int i = 0; i < frictionPools[p]->size(); ++i)
		{
			const int contact = (*frictionPools[p])[i].m_frictionIndex;
			const int layer = contact >= 0 && contact < numContacts ? contactRowLayer[contact] : -1;
			if (layer >= 0 && layer < numLayers) ++m_count[layer * 3 + FRICTION + p];
		}
	m_cursor.resize(keys + 1);
	int total = 0;
	for (int key = 0; key < keys; ++key)
	{
		m_cursor[key] = total;
		total += m_count[key];
	}
	m_cursor[keys] = total;
	m_layerStart.resize(numLayers + 1);
	for (int k = 0; k <= numLayers; ++k) m_layerStart[k] = m_cursor[k * 3];
	// The solver is called once per island, so these arrays shrink and grow within a step: a slot
	// that is written before it is read is not filled on growing (resizeNoInitialize), and the
	// per-body caches read only where this step formed them only grow (their size is no test).
	m_rows.resizeNoInitialize(total);  // addRow writes every slot
	const int numBodies = pools.m_bodies.size();
	m_supportSums.resizeNoInitialize(numBodies * 21);
	m_supportSumRows.resizeNoInitialize(numBodies);
	for (int i = 0; i < m_supportSums.size(); ++i) m_supportSums[i] = 0;
	for (int i = 0; i < numBodies; ++i) m_supportSumRows[i] = 0;
	for (int i = 0; i < numContacts; ++i)
		if (contactRowLayer[i] >= 0 && contactRowLayer[i] < numLayers)
			addRow(pools.m_contacts[i], 0, CONTACT, contactRowLayer[i], pools.m_bodies, heightOfSolverBody);
	for (int p = 0; p < 2; ++p)
		for (int i = 0; i < frictionPools[p]->size(); ++i)
		{
			btSolverConstraint& c = (*frictionPools[p])[i];
			const int contact = c.m_frictionIndex;
			const int layer = contact >= 0 && contact < numContacts ? contactRowLayer[contact] : -1;
			if (layer >= 0 && layer < numLayers) addRow(c, &pools.m_contacts[contact], FRICTION + p, layer, pools.m_bodies, heightOfSolverBody);
		}
	bucketSupportRows(pools.m_bodies.size());
	m_spanState.resize(pools.m_bodies.size());
	if (m_spanFactors.size() < numBodies) m_spanFactors.resize(numBodies);
	if (m_spanRowCount.size() < numBodies) m_spanRowCount.resize(numBodies);
	for (int i = 0; i < m_spanState.size(); ++i) m_spanState[i] = 0;
	groundRows(pools.m_bodies, heightOfSolverBody);
	// Grounding only frees rows (their free side becomes -1): where it freed none of the rows
	// bucketed, bucketing again gives the same lists.
	bool freed = false;
	for (int k = 0; k < m_supportRows.size() && !freed; ++k) freed = m_rows[m_supportRows[k]].m_free < 0;
	if (freed) bucketSupportRows(pools.m_bodies.size());
	formMobility(pools.m_bodies);
	m_inertiaState.resize(pools.m_bodies.size());
	for (int i = 0; i < m_inertiaState.size(); ++i) m_inertiaState[i] = 0;
	if (m_inertia.size() < numBodies) m_inertia.resize(numBodies);
	m_blockState.resize(pools.m_bodies.size());
	if (m_blockFactors.size() < numBodies) m_blockFactors.resize(numBodies);
	for (int i = 0; i < m_blockState.size(); ++i) m_blockState[i] = 0;
	m_blockIncluded.resizeNoInitialize(m_supportRows.size());  // read only after this step's block wrote it
}

void btShockPredictor::warmStartPastLimit(const Pools& pools, btScalar factor)
{
	for (int i = 0; i < m_rows.size(); ++i)
	{
		Row& r = m_rows[i];
		if (!r.m_pastLimit || r.m_kind != CONTACT) continue;
		btSolverConstraint& c = *r.m_row;
		const btManifoldPoint* point = static_cast<const btManifoldPoint*>(c.m_originalContactPoint);
		if (!point) continue;
		const btScalar impulse = point->m_appliedImpulse * factor;
		if (!(impulse > btScalar(0))) continue;
		c.m_appliedImpulse = impulse;
		applyToSide(c, true, impulse, pools.m_bodies);
		applyToSide(c, false, impulse, pools.m_bodies);
	}
}

void btShockPredictor::bucketSupportRows(int numBodies)
{
	// Support rows of each body: the rows where it is the free side (all in its layer); and each
	// layer's free bodies, once each, in the order of their first rows.
	m_supportStart.resize(numBodies + 1);
	for (int i = 0; i <= numBodies; ++i) m_supportStart[i] = 0;
	for (int i = 0; i < m_rows.size(); ++i)
		if (m_rows[i].m_free >= 0) ++m_supportStart[m_rows[i].m_free + 1];
	for (int i = 0; i < numBodies; ++i) m_supportStart[i + 1] += m_supportStart[i];
	m_supportRows.resizeNoInitialize(m_supportStart[numBodies]);  // every slot written below
	m_count.resizeNoInitialize(numBodies);
	for (int i = 0; i < numBodies; ++i) m_count[i] = m_supportStart[i];
	m_layerFreeStart.resize(m_numLayers + 1);
	m_layerFree.resize(0);
	for (int k = 0; k < m_numLayers; ++k)
	{
		m_layerFreeStart[k] = m_layerFree.size();
		for (int i = m_layerStart[k]; i < m_layerStart[k + 1]; ++i)
		{
			const int b = m_rows[i].m_free;
			if (b < 0) continue;
			if (m_count[b] == m_supportStart[b]) m_layerFree.push_back(b);
			m_supportRows[m_count[b]++] = i;
		}
	}
	m_layerFreeStart[m_numLayers] = m_layerFree.size();
}

const btMatrix3x3* btShockPredictor::worldInertia(int body, const btRigidBody& rb) const
{
	const btMatrix3x3& invInertia = rb.getInvInertiaTensorWorld();
	if (!(body < m_inertiaState.size()))
	{
		// Outside the step's arrays: formed for this call.
		if (!(btFabs(invInertia.determinant()) > SIMD_EPSILON)) return 0;
		m_inertiaScratch = invInertia.inverse();
		return &m_inertiaScratch;
	}
	if (m_inertiaState[body] == 0)
	{
		const bool regular = btFabs(invInertia.determinant()) > SIMD_EPSILON;
		if (regular) m_inertia[body] = invInertia.inverse();
		m_inertiaState[body] = regular ? 1 : 2;
	}
	return m_inertiaState[body] == 1 ? &m_inertia[body] : 0;
}

void btShockPredictor::recordStart(btAlignedObjectArray<btSolverBody>& bodies)
{
	m_startLinear.resize(bodies.size());
	m_startAngular.resize(bodies.size());
	for (int i = 0; i < bodies.size(); ++i)
	{
		m_startLinear[i] = bodies[i].internalGetDeltaLinearVelocity();
		m_startAngular[i] = bodies[i].internalGetDeltaAngularVelocity();
	}
	// The rows' impulses before the passes were recorded by the residual just before (residual):
	// one pass over the rows fewer.
}

btScalar btShockPredictor::lineSearch(btAlignedObjectArray<btSolverBody>& bodies)
{
	// The passes changed the bodies' velocities from u to u + du (every impulse delivered to both
	// bodies by now). Along u + alpha du the kinetic energy of a contact-graph component is
	//   E(alpha) = E(0) + alpha du.M u + alpha^2 / 2 du.M du,
	// so its step is alpha = clamp(-du.M u / du.M du, 0, 1): contact impulses are passive, and
	// where fixation is wrong (a support that slides: the up pass drags every body to the bottom
	// one's velocity and the delivered reactions hand the bottom body the carried mass times its
	// error) the step that would add energy is shortened. Components share no row, so each is
	// searched on its own: a ball's rebound beside a tower, which no minimum of E keeps, does not
	// shorten the tower's step. The impulses are scaled alike, so the velocities stay those of the
	// impulses and Newton's third law holds for any alpha. Returns the smallest alpha taken.
	const btAlignedObjectArray<int>& componentOf = *m_componentOfSolverBody;
	for (int c = 0; c < m_slope.size(); ++c) m_slope[c] = m_curvature[c] = 0;
	for (int i = 0; i < bodies.size(); ++i)
	{
		btSolverBody& body = bodies[i];
		const btRigidBody* rb = body.m_originalBody;
		const int component = i < componentOf.size() ? componentOf[i] : -1;
		if (!rb || !(rb->getInvMass() > btScalar(0)) || component < 0) continue;
		const btVector3 dv = body.internalGetDeltaLinearVelocity() - m_startLinear[i];
		const btVector3 dw = body.internalGetDeltaAngularVelocity() - m_startAngular[i];
		if (dv.isZero() && dw.isZero()) continue;
		const btVector3 v = body.m_linearVelocity + body.m_externalForceImpulse + m_startLinear[i];
		const btVector3 w = body.m_angularVelocity + body.m_externalTorqueImpulse + m_startAngular[i];
		const btScalar mass = btScalar(1) / rb->getInvMass();
		// I dw from I^-1 (I dw) = dw: the momentum the passes gave the body's spin.
		btVector3 Idw(0, 0, 0);
		if (const btMatrix3x3* inertia = worldInertia(i, *rb)) Idw = *inertia * dw;
		m_slope[component] += mass * dv.dot(v) + Idw.dot(w);
		m_curvature[component] += mass * dv.length2() + Idw.dot(dw);
	}
	btScalar smallest = 1, largest = 0;
	for (int c = 0; c < m_alpha.size(); ++c)
	{
		m_alpha[c] = m_curvature[c] > btScalar(0) ? btMax(btScalar(0), btMin(btScalar(1), -m_slope[c] / m_curvature[c])) : btScalar(1);
		if (m_alpha[c] < smallest) smallest = m_alpha[c];
		if (m_curvature[c] > btScalar(0) && m_alpha[c] > largest) largest = m_alpha[c];
	}
	if (!(smallest < btScalar(1))) return largest;
	for (int i = 0; i < m_rows.size(); ++i)
	{
		btSolverConstraint& c = *m_rows[i].m_row;
		// A row's component is that of its dynamic side (both sides share it when both are).
		int component = componentOf[c.m_solverBodyIdA];
		if (component < 0) component = componentOf[c.m_solverBodyIdB];
		if (component < 0) continue;
		c.m_appliedImpulse = m_rows[i].m_start + m_alpha[component] * (c.m_appliedImpulse - m_rows[i].m_start);
	}
	for (int i = 0; i < bodies.size(); ++i)
	{
		const int component = i < componentOf.size() ? componentOf[i] : -1;
		if (component < 0) continue;
		const btScalar alpha = m_alpha[component];
		btSolverBody& body = bodies[i];
		body.internalGetDeltaLinearVelocity() = m_startLinear[i] + alpha * (body.internalGetDeltaLinearVelocity() - m_startLinear[i]);
		body.internalGetDeltaAngularVelocity() = m_startAngular[i] + alpha * (body.internalGetDeltaAngularVelocity() - m_startAngular[i]);
	}
	return largest;
}

bool btShockPredictor::reachable(btScalar r, btScalar last, btScalar convergedSpeed, int cyclesLeft)
{
	// At the rate the last cycle lowered the coupled residual (r / last), can the cycles left
	// bring it to the convergence speed? A cycle that does not lower it cannot.
	if (!(r < last) || cyclesLeft <= 0) return false;
	const btScalar rate = r / last;
	btScalar reach = r;
	for (int i = 0; i < cyclesLeft && reach > convergedSpeed; ++i) reach *= rate;
	return reach <= convergedSpeed;
}

btScalar btShockPredictor::residual(const btAlignedObjectArray<btSolverBody>& bodies)
{
	btScalar worst = 0;
	for (int i = 0; i < m_rows.size(); ++i)
	{
		const btSolverConstraint& c = *m_rows[i].m_row;
		// The impulse the next cycle starts from (recordStart): no row changes between a residual
		// and the next cycle.
		m_rows[i].m_start = c.m_appliedImpulse;
		if (c.m_jacDiagABInv == btScalar(0)) continue;
		const btSolverBody& a = bodies[c.m_solverBodyIdA];
		const btSolverBody& b = bodies[c.m_solverBodyIdB];
		const btScalar velocity = rowVelocity(c, a.m_deltaLinearVelocity, a.m_deltaAngularVelocity, b.m_deltaLinearVelocity, b.m_deltaAngularVelocity);
		const btScalar error = (c.m_rhs - c.m_appliedImpulse * c.m_cfm) / c.m_jacDiagABInv - velocity;
		btScalar lower, upper;
		rowBounds(m_rows[i], lower, upper);
		if (error > worst && c.m_appliedImpulse < upper) worst = error;
		if (-error > worst && c.m_appliedImpulse > lower) worst = -error;
	}
	return worst;
}

void btShockPredictor::deliver(int layer, btAlignedObjectArray<btSolverBody>& bodies)
{
	for (int i = m_layerStart[layer]; i < m_layerStart[layer + 1]; ++i)
	{
		Row& r = m_rows[i];
		if (r.m_fixed == 0 || r.m_withheld == btScalar(0)) continue;
		applyToSide(*r.m_row, r.m_fixed == 1, r.m_withheld, bodies);
		moveFixated(r, r.m_withheld, btScalar(-1), bodies);
		r.m_withheld = 0;
	}
}

int btShockPredictor::predict(const Pools& pools, int sweeps, btScalar convergedSpeed, bool weightFeeling, int cycles, btScalar forcing)
{
	int run = 0;
	// The classic order delivers each cycle's reactions after its up pass and meets them only in
	// the next cycle: a load reaches the ground one layer per cycle and the ground's answer the
	// top one layer per cycle, so it may take 2 K cycles (header, "Cycles").
	const int cycleCount = weightFeeling ? btMax(1, cycles) : btMax(btMax(1, cycles), 2 * m_numLayers);
	// The coupled residual before the passes (m/s), then after each cycle.
	btScalar last = residual(pools.m_bodies);
	m_visitSpeed = convergedSpeed;
	for (int cycle = 0; cycle < cycleCount; ++cycle)
	{
		// A cycle after the first starts from the last one's velocities: each layer meets the
		// final motion of the layers below it, and its layer visits end at the forcing share of
		// the last cycle's residual (header, "Cycles"). Each cycle's change is line searched on
		// its own (header, "Line search"), so a cycle that would move away from the solution is
		// shortened before the next one starts from it. Cycles end once the coupled residual
		// (header) is within the convergence speed, once a search keeps nothing of its cycle (the
		// next cycle would start from the same velocities and repeat it), or, with weight
		// feeling, once a cycle does not lower the residual (the first: below its value before the
		// passes), and from the second cycle once no layer needs more than one sweep (its down
		// pass has then met every delivered reaction) or the cycles left, each lowering the
		// residual as the last one did, cannot bring it to the convergence speed.
		int most = 0;
		recordStart(pools.m_bodies);
		for (int k = 0; k < m_numLayers; ++k) most = btMax(most, sweepLayer(k, pools, sweeps, convergedSpeed, false));
		if (weightFeeling) findWelds(pools);
		for (int k = m_numLayers - 1; k >= 0; --k)
		{
			if (weightFeeling) most = btMax(most, sweepLayer(k, pools, sweeps, convergedSpeed, true));
			deliver(k, pools.m_bodies);
		}
		run += most;
		if (!(lineSearch(pools.m_bodies) > btScalar(0))) break;
		const btScalar r = residual(pools.m_bodies);
		if (r <= convergedSpeed) break;
		if (weightFeeling && (!(r < last) || (cycle > 0 && (most <= 1 || !reachable(r, last, convergedSpeed, cycleCount - cycle - 1))))) break;
		last = r;
		m_visitSpeed = btMax(convergedSpeed, forcing * r);
	}
	return run;
}
