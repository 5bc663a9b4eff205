// Accuracy measures shared by the demo program, the tests and the benchmarks.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <vector>

namespace harness
{
/// Largest penetration (metres, >= 0) over all manifold points, with the distance recomputed
/// from the bodies' current transforms (read-only: the manifolds are not refreshed).
double maxPenetration(btDispatcher& dispatcher);

/// Sum of 1/2 m v^2 + 1/2 w.I w over dynamic bodies (joules).
double kineticEnergy(const std::vector<btRigidBody*>& bodies);

/// Largest linear speed over the bodies (m/s).
double maxSpeed(const std::vector<btRigidBody*>& bodies);

/// Vertical contact force from the ground on the bodies in the last step (newtons), from
/// btManifoldPoint::m_appliedImpulse / timeStep, divided by the total weight of the dynamic bodies.
double groundReactionOverWeight(btDispatcher& dispatcher, const btCollisionObject* ground,
								const std::vector<btRigidBody*>& bodies, double timeStep, double gravity);

/// Vertical (+y) contact force (newtons) that `lower` exerted on `upper` in the last step, from
/// btManifoldPoint::m_appliedImpulse / timeStep.
double supportForce(btDispatcher& dispatcher, const btCollisionObject* upper, const btCollisionObject* lower, double timeStep);

/// Positions at a reference time; drift = displacement of each body's centre of mass since then.
class DriftTracker
{
public:
	explicit DriftTracker(const std::vector<btRigidBody*>& bodies);
	double maxDrift() const;  ///< metres, largest over bodies
	double rmsDrift() const;  ///< metres, root mean square over bodies
	double drift(const btRigidBody* body) const;

private:
	std::vector<btRigidBody*> m_bodies;
	std::vector<btVector3> m_start;
};

/// True if any body has a NaN or Inf position or velocity.
bool anyNonFinite(const std::vector<btRigidBody*>& bodies);
}  // namespace harness
