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

#ifndef BT_SHOCK_PROPAGATION_BODY_CHECKS_H
#define BT_SHOCK_PROPAGATION_BODY_CHECKS_H

#include "BulletCollision/NarrowPhaseCollision/btPersistentManifold.h"
#include "BulletDynamics/Dynamics/btRigidBody.h"
#include "LinearMath/btQuickprof.h"

/// What the solver asks of bodies and manifolds before it uses them (private to the plugin).
namespace btShockPropagationChecks
{
inline bool isFiniteScalar(btScalar x)
{
	return x == x && x - x == btScalar(0);  // false for NaN and for +-Inf
}

inline bool isFiniteVector(const btVector3& v)
{
	return isFiniteScalar(v.x() + v.y() + v.z());
}

/// Transform and velocities finite (a NaN or Inf anywhere makes the sum non-finite).
inline bool isHealthy(const btCollisionObject* object)
{
	const btTransform& t = object->getWorldTransform();
	const btMatrix3x3& m = t.getBasis();
	btScalar sum = t.getOrigin().x() + t.getOrigin().y() + t.getOrigin().z();
	for (int i = 0; i < 3; ++i) sum += m[i].x() + m[i].y() + m[i].z();
	if (const btRigidBody* rb = btRigidBody::upcast(object))
	{
		const btVector3& v = rb->getLinearVelocity();
		const btVector3& w = rb->getAngularVelocity();
		sum += v.x() + v.y() + v.z() + w.x() + w.y() + w.z();
	}
	return isFiniteScalar(sum);
}

/// A graph node: a dynamic body with finite mass (static, kinematic and zero-mass bodies are roots).
inline bool isNode(const btCollisionObject* object)
{
	const btRigidBody* rb = btRigidBody::upcast(object);
	return rb && !object->isStaticOrKinematicObject() && rb->getInvMass() != btScalar(0);
}

inline bool hasFinitePoints(const btPersistentManifold* manifold)
{
	for (int j = 0; j < manifold->getNumContacts(); ++j)
	{
		const btManifoldPoint& cp = manifold->getContactPoint(j);
		if (!isFiniteScalar(cp.getDistance()) || !isFiniteVector(cp.m_normalWorldOnB) ||
			!isFiniteVector(cp.getPositionWorldOnA()) || !isFiniteVector(cp.getPositionWorldOnB()))
		{
			return false;
		}
	}
	return true;
}

/// Up (unit, -gravity / |g|) of the manifold's dynamic end; zero without gravity.
inline btVector3 upOf(const btPersistentManifold* manifold)
{
	const btRigidBody* dynamic = btRigidBody::upcast(manifold->getBody0());
	if (!dynamic || dynamic->getInvMass() == btScalar(0)) dynamic = btRigidBody::upcast(manifold->getBody1());
	if (!dynamic) return btVector3(0, 0, 0);
	const btVector3 gravity = dynamic->getGravity();
	const btScalar g = gravity.length();
	return g > SIMD_EPSILON ? -gravity / g : btVector3(0, 0, 0);
}

inline double millisecondsSince(btClock& clock)
{
	return double(clock.getTimeMicroseconds()) * 1e-3;
}
}  // namespace btShockPropagationChecks

#endif  // BT_SHOCK_PROPAGATION_BODY_CHECKS_H
