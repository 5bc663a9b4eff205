// Seeded hostile worlds (scenes/HostileScene.h): construction and the between-step events.

#include "scenes/HostileScene.h"

#include <cmath>
#include <limits>

namespace scenes
{
namespace
{
/// Half width of the ground slab (m): far beyond where anything is placed or can travel in a test.
constexpr double kGroundHalfWidth = 50.0;
/// Centre distance between neighbouring stacks along x (m).
constexpr double kStackSpacing = 3.0;
/// Region loose bodies, new bodies and teleports are placed in (m): |x| <= 5, 0.2 <= y <= 4, |z| <= 3.
constexpr double kRegionHalfX = 5.0, kRegionLowY = 0.2, kRegionHighY = 4.0, kRegionHalfZ = 3.0;
/// Initial overlap of resting bodies (m), as in every registry scene (docs/bullet-facts.md).
constexpr double kRestOverlap = 1e-5;
/// Largest share of a box's height that a "sunk" stack box starts inside the one below.
constexpr double kMaxSinkFraction = 0.45;
/// Chance that a loose body starts inside another body rather than at a random place.
constexpr double kInsideOtherChance = 0.3;
/// Chance that a loose body starts moving (up to maxStartSpeed, and up to 3 rad/s).
constexpr double kMovingChance = 0.3;
constexpr double kMaxStartSpinRadPerSecond = 3.0;
/// Where a kinematic body starts (m before the stack it crosses) and its half extent (m).
constexpr double kKinematicLeadIn = 1.2;
constexpr double kKinematicHalfExtent = 0.3;

double nan() { return std::numeric_limits<double>::quiet_NaN(); }
double inf() { return std::numeric_limits<double>::infinity(); }

double kineticEnergyOf(const btRigidBody& body)
{
	if (body.getInvMass() == btScalar(0)) return 0;
	const btVector3 w = body.getAngularVelocity() * body.getWorldTransform().getBasis();  // body frame
	const btVector3 inertia = body.getLocalInertia();
	return 0.5 * double(body.getLinearVelocity().length2()) / double(body.getInvMass()) +
		   0.5 * double(inertia.x() * w.x() * w.x() + inertia.y() * w.y() * w.y() + inertia.z() * w.z() * w.z());
}
}  // namespace

HostileScene::HostileScene(btDiscreteDynamicsWorld& world, std::uint32_t seed, const HostileParams& params)
	: m_world(&world), m_params(params), m_rng(seed)
{
	// The ground (top at y = 0) and one static post beside the stacks, for joints to static bodies.
	m_shapes.emplace_back(new btBoxShape(btVector3(btScalar(kGroundHalfWidth), btScalar(0.5), btScalar(kGroundHalfWidth))));
	int ground = addBody(m_shapes.back().get(), 0, btTransform(btQuaternion::getIdentity(), btVector3(0, btScalar(-0.5), 0)));
	m_shapes.emplace_back(new btBoxShape(btVector3(btScalar(0.2), btScalar(1.5), btScalar(0.2))));
	int post = addBody(m_shapes.back().get(), 0, btTransform(btQuaternion::getIdentity(), btVector3(0, btScalar(1.5), btScalar(kRegionHalfZ + 1))));
	m_bodies[ground].isStatic = m_bodies[post].isStatic = true;

	buildStacks();
	buildLooseBodies();
	buildKinematics();
	buildJoints();

	// Poison only after every body is in the broadphase: a body added with a NaN transform would
	// put a NaN box into Bullet's AABB tree, which breaks collision detection for everyone.
	for (size_t i = 0; i < m_bodies.size(); ++i)
	{
		const HostileBody& b = m_bodies[i];
		if (!b.isStatic && !b.kinematic && random() < m_params.poisonFraction) poison(int(i));
	}
}

HostileScene::~HostileScene()
{
	for (Joint& joint : m_joints)
	{
		if (joint.inWorld) m_world->removeConstraint(joint.constraint);
		delete joint.constraint;
	}
	for (HostileBody& b : m_bodies)
	{
		if (b.inWorld) m_world->removeRigidBody(b.body);
		delete b.body;
	}
}

// ---------------------------------------------------------------------------------------------
// Random numbers: raw 32-bit draws, so a seed gives the same world with every standard library
// (the std:: distributions are implementation-defined).

double HostileScene::random() { return double(m_rng()) / 4294967296.0; }

double HostileScene::random(double low, double high) { return low + (high - low) * random(); }

int HostileScene::randomIndex(int count) { return count <= 0 ? 0 : int(random() * count) % count; }

btQuaternion HostileScene::randomRotation()
{
	// Uniform over rotations (Shoemake's method).
	const double u1 = random(), u2 = random(), u3 = random();
	const double a = std::sqrt(1 - u1), b = std::sqrt(u1), twoPi = 2 * SIMD_PI;
	return btQuaternion(btScalar(a * std::sin(twoPi * u2)), btScalar(a * std::cos(twoPi * u2)), btScalar(b * std::sin(twoPi * u3)),
						btScalar(b * std::cos(twoPi * u3)));
}

btCollisionShape* HostileScene::randomShape(double scale)
{
	const int kind = randomIndex(3);
	btCollisionShape* shape;
	if (kind == 0)
		shape = new btBoxShape(btVector3(btScalar(random(0.1, 0.5) * scale), btScalar(random(0.1, 0.5) * scale), btScalar(random(0.1, 0.5) * scale)));
	else if (kind == 1)
		shape = new btSphereShape(btScalar(random(0.1, 0.4) * scale));
	else
		shape = new btCapsuleShape(btScalar(random(0.08, 0.25) * scale), btScalar(random(0.1, 0.6) * scale));
	m_shapes.emplace_back(shape);
	return shape;
}

// ---------------------------------------------------------------------------------------------
// Bodies and joints

int HostileScene::addBody(btCollisionShape* shape, double mass, const btTransform& xf)
{
	btVector3 inertia(0, 0, 0);
	if (mass > 0) shape->calculateLocalInertia(btScalar(mass), inertia);
	btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), nullptr, shape, inertia);
	info.m_startWorldTransform = xf;
	info.m_friction = btScalar(random(0.2, 1.0));
	info.m_restitution = 0;  // no contact returns more energy than it takes
	HostileBody record;
	record.body = new btRigidBody(info);
	if (mass > 0) record.body->setActivationState(DISABLE_DEACTIVATION);
	record.highestY = xf.getOrigin().y();
	m_bodies.push_back(record);
	const int index = int(m_bodies.size()) - 1;
	m_kinematicStart.push_back(btVector3(0, 0, 0));
	m_kinematicDirection.push_back(btVector3(0, 0, 0));
	insert(index);
	return index;
}

void HostileScene::insert(int index)
{
	HostileBody& b = m_bodies[index];
	if (b.inWorld) return;
	m_world->addRigidBody(b.body);
	b.inWorld = true;
}

void HostileScene::remove(int index)
{
	HostileBody& b = m_bodies[index];
	if (!b.inWorld) return;
	// Joints first: Bullet does not remove a removed body's constraints.
	for (Joint& joint : m_joints)
	{
		if (joint.inWorld && (joint.bodyA == index || joint.bodyB == index))
		{
			m_world->removeConstraint(joint.constraint);
			joint.inWorld = false;
		}
	}
	m_world->removeRigidBody(b.body);
	b.inWorld = false;
}

bool HostileScene::hasJoint(int index) const
{
	for (const Joint& joint : m_joints)
		if (joint.bodyA == index || joint.bodyB == index) return true;
	return false;
}

double HostileScene::largestExtent()
{
	// Boxes up to 1 m per side (half extents <= 0.5), spheres up to 0.8 m, capsules up to
	// 2 * 0.25 + 0.6 = 1.1 m (randomShape, buildStacks).
	return 1.1;
}

bool HostileScene::isJointed(const btRigidBody* body) const
{
	for (const Joint& joint : m_joints)
		if (m_bodies[joint.bodyA].body == body || m_bodies[joint.bodyB].body == body) return true;
	return false;
}

void HostileScene::setMoving(int index)
{
	btRigidBody* body = m_bodies[index].body;
	const btVector3 direction = quatRotate(randomRotation(), btVector3(1, 0, 0));
	body->setLinearVelocity(direction * btScalar(random(0, m_params.maxStartSpeed)));
	body->setAngularVelocity(quatRotate(randomRotation(), btVector3(1, 0, 0)) * btScalar(random(0, kMaxStartSpinRadPerSecond)));
	m_bodies[index].startKineticEnergy = kineticEnergyOf(*body);
}

void HostileScene::makeZeroMass(int index)
{
	// What an application gets by calling setMassProps(0, ...) on a dynamic body and clearing the
	// static flag Bullet sets: inverse mass 0, yet not static.
	btRigidBody* body = m_bodies[index].body;
	const bool wasIn = m_bodies[index].inWorld;
	remove(index);
	body->setMassProps(0, btVector3(0, 0, 0));
	body->setCollisionFlags(body->getCollisionFlags() & ~btCollisionObject::CF_STATIC_OBJECT);
	body->setActivationState(DISABLE_DEACTIVATION);
	body->setLinearVelocity(btVector3(0, 0, 0));
	body->setAngularVelocity(btVector3(0, 0, 0));
	m_bodies[index].zeroMass = true;
	m_bodies[index].startKineticEnergy = 0;
	if (wasIn) insert(index);
}

void HostileScene::makeKinematic(int index)
{
	btRigidBody* body = m_bodies[index].body;
	remove(index);
	// Bullet flags a body made with mass 0 static; a kinematic body must not be.
	body->setCollisionFlags((body->getCollisionFlags() & ~btCollisionObject::CF_STATIC_OBJECT) | btCollisionObject::CF_KINEMATIC_OBJECT);
	body->setActivationState(DISABLE_DEACTIVATION);
	m_bodies[index].kinematic = true;
	insert(index);
}

void HostileScene::poison(int index)
{
	HostileBody& b = m_bodies[index];
	btRigidBody* body = b.body;
	b.yWhenPoisoned = body->getWorldTransform().getOrigin().y();
	b.poisoned = true;
	const int kind = randomIndex(6);
	const btScalar bad = btScalar(kind % 2 ? inf() : nan());
	btTransform xf = body->getWorldTransform();
	switch (kind)
	{
		case 0:
		case 1:
			xf.getOrigin().setY(bad);  // NaN or Inf position
			body->setWorldTransform(xf);
			body->setInterpolationWorldTransform(xf);
			break;
		case 2:
			xf.getBasis()[0].setX(bad);  // NaN rotation
			body->setWorldTransform(xf);
			body->setInterpolationWorldTransform(xf);
			break;
		case 3:
			body->setLinearVelocity(btVector3(bad, 0, 0));  // Inf velocity
			break;
		case 4:
			body->setLinearVelocity(btVector3(0, bad, 0));  // NaN velocity
			break;
		default:
			body->setAngularVelocity(btVector3(0, 0, bad));  // Inf spin
			break;
	}
}

void HostileScene::addJoint(int indexA, int indexB)
{
	m_joints.push_back(Joint{nullptr, randomIndex(3), indexA, indexB, false});
	if (m_bodies[indexA].inWorld && m_bodies[indexB].inWorld) attachJoint(m_joints.back());
}

void HostileScene::attachJoint(Joint& joint)
{
	btRigidBody* a = m_bodies[joint.bodyA].body;
	btRigidBody* b = m_bodies[joint.bodyB].body;
	// The joint frame sits midway between the two centres (at the dynamic body's centre for a static
	// partner), so the joint starts satisfied.
	const bool bStatic = m_bodies[joint.bodyB].isStatic;
	const btVector3 pivot = bStatic ? a->getWorldTransform().getOrigin()
									: (a->getWorldTransform().getOrigin() + b->getWorldTransform().getOrigin()) * btScalar(0.5);
	const btTransform frame(randomRotation(), pivot);
	const btTransform inA = a->getWorldTransform().inverse() * frame;
	const btTransform inB = b->getWorldTransform().inverse() * frame;
	delete joint.constraint;  // not in the world (or never made)
	if (joint.kind == 0)
		joint.constraint = new btPoint2PointConstraint(*a, *b, inA.getOrigin(), inB.getOrigin());
	else if (joint.kind == 1)
		joint.constraint = new btHingeConstraint(*a, *b, inA, inB);
	else
		joint.constraint = new btGeneric6DofConstraint(*a, *b, inA, inB, true);
	m_world->addConstraint(joint.constraint, random() < 0.5);
	joint.inWorld = true;
}

// ---------------------------------------------------------------------------------------------
// Construction

void HostileScene::buildStacks()
{
	// Stacks along x, centred on x = 0 at z = 0; masses log-uniform in [minMass, maxMass], so one
	// stack typically mixes grams and hundreds of tonnes.
	const double logMin = std::log(m_params.minMass), logMax = std::log(m_params.maxMass);
	for (int s = 0; s < m_params.stacks; ++s)
	{
		const double x = (s - 0.5 * (m_params.stacks - 1)) * kStackSpacing;
		const bool sunk = random() < 0.3;  // boxes start deep inside the ones below
		double top = 0;  // m, top face of the support
		for (int level = 0; level < m_params.stackHeight; ++level)
		{
			const btVector3 half(btScalar(random(0.2, 0.5)), btScalar(random(0.1, 0.3)), btScalar(random(0.2, 0.5)));
			m_shapes.emplace_back(new btBoxShape(half));
			const double overlap = sunk ? random(0, kMaxSinkFraction) * 2 * half.y() : kRestOverlap;
			const double y = top + half.y() - overlap;
			const btVector3 origin(btScalar(x + random(-0.1, 0.1)), btScalar(y), btScalar(random(-0.1, 0.1)));
			addBody(m_shapes.back().get(), std::exp(random(logMin, logMax)), btTransform(btQuaternion::getIdentity(), origin));
			top = y + half.y();
		}
	}
}

void HostileScene::buildLooseBodies()
{
	const double logMin = std::log(m_params.minMass), logMax = std::log(m_params.maxMass);
	for (int i = 0; i < m_params.looseBodies; ++i)
	{
		btVector3 origin(btScalar(random(-kRegionHalfX, kRegionHalfX)), btScalar(random(kRegionLowY, kRegionHighY)),
						 btScalar(random(-kRegionHalfZ, kRegionHalfZ)));
		if (random() < kInsideOtherChance)
		{
			// Deep overlap: centred near another non-static body's centre.
			const int other = randomIndex(int(m_bodies.size()));
			if (!m_bodies[other].isStatic)
				origin = m_bodies[other].body->getWorldTransform().getOrigin() + btVector3(btScalar(random(-0.1, 0.1)), btScalar(random(-0.1, 0.1)), btScalar(random(-0.1, 0.1)));
		}
		const int index = addBody(randomShape(1), std::exp(random(logMin, logMax)), btTransform(randomRotation(), origin));
		if (random() < m_params.zeroMassFraction)
			makeZeroMass(index);
		else if (random() < kMovingChance)
			setMoving(index);
	}
}

void HostileScene::buildKinematics()
{
	// Each kinematic box starts kKinematicLeadIn before a random stack and is driven through it
	// along a random horizontal direction at kinematicSpeed.
	for (int i = 0; i < m_params.kinematicBodies; ++i)
	{
		const int stack = randomIndex(btMax(1, m_params.stacks));
		const double x = (stack - 0.5 * (m_params.stacks - 1)) * kStackSpacing;
		const double angle = random(0, 2 * SIMD_PI);
		const btVector3 direction(btScalar(std::cos(angle)), 0, btScalar(std::sin(angle)));
		const btVector3 start = btVector3(btScalar(x), btScalar(random(0.3, 1.5)), 0) - direction * btScalar(kKinematicLeadIn);
		const btScalar h = btScalar(kKinematicHalfExtent);
		m_shapes.emplace_back(new btBoxShape(btVector3(h, h, h)));
		const int index = addBody(m_shapes.back().get(), 0, btTransform(btQuaternion::getIdentity(), start));
		makeKinematic(index);
		m_kinematicStart[index] = start;
		m_kinematicDirection[index] = direction;
	}
}

void HostileScene::buildJoints()
{
	const int n = int(m_bodies.size());
	for (int i = 0; i < m_params.joints; ++i)
	{
		const int a = randomIndex(n);
		if (m_bodies[a].isStatic || m_bodies[a].kinematic) continue;
		int b;
		if (random() < 0.3)
			b = random() < 0.5 ? 0 : 1;  // the ground or the post
		else
			b = randomIndex(n);
		if (b == a || m_bodies[b].kinematic) continue;
		addJoint(a, b);
	}
}

// ---------------------------------------------------------------------------------------------
// Between steps

void HostileScene::beforeStep(double timeStep)
{
	m_time += timeStep;
	// Kinematic bodies: placed where they are due at the end of this step; Bullet derives their
	// velocity from the move (saveKinematicState).
	for (size_t i = 0; i < m_bodies.size(); ++i)
	{
		HostileBody& b = m_bodies[i];
		if (!b.kinematic) continue;
		btTransform xf = b.body->getWorldTransform();
		xf.setOrigin(m_kinematicStart[i] + m_kinematicDirection[i] * btScalar(m_params.kinematicSpeed * m_time));
		b.body->setWorldTransform(xf);
	}
	if (random() < m_params.eventRate) eventRemoveBody();
	if (random() < m_params.eventRate) eventReaddBody();
	if (random() < m_params.eventRate) eventNewBody();
	if (random() < m_params.eventRate) eventTeleport();
	if (random() < m_params.eventRate) eventToggleJoint();
	if (random() < m_params.eventRate * 0.2) eventPoison();
}

void HostileScene::eventRemoveBody()
{
	const int index = randomIndex(int(m_bodies.size()));
	if (m_bodies[index].isStatic || m_bodies[index].kinematic) return;
	remove(index);
}

void HostileScene::eventReaddBody()
{
	// A removed body comes back where it was, with its joints whose other body is in the world
	// (re-anchored where the bodies are now).
	// Poisoned bodies stay out: adding a NaN transform would put a NaN box into the AABB tree.
	const int index = randomIndex(int(m_bodies.size()));
	HostileBody& b = m_bodies[index];
	if (b.inWorld || b.poisoned) return;
	insert(index);
	for (Joint& joint : m_joints)
	{
		if (!joint.inWorld && (joint.bodyA == index || joint.bodyB == index) && m_bodies[joint.bodyA].inWorld && m_bodies[joint.bodyB].inWorld)
			attachJoint(joint);
	}
}

void HostileScene::eventNewBody()
{
	const double logMin = std::log(m_params.minMass), logMax = std::log(m_params.maxMass);
	const btVector3 origin(btScalar(random(-kRegionHalfX, kRegionHalfX)), btScalar(random(kRegionLowY, kRegionHighY)),
						   btScalar(random(-kRegionHalfZ, kRegionHalfZ)));
	addBody(randomShape(1), std::exp(random(logMin, logMax)), btTransform(randomRotation(), origin));
}

void HostileScene::eventTeleport()
{
	// Anywhere in the region, possibly inside another body; velocity kept.
	const int index = randomIndex(int(m_bodies.size()));
	HostileBody& b = m_bodies[index];
	if (b.isStatic || b.kinematic || b.poisoned || hasJoint(index)) return;
	const btVector3 origin(btScalar(random(-kRegionHalfX, kRegionHalfX)), btScalar(random(kRegionLowY, kRegionHighY)),
						   btScalar(random(-kRegionHalfZ, kRegionHalfZ)));
	const btTransform xf(randomRotation(), origin);
	const double lift = double(origin.y()) - double(b.body->getWorldTransform().getOrigin().y());
	b.body->setWorldTransform(xf);
	b.body->setInterpolationWorldTransform(xf);
	// Heights less the lift (HostileBody::liftedBy): a teleport up keeps the height the body has
	// fallen from (and its velocity); one down adds to it, as a fall would.
	if (lift > 0) b.liftedBy += lift;
	b.highestY = btMax(b.highestY, double(origin.y()) - b.liftedBy);
}

void HostileScene::eventToggleJoint()
{
	if (m_joints.empty()) return;
	Joint& joint = m_joints[randomIndex(int(m_joints.size()))];
	if (joint.inWorld)
	{
		m_world->removeConstraint(joint.constraint);
		joint.inWorld = false;
	}
	else if (m_bodies[joint.bodyA].inWorld && m_bodies[joint.bodyB].inWorld)
	{
		attachJoint(joint);
	}
}

void HostileScene::eventPoison()
{
	if (m_params.poisonFraction <= 0) return;  // a world without poison stays without (draws nothing: other seeds unchanged)
	const int index = randomIndex(int(m_bodies.size()));
	const HostileBody& b = m_bodies[index];
	if (b.isStatic || b.kinematic || b.poisoned || !b.inWorld) return;
	poison(index);
}

// ---------------------------------------------------------------------------------------------
// Queries

int HostileScene::expectedCollisionObjects() const
{
	int n = 0;
	for (const HostileBody& b : m_bodies) n += b.inWorld ? 1 : 0;
	return n;
}

int HostileScene::expectedConstraints() const
{
	int n = 0;
	for (const Joint& joint : m_joints) n += joint.inWorld ? 1 : 0;
	return n;
}

std::vector<btRigidBody*> HostileScene::healthyBodies() const
{
	std::vector<btRigidBody*> healthy;
	for (const HostileBody& b : m_bodies)
		if (!b.isStatic && !b.poisoned) healthy.push_back(b.body);
	return healthy;
}

const HostileBody* HostileScene::find(const btRigidBody* body) const
{
	for (const HostileBody& b : m_bodies)
		if (b.body == body) return &b;
	return nullptr;
}

}  // namespace scenes
