// Bad input: documented safe behaviour, never a crash or NaN spreading into healthy bodies.
#include "Fixture.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace
{
struct BareWorld
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher{&configuration};
	btDbvtBroadphase broadphase;
	std::unique_ptr<btShockPropagationDynamicsWorld> world;
	BareWorld() : world(new btShockPropagationDynamicsWorld(&dispatcher, &broadphase, nullptr, &configuration))
	{
		world->setGravity(btVector3(0, btScalar(-9.81), 0));
	}
	void steps(int n)
	{
		for (int i = 0; i < n; ++i) world->stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
	}
};
}  // namespace

TEST(BadInput, NaNVelocityOnOneBodyDoesNotSpreadIntoTheStack)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 5}});
	run.run(0.5);
	btRigidBody* top = run.named("top");
	top->setLinearVelocity(btVector3(std::numeric_limits<btScalar>::quiet_NaN(), 0, 0));
	std::vector<btRigidBody*> healthy;
	for (btRigidBody* b : run.bodies())
		if (b != top) healthy.push_back(b);
	harness::DriftTracker drift(healthy);
	run.run(2.0);
	EXPECT_FALSE(harness::anyNonFinite(healthy));
	EXPECT_LT(drift.maxDrift(), harness::kStandingDriftMeters);
}

TEST(BadInput, InfiniteTransformOnOneBodyDoesNotSpread)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 5}});
	run.run(0.5);
	btRigidBody* top = run.named("top");
	btTransform t = top->getWorldTransform();
	t.getOrigin().setY(std::numeric_limits<btScalar>::infinity());
	top->setWorldTransform(t);
	std::vector<btRigidBody*> healthy;
	for (btRigidBody* b : run.bodies())
		if (b != top) healthy.push_back(b);
	run.run(2.0);
	EXPECT_FALSE(harness::anyNonFinite(healthy));
}

TEST(BadInput, ZeroMassBodyMarkedDynamicActsAsStaticSupport)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 3}});
	btRigidBody* bottom = run.named("bottom");
	run.simulation().world().removeRigidBody(bottom);
	bottom->setMassProps(0, btVector3(0, 0, 0));
	bottom->setCollisionFlags(bottom->getCollisionFlags() & ~btCollisionObject::CF_STATIC_OBJECT);
	run.simulation().world().addRigidBody(bottom);
	run.run(2.0);
	EXPECT_FALSE(harness::anyNonFinite(run.bodies()));
	EXPECT_LT(run.drift().drift(run.named("top")), harness::kStandingDriftMeters);
}

TEST(BadInput, BodyRemovedBetweenStepsLetsTheBoxesAboveFall)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 5}});
	run.run(0.5);
	btRigidBody* middle = run.bodies()[2];
	run.simulation().world().removeRigidBody(middle);
	run.run(2.0);
	EXPECT_FALSE(harness::anyNonFinite(run.bodies()));
	EXPECT_GT(run.drift().drift(run.named("top")), 0.4);  // fell by about one box height (0.5 m)
	EXPECT_LT(run.drift().drift(run.named("bottom")), harness::kStandingDriftMeters);
	run.simulation().world().addRigidBody(middle);  // back, so the scene removes it as usual
}

TEST(BadInput, EmptyWorldSteps)
{
	BareWorld w;
	w.steps(10);
	EXPECT_EQ(w.world->getShockPropagationSolver()->getStatistics().m_numLayers, 0);
}

TEST(BadInput, ManifoldWithZeroPointsIsHarmless)
{
	btBoxShape shape(btVector3(0.5, 0.5, 0.5));
	btRigidBody a(1, nullptr, &shape, btVector3(1, 1, 1));
	btRigidBody b(1, nullptr, &shape, btVector3(1, 1, 1));
	b.getWorldTransform().setOrigin(btVector3(0, 1, 0));
	btPersistentManifold manifold(&a, &b, 0, btScalar(0.02), btScalar(0.02));
	btCollisionObject* bodies[] = {&a, &b};
	btPersistentManifold* manifolds[] = {&manifold};
	btContactSolverInfo info;
	info.m_timeStep = btScalar(1.0 / 60.0);
	btShockPropagationConstraintSolver solver;
	solver.solveGroup(bodies, 2, manifolds, 1, nullptr, 0, info, nullptr, nullptr);
	EXPECT_TRUE(a.getLinearVelocity().isZero());
	EXPECT_TRUE(b.getLinearVelocity().isZero());
}

TEST(BadInput, ConstraintBetweenTwoStaticBodiesIsHarmless)
{
	BareWorld w;
	btBoxShape shape(btVector3(0.5, 0.5, 0.5));
	btRigidBody s1(0, nullptr, &shape);
	btRigidBody s2(0, nullptr, &shape);
	s2.getWorldTransform().setOrigin(btVector3(3, 0, 0));
	btPoint2PointConstraint joint(s1, s2, btVector3(1, 0, 0), btVector3(-1, 0, 0));
	btRigidBody box(1, nullptr, &shape, btVector3(btScalar(1) / 6, btScalar(1) / 6, btScalar(1) / 6));
	box.getWorldTransform().setOrigin(btVector3(0, btScalar(0.99999), 0));
	box.setActivationState(DISABLE_DEACTIVATION);
	w.world->addRigidBody(&s1);
	w.world->addRigidBody(&s2);
	w.world->addRigidBody(&box);
	w.world->addConstraint(&joint);
	w.steps(60);
	EXPECT_TRUE(std::isfinite(box.getCenterOfMassPosition().y()));
	EXPECT_NEAR(box.getCenterOfMassPosition().y(), 1.0, 0.01);
	w.world->removeConstraint(&joint);
	w.world->removeRigidBody(&box);
	w.world->removeRigidBody(&s2);
	w.world->removeRigidBody(&s1);
}

TEST(World, RejectsASolverOfAnotherTypeAtConstruction)
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btDbvtBroadphase broadphase;
	btSequentialImpulseConstraintSolver stock;
	EXPECT_THROW(btShockPropagationDynamicsWorld(&dispatcher, &broadphase, &stock, &configuration), std::invalid_argument);
}

TEST(World, CreatesAndOwnsItsSolverWhenGivenNull)
{
	BareWorld w;
	ASSERT_NE(w.world->getShockPropagationSolver(), nullptr);
	EXPECT_EQ(w.world->getConstraintSolver(), w.world->getShockPropagationSolver());
	btSequentialImpulseConstraintSolver stock;
	EXPECT_THROW(w.world->setConstraintSolver(&stock), std::invalid_argument);
	EXPECT_EQ(w.world->getConstraintSolver(), w.world->getShockPropagationSolver());
}

TEST(Settings, WeightingIsClampedAndNaNIgnored)
{
	btShockPropagationConstraintSolver solver;
	EXPECT_EQ(solver.getWeighting(), btShockPropagationSettings().m_weighting);
	solver.setWeighting(2);
	EXPECT_EQ(solver.getWeighting(), btScalar(1));
	solver.setWeighting(-1);
	EXPECT_EQ(solver.getWeighting(), btScalar(0));
	solver.setWeighting(btScalar(0.25));
	solver.setWeighting(std::numeric_limits<btScalar>::quiet_NaN());
	EXPECT_EQ(solver.getWeighting(), btScalar(0.25));
}
