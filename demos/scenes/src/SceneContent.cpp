// Parameters, SceneContent (ownership of everything a scene adds) and the private build helpers.

#include "SceneBuild.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scenes
{
namespace
{
std::string listNames(const Params& params)
{
	std::string names;
	for (const Param& param : params)
	{
		if (!names.empty())
			names += ", ";
		names += param.name;
	}
	return names.empty() ? std::string("(none)") : names;
}

/// Removes every broadphase pair that involves one of `bodies`, in one pass over the pair cache.
/// removeRigidBody() scans the whole cache for each body it removes (O(bodies x pairs): most of a
/// second for a 10,000-box pyramid); after this pass those scans find nothing to do.
void removePairsOf(btDiscreteDynamicsWorld& world, const std::vector<btRigidBody*>& bodies)
{
	std::unordered_set<const btBroadphaseProxy*> proxies;
	for (const btRigidBody* body : bodies)
	{
		if (body->getBroadphaseHandle())
			proxies.insert(body->getBroadphaseHandle());
	}
	btOverlappingPairCache* cache = world.getBroadphase()->getOverlappingPairCache();
	btDispatcher* dispatcher = world.getDispatcher();
	// Backwards: removal moves the last pair into the freed slot, and that one was already visited.
	for (int i = cache->getNumOverlappingPairs() - 1; i >= 0; --i)
	{
		if (i >= cache->getNumOverlappingPairs())
			continue;
		const btBroadphasePair& pair = cache->getOverlappingPairArrayPtr()[i];
		if (proxies.count(pair.m_pProxy0) || proxies.count(pair.m_pProxy1))
			cache->removeOverlappingPair(pair.m_pProxy0, pair.m_pProxy1, dispatcher);
	}
}

}  // namespace

double getParam(const Params& params, const std::string& name)
{
	for (const Param& param : params)
	{
		if (param.name == name)
			return param.value;
	}
	throw std::invalid_argument("unknown scene parameter '" + name + "'; valid parameters: " + listNames(params));
}

Params withOverrides(const Params& defaults, const std::vector<std::pair<std::string, double>>& overrides)
{
	Params result = defaults;
	for (const std::pair<std::string, double>& entry : overrides)
	{
		const std::string& name = entry.first;
		const double value = entry.second;
		auto it = std::find_if(result.begin(), result.end(), [&name](const Param& param) { return param.name == name; });
		if (it == result.end())
			throw std::invalid_argument("unknown scene parameter '" + name + "'; valid parameters: " + listNames(defaults));
		if (!std::isfinite(value))
			throw std::invalid_argument("scene parameter '" + name + "' must be a finite number");
		it->value = value;
	}
	return result;
}

// ---------------------------------------------------------------------------------------------------
// SceneContent

SceneContent::SceneContent(btDiscreteDynamicsWorld& world)
	: m_world(&world)
{
}

SceneContent::~SceneContent()
{
	// Constraints first: they reference the bodies.
	for (auto it = m_constraints.rbegin(); it != m_constraints.rend(); ++it)
	{
		m_world->removeConstraint(*it);
		delete *it;
	}
	removePairsOf(*m_world, m_bodies);
	for (auto it = m_bodies.rbegin(); it != m_bodies.rend(); ++it)
	{
		btRigidBody* body = *it;
		m_world->removeRigidBody(body);
		delete body->getMotionState();
		delete body;
	}
	for (btCollisionShape* shape : m_shapes)
		delete shape;
}

btDiscreteDynamicsWorld& SceneContent::world() { return *m_world; }

btCollisionShape* SceneContent::addShape(btCollisionShape* shape)
{
	if (shape && m_ownedShapes.insert(shape).second)
		m_shapes.push_back(shape);
	return shape;
}

btRigidBody* SceneContent::addBody(btCollisionShape* shape, btScalar mass, const btTransform& xf, btScalar friction, btScalar restitution)
{
	if (!shape)
		throw std::invalid_argument("SceneContent::addBody: shape is null");
	if (!(mass >= 0) || !(friction >= 0) || !(restitution >= 0))
		throw std::invalid_argument("SceneContent::addBody: mass, friction and restitution must be >= 0");
	addShape(shape);

	btVector3 localInertia(0, 0, 0);
	if (mass > 0)
		shape->calculateLocalInertia(mass, localInertia);
	btRigidBody::btRigidBodyConstructionInfo info(mass, new btDefaultMotionState(xf), shape, localInertia);
	// Bullet combines a pair's friction as the product of the two coefficients: sqrt on each body makes
	// any two bodies of the scene combine to `friction`.
	info.m_friction = btSqrt(friction);
	info.m_restitution = restitution;

	btRigidBody* body = new btRigidBody(info);
	if (mass > 0)
		body->setActivationState(DISABLE_DEACTIVATION);  // sleeping would hide a collapse
	m_bodies.push_back(body);  // owned before it is added: a world that refuses it throws
	m_world->addRigidBody(body);
	return body;
}

btTypedConstraint* SceneContent::addConstraint(btTypedConstraint* c, bool disableCollisionsBetweenLinkedBodies)
{
	if (!c)
		throw std::invalid_argument("SceneContent::addConstraint: constraint is null");
	m_world->addConstraint(c, disableCollisionsBetweenLinkedBodies);
	m_constraints.push_back(c);
	return c;
}

void SceneContent::name(const std::string& key, btRigidBody* body) { m_names[key] = body; }

btRigidBody* SceneContent::named(const std::string& key) const
{
	auto it = m_names.find(key);
	return it == m_names.end() ? nullptr : it->second;
}

const std::vector<btRigidBody*>& SceneContent::bodies() const { return m_bodies; }

std::vector<btRigidBody*> SceneContent::dynamicBodies() const
{
	std::vector<btRigidBody*> result;
	result.reserve(m_bodies.size());
	for (btRigidBody* body : m_bodies)
	{
		if (body->getInvMass() > 0)
			result.push_back(body);
	}
	return result;
}

const std::vector<btTypedConstraint*>& SceneContent::constraints() const { return m_constraints; }

btRigidBody* SceneContent::ground() const { return named("ground"); }

// ---------------------------------------------------------------------------------------------------
// Build helpers

namespace build
{
btRigidBody* addGround(SceneContent& content, btScalar footprintHalfWidth, btScalar mu)
{
	const btScalar halfWidth = btMax(btScalar(kMinGroundHalfWidth), footprintHalfWidth);
	const btScalar halfThickness = btScalar(kGroundHalfThickness);
	btCollisionShape* shape = content.addShape(new btBoxShape(btVector3(halfWidth, halfThickness, halfWidth)));
	btRigidBody* ground = content.addBody(shape, 0, at(0, -halfThickness, 0), mu);
	content.name("ground", ground);
	return ground;
}

btTransform at(btScalar x, btScalar y, btScalar z)
{
	return btTransform(btQuaternion::getIdentity(), btVector3(x, y, z));
}

btTransform rotatedAt(const btVector3& axis, btScalar angleRad, const btVector3& origin)
{
	return btTransform(btQuaternion(axis, angleRad), origin);
}

btScalar columnCentreY(btScalar baseY, btScalar halfHeight, int level, btScalar overlap)
{
	// Each body sinks `overlap` into its support: the first into the base, the others into the body below.
	return baseY + btScalar(level) * (2 * halfHeight - overlap) + halfHeight - overlap;
}

int countParam(const Params& params, const std::string& name, int minimum)
{
	const double value = getParam(params, name);
	const double rounded = std::round(value);
	if (std::fabs(value - rounded) > 1e-9 || rounded < minimum || rounded > kMaxCount)
	{
		throw std::invalid_argument("scene parameter '" + name + "' must be a whole number in [" +
									std::to_string(minimum) + ", " + std::to_string(kMaxCount) + "], got " + std::to_string(value));
	}
	return static_cast<int>(rounded);
}

btScalar positiveParam(const Params& params, const std::string& name)
{
	const double value = getParam(params, name);
	if (!(value > 0))
		throw std::invalid_argument("scene parameter '" + name + "' must be > 0, got " + std::to_string(value));
	return btScalar(value);
}

btScalar nonNegativeParam(const Params& params, const std::string& name)
{
	const double value = getParam(params, name);
	if (!(value >= 0))
		throw std::invalid_argument("scene parameter '" + name + "' must be >= 0, got " + std::to_string(value));
	return btScalar(value);
}

std::uint32_t seedParam(const Params& params)
{
	const double seed = getParam(params, "seed");
	require(seed >= 0 && seed < 4294967296.0 && seed == std::floor(seed), "seed must be a whole number in [0, 2^32)");
	return static_cast<std::uint32_t>(seed);
}

void addSquarePit(SceneContent& content, btScalar width, btScalar halfHeight, btScalar mu)
{
	const btScalar halfThickness = btScalar(0.1);           // m
	const btScalar halfLength = width / 2 + 2 * halfThickness;  // closes the corners
	const btScalar centre = width / 2 + halfThickness;
	btCollisionShape* wallX = content.addShape(new btBoxShape(btVector3(halfThickness, halfHeight, halfLength)));
	btCollisionShape* wallZ = content.addShape(new btBoxShape(btVector3(halfLength, halfHeight, halfThickness)));
	content.addBody(wallX, 0, at(-centre, halfHeight, 0), mu);
	content.addBody(wallX, 0, at(centre, halfHeight, 0), mu);
	content.addBody(wallZ, 0, at(0, halfHeight, -centre), mu);
	content.addBody(wallZ, 0, at(0, halfHeight, centre), mu);
}

void require(bool ok, const std::string& what)
{
	if (!ok)
		throw std::invalid_argument(what);
}

void finishScene(SceneContent& content, bool expectStanding)
{
	content.facts["expectStanding"] = expectStanding ? 1 : 0;
	content.facts["bodies"] = double(content.dynamicBodies().size());
}

}  // namespace build
}  // namespace scenes
