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

#ifndef BT_SHOCK_PROPAGATION_DYNAMICS_WORLD_H
#define BT_SHOCK_PROPAGATION_DYNAMICS_WORLD_H

#include "BulletCollision/NarrowPhaseCollision/btPersistentManifold.h"
#include "BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h"
#include "LinearMath/btThreads.h"  // BT_OVERRIDE
#include "btShockPropagationExport.h"

class btShockPropagationConstraintSolver;

/// A btDiscreteDynamicsWorld that runs Erleben's full time step (ACM TOG 2007, "final algorithm").
/// One internal step, in the order it runs:
///
///   what runs                                                     Bullet call
///   1. collision detection at t, islands                          performDiscreteCollisionDetection,
///                                                                 calculateSimulationIslands
///   2. velocities: the converging step (predictor, corrector),    solveConstraints (the solver's
///      position correction at the contacts of 1                   solveGroup)
///   3. positions advance with the final velocities                integrateTransforms
///   4. collision detection at t + dt: broadphase (new pairs       inside integrateTransforms, after
///      included) and narrowphase of every overlapping pair with   Bullet's: setAabb,
///      a body in a stacked island of 2 (an island holding a body  calculateOverlappingPairs, the
///      at stack height 2 or more); skipped if 2 had no stack      dispatcher's near callback
///   5. correction at t + dt: the penetration beyond the slop of   btPositionCorrection, layered
///      the contacts of 4, layer by layer bottom-up, lower bodies
///      fixated; positions only, velocities untouched
///   4-5 again (m_secondPhaseRounds, 2): the first round removes 0.8 of each depth, the second
///      detects what the first pushed bodies into and removes all that is left
///   6. the manifolds are put back as 1 and 2 left them            (see below)
///   then Bullet's own: actions, sleeping, internal tick callback.
///
/// 4-6 are the second phase (btShockPropagationSettings::m_secondCorrection, on by default; D4).
/// A constraint solver runs before the positions advance, so the solver-only mode
/// (btDiscreteDynamicsWorld + btShockPropagationConstraintSolver) cannot do 4-5: a contact that
/// appears during a step stays in the bodies until the next step's solve pushes it out.
///
/// What an app sees of the second detection:
/// - contact callbacks: none. gContactAddedCallback, gContactProcessedCallback,
///   gContactStartedCallback, gContactEndedCallback and gContactDestroyedCallback are cleared
///   while it runs and restored after, so each fires as often as in a stock step (the next
///   step's detection reports the points it found, as stock's does);
/// - manifolds after stepSimulation: every manifold that existed after the solve holds exactly
///   the points it held then (positions, distances, getAppliedImpulse(), lifetimes, user data),
///   as after a stock step, so warm starting and impulse read-back are stock's; a manifold the
///   second detection created (a pair new at t + dt) is left empty, as a broadphase pair without
///   contact is after a stock step; a manifold it released (a compound's child that separated)
///   is gone, its points' gContactDestroyedCallback and the manifold's gContactEndedCallback
///   (given a copy of it) fired at the end of the step, where stock would fire them in the next
///   step's detection;
/// - the app's near callback (btCollisionDispatcher::setNearCallback) and overlap filter
///   (btOverlapFilterCallback) are called again for the pairs of 4, once per round (a dispatcher
///   that is not a btCollisionDispatcher dispatches every pair its own way), and a ghost object's
///   pair list (btGhostPairCallback) can gain a pair at t + dt, one step earlier than in stock;
///   the broadphase bounds of moving bodies enclose both t and t + dt until the next step's
///   updateAabbs (so no pair a stock step keeps is removed);
/// - bodies in stacked islands end the step up to their penetration beyond the slop away from
///   where stock's integration put them; their velocities are those the solver left.
ATTRIBUTE_ALIGNED16(class)
BT_SHOCK_PROPAGATION_API btShockPropagationDynamicsWorld : public btDiscreteDynamicsWorld
{
public:
	BT_DECLARE_ALIGNED_ALLOCATOR();

	/// solver: nullptr makes the world create and own a btShockPropagationConstraintSolver; any
	/// other solver must be a btShockPropagationConstraintSolver (the caller keeps ownership):
	/// another type throws std::invalid_argument.
	btShockPropagationDynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* pairCache, btConstraintSolver* solver,
									btCollisionConfiguration* collisionConfiguration);
	virtual ~btShockPropagationDynamicsWorld();

	/// Throws std::invalid_argument unless solver is a btShockPropagationConstraintSolver. A solver
	/// the world created (constructed with nullptr) is destroyed; the new one stays the caller's.
	virtual void setConstraintSolver(btConstraintSolver* solver) BT_OVERRIDE;

	/// Bullet's, after a check of the object's shape: a btConvexHullShape without points (alone or
	/// a compound's child) throws std::invalid_argument. Bullet's support function reads such a
	/// hull's point 0, so the first collision test that reaches it crashes, in stock Bullet too; a
	/// world that owns the step can say so when the body is added (in solver-only mode the crash
	/// happens in the app's world, before the solver runs).
	virtual void addCollisionObject(btCollisionObject * collisionObject, int collisionFilterGroup = btBroadphaseProxy::StaticFilter,
									int collisionFilterMask = btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter) BT_OVERRIDE;

	btShockPropagationConstraintSolver* getShockPropagationSolver() { return m_shockSolver; }
	const btShockPropagationConstraintSolver* getShockPropagationSolver() const { return m_shockSolver; }

protected:
	virtual void internalSingleStepSimulation(btScalar timeStep) BT_OVERRIDE;
	/// Bullet's integration, then the second phase (m_secondCorrection): 4-6 above.
	virtual void integrateTransforms(btScalar timeStep) BT_OVERRIDE;

	/// The second phase at t + dt: detection (or, m_diagnostics.m_secondDetection off, the step's
	/// own points at refreshed depths), correction, manifolds put back.
	void correctionPhase(btScalar timeStep);

private:
	/// Marks the islands of step 2 that hold a stacked body; false if none does.
	bool markStackedIslands();
	/// Step 4: broadphase bounds enclosing t and t + dt, new pairs, narrowphase of the pairs.
	void detectCollisionsAfterStep(bool allPairs);
	void saveManifolds();
	void restoreManifolds(ContactDestroyedCallback destroyed, ContactEndedCallback ended);

	btShockPropagationConstraintSolver* m_shockSolver;

	// Second phase working sets (memory kept across steps).
	btAlignedObjectArray<char> m_stackedIsland;               // by island tag
	btAlignedObjectArray<btPersistentManifold*> m_savedManifolds;
	btAlignedObjectArray<const btCollisionObject*> m_savedBodies;  // two per saved manifold
	btAlignedObjectArray<int> m_savedFirstPoint;             // one more than saved manifolds
	btAlignedObjectArray<btManifoldPoint> m_savedPoints;
	btAlignedObjectArray<char> m_savedFound;
	btAlignedObjectArray<int> m_savedByPointer;  // saved indices by address (after a release)
};

#endif  // BT_SHOCK_PROPAGATION_DYNAMICS_WORLD_H
