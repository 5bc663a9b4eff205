#include "harness/Metrics.h"

#include <algorithm>
#include <cmath>

namespace harness
{
double maxPenetration(btDispatcher& dispatcher)
{
	double deepest = 0;
	for (int i = 0; i < dispatcher.getNumManifolds(); ++i)
	{
		const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
		const btTransform& trA = m->getBody0()->getWorldTransform();
		const btTransform& trB = m->getBody1()->getWorldTransform();
		for (int j = 0; j < m->getNumContacts(); ++j)
		{
			const btManifoldPoint& cp = m->getContactPoint(j);
			// Same formula as btPersistentManifold::refreshContactPoints, without changing it.
			const btScalar distance = (trA(cp.m_localPointA) - trB(cp.m_localPointB)).dot(cp.m_normalWorldOnB);
			deepest = std::max(deepest, double(-distance));
		}
	}
	return deepest;
}

double kineticEnergy(const std::vector<btRigidBody*>& bodies)
{
	double energy = 0;
	for (const btRigidBody* b : bodies)
	{
		if (b->getInvMass() == 0) continue;
		const btVector3& v = b->getLinearVelocity();
		const btVector3& w = b->getAngularVelocity();
		const btVector3 inertiaLocal = b->getLocalInertia();
		const btMatrix3x3& basis = b->getWorldTransform().getBasis();
		const btVector3 wLocal = w * basis;  // basis^T w
		energy += 0.5 * v.length2() / b->getInvMass();
		energy += 0.5 * (inertiaLocal.x() * wLocal.x() * wLocal.x() + inertiaLocal.y() * wLocal.y() * wLocal.y() + inertiaLocal.z() * wLocal.z() * wLocal.z());
	}
	return energy;
}

double maxSpeed(const std::vector<btRigidBody*>& bodies)
{
	double fastest = 0;
	for (const btRigidBody* b : bodies) fastest = std::max(fastest, double(b->getLinearVelocity().length()));
	return fastest;
}

namespace
{
/// Vertical (+y) impulse of one manifold's points on `supported`, one of its two bodies.
double upwardImpulseOn(const btPersistentManifold* m, const btCollisionObject* supported)
{
	double impulseUp = 0;
	for (int j = 0; j < m->getNumContacts(); ++j)
	{
		const btManifoldPoint& cp = m->getContactPoint(j);
		// m_normalWorldOnB points from B to A: the impulse on A is +normal * impulse.
		impulseUp += cp.m_normalWorldOnB.y() * cp.m_appliedImpulse;
	}
	return m->getBody0() == supported ? impulseUp : -impulseUp;
}
}  // namespace

double groundReactionOverWeight(btDispatcher& dispatcher, const btCollisionObject* ground,
								const std::vector<btRigidBody*>& bodies, double timeStep, double gravity)
{
	double weight = 0;
	for (const btRigidBody* b : bodies)
		if (b->getInvMass() != 0) weight += gravity / b->getInvMass();
	if (weight <= 0) return 0;
	double impulseUp = 0;
	for (int i = 0; i < dispatcher.getNumManifolds(); ++i)
	{
		const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
		if (m->getBody0() == ground) impulseUp += upwardImpulseOn(m, m->getBody1());
		else if (m->getBody1() == ground) impulseUp += upwardImpulseOn(m, m->getBody0());
	}
	return impulseUp / timeStep / weight;
}

double supportForce(btDispatcher& dispatcher, const btCollisionObject* upper, const btCollisionObject* lower, double timeStep)
{
	double impulseUp = 0;
	for (int i = 0; i < dispatcher.getNumManifolds(); ++i)
	{
		const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
		const bool pair = (m->getBody0() == upper && m->getBody1() == lower) || (m->getBody0() == lower && m->getBody1() == upper);
		if (pair) impulseUp += upwardImpulseOn(m, upper);
	}
	return impulseUp / timeStep;
}

DriftTracker::DriftTracker(const std::vector<btRigidBody*>& bodies) : m_bodies(bodies)
{
	for (const btRigidBody* b : m_bodies) m_start.push_back(b->getCenterOfMassPosition());
}

double DriftTracker::drift(const btRigidBody* body) const
{
	for (size_t i = 0; i < m_bodies.size(); ++i)
		if (m_bodies[i] == body) return (body->getCenterOfMassPosition() - m_start[i]).length();
	return 0;
}

double DriftTracker::maxDrift() const
{
	double worst = 0;
	for (size_t i = 0; i < m_bodies.size(); ++i)
		worst = std::max(worst, double((m_bodies[i]->getCenterOfMassPosition() - m_start[i]).length()));
	return worst;
}

double DriftTracker::rmsDrift() const
{
	if (m_bodies.empty()) return 0;
	double sum = 0;
	for (size_t i = 0; i < m_bodies.size(); ++i)
		sum += (m_bodies[i]->getCenterOfMassPosition() - m_start[i]).length2();
	return std::sqrt(sum / double(m_bodies.size()));
}

bool anyNonFinite(const std::vector<btRigidBody*>& bodies)
{
	for (const btRigidBody* b : bodies)
	{
		const btVector3& p = b->getCenterOfMassPosition();
		const btVector3& v = b->getLinearVelocity();
		const double sum = double(p.x()) + p.y() + p.z() + v.x() + v.y() + v.z();
		if (!std::isfinite(sum)) return true;
	}
	return false;
}
}  // namespace harness
