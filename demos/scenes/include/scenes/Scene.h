// Scene library for BulletShockPropagation: renderer-free scenes shared by the demo, the tests and the
// benchmarks. Every scene is defined once, in demos/scenes/src, and listed in one explicit table
// (scenes/Registry.h).
//
// Conventions every scene follows (Y is up, SI units):
// - The caller makes the world (gravity, solver, solver settings); a scene only adds bodies and
//   constraints to it.
// - Every scene has a static ground box whose top face is at y = 0, named "ground".
// - Every dynamic body has DISABLE_DEACTIVATION (sleeping freezes a collapsing stack mid-fall and makes
//   it look stable) and starts at rest unless the scene says otherwise.
// - Resting bodies overlap what they rest on by 10 micrometres, so every resting contact exists at
//   step 1 (exactly touching boxes may get no contact in float); side neighbours keep a 1 mm gap.
// - Friction: Bullet multiplies the two coefficients of a pair, so addBody() gives each body sqrt(mu)
//   and any two bodies of a scene combine to the scene's mu.
// - SceneContent::facts says what the scene expects, e.g. "expectStanding" = 1 if a correct solver
//   keeps every body within 1 cm of where it started, 0 if the scene is meant to move.

#ifndef SCENES_SCENE_H
#define SCENES_SCENE_H

#include <btBulletDynamicsCommon.h>

#include <map>
#include <memory>
#include <stdexcept>  // std::invalid_argument, thrown by this API
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace scenes
{
/// One tunable of a scene: its value with a unit ("m", "kg", "-" for dimensionless, "deg", ...).
struct Param
{
	std::string name;
	double value;
	std::string unit;
	std::string description;
};
using Params = std::vector<Param>;

/// Value of the parameter `name`; throws std::invalid_argument listing the valid names if it is missing.
double getParam(const Params& params, const std::string& name);

/// `defaults` with the given values replaced; throws std::invalid_argument (listing the valid names) on
/// an unknown name, or if a value is not finite.
Params withOverrides(const Params& defaults, const std::vector<std::pair<std::string, double>>& overrides);

/// Everything a scene created, and the owner of it. The destructor removes the constraints and the
/// bodies from the world and deletes them, their motion states and the shapes, so the world must
/// outlive the SceneContent.
class SceneContent
{
public:
	explicit SceneContent(btDiscreteDynamicsWorld& world);
	~SceneContent();
	SceneContent(const SceneContent&) = delete;
	SceneContent& operator=(const SceneContent&) = delete;

	btDiscreteDynamicsWorld& world();

	/// Takes ownership of `shape` (adding the same shape twice is harmless); returns it.
	btCollisionShape* addShape(btCollisionShape* shape);
	/// Adds a rigid body to the world and returns it. `shape` is owned from now on (see addShape).
	/// mass in kg (0: static); `friction` is the combined mu this body should have against another body
	/// of the scene, so the body gets sqrt(friction). Dynamic bodies get DISABLE_DEACTIVATION.
	btRigidBody* addBody(btCollisionShape* shape, btScalar mass, const btTransform& xf, btScalar friction, btScalar restitution = 0);
	/// Keeps `object` (a mesh's vertex data, a heightfield's samples, a triangle-info map: what a
	/// shape points to but does not own) alive until the shapes are gone; returns it.
	template <class T>
	T* keep(T* object)
	{
		m_kept.emplace_back(object);
		return object;
	}
	/// Adds a constraint to the world; owned from now on.
	btTypedConstraint* addConstraint(btTypedConstraint* c, bool disableCollisionsBetweenLinkedBodies = true);

	/// Gives `body` a name tests can look up ("top", "bottom", "lintel", ...); a later call with the same
	/// key replaces the earlier body.
	void name(const std::string& key, btRigidBody* body);
	/// The body named `key`, or nullptr.
	btRigidBody* named(const std::string& key) const;

	/// All bodies this scene added, static ones included, in creation order.
	const std::vector<btRigidBody*>& bodies() const;
	/// The bodies with mass > 0, in creation order.
	std::vector<btRigidBody*> dynamicBodies() const;
	const std::vector<btTypedConstraint*>& constraints() const;
	/// The static ground body (named "ground"; every scene has one).
	btRigidBody* ground() const;

	/// What the scene expects, free-form numbers by name (read by tests and the demo). Every scene sets
	/// "expectStanding" (1 or 0) and "bodies" (number of dynamic bodies).
	std::map<std::string, double> facts;

private:
	btDiscreteDynamicsWorld* m_world;
	std::vector<btCollisionShape*> m_shapes;
	std::unordered_set<btCollisionShape*> m_ownedShapes;
	std::vector<btRigidBody*> m_bodies;
	std::vector<btTypedConstraint*> m_constraints;
	std::map<std::string, btRigidBody*> m_names;
	std::vector<std::shared_ptr<void>> m_kept;  ///< destroyed after the destructor's body has deleted the shapes
};

/// Builds one scene into `world` from a complete parameter list (see SceneEntry::defaults).
using CreateFn = std::unique_ptr<SceneContent> (*)(btDiscreteDynamicsWorld& world, const Params& params);

/// One row of the registry table.
struct SceneEntry
{
	std::string category;     ///< "basic", "seed" (from the source paper), "hard", "truth" (the truth suite) or "benchmark" (after BenchmarkDemo, PyBullet)
	std::string name;         ///< unique, snake_case, e.g. "pyramid"
	std::string description;  ///< one line
	CreateFn create;
	Params defaults;  ///< every parameter the scene reads, with its default value and unit
};

}  // namespace scenes

// The registry (registry(), findScene(), sceneNames(), createScene()) is part of this API too.
#include "scenes/Registry.h"

#endif  // SCENES_SCENE_H
