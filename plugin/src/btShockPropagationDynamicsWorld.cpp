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

#include "BulletShockPropagation/btShockPropagationDynamicsWorld.h"

#include "BulletShockPropagation/btShockPropagationConstraintSolver.h"
#include "LinearMath/btQuickprof.h"

#include <stdexcept>

namespace
{
btShockPropagationConstraintSolver* requireShockSolver(btConstraintSolver* solver)
{
	btShockPropagationConstraintSolver* shock = dynamic_cast<btShockPropagationConstraintSolver*>(solver);
	if (!shock)
	{
		throw std::invalid_argument(
			"btShockPropagationDynamicsWorld needs a btShockPropagationConstraintSolver (or nullptr to create one); "
			"to use another solver, use btDiscreteDynamicsWorld");
	}
	return shock;
}

btConstraintSolver* solverOrNew(btConstraintSolver* solver)
{
	return solver ? static_cast<btConstraintSolver*>(requireShockSolver(solver)) : new btShockPropagationConstraintSolver();
}
}  // namespace

btShockPropagationDynamicsWorld::btShockPropagationDynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* pairCache,
																 btConstraintSolver* solver, btCollisionConfiguration* collisionConfiguration)
	: btDiscreteDynamicsWorld(dispatcher, pairCache, solverOrNew(solver), collisionConfiguration)
{
	m_shockSolver = static_cast<btShockPropagationConstraintSolver*>(m_constraintSolver);
	// A solver we created is ours to delete (btDiscreteDynamicsWorld frees it with btAlignedFree,
	// which matches the aligned operator new of Bullet classes).
	m_ownsConstraintSolver = (solver == 0);
}

btShockPropagationDynamicsWorld::~btShockPropagationDynamicsWorld()
{
}

void btShockPropagationDynamicsWorld::setConstraintSolver(btConstraintSolver* solver)
{
	btShockPropagationConstraintSolver* shock = requireShockSolver(solver);
	if (solver == m_constraintSolver)
	{
		return;  // Bullet would free a solver the world owns and keep using it
	}
	// Bullet releases an owned solver's memory without running its destructor, which leaks the
	// solver's buffers (LeakSanitizer, tests/robustness/LifecycleTest.cpp): destroy it here.
	btConstraintSolver* owned = m_ownsConstraintSolver ? m_constraintSolver : 0;
	m_ownsConstraintSolver = false;
	btDiscreteDynamicsWorld::setConstraintSolver(solver);
	m_shockSolver = shock;
	if (owned)
	{
		owned->~btConstraintSolver();
		btAlignedFree(owned);
	}
}

void btShockPropagationDynamicsWorld::internalSingleStepSimulation(btScalar timeStep)
{
	// btDiscreteDynamicsWorld's step, with the second correction after the positions advance.
	BT_PROFILE("btShockPropagationDynamicsWorld::internalSingleStepSimulation");
	btDiscreteDynamicsWorld::internalSingleStepSimulation(timeStep);
}

void btShockPropagationDynamicsWorld::integrateTransforms(btScalar timeStep)
{
	btDiscreteDynamicsWorld::integrateTransforms(timeStep);
	if (m_shockSolver->getSettings().m_secondCorrection)
	{
		correctionPhase(timeStep);
	}
}

void btShockPropagationDynamicsWorld::correctionPhase(btScalar timeStep)
{
	// The paper's second correction at t + dt (D4): depths from the new transforms and the
	// contact points' anchors, no second narrowphase (so no callbacks fire twice and islands stay
	// as Bullet computed them).
	BT_PROFILE("correctionPhase");
	btContactSolverInfo info = getSolverInfo();
	info.m_timeStep = timeStep;
	btCollisionObjectArray& objects = getCollisionObjectArray();
	m_shockSolver->correctAfterStep(objects.size() ? &objects[0] : 0, objects.size(),
									m_dispatcher1->getNumManifolds() ? m_dispatcher1->getInternalManifoldPointer() : 0,
									m_dispatcher1->getNumManifolds(), info);
}
