// D30 (docs/design.md, section 11; btShockPropagationSettings::m_keepBoxFaceCorners): a box face
// resting on a box keeps the corners that lie on the other face as contact points. The first
// tests call the private routine (plugin/src/btBoxFaceCorners.h) on hand-made manifolds, whose
// expected points are geometry; the last ones run the pushed stack, whose expected motion is
// Coulomb's (one body at (F - mu W) / M, boxes within 1 cm of where the bottom box carries them).
#include "Fixture.h"

#include <BulletShockPropagation/btShockPropagationConstraintSolver.h>
#include <btBulletDynamicsCommon.h>

#include "btBoxFaceCorners.h"  // private to the plugin (plugin/src)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace
{
/// Two boxes as collision objects (no world): a 1 x 0.5 x 1 m box A whose bottom face is at
/// height `bottom` (tilted by `tiltRad` about z through its centre), on a 10 x 1 x 10 m ground box
/// B whose top face is at y = 0, and a manifold between them holding the points Bullet's box-box
/// test would report for A's corners at x = +0.5 (one edge), normal +y (from B into A).
struct BoxOnGround
{
	btBoxShape boxShape{btVector3(btScalar(0.5), btScalar(0.25), btScalar(0.5))};
	btBoxShape groundShape{btVector3(5, btScalar(0.5), 5)};
	btCollisionObject box, ground;
	std::unique_ptr<btPersistentManifold> manifold;

	explicit BoxOnGround(btScalar bottom, btScalar tiltRad = 0, btScalar boxX = 0)
	{
		box.setCollisionShape(&boxShape);
		ground.setCollisionShape(&groundShape);
		btTransform t(btQuaternion(btVector3(0, 0, 1), tiltRad), btVector3(boxX, bottom + boxShape.getHalfExtentsWithMargin().y(), 0));
		box.setWorldTransform(t);
		ground.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, btScalar(-0.5), 0)));
		box.setFriction(btScalar(0.8));
		ground.setFriction(btScalar(0.5));
		manifold.reset(new btPersistentManifold(&box, &ground, 0, btScalar(0.02), btScalar(0.02)));
		for (btScalar z : {btScalar(-0.5), btScalar(0.5)}) addCorner(btVector3(btScalar(0.5), btScalar(-0.25), z));
	}

	/// A's corner (box-local) as Bullet would report it: on B's face, at the corner's height.
	void addCorner(const btVector3& local)
	{
		const btVector3 onA = box.getWorldTransform() * local;
		const btVector3 onB(onA.x(), 0, onA.z());
		const btScalar distance = onA.y();
		btManifoldPoint p(box.getWorldTransform().invXform(onA), ground.getWorldTransform().invXform(onB), btVector3(0, 1, 0), distance);
		p.m_positionWorldOnA = onA;
		p.m_positionWorldOnB = onB;
		p.m_combinedFriction = box.getFriction() * ground.getFriction();
		p.m_combinedRestitution = btScalar(0.25);
		manifold->addManifoldPoint(p);
	}
};

/// gContactAddedCallback for the callback test: counts calls and sets a friction of its own.
int gCallbackCalls = 0;
bool customFriction(btManifoldPoint& cp, const btCollisionObjectWrapper*, int, int, const btCollisionObjectWrapper*, int, int)
{
	++gCallbackCalls;
	cp.m_combinedFriction = btScalar(0.123);
	return true;
}

/// Largest displacement of any box relative to the bottom box's displacement (m) over 2 s of the
/// pushed stack (5 boxes, ground mu 0.5, box mu 1, pushed at the bottom with 1.4 mu W), and the
/// fitted acceleration of the bottom box (m/s^2) over 0.25-2 s.
struct PushedRun
{
	double apart = 0;
	double acceleration = 0;
	long corners = 0;
};

PushedRun pushStack(const harness::SolverSpec& spec)
{
	harness::Trial trial(spec, "pushed_stack", {{"n", 5}, {"groundMu", 0.5}, {"boxMu", 1.0}});
	const std::vector<btRigidBody*>& boxes = trial.bodies();
	btRigidBody* bottom = trial.scene().named("bottom");
	double mass = 0;
	for (const btRigidBody* b : boxes) mass += 1.0 / double(b->getInvMass());
	const double force = 1.4 * 0.5 * mass * 9.81;
	std::vector<btVector3> start;
	for (const btRigidBody* b : boxes) start.push_back(b->getCenterOfMassPosition());
	const btVector3 bottomStart = bottom->getCenterOfMassPosition();
	PushedRun run;
	double v1 = 0, t1 = 0;
	for (int k = 0; k < 120; ++k)
	{
		bottom->applyCentralForce(btVector3(btScalar(force), 0, 0));
		trial.step();
		if (btShockPropagationConstraintSolver* solver = trial.simulation().shockSolver())
			run.corners += solver->getStatistics().m_numBoxFaceCorners;
		const btVector3 moved = bottom->getCenterOfMassPosition() - bottomStart;
		for (size_t i = 0; i < boxes.size(); ++i)
			run.apart = std::max(run.apart, double((boxes[i]->getCenterOfMassPosition() - start[i] - moved).length()));
		if (k == 14)
		{
			v1 = bottom->getLinearVelocity().x();
			t1 = trial.simulation().time();
		}
	}
	run.acceleration = (bottom->getLinearVelocity().x() - v1) / (trial.simulation().time() - t1);
	return run;
}
}  // namespace

TEST(BoxFaceCorners, AFaceMissingAnEdgeGetsItsOtherCornersAtTheirDistances)
{
	for (const btScalar bottom : {btScalar(-2e-5), btScalar(0), btScalar(1e-5)})  // 20 um deep, touching, 10 um out
	{
		BoxOnGround pair(bottom);
		ASSERT_EQ(pair.manifold->getNumContacts(), 2);
		EXPECT_EQ(btKeepBoxFaceCorners(*pair.manifold, btScalar(2.7e-5)), 2);
		ASSERT_EQ(pair.manifold->getNumContacts(), 4);
		int trailing = 0;
		for (int j = 2; j < 4; ++j)
		{
			const btManifoldPoint& p = pair.manifold->getContactPoint(j);
			// The corners at x = -0.5 (A's margin is inside its half extents: corners are the box's).
			EXPECT_NEAR(p.getPositionWorldOnA().x(), -0.5, 1e-6);
			EXPECT_NEAR(std::fabs(p.getPositionWorldOnA().z()), 0.5, 1e-6);
			EXPECT_NEAR(p.getDistance(), bottom, 1e-7);
			EXPECT_NEAR((p.getPositionWorldOnA() - p.getPositionWorldOnB() - p.m_normalWorldOnB * p.getDistance()).length(), 0, 1e-7);
			EXPECT_NEAR(p.m_normalWorldOnB.y(), 1, 1e-7);
			EXPECT_FLOAT_EQ(p.m_combinedFriction, btScalar(0.4));  // the pair's, from the reported points
			EXPECT_FLOAT_EQ(p.m_combinedRestitution, btScalar(0.25));
			EXPECT_EQ(p.getAppliedImpulse(), 0);
			EXPECT_EQ(p.getLifeTime(), 0);
			trailing += p.getPositionWorldOnA().x() < 0;
		}
		EXPECT_EQ(trailing, 2);
		// A full manifold is left alone.
		EXPECT_EQ(btKeepBoxFaceCorners(*pair.manifold, btScalar(2.7e-5)), 0);
	}
}

TEST(BoxFaceCorners, ACornerLiftedPastTheReachOrOffTheFaceBelowIsNotAdded)
{
	// Tilted by 1 mrad about z through its centre: the corners at x = +0.5 sink 0.5 mm, those at
	// x = -0.5 lift 0.5 mm off the ground.
	BoxOnGround tilted(0, btScalar(-1e-3));
	EXPECT_EQ(btKeepBoxFaceCorners(*tilted.manifold, btScalar(2.7e-5)), 0);
	// With a reach of 1 mm they are on the face (speculative points at their distance).
	EXPECT_EQ(btKeepBoxFaceCorners(*tilted.manifold, btScalar(1e-3)), 2);
	EXPECT_NEAR(tilted.manifold->getContactPoint(2).getDistance(), 5e-4, 1e-5);
	// A box whose trailing edge hangs past the ground's edge (ground ends at x = 5): only the
	// corners over the face below are contacts.
	BoxOnGround overhang(0, 0, btScalar(-5.2));
	overhang.manifold->clearManifold();
	overhang.addCorner(btVector3(btScalar(0.5), btScalar(-0.25), btScalar(0.5)));
	EXPECT_EQ(btKeepBoxFaceCorners(*overhang.manifold, btScalar(2.7e-5)), 1);  // (+0.5, -0.5) only; x = -5.7 is off the ground
	EXPECT_NEAR(overhang.manifold->getContactPoint(1).getPositionWorldOnA().x(), -4.7, 1e-5);
	// Not two boxes: nothing.
	btSphereShape sphere(btScalar(0.5));
	BoxOnGround notBoxes(0);
	notBoxes.box.setCollisionShape(&sphere);
	EXPECT_EQ(btKeepBoxFaceCorners(*notBoxes.manifold, btScalar(2.7e-5)), 0);
}

TEST(BoxFaceCorners, AnAppsContactAddedCallbackSeesTheAddedCorners)
{
	// Drop-in: a body that asks for custom material callbacks gets them for these points too, and
	// what the callback sets is what the point keeps.
	BoxOnGround pair(0);
	pair.box.setCollisionFlags(pair.box.getCollisionFlags() | btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
	ContactAddedCallback previous = gContactAddedCallback;
	gContactAddedCallback = customFriction;
	gCallbackCalls = 0;
	const int added = btKeepBoxFaceCorners(*pair.manifold, btScalar(2.7e-5));
	gContactAddedCallback = previous;
	EXPECT_EQ(added, 2);
	EXPECT_EQ(gCallbackCalls, 2);
	EXPECT_FLOAT_EQ(pair.manifold->getContactPoint(2).m_combinedFriction, btScalar(0.123));
	EXPECT_FLOAT_EQ(pair.manifold->getContactPoint(3).m_combinedFriction, btScalar(0.123));
}

TEST(BoxFaceCorners, APushedStackSlidesAsOneOnlyWithTheCorners)
{
	// Coulomb: 5 boxes (ground mu 0.5, box mu 1) pushed at the bottom with 1.4 mu W slide as one at
	// (F - mu W) / M = 0.4 mu g; box-box friction holds them (they need 0.2 g of it, against g).
	const double expected = 0.4 * 0.5 * 9.81;
	for (const harness::SolverSpec& spec : {spec::shock(), spec::shockSolverOnly()})
	{
		const PushedRun on = pushStack(spec);
		EXPECT_LT(on.apart, 0.01) << spec.label();
		EXPECT_NEAR(on.acceleration, expected, 0.1 * expected) << spec.label();
		EXPECT_GT(on.corners, 0) << spec.label();  // from about 0.45 s, when the base slides 1.5 cm a step
	}
	// Without D30: Bullet's points alone, and the stack pivots apart on its missing edges (13 cm
	// and more at 10 iterations, docs/design.md, section 11). Measured in the solver-only mode: the
	// world's second phase (D4, issue 38) detects the missing edge again at t + dt and corrects it,
	// which keeps the world's stack within 1.6 cm even without D30.
	harness::SolverSpec off = spec::shockSolverOnly();
	off.settings.m_keepBoxFaceCorners = false;
	const PushedRun without = pushStack(off);
	EXPECT_GT(without.apart, 0.05);
	EXPECT_EQ(without.corners, 0);
}

TEST(BoxFaceCorners, RestingStacksAddNone)
{
	// A resting face's points persist (Bullet's manifold keeps them while they stay within its
	// breaking threshold), so standing stacks get no point from D30 and stand as before.
	for (const auto& scene : std::vector<std::pair<const char*, std::vector<std::pair<std::string, double>>>>{
			 {"tower", {{"n", 20}}}, {"wall", {}}, {"pyramid", {{"base", 10}}}})
	{
		harness::Trial trial(spec::shock(), scene.first, scene.second);
		const long corners = spec::sumOverSteps(trial, 120, &btShockPropagationStatistics::m_numBoxFaceCorners);
		EXPECT_EQ(corners, 0) << scene.first;
		EXPECT_LT(trial.summary().maxDrift, 0.01) << scene.first;
	}
}
