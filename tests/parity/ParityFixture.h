// Parity specs: the plugin against stock Bullet on the same scene, in the same test.
//
// Every test builds its scene three times, once per Mode:
//   Stock  - btDiscreteDynamicsWorld + btSequentialImpulseConstraintSolver
//   World  - btShockPropagationDynamicsWorld(dispatcher, broadphase, nullptr, configuration)
//   Solver - btDiscreteDynamicsWorld + new btShockPropagationConstraintSolver() (solver-only drop-in)
// exactly as an application writes it: Bullet's defaults everywhere (btContactSolverInfo, 10
// iterations) and the plugin's default settings, so an app's own settings reach the plugin the
// way they reach stock Bullet. That is why these specs do not use harness::Trial: the harness
// wraps every solver in a contact recorder, times collision detection in a world subclass and
// hands the plugin's solver its settings, and its scenes come from the registry; here the world
// creates its own solver (nullptr), nothing is wrapped, and each case builds the small scene its
// Bullet feature needs. They share the harness's meaning of "standing" (harness/Standing.h).
//
// Expected values come from stock Bullet in the same test or from physics (statics), never from
// the plugin's own output. Each test prints one line
//   PARITY | <case> | stock <figure> | world <figure> | solver <figure>
// before it asserts, so a table can be built from the log whatever the outcome.
#pragma once

#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace parity
{
enum class Mode
{
	Stock,
	World,
	Solver
};
constexpr Mode kModes[] = {Mode::Stock, Mode::World, Mode::Solver};
constexpr Mode kPluginModes[] = {Mode::World, Mode::Solver};

inline const char* modeName(Mode mode)
{
	switch (mode)
	{
		case Mode::Stock:
			return "stock";
		case Mode::World:
			return "world";
		default:
			return "solver";
	}
}

/// One value per mode, indexed by Mode.
template <class T>
struct PerMode
{
	std::array<T, 3> values{};
	T& operator[](Mode mode) { return values[size_t(mode)]; }
	const T& operator[](Mode mode) const { return values[size_t(mode)]; }
};

constexpr double kGravity = 9.81;		  // m/s^2
constexpr double kTimeStep = 1.0 / 60.0;  // s
/// Resting bodies overlap by 10 micrometres: Bullet's box-box test can miss exactly touching faces.
constexpr double kOverlap = 1e-5;  // m
constexpr double kPi = 3.14159265358979323846;

inline btVector3 vec(double x, double y, double z) { return btVector3(btScalar(x), btScalar(y), btScalar(z)); }
inline btVector3 axisVector(int axis, double length = 1)
{
	btVector3 v(0, 0, 0);
	v[axis] = btScalar(length);
	return v;
}

/// "1.234 unit" with the given number of decimals.
inline std::string fmt(double value, const char* unit, int decimals = 3)
{
	char text[64];
	std::snprintf(text, sizeof(text), "%.*f%s%s", decimals, value, unit[0] ? " " : "", unit);
	return text;
}

inline void printParity(const std::string& name, const PerMode<std::string>& figure)
{
	std::cout << "PARITY | " << name << " | stock " << figure[Mode::Stock] << " | world " << figure[Mode::World] << " | solver "
			  << figure[Mode::Solver] << std::endl;
}

/// A Bullet world of one Mode that owns its bodies, shapes and constraints; and its solver, unless
/// the caller hands one in (sharedSolver: kept by the caller, of the mode's kind).
class Scene
{
public:
	explicit Scene(Mode mode, double timeStep = kTimeStep, const btVector3& gravity = vec(0, -kGravity, 0), btConstraintSolver* sharedSolver = nullptr)
		: m_mode(mode), m_timeStep(timeStep)
	{
		m_configuration.reset(new btDefaultCollisionConfiguration());
		m_dispatcher.reset(new btCollisionDispatcher(m_configuration.get()));
		m_broadphase.reset(new btDbvtBroadphase());
		if (mode == Mode::World)
		{
			// Without a solver handed in, the world creates and owns its btShockPropagationConstraintSolver.
			m_world.reset(new btShockPropagationDynamicsWorld(m_dispatcher.get(), m_broadphase.get(), sharedSolver, m_configuration.get()));
		}
		else
		{
			if (!sharedSolver && mode == Mode::Solver) m_solver.reset(new btShockPropagationConstraintSolver());
			if (!sharedSolver && mode == Mode::Stock) m_solver.reset(new btSequentialImpulseConstraintSolver());
			m_world.reset(new btDiscreteDynamicsWorld(m_dispatcher.get(), m_broadphase.get(), sharedSolver ? sharedSolver : m_solver.get(),
													  m_configuration.get()));
		}
		m_world->setGravity(gravity);
	}

	~Scene()
	{
		for (auto& c : m_constraints) m_world->removeConstraint(c.get());
		for (auto& b : m_bodies) m_world->removeRigidBody(b.get());
		m_constraints.clear();
		m_bodies.clear();
		m_world.reset();
		m_solver.reset();
	}

	Scene(const Scene&) = delete;
	Scene& operator=(const Scene&) = delete;

	btDiscreteDynamicsWorld& world() { return *m_world; }
	Mode mode() const { return m_mode; }
	double timeStep() const { return m_timeStep; }
	int steps() const { return m_steps; }
	double time() const { return m_steps * m_timeStep; }
	/// Steps needed for the given simulated time.
	int stepsFor(double seconds) const { return int(seconds / m_timeStep + 0.5); }

	/// One fixed step of timeStep (one internal step per call).
	void step()
	{
		const btScalar dt = btScalar(m_timeStep);
		m_world->stepSimulation(dt, 1, dt);
		++m_steps;
	}

	/// A body of the given shape (the scene takes it). mass 0 = static. Sleeping is disabled
	/// unless allowSleeping. group/mask as btDiscreteDynamicsWorld::addRigidBody (-1 = Bullet's).
	btRigidBody* addBody(btCollisionShape* shape, double mass, const btTransform& transform, bool allowSleeping = false,
						 int group = -1, int mask = -1, btMotionState* motionState = nullptr)
	{
		m_shapes.emplace_back(shape);
		btVector3 inertia(0, 0, 0);
		if (mass > 0) shape->calculateLocalInertia(btScalar(mass), inertia);
		if (motionState) m_motionStates.emplace_back(motionState);
		btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), motionState, shape, inertia);
		info.m_startWorldTransform = transform;
		m_bodies.emplace_back(new btRigidBody(info));
		btRigidBody* body = m_bodies.back().get();
		if (!allowSleeping) body->setActivationState(DISABLE_DEACTIVATION);
		if (group == -1 && mask == -1)
			m_world->addRigidBody(body);
		else
			m_world->addRigidBody(body, group, mask);
		return body;
	}

	btRigidBody* addBox(const btVector3& halfExtents, double mass, const btVector3& position, bool allowSleeping = false)
	{
		return addBody(new btBoxShape(halfExtents), mass, btTransform(btQuaternion::getIdentity(), position), allowSleeping);
	}

	btRigidBody* addSphere(double radius, double mass, const btVector3& position, bool allowSleeping = false)
	{
		return addBody(new btSphereShape(btScalar(radius)), mass, btTransform(btQuaternion::getIdentity(), position), allowSleeping);
	}

	/// A static slab (100 x 100 x 1 m times scale) whose top face is the plane through the
	/// origin normal to upAxis (1 = y, 2 = z).
	btRigidBody* addGround(double scale = 1, int upAxis = 1)
	{
		btVector3 half = vec(50 * scale, 50 * scale, 50 * scale);
		half[upAxis] = btScalar(0.5 * scale);
		return addBody(new btBoxShape(half), 0, btTransform(btQuaternion::getIdentity(), axisVector(upAxis, -0.5 * scale)));
	}

	/// A column of count cubes of the given edge standing on the ground plane at base (along
	/// upAxis), each resting on the one below with kOverlap (scaled) of overlap.
	std::vector<btRigidBody*> addTower(int count, double edge, double mass, const btVector3& base, int upAxis = 1, bool allowSleeping = false)
	{
		std::vector<btRigidBody*> boxes;
		const double overlap = kOverlap * edge;
		for (int i = 0; i < count; ++i)
		{
			const double height = edge * (0.5 + i) - overlap * (i + 1);
			boxes.push_back(addBox(vec(edge / 2, edge / 2, edge / 2), mass, base + axisVector(upAxis, height), allowSleeping));
		}
		return boxes;
	}

	/// Adds the constraint (the scene owns it).
	template <class T>
	T* addConstraint(T* constraint, bool disableCollisionsBetweenLinkedBodies = true)
	{
		m_constraints.emplace_back(constraint);
		m_world->addConstraint(constraint, disableCollisionsBetweenLinkedBodies);
		return constraint;
	}

private:
	Mode m_mode;
	double m_timeStep;
	int m_steps = 0;
	std::unique_ptr<btDefaultCollisionConfiguration> m_configuration;
	std::unique_ptr<btCollisionDispatcher> m_dispatcher;
	std::unique_ptr<btBroadphaseInterface> m_broadphase;
	std::unique_ptr<btConstraintSolver> m_solver;
	std::unique_ptr<btDiscreteDynamicsWorld> m_world;
	std::vector<std::unique_ptr<btCollisionShape>> m_shapes;
	std::vector<std::unique_ptr<btMotionState>> m_motionStates;
	std::vector<std::unique_ptr<btRigidBody>> m_bodies;
	std::vector<std::unique_ptr<btTypedConstraint>> m_constraints;
};

/// Largest displacement of any of the bodies from where they were when the tracker was made (m).
class DriftTracker
{
public:
	explicit DriftTracker(std::vector<btRigidBody*> bodies) : m_bodies(std::move(bodies))
	{
		for (btRigidBody* b : m_bodies) m_start.push_back(b->getCenterOfMassPosition());
	}
	double current() const
	{
		double drift = 0;
		for (size_t i = 0; i < m_bodies.size(); ++i) drift = std::max(drift, double((m_bodies[i]->getCenterOfMassPosition() - m_start[i]).length()));
		return drift;
	}
	/// Call after each step: keeps the worst drift seen.
	void update() { m_worst = std::max(m_worst, current()); }
	double worst() const { return m_worst; }

private:
	std::vector<btRigidBody*> m_bodies;
	std::vector<btVector3> m_start;
	double m_worst = 0;
};

inline bool touches(const btPersistentManifold* m, const btCollisionObject* body)
{
	return m->getBody0() == body || m->getBody1() == body;
}

/// Sum of btManifoldPoint::getAppliedImpulse over the contact points touching body (N s); every
/// contact point when body is null. What an application reads after a step.
inline double appliedImpulse(btDynamicsWorld& world, const btCollisionObject* body = nullptr)
{
	btDispatcher* dispatcher = world.getDispatcher();
	double total = 0;
	for (int i = 0; i < dispatcher->getNumManifolds(); ++i)
	{
		const btPersistentManifold* m = dispatcher->getManifoldByIndexInternal(i);
		if (body && !touches(m, body)) continue;
		for (int j = 0; j < m->getNumContacts(); ++j) total += m->getContactPoint(j).getAppliedImpulse();
	}
	return total;
}

/// Deepest penetration (positive metres, 0 if none) among the contact points touching body.
inline double penetration(btDynamicsWorld& world, const btCollisionObject* body)
{
	btDispatcher* dispatcher = world.getDispatcher();
	double deepest = 0;
	for (int i = 0; i < dispatcher->getNumManifolds(); ++i)
	{
		const btPersistentManifold* m = dispatcher->getManifoldByIndexInternal(i);
		if (!touches(m, body)) continue;
		for (int j = 0; j < m->getNumContacts(); ++j) deepest = std::max(deepest, -double(m->getContactPoint(j).getDistance()));
	}
	return deepest;
}

/// Kinetic energy, translational and rotational (J).
inline double kineticEnergy(const btRigidBody& body)
{
	if (body.getInvMass() == 0) return 0;
	const double mass = 1.0 / body.getInvMass();
	const btVector3 omegaLocal = body.getWorldTransform().getBasis().transpose() * body.getAngularVelocity();
	const btVector3 inertia = body.getLocalInertia();
	double energy = 0.5 * mass * body.getLinearVelocity().length2();
	for (int k = 0; k < 3; ++k) energy += 0.5 * double(inertia[k]) * double(omegaLocal[k]) * double(omegaLocal[k]);
	return energy;
}

/// Tracks a ball bouncing on a surface: the first apex after its first bounce.
class BounceTracker
{
public:
	/// surfaceHeight: height of the surface the ball lands on; radius: the ball's.
	BounceTracker(const btRigidBody* ball, double surfaceHeight, double radius, int upAxis = 1)
		: m_ball(ball), m_surface(surfaceHeight), m_radius(radius), m_up(upAxis)
	{
	}
	/// Call after each step; returns true on the impact step (the step that turned the ball round).
	bool update(int step)
	{
		const double v = m_ball->getLinearVelocity()[m_up];
		const double gap = m_ball->getCenterOfMassPosition()[m_up] - m_radius - m_surface;
		bool impact = false;
		if (m_phase == Falling && v < 0)
			m_phase = Landing;
		else if (m_phase == Landing && v > 0)
		{
			m_phase = Rising;
			m_impactStep = step;
			impact = true;
		}
		if (m_phase == Rising)
		{
			m_apex = std::max(m_apex, gap);
			if (v <= 0) m_phase = Done;
		}
		return impact;
	}
	/// Height of the ball's bottom above the surface at the first apex after the bounce (m; 0 if none).
	double apex() const { return m_apex; }
	int impactStep() const { return m_impactStep; }
	bool done() const { return m_phase == Done; }

private:
	enum Phase
	{
		Falling,
		Landing,
		Rising,
		Done
	};
	const btRigidBody* m_ball;
	double m_surface;
	double m_radius;
	int m_up;
	Phase m_phase = Falling;
	double m_apex = 0;
	int m_impactStep = -1;
};
}  // namespace parity
