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
// btShockPropagationConstraintSolver.h and docs/design.md (decisions D1-D15).

#include "BulletShockPropagation/btShockPropagationConstraintSolver.h"

#include "BulletCollision/NarrowPhaseCollision/btPersistentManifold.h"
#include "BulletDynamics/Dynamics/btRigidBody.h"
#include "LinearMath/btQuickprof.h"
#include "btBodyChecks.h"
#include "btBoxFaceCorners.h"
#include "btLayeredPasses.h"
#include "btShockPredictor.h"
#include "btWithheldReactions.h"
#include "btPositionCorrection.h"

#include <cmath>
#include <cstdio>
#include <new>
#include <stdexcept>

using namespace btShockPropagationChecks;

btShockPropagationConstraintSolver::btShockPropagationConstraintSolver()
	: m_passes(new (btAlignedAlloc(sizeof(btLayeredPasses), 16)) btLayeredPasses),
	  m_correction(new (btAlignedAlloc(sizeof(btPositionCorrection), 16)) btPositionCorrection),
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
	m_passes->~btLayeredPasses();
	btAlignedFree(m_passes);
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
	m_settings.m_layerIterations = btMax(int(BT_SHOCK_ITERATIONS_FROM_WORLD), settings.m_layerIterations);
	m_settings.m_layerIterationFloor = btMax(0, settings.m_layerIterationFloor);
	m_settings.m_layerMinIterations = btMax(int(BT_SHOCK_ITERATIONS_FROM_WORLD), settings.m_layerMinIterations);
	m_settings.m_correctionIterations = btMax(int(BT_SHOCK_ITERATIONS_FROM_WORLD), settings.m_correctionIterations);
	if (!(settings.m_diagnostics.m_correctionFraction >= 0 && settings.m_diagnostics.m_correctionFraction <= 1)) m_settings.m_diagnostics.m_correctionFraction = defaults.m_diagnostics.m_correctionFraction;
	if (!(settings.m_diagnostics.m_secondCorrectionFraction > 0 && settings.m_diagnostics.m_secondCorrectionFraction <= 1)) m_settings.m_diagnostics.m_secondCorrectionFraction = defaults.m_diagnostics.m_secondCorrectionFraction;
	if (settings.m_diagnostics.m_secondPhaseRounds < 1) m_settings.m_diagnostics.m_secondPhaseRounds = defaults.m_diagnostics.m_secondPhaseRounds;
	if (!isFiniteScalar(settings.m_correctionSlop)) m_settings.m_correctionSlop = defaults.m_correctionSlop;
	if (!(settings.m_correctionSlopPerFall >= 0) || !isFiniteScalar(settings.m_correctionSlopPerFall))
		m_settings.m_correctionSlopPerFall = defaults.m_correctionSlopPerFall;
	m_settings.m_weightIterations = btMax(int(BT_SHOCK_ITERATIONS_FROM_WORLD), settings.m_weightIterations);
	if (!(settings.m_diagnostics.m_weightConvergence >= 0) || !isFiniteScalar(settings.m_diagnostics.m_weightConvergence)) m_settings.m_diagnostics.m_weightConvergence = defaults.m_diagnostics.m_weightConvergence;
	if (!(settings.m_diagnostics.m_predictorConvergence >= 0) || !isFiniteScalar(settings.m_diagnostics.m_predictorConvergence))
		m_settings.m_diagnostics.m_predictorConvergence = defaults.m_diagnostics.m_predictorConvergence;
	m_settings.m_diagnostics.m_predictorIterations = btMax(0, settings.m_diagnostics.m_predictorIterations);
	m_settings.m_diagnostics.m_predictorCycles = btMax(1, settings.m_diagnostics.m_predictorCycles);
	if (!(settings.m_diagnostics.m_warmStartFactor <= 1) || !isFiniteScalar(settings.m_diagnostics.m_warmStartFactor)) m_settings.m_diagnostics.m_warmStartFactor = defaults.m_diagnostics.m_warmStartFactor;
	if (!isFiniteScalar(settings.m_diagnostics.m_supportAngle)) m_settings.m_diagnostics.m_supportAngle = defaults.m_diagnostics.m_supportAngle;
	if (!(settings.m_diagnostics.m_warmStartCoupling >= 0 && settings.m_diagnostics.m_warmStartCoupling <= 1)) m_settings.m_diagnostics.m_warmStartCoupling = defaults.m_diagnostics.m_warmStartCoupling;
	if (!(settings.m_diagnostics.m_warmStartWeights >= 0)) m_settings.m_diagnostics.m_warmStartWeights = defaults.m_diagnostics.m_warmStartWeights;
	if (!(settings.m_diagnostics.m_weightGuardSlack >= 0) || !isFiniteScalar(settings.m_diagnostics.m_weightGuardSlack)) m_settings.m_diagnostics.m_weightGuardSlack = defaults.m_diagnostics.m_weightGuardSlack;
	if (!(settings.m_diagnostics.m_weightGuardTipMargin >= 0) || !isFiniteScalar(settings.m_diagnostics.m_weightGuardTipMargin)) m_settings.m_diagnostics.m_weightGuardTipMargin = defaults.m_diagnostics.m_weightGuardTipMargin;
	if (!(settings.m_diagnostics.m_weightGuardTipping >= 0) || !isFiniteScalar(settings.m_diagnostics.m_weightGuardTipping)) m_settings.m_diagnostics.m_weightGuardTipping = defaults.m_diagnostics.m_weightGuardTipping;
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
	m_passes->endStep();
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
	m_stats.m_numLayeredGroups += 1;
	m_stats.m_numFixatedBodies += m_layers.getTotalFixated();
	if (m_settings.m_diagnostics.m_convergingStep)
		solveConverging(info, debugDrawer);
	else
		solveLayered(info, debugDrawer);
	return btScalar(0);
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

void btShockPropagationConstraintSolver::solveLayered(const btContactSolverInfo& info, btIDebugDraw* debugDrawer)
{
	btClock clock;
	const int worldIterations = info.m_numIterations;
	const btScalar f = m_settings.m_weighting;
	int globalSweeps = sweepCount(m_settings.m_globalIterations, worldIterations);
	// Default: ceil(f N), at least one sweep when f > 0 (the global pass's share of the sweeps).
	if (m_settings.m_globalIterations < 0 && f > btScalar(0))
		globalSweeps = btMax(1, int(std::ceil(double(f) * worldIterations - 1e-4)));
	else if (m_settings.m_globalIterations < 0)
		globalSweeps = 0;
	const int appLayerSweeps = sweepCount(m_settings.m_layerIterations, worldIterations);
	// D22: an app's small N does not cut a layer's sub-problem short (the joints' layer keeps N).
	const int layerSweeps = m_settings.m_layerIterations < 0 ? btMax(appLayerSweeps, m_settings.m_layerIterationFloor) : appLayerSweeps;
	// The weight pass's convergence speed (D16), also D18's scale of "at rest" (m/s).
	const btScalar gravity = largestGravity();  // m/s^2: the scale of the speeds below
	const btScalar convergedSpeed = m_settings.m_diagnostics.m_weightConvergence * gravity * info.m_timeStep;

	// One setup for the step, as a stock step: the app's time step and settings. Penetration is
	// the position correction's (D6): no Baumgarte term, no split impulse.
	btContactSolverInfo stepInfo = info;
	stepInfo.m_erp2 = btScalar(0);
	stepInfo.m_splitImpulse = false;
	if (m_settings.m_weightFeeling && m_settings.m_diagnostics.m_warmStartFactor >= btScalar(0)) stepInfo.m_warmstartingFactor = m_settings.m_diagnostics.m_warmStartFactor;  // D16
	if (m_settings.m_diagnostics.m_twoFrictionDirections) stepInfo.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
	btCollisionObject** bodies = m_bodies.size() ? &m_bodies[0] : 0;
	// D30: a box face resting on a box keeps its corners (Bullet's box-box test keeps only those
	// that penetrate), before the rows are set up from the points.
	if (m_settings.m_keepBoxFaceCorners)
	{
		const btScalar reach = m_settings.m_diagnostics.m_boxFaceReachPerFall * gravity * info.m_timeStep * info.m_timeStep;
		for (int i = 0; i < m_manifolds.size(); ++i) m_stats.m_numBoxFaceCorners += btKeepBoxFaceCorners(*m_manifolds[i], reach);
	}
	// D18: a resting pair keeps its load when Bullet replaces its points (within the weight pass's
	// convergence speed: the same scale of "at rest").
	if (m_settings.m_weightFeeling && m_manifolds.size())
		m_passes->restorePairLoads(&m_manifolds[0], m_manifolds.size(), convergedSpeed);
	limitWarmStart(info);
	btPersistentManifold** manifolds = m_manifolds.size() ? &m_manifolds[0] : 0;
	btTypedConstraint** constraints = m_constraints.size() ? &m_constraints[0] : 0;
	solveGroupCacheFriendlySetup(bodies, m_bodies.size(), manifolds, m_manifolds.size(), constraints, m_constraints.size(), stepInfo, debugDrawer);
	assignRowsToLayers();
	const btSolverPools pools{m_tmpSolverBodyPool,
							  m_tmpSolverContactConstraintPool,
							  m_tmpSolverContactFrictionConstraintPool,
							  m_tmpSolverContactRollingFrictionConstraintPool,
							  m_tmpSolverNonContactConstraintPool,
							  getActiveConstraintRowSolverGeneric(),
							  getActiveConstraintRowSolverLowerLimit()};
	m_passes->build(m_layers, m_contactRowLayer, m_solverBodyOfNode, pools);
	// D5: the warm start is the state last step ended in: a lower body feels only the share of a
	// contact's impulse it felt then.
	if (stepInfo.m_solverMode & SOLVER_USE_WARMSTARTING)
		m_passes->withholdUnfeltWarmStart(pools, stepInfo.m_warmstartingFactor, m_settings.m_diagnostics.m_warmStartCoupling);
	// D23: the friction rows that slip as the step begins (last step's velocities, this step's forces).
	const bool composites = m_settings.m_weightFeeling && m_settings.m_diagnostics.m_slidingComposites;
	const btScalar compositeSlip = m_settings.m_diagnostics.m_compositeSlip * gravity * info.m_timeStep;
	if (composites) m_passes->markSlipsAtSetup(pools, compositeSlip);
	m_stats.m_timeSetupMs += millisecondsSince(clock);

	// Global pass: Bullet's own sweeps over every row, every body free; it ends early once
	// converged (D21) or below the app's residual threshold.
	clock.reset();
	btContactSolverInfo sweepInfo = stepInfo;
	sweepInfo.m_numIterations = globalSweeps;
	for (int iteration = 0; iteration < globalSweeps; ++iteration)
	{
		++m_stats.m_numGlobalSweeps;
		m_leastSquaresResidual = solveSingleIteration(iteration, bodies, m_bodies.size(), manifolds, m_manifolds.size(), constraints,
													  m_constraints.size(), sweepInfo, debugDrawer);
		if (m_leastSquaresResidual <= info.m_leastSquaresResidualThreshold) break;
		// D21: converged (Bullet's residual: the sum of the rows' squared velocity changes).
		if (m_settings.m_diagnostics.m_convergedGlobalPass && m_leastSquaresResidual <= convergedSpeed * convergedSpeed) break;
	}
	m_stats.m_timeGlobalDynamicsMs += millisecondsSince(clock);

	// Layer passes, bottom-up.
	clock.reset();
	btLayerFixationParams params;
	params.m_mode = m_settings.m_fixationMode;
	params.m_sor = info.m_sor;
	params.m_jointDamping = info.m_damping;
	params.m_inelasticFixation = m_settings.m_diagnostics.m_inelasticFixation;
	params.m_restSpeed = m_settings.m_diagnostics.m_fixationRestSpeed ? convergedSpeed : btScalar(0);
	const bool weightFeeling = m_settings.m_weightFeeling;
	// Joints with more iterations than the app's (btTypedConstraint::setOverrideNumSolverIterations)
	// get them, as in a stock solve: their rows are in layer 0.
	m_passes->setJointSweeps(btMax(appLayerSweeps, m_maxOverrideNumSolverIterations));
	btLayerSweeps sweeps;
	sweeps.m_max = layerSweeps;
	sweeps.m_jointLayerMax = appLayerSweeps;
	sweeps.m_block = m_settings.m_diagnostics.m_supportBlocks;
	m_passes->setSharedBlockFactor(weightFeeling && m_settings.m_diagnostics.m_loadTransfer && m_settings.m_diagnostics.m_sharedBlockFactor);
	sweeps.m_min = m_settings.m_layerMinIterations;
	sweeps.m_convergedSpeed = convergedSpeed;
	sweeps.m_compositeSlip = composites ? compositeSlip : btScalar(0);
	sweeps.m_markSliding = weightFeeling && m_settings.m_diagnostics.m_tippingComposites && m_settings.m_diagnostics.m_rigidSlidingComposites;
	for (int k = 0; k < m_passes->getNumLayers(); ++k) m_stats.m_numLayerSweeps += m_passes->solveLayer(k, sweeps, params, weightFeeling, pools);
	m_stats.m_timeLayersMs += millisecondsSince(clock);
	if (weightFeeling)
	{
		clock.reset();
		// The guard's scales (D16), per body and per step: shares of the speed gravity gives in one step.
		btWeightPassParams weight;
		weight.m_transfer = m_settings.m_diagnostics.m_loadTransfer;
		weight.m_timeStep = info.m_timeStep;
		weight.m_slack = m_settings.m_diagnostics.m_weightGuardSlack;
		weight.m_tipGain = m_settings.m_diagnostics.m_weightGuardTipping;
		weight.m_tipMargin = m_settings.m_diagnostics.m_weightGuardTipMargin;
		weight.m_convergedSpeed = convergedSpeed;
		weight.m_transferSmallLoads = m_settings.m_diagnostics.m_transferSmallLoads;
		weight.m_finalBlocks = m_settings.m_diagnostics.m_weightPassBlocks && m_settings.m_diagnostics.m_supportBlocks;
		weight.m_compositeTolerance = composites ? compositeSlip : btScalar(0);
		weight.m_tippingComposites = m_settings.m_diagnostics.m_tippingComposites;
		weight.m_rejectPerIsland = m_settings.m_diagnostics.m_rejectPerIsland;
		weight.m_impactTipping = m_settings.m_diagnostics.m_impactTipping;
		weight.m_guardSpin = m_settings.m_diagnostics.m_guardSpin;
		weight.m_rigidSliding = sweeps.m_markSliding;
		// Default: at most 3 N sweeps per layer, ended as soon as the layer converges (D16).
		const int weightSweeps = m_settings.m_weightIterations >= 0 ? m_settings.m_weightIterations : 3 * btMax(1, worldIterations);
		m_stats.m_numWeightSweeps += m_passes->solveWeightPass(weightSweeps, params, pools,
															   weight, &m_stats.m_numWeightRejections);
		m_stats.m_numSlidingComposites += m_passes->finishComposites(pools);
		m_stats.m_numSharedFactorTransfers += m_passes->takeSharedFactorTransfers();
		m_stats.m_numTippingComposites += m_passes->takeTippingComposites();
		m_stats.m_numRigidSlidingComposites += m_passes->takeRigidSlidingComposites();
		m_stats.m_timeWeightFeelingMs += millisecondsSince(clock);
	}

	// Finish once: contact impulses (warm start and what apps read), joint feedback and
	// breaking, velocities. Each point keeps the share its lower body felt, for the next warm start.
	clock.reset();
	m_passes->storeFeltShares(pools, weightFeeling);
	solveGroupCacheFriendlyFinish(bodies, m_bodies.size(), stepInfo);
	if (m_settings.m_weightFeeling && m_manifolds.size()) m_passes->recordPairLoads(&m_manifolds[0], m_manifolds.size());
	correctPositions(info, false, true);
	m_stats.m_timeCorrectionMs += millisecondsSince(clock);
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
	// A group without stacks, as a stock step solves it: its warm start made Bullet's (the
	// default step caps it, D5, since a group layered last step may have left impulses sized for
	// a heavy upper body on a light one; the converging step's points start from zero), Bullet's
	// solveGroup, and each point's impulse recorded as felt by both bodies.
	if (m_settings.m_diagnostics.m_convergingStep)
		startFromOwnImpulses();
	else
		limitWarmStart(info);
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
	// an 18 g body into 1.7e3 m/s (hostile seed 876; docs/design.md 4u). A point Bullet's solve
	// left keeps its impulse (markPointsFelt), so a group that stays flat is warm started as stock.
	for (int i = 0; i < m_manifolds.size(); ++i)
		for (int j = 0; j < m_manifolds[i]->getNumContacts(); ++j)
		{
			btManifoldPoint& cp = m_manifolds[i]->getContactPoint(j);
			if (btWithheldReactions::feltShare(cp) == cp.m_appliedImpulse) continue;
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
			btWithheldReactions::setFeltShare(cp, cp.m_appliedImpulse);
		}
}

void btShockPropagationConstraintSolver::limitWarmStart(const btContactSolverInfo& info)
{
	// D5: Bullet warm-starts each contact from last step's impulse, applied to both bodies at
	// setup. Under fixation a contact's impulse is sized for its upper body alone: a heavy body
	// resting on a light one leaves the heavy body's weight in the cache, and when their roles
	// change (hostile worlds: 1e-3 to 1e6 kg) that impulse hits the light body at once and the
	// sweeps cannot take it back (measured: 56 of 100 hostile seeds over the energy bound, 0
	// without warm starting). So a warm start is at most m_warmStartWeights times the lighter
	// body's weight impulse m g dt; equal masses keep theirs up to that many bodies' weight.
	const btScalar dt = info.m_timeStep;
	for (int i = 0; i < m_manifolds.size(); ++i)
	{
		btPersistentManifold* m = m_manifolds[i];
		btScalar lighter = SIMD_INFINITY;
		const btCollisionObject* ends[2] = {m->getBody0(), m->getBody1()};
		for (const btCollisionObject* end : ends)
		{
			const btRigidBody* rb = btRigidBody::upcast(end);
			// Weight impulse of each dynamic end; a body without gravity has no weight to scale by.
			const btScalar g = rb ? rb->getGravity().length() : btScalar(0);
			if (rb && rb->getInvMass() > btScalar(0) && g > btScalar(0)) lighter = btMin(lighter, g / rb->getInvMass());
		}
		if (!(lighter < SIMD_INFINITY)) continue;
		const btScalar cap = m_settings.m_diagnostics.m_warmStartWeights * lighter * dt;
		if (!(cap > btScalar(0))) continue;
		for (int j = 0; j < m->getNumContacts(); ++j)
		{
			btManifoldPoint& cp = m->getContactPoint(j);
			if (cp.m_appliedImpulse > cap) cp.m_appliedImpulse = cap;
		}
	}
}
