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

// Position correction of the step (D6) and the world's second correction after the positions
// advance (D4).

#include "BulletShockPropagation/btShockPropagationConstraintSolver.h"

#include "btBodyChecks.h"
#include "btPositionCorrection.h"
#include "btShockPredictor.h"

using namespace btShockPropagationChecks;

bool btShockPropagationConstraintSolver::correctPositions(const btContactSolverInfo& info, bool fresh, bool layered, btScalar fraction)
{
	const int sweeps = sweepCount(m_settings.m_correctionIterations, info.m_numIterations);
	if (sweeps <= 0 || m_bodies.size() == 0) return false;
	int numPoints = 0;
	for (int i = 0; i < m_manifolds.size(); ++i) numPoints += m_manifolds[i]->getNumContacts();
	m_correction->reset(m_bodies.size(), m_layers.getNumLayers(), numPoints);
	for (int i = 0; i < m_bodies.size(); ++i) m_correction->setBody(i, btRigidBody::upcast(m_bodies[i]));
	// A body with a contact edge (any manifold with points, before the second phase keeps only
	// the stacked components' ones) is moved by its contacts, never carried by its joints.
	for (int i = 0; i < m_bodies.size(); ++i)
		if (m_graph.getNumIncidentEdges(i) > 0) m_correction->markTouching(i);
	for (int i = 0; i < m_bodies.size(); ++i) m_bodies[i]->setCompanionId(i);
	const btScalar dt = info.m_timeStep;
	const btScalar tolerance = m_settings.m_diagnostics.m_weightConvergence * largestGravity() * dt * dt;
	if (fraction < btScalar(0)) fraction = m_settings.m_diagnostics.m_correctionFraction;
	for (int i = 0; i < m_manifolds.size(); ++i)
	{
		const int edge = m_edgeOfManifold[i];
		if (edge < 0) continue;
		const btContactGraphEdge& e = m_graph.getEdge(edge);
		const btPersistentManifold* m = m_manifolds[i];
		const btCollisionObject* a = m->getBody0();
		const btCollisionObject* b = m->getBody1();
		// Slop (D6): fixed, or a share of the distance a body falls from rest in one step.
		btScalar slop = m_settings.m_correctionSlop;
		if (slop < btScalar(0))
		{
			const btVector3 up = upOf(m);
			const btRigidBody* dynamic = btRigidBody::upcast(e.m_bodyA >= 0 ? a : b);
			const btScalar g = (dynamic && !up.isZero()) ? dynamic->getGravity().length() : btScalar(0);
			slop = m_settings.m_correctionSlopPerFall * g * dt * dt;
		}
		for (int j = 0; j < m->getNumContacts(); ++j)
		{
			const btManifoldPoint& cp = m->getContactPoint(j);
			btVector3 pointA = cp.getPositionWorldOnA();
			btVector3 pointB = cp.getPositionWorldOnB();
			btScalar distance = cp.getDistance();
			if (fresh)
			{
				// As Bullet's refreshContactPoints, without changing the manifold.
				pointA = a->getWorldTransform() * cp.m_localPointA;
				pointB = b->getWorldTransform() * cp.m_localPointB;
				distance = (pointA - pointB).dot(cp.m_normalWorldOnB);
			}
			// Beyond the slop by more than the step's own tolerance: a resting contact sits at the
			// slop where the last correction left it, and the velocity solve leaves each row's
			// velocity within the corrector's convergence speed, so a depth within that speed times
			// dt of the slop is no penetration to correct (docs/design.md, section 7).
			const btScalar depth = -distance - slop;
			if (!(depth > tolerance)) continue;
			m_correction->addPoint(e.m_bodyA, e.m_bodyB, pointA, pointB, cp.m_normalWorldOnB, fraction * depth,
								   m_layers.getEdgeLayer(edge));
		}
	}
	// The group's joints, for the bodies that hang on them touching nothing.
	for (int i = 0; i < m_constraints.size(); ++i)
		if (m_constraints[i]->isEnabled()) m_correction->addJoint(nodeOf(&m_constraints[i]->getRigidBodyA()), nodeOf(&m_constraints[i]->getRigidBodyB()));
	for (int i = 0; i < m_bodies.size(); ++i) m_bodies[i]->setCompanionId(-1);
	if (m_correction->getNumPoints() == 0) return false;
	// The converging step fixates a row's lower body only up to the predictor's limit on s
	// (btShockPredictor::maxFixationScale); its positions follow the same rule.
	const btScalar maxScale = btShockPredictor::maxFixationScale();
	m_correction->solve(sweeps, layered ? &m_layers : 0, maxScale);
	m_correction->apply();
	return true;
}

bool btShockPropagationConstraintSolver::correctAfterStep(btCollisionObject** objects, int numObjects, btPersistentManifold** manifolds,
														  int numManifolds, btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info,
														  btScalar fraction)
{
	BT_PROFILE("btShockPropagationConstraintSolver::correctAfterStep");
	btClock clock;
	filterInput(objects, numObjects, manifolds, numManifolds, constraints, numConstraints, false);
	// Sleeping bodies are not moved: they are roots here, as static bodies are.
	int kept = 0;
	for (int i = 0; i < m_bodies.size(); ++i)
		if (m_bodies[i]->isActive()) m_bodies[kept++] = m_bodies[i];
	m_bodies.resize(kept);
	buildGraph();
	// Only stacked components are corrected (groups without stacks were Bullet's own solve).
	bool anyStack = m_layers.getNumLayers() > 1 || m_settings.m_diagnostics.m_layerFlatGroups;
	bool moved = false;
	if (anyStack)
	{
		const btAlignedObjectArray<int>& tallest = tallestOfComponents();
		int keptManifolds = 0;
		btAlignedObjectArray<int>& keptEdges = m_keptEdges;
		keptEdges.resize(0);
		for (int i = 0; i < m_manifolds.size(); ++i)
		{
			const int edge = m_edgeOfManifold[i];
			if (edge < 0) continue;
			const btContactGraphEdge& e = m_graph.getEdge(edge);
			const int node = e.m_bodyA >= 0 ? e.m_bodyA : e.m_bodyB;
			if (!m_settings.m_diagnostics.m_layerFlatGroups && tallest[m_layers.getComponent(node)] <= 1) continue;
			m_manifolds[keptManifolds] = m_manifolds[i];
			keptEdges.push_back(edge);
			++keptManifolds;
		}
		m_manifolds.resize(keptManifolds);
		m_edgeOfManifold.resize(keptManifolds);
		for (int i = 0; i < keptManifolds; ++i) m_edgeOfManifold[i] = keptEdges[i];
		// The detection at t + dt found one new point per GJK pair, as the step's did: their
		// patches are completed as for the solve (D33), so the correction does not turn a body
		// about a single point. (D30 is not run here: box pairs' points are the box-box test's,
		// and adding corners here changed falling boxes, the pit's deepest point 6.4 -> 6.8 cm.)
		completeContactPatches(info.m_timeStep);
		moved = correctPositions(info, true, m_settings.m_diagnostics.m_layeredSecondCorrection, fraction);
	}
	m_stats.m_timeCorrectionMs += millisecondsSince(clock);
	return moved;
}
