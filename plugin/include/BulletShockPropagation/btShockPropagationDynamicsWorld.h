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

#include "BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h"
#include "LinearMath/btThreads.h"  // BT_OVERRIDE
#include "btShockPropagationExport.h"

class btShockPropagationConstraintSolver;

/// A btDiscreteDynamicsWorld that runs Erleben's full time step (ACM TOG 2007, "final algorithm"):
///
///   what runs                                                     Bullet call
///   CD(t), islands                                                performDiscreteCollisionDetection
///   global pass, layers bottom-up, position correction at CD(t)   solveConstraints (solver's solveGroup)
///   positions advance with the final velocity                     integrateTransforms
///   second correction at t + dt ("anti-rippling")                 after integrateTransforms
///
/// Everything else is btDiscreteDynamicsWorld's own step (predictive contacts, actions, sleeping,
/// callbacks), unchanged. The second correction recomputes each contact point's depth from the
/// new transforms, as Bullet's refreshContactPoints does, without changing the manifolds (D4).
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

	btShockPropagationConstraintSolver* getShockPropagationSolver() { return m_shockSolver; }
	const btShockPropagationConstraintSolver* getShockPropagationSolver() const { return m_shockSolver; }

protected:
	virtual void internalSingleStepSimulation(btScalar timeStep) BT_OVERRIDE;
	/// Bullet's integration, then the second correction (m_secondCorrection).
	virtual void integrateTransforms(btScalar timeStep) BT_OVERRIDE;

	/// The second correction at t + dt.
	void correctionPhase(btScalar timeStep);

private:
	btShockPropagationConstraintSolver* m_shockSolver;
};

#endif  // BT_SHOCK_PROPAGATION_DYNAMICS_WORLD_H
