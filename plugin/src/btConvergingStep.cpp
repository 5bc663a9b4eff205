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

// The converging velocity step: the plugin's velocity step for every group that holds a stack
// (docs/design.md, section 2). One stacked group's step is a list of stages called in order:
//
//   setupRows          Bullet's rows for the step's dt, as a stock step sets them up (no
//                      Baumgarte term, no split impulse: the position correction's job; two
//                      friction rows per point), every row from zero impulse, each contact row
//                      given its layer;
//                      (a contact row past the fixation limit starts from its point's last
//                      impulse, as a stock step starts it: predictVelocities);
//   predictVelocities  shock propagation (btShockPredictor): up-and-down cycles of a fixated up pass
//                      and a weight-feeling down pass (support blocks; a body its supports do not
//                      hold carries what is welded to it), every withheld impulse delivered, then
//                      a kinetic-energy line search;
//   correctVelocities  Bullet's own sweeps over every row, every body free, from the predictor's
//                      impulses, ceil(f N) at most, ended once no row changes by more than the
//                      convergence speed;
//   finishRows         Bullet's finish (applied impulses, joint feedback and breaking, velocities);
//   correctPositions   the layered position correction at CD(t) (btPositionCorrection).
//
// Every impulse of every stage acts on both bodies of its row once the predictor has delivered
// what it withheld, so momentum and angular momentum change only through static and kinematic
// bodies and external forces.

#include "BulletShockPropagation/btShockPropagationConstraintSolver.h"

#include "btBodyChecks.h"
#include "btBoxFaceCorners.h"
#include "btContactPatch.h"
#include "btShockPredictor.h"
#include "btFeltShares.h"

#include <cmath>

using namespace btShockPropagationChecks;

void btShockPropagationConstraintSolver::solveConverging(const btContactSolverInfo& info, btIDebugDraw* debugDrawer)
{
	btClock clock;
	const btContactSolverInfo stepInfo = setupRows(info, debugDrawer);
	m_stats.m_timeSetupMs += millisecondsSince(clock);
	clock.reset();
	predictVelocities(info);
	m_stats.m_timeLayersMs += millisecondsSince(clock);
	clock.reset();
	correctVelocities(info, stepInfo);
	m_stats.m_timeGlobalDynamicsMs += millisecondsSince(clock);
	clock.reset();
	finishRows(stepInfo);
	markPointsSolved();
	correctPositions(info, false, true);
	m_stats.m_timeCorrectionMs += millisecondsSince(clock);
}

btScalar btShockPropagationConstraintSolver::faceReach(btScalar timeStep) const
{
	return m_settings.m_diagnostics.m_boxFaceReachPerFall * largestGravity() * timeStep * timeStep;
}

int btShockPropagationConstraintSolver::completeContactPatches(btScalar timeStep)
{
	if (!m_settings.m_completeContactPatches) return 0;
	const btScalar reach = faceReach(timeStep);
	// Points deeper than the correction's slop are never traded (D33, spread).
	const btScalar slop = m_settings.m_correctionSlop >= btScalar(0) ? m_settings.m_correctionSlop
																	  : m_settings.m_correctionSlopPerFall * largestGravity() * timeStep * timeStep;
	int changed = 0;
	for (int i = 0; i < m_manifolds.size(); ++i) changed += btCompleteContactPatch(*m_manifolds[i], reach, slop);
	return changed;
}

btContactSolverInfo btShockPropagationConstraintSolver::setupRows(const btContactSolverInfo& info, btIDebugDraw* debugDrawer)
{
	// Bullet's setup, every row starting from zero impulse: the predictor builds the step's
	// impulses layer by layer from the bottom, and a warm start from last step's points is not the
	// last step's solution once Bullet has replaced some of them (docs/design.md, section 6).
	// The app's SOLVER_USE_WARMSTARTING is kept: with it Bullet's finish writes each point's
	// impulses (getAppliedImpulse), as in a stock step.
	btContactSolverInfo stepInfo = info;
	stepInfo.m_erp2 = btScalar(0);
	stepInfo.m_splitImpulse = false;
	stepInfo.m_warmstartingFactor = btScalar(0);
	if (m_settings.m_diagnostics.m_twoFrictionDirections) stepInfo.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
	if (m_settings.m_keepBoxFaceCorners)
	{
		const btScalar reach = faceReach(info.m_timeStep);
		for (int i = 0; i < m_manifolds.size(); ++i) m_stats.m_numBoxFaceCorners += btKeepBoxFaceCorners(*m_manifolds[i], reach);
	}
	m_stats.m_numPatchPoints += completeContactPatches(info.m_timeStep);
	btCollisionObject** bodies = m_bodies.size() ? &m_bodies[0] : 0;
	btPersistentManifold** manifolds = m_manifolds.size() ? &m_manifolds[0] : 0;
	btTypedConstraint** constraints = m_constraints.size() ? &m_constraints[0] : 0;
	solveGroupCacheFriendlySetup(bodies, m_bodies.size(), manifolds, m_manifolds.size(), constraints, m_constraints.size(), stepInfo, debugDrawer);
	assignRowsToLayers();
	return stepInfo;
}

void btShockPropagationConstraintSolver::predictVelocities(const btContactSolverInfo& info)
{
	const btShockPredictor::Pools pools{m_tmpSolverBodyPool, m_tmpSolverContactConstraintPool, m_tmpSolverContactFrictionConstraintPool,
										m_tmpSolverContactRollingFrictionConstraintPool};
	// Stack height and contact-graph component of each solver body; static and kinematic ones
	// (Bullet's fixed body) are at height 0 in no component (-1).
	m_heightOfSolverBody.resize(m_tmpSolverBodyPool.size());
	m_componentOfSolverBody.resize(m_tmpSolverBodyPool.size());
	for (int i = 0; i < m_heightOfSolverBody.size(); ++i)
	{
		m_heightOfSolverBody[i] = 0;
		m_componentOfSolverBody[i] = -1;
	}
	for (int i = 0; i < m_bodies.size(); ++i)
		if (m_solverBodyOfNode[i] >= 0 && m_solverBodyOfNode[i] < m_heightOfSolverBody.size())
		{
			m_heightOfSolverBody[m_solverBodyOfNode[i]] = m_layers.getHeight(i);
			m_componentOfSolverBody[m_solverBodyOfNode[i]] = m_layers.getComponent(i);
		}
	m_predictor->build(pools, m_layers.getNumLayers(), m_contactRowLayer, m_heightOfSolverBody, m_componentOfSolverBody,
					   m_layers.getNumComponents());
	// A row past the fixation limit is Bullet's own, both bodies free, and starts as a stock step
	// starts it: from its point's last impulse (docs/design.md, section 4.3).
	if (info.m_solverMode & SOLVER_USE_WARMSTARTING) m_predictor->warmStartPastLimit(pools, info.m_warmstartingFactor);
	const int sweeps = m_settings.m_diagnostics.m_predictorIterations;
	const btScalar converged = m_settings.m_diagnostics.m_predictorConvergence * largestGravity() * info.m_timeStep;
	m_stats.m_numLayerSweeps += m_predictor->predict(pools, sweeps, converged, m_settings.m_weightFeeling, m_settings.m_diagnostics.m_predictorCycles,
													 m_settings.m_diagnostics.m_predictorForcing);
}

void btShockPropagationConstraintSolver::correctVelocities(const btContactSolverInfo& info, const btContactSolverInfo& stepInfo)
{
	const btScalar f = m_settings.m_weighting;
	int sweeps = sweepCount(m_settings.m_globalIterations, info.m_numIterations);
	if (m_settings.m_globalIterations < 0) sweeps = f > btScalar(0) ? btMax(1, int(std::ceil(double(f) * info.m_numIterations - 1e-4))) : 0;
	// Joints that ask for more iterations (setOverrideNumSolverIterations) get them, as in a stock solve.
	sweeps = btMax(sweeps, m_maxOverrideNumSolverIterations);
	const btScalar converged = m_settings.m_diagnostics.m_weightConvergence * largestGravity() * info.m_timeStep;
	btCollisionObject** bodies = m_bodies.size() ? &m_bodies[0] : 0;
	btPersistentManifold** manifolds = m_manifolds.size() ? &m_manifolds[0] : 0;
	btTypedConstraint** constraints = m_constraints.size() ? &m_constraints[0] : 0;
	btContactSolverInfo sweepInfo = stepInfo;
	sweepInfo.m_numIterations = sweeps;
	for (int iteration = 0; iteration < sweeps; ++iteration)
	{
		++m_stats.m_numGlobalSweeps;
		m_leastSquaresResidual = solveSingleIteration(iteration, bodies, m_bodies.size(), manifolds, m_manifolds.size(), constraints,
													  m_constraints.size(), sweepInfo, 0);
		if (m_leastSquaresResidual <= info.m_leastSquaresResidualThreshold) break;
		// Bullet's residual is the sum of the rows' squared velocity changes.
		if (iteration + 1 >= m_maxOverrideNumSolverIterations && m_leastSquaresResidual <= converged * converged) break;
	}
}

void btShockPropagationConstraintSolver::finishRows(const btContactSolverInfo& stepInfo)
{
	solveGroupCacheFriendlyFinish(m_bodies.size() ? &m_bodies[0] : 0, m_bodies.size(), stepInfo);
}

void btShockPropagationConstraintSolver::markPointsSolved()
{
	// The points' impulses are this step's (getAppliedImpulse), but no warm start for Bullet's own
	// solve of a group without stacks: their felt share is set unequal to them (solveGroup).
	for (int i = 0; i < m_manifolds.size(); ++i)
		for (int j = 0; j < m_manifolds[i]->getNumContacts(); ++j)
		{
			btManifoldPoint& cp = m_manifolds[i]->getContactPoint(j);
			btFeltShares::setFeltShare(cp, cp.m_appliedImpulse == btScalar(0) ? btScalar(1) : btScalar(0));
		}
}
