// Seeded hostile worlds for robustness tests: everything an application can do wrong to a
// physics world, at random but reproducibly from one seed. Not in the registry table: a hostile
// world changes between steps (HostileScene::beforeStep), which a registry scene cannot express.
//
// What a world holds (all sizes in metres, masses in kg, Y up, ground top at y = 0):
// - stacks of boxes whose masses are drawn log-uniformly from [minMass, maxMass] (1e-3 to 1e6
//   by default) in one stack, some stacks sunk deep into each other;
// - loose boxes, spheres and capsules, some placed deep inside another body, some moving;
// - dynamic bodies with zero mass (mass 0 without the static flag);
// - bodies whose transform or velocity holds NaN or Inf, from the start or from a later step;
// - kinematic boxes driven through the stacks at a fixed speed;
// - joints (point-to-point, hinge, 6-dof) between random pairs of bodies and to static bodies,
//   each created where it is already satisfied (no initial joint error);
// and between steps, drawn from the seed: bodies and joints removed, removed ones added back,
// new bodies added, bodies teleported (possibly into others).
//
// Conventions: every dynamic body has DISABLE_DEACTIVATION; restitution is 0, so no contact
// can return more energy than it takes (tests bound the kinetic energy on that basis).
// Teleports pick bodies without joints, and a joint added back is re-anchored where its bodies
// are now (a new constraint of the same kind): a stretched joint is pulled back by Bullet's joint
// ERP at erp * error / dt (12 m/s per metre of error at 60 Hz, erp 0.2), an energy input that is
// Bullet's by design and that no energy bound on contacts should have to include.

#ifndef SCENES_HOSTILE_SCENE_H
#define SCENES_HOSTILE_SCENE_H

#include <btBulletDynamicsCommon.h>

#include <cstdint>
#include <memory>
#include <random>
#include <vector>

namespace scenes
{
/// Sizes and rates of a hostile world. Defaults keep a world at about 40 bodies, so 1,000 seeds
/// of 120 steps run in about a minute.
struct HostileParams
{
	int stacks = 2;               ///< box stacks
	int stackHeight = 5;          ///< boxes per stack
	int looseBodies = 10;         ///< boxes, spheres and capsules placed at random
	int joints = 5;               ///< joints created at the start
	int kinematicBodies = 1;      ///< kinematic boxes sweeping through the stacks
	double minMass = 1e-3;        ///< kg, lightest body
	double maxMass = 1e6;         ///< kg, heaviest body
	double maxStartSpeed = 3;     ///< m/s, largest initial speed of a moving loose body
	double kinematicSpeed = 1;    ///< m/s, speed of every kinematic body
	double poisonFraction = 0.1;  ///< share of bodies given NaN or Inf at the start
	double zeroMassFraction = 0.1;  ///< share of loose bodies with mass 0 and no static flag
	double eventRate = 0.15;      ///< chance per step of each between-step event kind
};

/// One body the scene made, with what tests need to judge it.
struct HostileBody
{
	btRigidBody* body = nullptr;
	bool poisoned = false;   ///< given a NaN or Inf transform or velocity (at the start or later)
	bool zeroMass = false;   ///< mass 0 without the static flag
	bool kinematic = false;  ///< driven by the scene
	bool isStatic = false;   ///< the ground and the static posts
	bool inWorld = false;    ///< currently added to the world
	/// m, highest centre height it was ever placed at (start or teleport), less liftedBy
	double highestY = 0;
	/// m, how far its teleports have moved it up. A teleport keeps the velocity, so the body keeps
	/// the energy its fall so far released: the energy budget measures its heights less this.
	double liftedBy = 0;
	double startKineticEnergy = 0;  ///< J, 1/2 m v^2 + 1/2 w.I w when it was created
	double yWhenPoisoned = 0;  ///< m, centre height just before it was poisoned (if poisoned)
};

class HostileScene
{
public:
	/// Builds the world for `seed` into `world` (which must outlive the scene).
	HostileScene(btDiscreteDynamicsWorld& world, std::uint32_t seed, const HostileParams& params = HostileParams());
	/// Removes from the world and deletes everything the scene made.
	~HostileScene();
	HostileScene(const HostileScene&) = delete;
	HostileScene& operator=(const HostileScene&) = delete;

	/// Applies what the seed holds for the step about to run (call before each stepSimulation of
	/// `timeStep` seconds): moves the kinematic bodies, then possibly removes, re-adds, creates,
	/// teleports or poisons bodies and removes or re-adds joints.
	void beforeStep(double timeStep);

	/// Collision objects the world must hold now (bodies added and not removed).
	int expectedCollisionObjects() const;
	/// Constraints the world must hold now.
	int expectedConstraints() const;

	/// Every body the scene made, in creation order (removed ones included).
	const std::vector<HostileBody>& bodies() const { return m_bodies; }
	/// Non-static bodies never poisoned: dynamic, zero-mass and kinematic, removed ones included.
	std::vector<btRigidBody*> healthyBodies() const;
	/// The record of `body`, or nullptr.
	const HostileBody* find(const btRigidBody* body) const;

	/// Speed of the kinematic bodies (m/s) and elapsed simulated time (s, sum of beforeStep steps).
	double kinematicSpeed() const { return m_params.kinematicSpeed; }
	double elapsedTime() const { return m_time; }
	/// Largest initial speed of any body (m/s).
	double maxStartSpeed() const { return m_params.maxStartSpeed; }
	/// Largest extent of any body the scene makes (m): the deepest overlap a body can start in or
	/// be teleported into, and so the farthest a position correction can move one body in a step.
	static double largestExtent();
	/// True if a joint of the scene (in the world or not) has `body` as one of its bodies.
	bool isJointed(const btRigidBody* body) const;

private:
	struct Joint
	{
		btTypedConstraint* constraint;
		int kind;   // 0 point-to-point, 1 hinge, 2 6-dof
		int bodyA;  // index into m_bodies
		int bodyB;
		bool inWorld;
	};

	double random();                      // [0, 1)
	double random(double low, double high);
	int randomIndex(int count);           // [0, count)
	btCollisionShape* randomShape(double scale);
	btQuaternion randomRotation();

	int addBody(btCollisionShape* shape, double mass, const btTransform& xf);
	void makeZeroMass(int index);
	void makeKinematic(int index);
	void poison(int index);
	void addJoint(int indexA, int indexB);
	/// A new constraint of the joint's kind, satisfied at the bodies' current poses, into the world.
	void attachJoint(Joint& joint);
	void insert(int index);   // body into the world
	void remove(int index);   // body and its joints out of the world
	bool hasJoint(int index) const;
	void setMoving(int index);

	void buildStacks();
	void buildLooseBodies();
	void buildJoints();
	void buildKinematics();

	void eventRemoveBody();
	void eventReaddBody();
	void eventNewBody();
	void eventTeleport();
	void eventToggleJoint();
	void eventPoison();

	btDiscreteDynamicsWorld* m_world;
	HostileParams m_params;
	std::mt19937 m_rng;
	double m_time = 0;
	std::vector<std::unique_ptr<btCollisionShape>> m_shapes;
	std::vector<HostileBody> m_bodies;
	std::vector<Joint> m_joints;
	std::vector<btVector3> m_kinematicStart;      // per body index (zero for non-kinematic)
	std::vector<btVector3> m_kinematicDirection;  // per body index, unit (zero for non-kinematic)
};

}  // namespace scenes

#endif  // SCENES_HOSTILE_SCENE_H
