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

#include "BulletCollision/BroadphaseCollision/btOverlappingPairCache.h"
#include "BulletCollision/CollisionDispatch/btCollisionDispatcher.h"
#include "BulletCollision/CollisionDispatch/btManifoldResult.h"
#include "BulletCollision/CollisionShapes/btCollisionShape.h"
#include "BulletCollision/CollisionShapes/btCompoundShape.h"
#include "BulletCollision/CollisionShapes/btConvexHullShape.h"
#include "BulletCollision/NarrowPhaseCollision/btPersistentManifold.h"
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

/// A btConvexHullShape without points in `shape` (itself or, recursively, a compound's child).
bool hasEmptyHull(const btCollisionShape* shape)
{
	if (!shape) return false;
	if (shape->getShapeType() == CONVEX_HULL_SHAPE_PROXYTYPE) return static_cast<const btConvexHullShape*>(shape)->getNumPoints() == 0;
	if (shape->getShapeType() == COMPOUND_SHAPE_PROXYTYPE)
	{
		const btCompoundShape* compound = static_cast<const btCompoundShape*>(shape);
		for (int i = 0; i < compound->getNumChildShapes(); ++i)
			if (hasEmptyHull(compound->getChildShape(i))) return true;
	}
	return false;
}

btConstraintSolver* solverOrNew(btConstraintSolver* solver)
{
	return solver ? static_cast<btConstraintSolver*>(requireShockSolver(solver)) : new btShockPropagationConstraintSolver();
}

/// Bullet's global contact callbacks, cleared while it lives and restored after: the second
/// detection fires none of them (the world's header says why).
class btSilencedContactCallbacks
{
public:
	btSilencedContactCallbacks()
		: m_added(gContactAddedCallback),
		  m_processed(gContactProcessedCallback),
		  m_destroyed(gContactDestroyedCallback),
		  m_started(gContactStartedCallback),
		  m_ended(gContactEndedCallback)
	{
		gContactAddedCallback = 0;
		gContactProcessedCallback = 0;
		gContactDestroyedCallback = 0;
		gContactStartedCallback = 0;
		gContactEndedCallback = 0;
	}
	~btSilencedContactCallbacks()
	{
		gContactAddedCallback = m_added;
		gContactProcessedCallback = m_processed;
		gContactDestroyedCallback = m_destroyed;
		gContactStartedCallback = m_started;
		gContactEndedCallback = m_ended;
	}
	ContactDestroyedCallback destroyed() const { return m_destroyed; }
	ContactEndedCallback ended() const { return m_ended; }

private:
	ContactAddedCallback m_added;
	ContactProcessedCallback m_processed;
	ContactDestroyedCallback m_destroyed;
	ContactStartedCallback m_started;
	ContactEndedCallback m_ended;
};

/// Orders saved manifold indices by the manifolds' addresses.
struct btSavedManifoldOrder
{
	const btAlignedObjectArray<btPersistentManifold*>& m_manifolds;
	explicit btSavedManifoldOrder(const btAlignedObjectArray<btPersistentManifold*>& manifolds) : m_manifolds(manifolds) {}
	bool operator()(int a, int b) const { return m_manifolds[a] < m_manifolds[b]; }
};

/// The narrowphase of the second detection: each overlapping pair with a body in a marked
/// island (or every pair) goes through the dispatcher's near callback, as
/// btCollisionDispatcher::dispatchAllCollisionPairs sends it (the app's near callback included).
struct btSecondDetectionCallback : public btOverlapCallback
{
	btCollisionDispatcher* m_dispatcher;
	const btDispatcherInfo* m_info;
	const btAlignedObjectArray<char>* m_stackedIsland;
	bool m_allPairs;

	bool inStackedIsland(const btBroadphaseProxy* proxy) const
	{
		const btCollisionObject* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
		const int tag = object ? object->getIslandTag() : -1;
		return tag >= 0 && tag < m_stackedIsland->size() && (*m_stackedIsland)[tag];
	}

	virtual bool processOverlap(btBroadphasePair& pair)
	{
		if (m_allPairs || inStackedIsland(pair.m_pProxy0) || inStackedIsland(pair.m_pProxy1))
			m_dispatcher->getNearCallback()(pair, *m_dispatcher, *m_info);
		return false;  // keep the pair
	}
};
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

void btShockPropagationDynamicsWorld::addCollisionObject(btCollisionObject* collisionObject, int collisionFilterGroup, int collisionFilterMask)
{
	if (collisionObject && hasEmptyHull(collisionObject->getCollisionShape()))
	{
		// addRigidBody listed the body before calling this: the world must not keep it.
		if (btRigidBody* body = btRigidBody::upcast(collisionObject)) m_nonStaticRigidBodies.remove(body);
		throw std::invalid_argument(
			"btShockPropagationDynamicsWorld: a btConvexHullShape without points cannot collide (Bullet's support function "
			"reads its point 0: stock Bullet crashes on it too); give the hull at least one point");
	}
	btDiscreteDynamicsWorld::addCollisionObject(collisionObject, collisionFilterGroup, collisionFilterMask);
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

bool btShockPropagationDynamicsWorld::markStackedIslands()
{
	// Island tags are union-find roots, indices into the world's collision objects.
	const int numTags = m_collisionObjects.size();
	m_stackedIsland.resize(numTags);
	for (int i = 0; i < numTags; ++i) m_stackedIsland[i] = 0;
	bool any = false;
	for (int i = 0; i < m_shockSolver->getNumLayeredBodies(); ++i)
	{
		if (m_shockSolver->getLayeredBodyHeight(i) < 2) continue;  // on the ground, or unreached
		const int tag = m_shockSolver->getLayeredBody(i)->getIslandTag();
		if (tag < 0 || tag >= numTags) continue;
		m_stackedIsland[tag] = 1;
		any = true;
	}
	return any;
}

void btShockPropagationDynamicsWorld::detectCollisionsAfterStep(bool allPairs)
{
	BT_PROFILE("secondDetection");
	// Broadphase bounds at t + dt, as btCollisionWorld::updateSingleAabb computes them, merged
	// with the bounds of step 1 so that no pair the next stock detection keeps is removed here
	// (its bounds then enclose the predicted motion; ours could not).
	const btVector3 threshold(gContactBreakingThreshold, gContactBreakingThreshold, gContactBreakingThreshold);
	for (int i = 0; i < m_collisionObjects.size(); ++i)
	{
		btCollisionObject* object = m_collisionObjects[i];
		btBroadphaseProxy* proxy = object->getBroadphaseHandle();
		if (!proxy || !(m_forceUpdateAllAabbs || object->isActive())) continue;
		btVector3 minAabb, maxAabb;
		object->getCollisionShape()->getAabb(object->getWorldTransform(), minAabb, maxAabb);
		minAabb -= threshold;
		maxAabb += threshold;
		minAabb.setMin(proxy->m_aabbMin);
		maxAabb.setMax(proxy->m_aabbMax);
		// Bounds Bullet would refuse (it disables the body and warns in the next step).
		if (!((maxAabb - minAabb).length2() < btScalar(1e12))) continue;
		m_broadphasePairCache->setAabb(proxy, minAabb, maxAabb, m_dispatcher1);
	}
	computeOverlappingPairs();

	btCollisionDispatcher* dispatcher = dynamic_cast<btCollisionDispatcher*>(m_dispatcher1);
	btDispatcherInfo& info = getDispatchInfo();
	if (!dispatcher)
	{
		// Another btDispatcher: its own dispatch of every pair.
		m_dispatcher1->dispatchAllCollisionPairs(m_broadphasePairCache->getOverlappingPairCache(), info, m_dispatcher1);
		return;
	}
	btSecondDetectionCallback callback;
	callback.m_dispatcher = dispatcher;
	callback.m_info = &info;
	callback.m_stackedIsland = &m_stackedIsland;
	callback.m_allPairs = allPairs;
	m_broadphasePairCache->getOverlappingPairCache()->processAllOverlappingPairs(&callback, m_dispatcher1, info);
}

void btShockPropagationDynamicsWorld::saveManifolds()
{
	const int numManifolds = m_dispatcher1->getNumManifolds();
	m_savedManifolds.resize(numManifolds);
	m_savedBodies.resize(2 * numManifolds);
	m_savedFirstPoint.resize(numManifolds + 1);
	int numPoints = 0;
	for (int i = 0; i < numManifolds; ++i) numPoints += m_dispatcher1->getManifoldByIndexInternal(i)->getNumContacts();
	m_savedPoints.resize(numPoints);
	numPoints = 0;
	for (int i = 0; i < numManifolds; ++i)
	{
		btPersistentManifold* m = m_dispatcher1->getManifoldByIndexInternal(i);
		m_savedManifolds[i] = m;
		m_savedBodies[2 * i] = m->getBody0();
		m_savedBodies[2 * i + 1] = m->getBody1();
		m_savedFirstPoint[i] = numPoints;
		for (int j = 0; j < m->getNumContacts(); ++j) m_savedPoints[numPoints++] = m->getContactPoint(j);
	}
	m_savedFirstPoint[numManifolds] = numPoints;
}

void btShockPropagationDynamicsWorld::restoreManifolds(ContactDestroyedCallback destroyed, ContactEndedCallback ended)
{
	const int numSaved = m_savedManifolds.size();
	m_savedFound.resize(numSaved);
	for (int i = 0; i < numSaved; ++i) m_savedFound[i] = 0;
	// The dispatcher keeps its manifolds in order and appends new ones; only a release moves the
	// last one into the freed slot. So manifold i is saved manifold i unless something was
	// released; then the saved ones are found by pointer in a sorted copy (no allocation once
	// the arrays have grown).
	const int numNow = m_dispatcher1->getNumManifolds();
	bool inOrder = numNow >= numSaved;
	for (int i = 0; inOrder && i < numSaved; ++i) inOrder = m_dispatcher1->getManifoldByIndexInternal(i) == m_savedManifolds[i];
	if (!inOrder)
	{
		m_savedByPointer.resize(numSaved);
		for (int i = 0; i < numSaved; ++i) m_savedByPointer[i] = i;
		m_savedByPointer.quickSort(btSavedManifoldOrder(m_savedManifolds));
	}
	for (int i = 0; i < numNow; ++i)
	{
		btPersistentManifold* m = m_dispatcher1->getManifoldByIndexInternal(i);
		int saved = -1;
		if (inOrder)
			saved = i < numSaved ? i : -1;
		else
		{
			int low = 0, high = numSaved;  // first entry whose pointer is not below m
			while (low < high)
			{
				const int middle = (low + high) / 2;
				if (m_savedManifolds[m_savedByPointer[middle]] < m)
					low = middle + 1;
				else
					high = middle;
			}
			if (low < numSaved && m_savedManifolds[m_savedByPointer[low]] == m) saved = m_savedByPointer[low];
		}
		if (saved >= 0 && m_savedBodies[2 * saved] == m->getBody0() && m_savedBodies[2 * saved + 1] == m->getBody1())
		{
			// The points it held after the solve (a refreshed or replaced point keeps its slot's
			// impulse and user data in Bullet, so nothing of the second detection is kept).
			const int first = m_savedFirstPoint[saved], count = m_savedFirstPoint[saved + 1] - first;
			m->setNumContacts(count);
			for (int j = 0; j < count; ++j) m->getContactPoint(j) = m_savedPoints[first + j];
			m_savedFound[saved] = 1;
		}
		else
		{
			// Created by the second detection: its points were found with the callbacks cleared
			// (no user data); the next step's detection finds them again, as stock's does.
			m->setNumContacts(0);
		}
	}
	// Released by the second detection: what stock's next detection would have fired.
	for (int i = 0; i < numSaved; ++i)
	{
		if (m_savedFound[i]) continue;
		const int first = m_savedFirstPoint[i], count = m_savedFirstPoint[i + 1] - first;
		if (count == 0) continue;
		if (destroyed)
			for (int j = 0; j < count; ++j)
				if (m_savedPoints[first + j].m_userPersistentData) (*destroyed)(m_savedPoints[first + j].m_userPersistentData);
		if (ended)
		{
			btPersistentManifold copy(m_savedBodies[2 * i], m_savedBodies[2 * i + 1], 0, gContactBreakingThreshold, gContactBreakingThreshold);
			btPersistentManifold* pointer = &copy;
			copy.setNumContacts(count);
			for (int j = 0; j < count; ++j)
			{
				copy.getContactPoint(j) = m_savedPoints[first + j];
				copy.getContactPoint(j).m_userPersistentData = 0;
			}
			ended(pointer);
			copy.setNumContacts(0);
		}
	}
}

void btShockPropagationDynamicsWorld::correctionPhase(btScalar timeStep)
{
	// The paper's second phase (D4): collision detection at t + dt, then the layered position
	// correction of the stacked components at the depths it found; the manifolds are then put
	// back as the step's solve left them (the world's header: what an app sees).
	BT_PROFILE("correctionPhase");
	const btShockPropagationSettings& settings = m_shockSolver->getSettings();
	btContactSolverInfo info = getSolverInfo();
	info.m_timeStep = timeStep;
	btCollisionObjectArray& objects = getCollisionObjectArray();
	const bool detect = settings.m_diagnostics.m_secondDetection;
	const bool allPairs = settings.m_diagnostics.m_secondDetectionAllPairs;
	if (detect)
	{
		// A step whose solve saw no stack has nothing for the layered correction.
		if (!markStackedIslands() && !allPairs) return;
		saveManifolds();
		ContactDestroyedCallback destroyed;
		ContactEndedCallback ended;
		{
			btSilencedContactCallbacks silenced;
			destroyed = silenced.destroyed();
			ended = silenced.ended();
			// Rounds: each but the last removes a fraction of the depths (it cannot see the
			// contacts it pushes bodies into); the last round's detection sees them, and it
			// removes all that is left. A round that found nothing beyond the slop moved nothing,
			// so another detection would find the same: the phase ends (a resting stack pays one).
			const int rounds = btMax(1, settings.m_diagnostics.m_secondPhaseRounds);
			for (int round = 0; round < rounds; ++round)
			{
				detectCollisionsAfterStep(allPairs);
				const btScalar fraction = round + 1 < rounds ? settings.m_diagnostics.m_secondCorrectionFraction : btScalar(1);
				const bool moved = m_shockSolver->correctAfterStep(objects.size() ? &objects[0] : 0, objects.size(),
																   m_dispatcher1->getNumManifolds() ? m_dispatcher1->getInternalManifoldPointer() : 0,
																   m_dispatcher1->getNumManifolds(), m_constraints.size() ? &m_constraints[0] : 0,
																   m_constraints.size(), info, fraction);
				if (!moved) break;
			}
		}
		// Putting points back fires nothing; a released manifold's callbacks fire here, restored.
		restoreManifolds(destroyed, ended);
		return;
	}
	// Ablation (before issue 38): the step's own points, depths from the new transforms.
	m_shockSolver->correctAfterStep(objects.size() ? &objects[0] : 0, objects.size(),
									m_dispatcher1->getNumManifolds() ? m_dispatcher1->getInternalManifoldPointer() : 0,
									m_dispatcher1->getNumManifolds(), m_constraints.size() ? &m_constraints[0] : 0, m_constraints.size(), info,
									settings.m_diagnostics.m_correctionFraction);
}
