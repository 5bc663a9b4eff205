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

// A layer visit of the converging step's predictor (btShockPredictor.h; docs/design.md 4.4).
//
// Layer k's rows are swept in order, each by its one-sided update (lower end fixated,
//   dL' = s (m_rhs + restTarget - L m_cfm - m_jacDiagABInv J v),   s = (D_A + D_B + c) / (D_A + J_B W' J_B^T + c),
// projected on its bounds, applied to the free side, the fixated side's share withheld), after the
// layer's support blocks (btSupportBlocks.cpp). A visit ends once a sweep changes no row's velocity
// by more than the visit speed v_c, or once the sweeps' rate says they cannot reach it within their
// budget (cannotConverge). A row is swept only while one of its bodies moved by more than v_c in the
// last sweep, so a converged body costs nothing while its neighbours still move. A fixated support
// whose motion along a row is below v_c is shown to the layer as at rest (showRestingSupports): that
// motion is its own layer's error, and handed up it would grow.

#include "btShockPredictor.h"

#include "BulletDynamics/Dynamics/btRigidBody.h"

btScalar btShockPredictor::solveRow(Row& r, btAlignedObjectArray<btSolverBody>& bodies)
{
	const btScalar delta = updateRow(r, bodies);
	const btSolverConstraint& c = *r.m_row;
	if (r.m_scale == btScalar(0)) return 0;
	// The velocity change of the row (m/s): the impulse over its effective mass.
	return c.m_jacDiagABInv != btScalar(0) ? btFabs(delta / (r.m_scale * c.m_jacDiagABInv)) : btScalar(0);
}

btScalar btShockPredictor::updateRow(Row& r, btAlignedObjectArray<btSolverBody>& bodies)
{
	btSolverConstraint& c = *r.m_row;
	boundByNormal(r);
	if (r.m_scale == btScalar(0)) return 0;
	btSolverBody& a = bodies[c.m_solverBodyIdA];
	btSolverBody& b = bodies[c.m_solverBodyIdB];
	const btScalar velocity = rowVelocity(c, a.internalGetDeltaLinearVelocity(), a.internalGetDeltaAngularVelocity(), b.internalGetDeltaLinearVelocity(),
										  b.internalGetDeltaAngularVelocity());
	btScalar delta = r.m_scale * (c.m_rhs + r.m_restTarget - c.m_appliedImpulse * c.m_cfm - velocity * c.m_jacDiagABInv);
	const btScalar sum = c.m_appliedImpulse + delta;
	const btScalar clamped = btMax(c.m_lowerLimit, btMin(c.m_upperLimit, sum));
	delta = clamped - c.m_appliedImpulse;
	c.m_appliedImpulse = clamped;
	if (r.m_fixed != 1) applyToSide(c, true, delta, bodies);
	if (r.m_fixed != 2) applyToSide(c, false, delta, bodies);
	if (r.m_fixed)
	{
		r.m_withheld += delta;
		moveFixated(r, delta, btScalar(1), bodies);
	}
	return delta;
}

int btShockPredictor::sweepLayer(int layer, const Pools& pools, int sweeps, btScalar convergedSpeed, bool composites)
{
	// Each free body first against its fixated supports alone; a body its supports do not hold
	// (it slides, tips or lifts) then carries what is welded to it, and the layer is swept again.
	showRestingSupports(layer, pools.m_bodies, convergedSpeed);
	int run = sweepRows(layer, pools, sweeps, convergedSpeed, false);
	if (composites)
	{
		formComposites(layer, pools, convergedSpeed);
		// A body its supports do not hold meets their every motion (measured: the leaning columns
		// topple later with resting supports shown here too; docs/design.md, section 4.4). Without
		// composites no row of the layer is solved again before its next visit shows its resting
		// supports anew, so the targets are left as they are.
		if (m_composites.size())
		{
			showRestingSupports(layer, pools.m_bodies, btScalar(0));
			run += sweepRows(layer, pools, sweeps, convergedSpeed, true);
		}
	}
	return run;
}

void btShockPredictor::showRestingSupports(int layer, btAlignedObjectArray<btSolverBody>& bodies, btScalar restSpeed)
{
	// A fixated dynamic support whose whole motion along a row is slower than restSpeed (the
	// convergence speed) is shown to the layer as at rest: that motion is within the tolerance
	// its own layer was solved to, so it is that solve's error, not motion. Handed up, it grows:
	// a box fitted to two supports whose rows move unequally turns, and the box above it turns
	// further (the 2-D pyramids' first up-and-down cycle from rest left 3.3e-7, 2.3e-5 and
	// 1.8e-4 m/s of row error at bases 40, 60 and 80 in float, and each later cycle handed it up
	// again until base 60 moved at 0.08 s; docs/design.md, section 4.4). Only the predictor's target
	// changes: the impulses still act on both bodies, and the corrector's sweeps see every
	// motion. A restSpeed of 0 shows every motion.
	// One pass over the layer's rows: each row's target is reset where it is not set.
	const int begin = m_layerStart[layer], end = m_layerStart[layer + 1];
	const bool show = restSpeed > btScalar(0);
	for (int i = begin; i < end; ++i)
	{
		Row& r = m_rows[i];
		r.m_restTarget = 0;
		if (!show || !r.m_fixed) continue;
		const btSolverConstraint& c = *r.m_row;
		const bool sideA = r.m_fixed == 1;
		btSolverBody& support = bodies[sideA ? c.m_solverBodyIdA : c.m_solverBodyIdB];
		if (!(support.internalGetInvMass().length2() > btScalar(0))) continue;
		const btScalar motion = (sideA ? c.m_contactNormal1 : c.m_contactNormal2).dot(wholeLinear(support)) +
								(sideA ? c.m_relpos1CrossNormal : c.m_relpos2CrossNormal).dot(wholeAngular(support));
		if (btFabs(motion) < restSpeed) r.m_restTarget = motion * c.m_jacDiagABInv;
	}
}

int btShockPredictor::sweepRows(int layer, const Pools& pools, int sweeps, btScalar convergedSpeed, bool composites)
{
	const int begin = m_layerStart[layer];
	const int end = m_layerStart[layer + 1];
	if (begin == end) return 0;
	int run = 0;
	btAlignedObjectArray<btSolverBody>& bodies = pools.m_bodies;
	// Grown only (the solver runs once per island): a record's stamps are older than any this visit
	// sets, whichever island left them.
	if (m_sweepBodies.size() < bodies.size()) m_sweepBodies.resize(bodies.size());
	const bool anyComposite = composites && m_composites.size() > 0;
	if (!anyComposite) m_composites.resize(0);
	solveBlocks(layer, pools);
	// A row is swept while one of its bodies moved in the last sweep: a row whose bodies kept
	// their velocities would not change. A sweep's change marks only the sides it may move (the
	// free side; both sides of a row solved with both bodies free), so a fixated support that no
	// row of the layer moves does not wake the other bodies it carries. A welded composite couples
	// its members' rows, so a layer with composites sweeps all of them.
	const bool perBody = !anyComposite;
	m_rowActive.resize(end - begin);
	if (m_stamp > 0xffffffffu - unsigned(sweeps) - 2u)
	{
		// Before the stamps wrap (after about 4e9 sweeps), no body has moved or been recorded.
		for (int i = 0; i < m_sweepBodies.size(); ++i) m_sweepBodies[i].m_movedAt = m_sweepBodies[i].m_diffAt = 0;
		m_stamp = 0;
	}
	const unsigned first = ++m_stamp;
	// Each body's velocity as the first sweep begins, recorded in the first sweep as its first row
	// is met (marked moved at the first stamp, so every row is swept): a row's update moves only its
	// own bodies, so until then the body has its velocity from before the sweep. Only the layer's
	// rows change a velocity during the visit, so a body's velocity as a sweep begins is the one
	// recorded when its change over the last sweep that touched it was formed (below), or this one.
	for (int s = 0; s < sweeps; ++s)
	{
		for (int i = 0; i < m_composites.size() && anyComposite; ++i)
		{
			m_composites[i].m_sweepDv = m_composites[i].m_dv;
			m_composites[i].m_sweepDw = m_composites[i].m_dw;
		}
		const unsigned moved = m_stamp++;
		// Converged once a whole sweep moves no row's bodies by more than convergedSpeed (m/s)
		// along the row: a sweep whose row updates only shift load among a body's supports
		// (statically indeterminate) changes no velocity and ends the layer.
		for (int i = begin; i < end; ++i)
		{
			Row& r = m_rows[i];
			if (s == 0)
			{
				const int ends[2] = {r.m_bodyA, r.m_bodyB};
				for (int e = 0; e < 2; ++e)
				{
					SweepBody& record = m_sweepBodies[ends[e]];
					if (record.m_movedAt == first) continue;
					record.m_movedAt = first;
					record.m_linear = bodies[ends[e]].internalGetDeltaLinearVelocity();
					record.m_angular = bodies[ends[e]].internalGetDeltaAngularVelocity();
				}
			}
			const bool active = !perBody || m_sweepBodies[r.m_bodyA].m_movedAt == moved || m_sweepBodies[r.m_bodyB].m_movedAt == moved;
			m_rowActive[i - begin] = active;
			if (!active) continue;
			if (anyComposite && r.m_free >= 0 && m_compositeOf[r.m_free] >= 0)
				solveCompositeRow(r, m_composites[m_compositeOf[r.m_free]], bodies);
			else
				updateRow(r, bodies);  // the sweep measures its change from the bodies' velocities
		}
		++run;
		btScalar largest = anyComposite ? compositeMotion(layer, bodies) : btScalar(0);
		for (int i = begin; i < end; ++i)
		{
			if (!m_rowActive[i - begin]) continue;
			const Row& r = m_rows[i];
			const btSolverConstraint& c = *r.m_row;
			// Each body's velocity change over the sweep, formed once; its velocity now is the
			// next sweep's start.
			const int ends[2] = {r.m_bodyA, r.m_bodyB};
			SweepBody* records[2] = {&m_sweepBodies[r.m_bodyA], &m_sweepBodies[r.m_bodyB]};
			for (int e = 0; e < 2; ++e)
			{
				SweepBody& record = *records[e];
				if (record.m_diffAt == moved) continue;
				record.m_diffAt = moved;
				const btVector3& linear = bodies[ends[e]].internalGetDeltaLinearVelocity();
				const btVector3& angular = bodies[ends[e]].internalGetDeltaAngularVelocity();
				record.m_diffLinear = linear - record.m_linear;
				record.m_diffAngular = angular - record.m_angular;
				record.m_linear = linear;
				record.m_angular = angular;
			}
			const btScalar change = rowVelocity(c, records[0]->m_diffLinear, records[0]->m_diffAngular, records[1]->m_diffLinear, records[1]->m_diffAngular);
			largest = btMax(largest, btFabs(change));
			if (btFabs(change) > m_visitSpeed)
			{
				const bool mobile = mobileFixated(r);
				if (r.m_fixed != 1 || mobile) records[0]->m_movedAt = m_stamp;
				if (r.m_fixed != 2 || mobile) records[1]->m_movedAt = m_stamp;
			}
		}
		if (!(largest > m_visitSpeed)) break;
		if (cannotConverge(m_sweepChange, s, largest, m_visitSpeed, sweeps)) break;
	}
	if (anyComposite) finishComposites(layer, pools, sweeps, convergedSpeed);
	return run;
}

bool btShockPredictor::cannotConverge(btAlignedObjectArray<btScalar>& changes, int sweep, btScalar largest, btScalar convergedSpeed, int sweeps)
{
	// Sweeps that cannot reach the convergence speed within their budget end now. Every second
	// sweep from the eighth, the largest change of the last quarter of the sweeps run over that
	// of the quarter before is their rate per quarter (a quarter's largest, not one sweep's: a
	// sweep's change is not monotone while rows reach and leave their bounds); at that rate they
	// need log(converged / largest) / log(rate) quarters more. A solve without a solution keeps
	// its rate at 1 and ends at 8 sweeps: a free body wedged between fixated ones whose
	// velocities close on it (no velocity of it holds both rows; its impulses grow by the same
	// amount each sweep), as in a pile. Checked only as the count doubled (8, 16, 32, ...), a
	// visit that would end at 128 ran 64 sweeps past the check at 64 that could have ended it:
	// the pit cost 27.7 times stock, checked every second sweep 14.8 (docs/design.md, section 4.4).
	changes.resize(sweep + 1);
	changes[sweep] = largest;
	const int done = sweep + 1;
	if (done < 8 || done % 2 != 0) return false;
	const int quarter = done / 4;
	btScalar before = 0, last = 0;
	for (int j = done - 2 * quarter; j < done - quarter; ++j) before = btMax(before, changes[j]);
	for (int j = done - quarter; j < done; ++j) last = btMax(last, changes[j]);
	const btScalar rate = last / before;
	if (!(rate < btScalar(1))) return true;
	const btScalar needed = quarter * btLog(convergedSpeed / largest) / btLog(rate);
	return done + needed > sweeps;
}
