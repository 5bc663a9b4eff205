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

// Velocity-based shock propagation: K. Erleben, "Velocity-Based Shock Propagation for Multibody
// Dynamics Animation", ACM TOG 26(2), Article 12, 2007. The step as built is described in
// btShockPropagationConstraintSolver.h and docs/design.md (decisions D1-D15: docs/history.md).

#include "BulletShockPropagation/btShockPropagationConstraintSolver.h"

#include "BulletCollision/NarrowPhaseCollision/btPersistentManifold.h"
#include "BulletDynamics/Dynamics/btRigidBody.h"
#include "LinearMath/btQuickprof.h"
#include "btBodyChecks.h"
#include "btBoxFaceCorners.h"
#include "btShockPredictor.h"
#include "btFeltShares.h"
#include "btPositionCorrection.h"

#include <cmath>
#include <cstdio>
#include <new>
#include <stdexcept>

using namespace btShockPropagationChecks;

btShockPropagationConstraintSolver::btShockPropagationConstraintSolver()
	: m_correction(new (btAlignedAlloc(sizeof(btPositionCorrection), 16)) btPositionCorrection),
	  m_predictor(new (btAlignedAlloc(sizeof(btShockPredictor), 16)) btShockPredictor)
{
}

btShockPropagationConstraintSolver::btShockPropagationConstraintSolver(const btShockPropagationSettings& settings)
	: btShockPropagationConstraintSolver()
{
	setSettings(settings);
}

btShockPropagationConstraintSolver::~btShockPropagationConstraintSolver()
{
	m_correction->~btPositionCorrection();
	btAlignedFree(m_correction);
	m_predictor->~btShockPredictor();
	btAlignedFree(m_predictor);
}

void btShockPropagationConstraintSolver::setWeighting(btScalar f)
{
	if (f != f) return;  // NaN: keep the current value
	m_settings.m_weighting = btMax(btScalar(0), btMin(btScalar(1), f));
}

void btShockPropagationConstraintSolver::setSettings(const btShockPropagationSettings& settings)
{
	const btShockPropagationSettings defaults;
	const btScalar f = m_settings.m_weighting;
	m_settings = settings;
	m_settings.m_weighting = f;
	setWeighting(settings.m_weighting);
	m_settings.m_globalIterations = btMax(int(BT_SHOCK_ITERATIONS_FROM_WORLD), settings.m_globalIterations);
	m_settings.m_correctionIterations = btMax(int(BT_SHOCK_ITERATIONS_FROM_WORLD), settings.m_correctionIterations);
	if (!(settings.m_diagnostics.m_correctionFraction >= 0 && settings.m_diagnostics.m_correctionFraction <= 1)) m_settings.m_diagnostics.m_correctionFraction = defaults.m_diagnostics.m_correctionFraction;
	if (!(settings.m_diagnostics.m_secondCorrectionFraction > 0 && settings.m_diagnostics.m_secondCorrectionFraction <= 1)) m_settings.m_diagnostics.m_secondCorrectionFraction = defaults.m_diagnostics.m_secondCorrectionFraction;
	if (settings.m_diagnostics.m_secondPhaseRounds < 1) m_settings.m_diagnostics.m_secondPhaseRounds = defaults.m_diagnostics.m_secondPhaseRounds;
	if (!isFiniteScalar(settings.m_correctionSlop)) m_settings.m_correctionSlop = defaults.m_correctionSlop;
	if (!(settings.m_correctionSlopPerFall >= 0) || !isFiniteScalar(settings.m_correctionSlopPerFall))
		m_settings.m_correctionSlopPerFall = defaults.m_correctionSlopPerFall;
	if (!(settings.m_diagnostics.m_weightConvergence >= 0) || !isFiniteScalar(settings.m_diagnostics.m_weightConvergence)) m_settings.m_diagnostics.m_weightConvergence = defaults.m_diagnostics.m_weightConvergence;
	if (!(settings.m_diagnostics.m_predictorConvergence >= 0) || !isFiniteScalar(settings.m_diagnostics.m_predictorConvergence))
		m_settings.m_diagnostics.m_predictorConvergence = defaults.m_diagnostics.m_predictorConvergence;
	m_settings.m_diagnostics.m_predictorIterations = btMax(0, settings.m_diagnostics.m_predictorIterations);
	m_settings.m_diagnostics.m_predictorCycles = btMax(1, settings.m_diagnostics.m_predictorCycles);
	if (!isFiniteScalar(settings.m_diagnostics.m_supportAngle)) m_settings.m_diagnostics.m_supportAngle = defaults.m_diagnostics.m_supportAngle;
}

int btShockPropagationConstraintSolver::sweepCount(int setting, int worldIterations) const
{
	return setting >= 0 ? setting : btMax(0, worldIterations);
}

void btShockPropagationConstraintSolver::prepareSolve(int numBodies, int numManifolds)
{
	btSequentialImpulseConstraintSolver::prepareSolve(numBodies, numManifolds);
	// Every world calls this once per step, before the step's solveGroup calls.
	m_stats = btShockPropagationStatistics();
	m_layeredBodies.resize(0);
	m_layeredBodyHeights.resize(0);
	m_solveGroupCalls = 0;
}

void btShockPropagationConstraintSolver::allSolved(const btContactSolverInfo& info, btIDebugDraw* debugDrawer)
{
	btSequentialImpulseConstraintSolver::allSolved(info, debugDrawer);
	if (m_solveGroupCalls == 0)
	{
		throw std::logic_error(
			"btShockPropagationConstraintSolver: the world prepared a step but never called solveGroup. "
			"btMultiBodyDynamicsWorld keeps solving with its own btMultiBodyConstraintSolver, so the plugin cannot run "
			"there (not supported); use btDiscreteDynamicsWorld or btShockPropagationDynamicsWorld");
	}
}

btScalar btShockPropagationConstraintSolver::solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
														int numManifolds, btTypedConstraint** constraints, int numConstraints,
														const btContactSolverInfo& info, btIDebugDraw* debugDrawer, btDispatcher* /*dispatcher*/)
{
	BT_PROFILE("btShockPropagationConstraintSolver::solveGroup");
	++m_solveGroupCalls;
	filterInput(bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, true);
	btClock clock;
	buildGraph();
	for (int i = 0; i < m_bodies.size(); ++i)
	{
		m_layeredBodies.push_back(m_bodies[i]);
		m_layeredBodyHeights.push_back(m_layers.getHeight(i));
	}
	const int numLayers = m_layers.getNumLayers();
	m_stats.m_numGroups += 1;
	m_stats.m_numComponents += m_layers.getNumComponents();
	m_stats.m_numLayers = btMax(m_stats.m_numLayers, numLayers);
	m_stats.m_largestLayer = btMax(m_stats.m_largestLayer, m_layers.getLargestLayer());
	m_stats.m_timeGraphMs += millisecondsSince(clock);

	if ((numLayers <= 1 && !m_settings.m_diagnostics.m_layerFlatGroups) || m_bodies.size() == 0)
	{
		// No stacks: Bullet's own solve of the group, with the app's settings (D9).
		clock.reset();
		solveFlat(info, debugDrawer);
		m_stats.m_timeGlobalDynamicsMs += millisecondsSince(clock);
		return btScalar(0);
	}
	if (!m_settings.m_diagnostics.m_layerFlatGroups && splitOffFlatComponents())
	{
		// Bullet batches small islands into one call: the components without stacks are Bullet's
		// own solve, as a group of them alone is (D9), and the stacked rest is solved as below.
		// Components share no body and no row, so each gets the result it would get alone.
		clock.reset();
		m_bodies.copyFromArray(m_flatBodies);
		m_manifolds.copyFromArray(m_flatManifolds);
		m_constraints.copyFromArray(m_flatConstraints);
		solveFlat(info, debugDrawer);
		m_bodies.copyFromArray(m_stackedBodies);
		m_manifolds.copyFromArray(m_stackedManifolds);
		m_constraints.copyFromArray(m_stackedConstraints);
		m_stats.m_timeGlobalDynamicsMs += millisecondsSince(clock);
		clock.reset();
		buildGraph();
		m_stats.m_timeGraphMs += millisecondsSince(clock);
	}
	m_stats.m_numLayeredGroups += 1;
	m_stats.m_numFixatedBodies += m_layers.getTotalFixated();
	solveConverging(info, debugDrawer);
	return btScalar(0);
}

bool btShockPropagationConstraintSolver::splitOffFlatComponents()
{
	// A component is stacked if a body of it stands at height 2 or more (one stack layer is
	// flat). Components joined by a joint (joints are no graph edges, D8) or by a manifold without
	// an edge (points beyond the processing threshold, which Bullet's setup still takes the bodies
	// of) are solved together, stacked if either is: a lamp hung from a tower is the tower's. Else
	// one part's solve would write the other part's body too, and gravity would reach it twice.
	btAlignedObjectArray<int>& tallest = tallestOfComponents();
	// Flat: the node's component has no body at height 2 (no node, a static pair: stacked part).
	auto flat = [&](int node) { return node >= 0 && m_layers.getComponent(node) >= 0 && tallest[m_layers.getComponent(node)] < 2; };
	for (int i = 0; i < m_bodies.size(); ++i) m_bodies[i]->setCompanionId(i);
	for (bool changed = true; changed;)
	{
		changed = false;
		for (int i = 0; i < m_constraints.size() + m_manifolds.size(); ++i)
		{
			const bool joint = i < m_constraints.size();
			const btCollisionObject* bodyA = joint ? &m_constraints[i]->getRigidBodyA() : m_manifolds[i - m_constraints.size()]->getBody0();
			const btCollisionObject* bodyB = joint ? &m_constraints[i]->getRigidBodyB() : m_manifolds[i - m_constraints.size()]->getBody1();
			const int a = nodeOf(bodyA), b = nodeOf(bodyB);
			if (a < 0 || b < 0 || m_layers.getComponent(a) < 0 || m_layers.getComponent(b) < 0 || flat(a) == flat(b)) continue;
			tallest[m_layers.getComponent(a)] = tallest[m_layers.getComponent(b)] = 2;
			changed = true;
		}
	}
	// A body's, manifold's or joint's part: that of its (first) dynamic node. A manifold goes by
	// its bodies, not its graph edge: one without an edge still gives Bullet's setup its bodies.
	m_flatBodies.resize(0);
	m_flatManifolds.resize(0);
	m_flatConstraints.resize(0);
	m_stackedBodies.resize(0);
	m_stackedManifolds.resize(0);
	m_stackedConstraints.resize(0);
	for (int i = 0; i < m_bodies.size(); ++i) (flat(i) ? m_flatBodies : m_stackedBodies).push_back(m_bodies[i]);
	for (int i = 0; i < m_manifolds.size(); ++i)
	{
		const int a = nodeOf(m_manifolds[i]->getBody0());
		(flat(a >= 0 ? a : nodeOf(m_manifolds[i]->getBody1())) ? m_flatManifolds : m_stackedManifolds).push_back(m_manifolds[i]);
	}
	for (int i = 0; i < m_constraints.size(); ++i)
	{
		const int a = nodeOf(&m_constraints[i]->getRigidBodyA());
		(flat(a >= 0 ? a : nodeOf(&m_constraints[i]->getRigidBodyB())) ? m_flatConstraints : m_stackedConstraints).push_back(m_constraints[i]);
	}
	for (int i = 0; i < m_bodies.size(); ++i) m_bodies[i]->setCompanionId(-1);
	return m_flatBodies.size() > 0 && m_stackedBodies.size() > 0;
}

btAlignedObjectArray<int>& btShockPropagationConstraintSolver::tallestOfComponents()
{
	btAlignedObjectArray<int>& tallest = m_tallestOfComponent;
	tallest.resize(m_layers.getNumComponents());
	for (int c = 0; c < tallest.size(); ++c) tallest[c] = 0;
	for (int i = 0; i < m_bodies.size(); ++i)
	{
		const int c = m_layers.getComponent(i);
		if (c >= 0) tallest[c] = btMax(tallest[c], m_layers.getHeight(i));
	}
	return tallest;
}

void btShockPropagationConstraintSolver::assignRowsToLayers()
{
	// Bullet's setup converts the manifolds in the order given, one contact row per point within
	// the processing threshold, so a manifold's rows are consecutive and point into its cache.
	const int numRows = m_tmpSolverContactConstraintPool.size();
	m_contactRowLayer.resize(numRows);
	int row = 0;
	for (int i = 0; i < m_manifolds.size() && row < numRows; ++i)
	{
		if (m_manifolds[i]->getNumContacts() == 0) continue;  // no rows (and no point 0 to address)
		const btManifoldPoint* first = &m_manifolds[i]->getContactPoint(0);
		const btManifoldPoint* last = first + MANIFOLD_CACHE_SIZE;
		const int edge = m_edgeOfManifold[i];
		const int layer = edge >= 0 ? m_layers.getEdgeLayer(edge) : -1;
		while (row < numRows)
		{
			const btManifoldPoint* cp = static_cast<const btManifoldPoint*>(m_tmpSolverContactConstraintPool[row].m_originalContactPoint);
			if (cp < first || cp >= last) break;
			m_contactRowLayer[row++] = layer;
		}
	}
	for (; row < numRows; ++row)
	{
		m_contactRowLayer[row] = -1;
	}

	m_solverBodyOfNode.resize(m_bodies.size());
	for (int i = 0; i < m_bodies.size(); ++i) m_solverBodyOfNode[i] = m_bodies[i]->getCompanionId();
}

btScalar btShockPropagationConstraintSolver::largestGravity() const
{
	btScalar g = 0;
	for (int i = 0; i < m_bodies.size(); ++i)
	{
		const btRigidBody* rb = btRigidBody::upcast(m_bodies[i]);
		if (rb && rb->getInvMass() > btScalar(0)) g = btMax(g, rb->getGravity().length());
	}
	return g;
}

void btShockPropagationConstraintSolver::solveFlat(const btContactSolverInfo& info, btIDebugDraw* debugDrawer)
{
	// A group without stacks, as a stock step solves it: its warm start made Bullet's (points the
	// converging step solved start from zero), Bullet's solveGroup, and each point's impulse
	// recorded as felt by both bodies.
	startFromOwnImpulses();
	btSequentialImpulseConstraintSolver::solveGroup(m_bodies.size() ? &m_bodies[0] : 0, m_bodies.size(), m_manifolds.size() ? &m_manifolds[0] : 0,
													m_manifolds.size(), m_constraints.size() ? &m_constraints[0] : 0, m_constraints.size(), info,
													debugDrawer, 0);
	markPointsFelt();
}

void btShockPropagationConstraintSolver::startFromOwnImpulses()
{
	// Bullet's solve warm starts from its own impulses only: a point last solved by the converging
	// step (which starts its rows from zero; markPointsSolved set its felt share unequal to its
	// impulse) starts from zero here too. Those impulses are a stacked group's loads; where the
	// group came apart they no longer balance, and Bullet's few sweeps turned a column's load on
	// an 18 g body into 1.7e3 m/s (hostile seed 876; docs/design.md, section 6). A point Bullet's solve
	// left keeps its impulse (markPointsFelt), so a group that stays flat is warm started as stock.
	for (int i = 0; i < m_manifolds.size(); ++i)
		for (int j = 0; j < m_manifolds[i]->getNumContacts(); ++j)
		{
			btManifoldPoint& cp = m_manifolds[i]->getContactPoint(j);
			if (btFeltShares::feltShare(cp) == cp.m_appliedImpulse) continue;
			cp.m_appliedImpulse = cp.m_appliedImpulseLateral1 = cp.m_appliedImpulseLateral2 = 0;
		}
}

void btShockPropagationConstraintSolver::markPointsFelt()
{
	// Every body felt every impulse of Bullet's solve (D5: the next warm start gives it to both).
	for (int i = 0; i < m_manifolds.size(); ++i)
		for (int j = 0; j < m_manifolds[i]->getNumContacts(); ++j)
		{
			btManifoldPoint& cp = m_manifolds[i]->getContactPoint(j);
			btFeltShares::setFeltShare(cp, cp.m_appliedImpulse);
		}
}
