// Lifecycle: what applications do to a world around and between steps, in the world mode
// (btShockPropagationDynamicsWorld) and the solver-only mode (stock world, plugin solver), each
// with a physical outcome: removed supports let boxes fall, kept ones hold, nothing turns NaN.
// Destruction-order specs are checked for memory errors by the sanitizer build (tests/run.sh).

#include "../behavior/Fixture.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{
using harness::kStandingDriftMeters;
using spec::kTimeStepSeconds;
using spec::plugin;
constexpr double kBoxHeightMeters = 0.5;  // the registry's standard box (1 x 0.5 x 1 m)

/// What the tick callbacks below do, reached through the world's user info.
struct TickAction
{
	int stepsLeft = 0;                      // acts when this reaches 0
	btRigidBody* bodyToRemove = nullptr;
	btTypedConstraint* constraintToRemove = nullptr;
	bool done = false;
};

void actOnTick(btDynamicsWorld* world, btScalar /*timeStep*/)
{
	TickAction* action = static_cast<TickAction*>(world->getWorldUserInfo());
	if (action->done || action->stepsLeft-- > 0) return;
	if (action->constraintToRemove) world->removeConstraint(action->constraintToRemove);
	if (action->bodyToRemove) world->removeRigidBody(action->bodyToRemove);
	action->done = true;
}

class Lifecycle : public ::testing::TestWithParam<harness::SolverKind>
{
};

std::string kindName(const ::testing::TestParamInfo<harness::SolverKind>& info)
{
	return info.param == harness::SolverKind::ShockWorld ? "ShockWorld" : "SolverOnly";
}

void removeMiddleBoxFromTickCallback(harness::SolverKind kind, bool preTick)
{
	harness::Trial run(plugin(kind), "tower", {{"n", 5}});
	TickAction action;
	action.stepsLeft = 30;  // 0.5 s of standing first
	action.bodyToRemove = run.bodies()[2];
	run.simulation().world().setInternalTickCallback(actOnTick, &action, preTick);
	run.run(2.5);
	ASSERT_TRUE(action.done);
	EXPECT_EQ(run.simulation().world().getNumCollisionObjects(), int(run.scene().bodies().size()) - 1);
	EXPECT_FALSE(harness::anyNonFinite(run.bodies()));
	// The two boxes above the gap fall by about one box height; the two below do not move.
	EXPECT_GT(run.drift().drift(run.bodies()[3]), 0.8 * kBoxHeightMeters);
	EXPECT_GT(run.drift().drift(run.bodies()[4]), 0.8 * kBoxHeightMeters);
	EXPECT_LT(run.drift().drift(run.bodies()[0]), kStandingDriftMeters);
	EXPECT_LT(run.drift().drift(run.bodies()[1]), kStandingDriftMeters);
	run.simulation().world().setInternalTickCallback(nullptr);
	run.simulation().world().addRigidBody(action.bodyToRemove);  // back, so the scene removes it as usual
}
}  // namespace

TEST_P(Lifecycle, BodyRemovedInPreTickCallbackLetsTheBoxesAboveFall) { removeMiddleBoxFromTickCallback(GetParam(), true); }

TEST_P(Lifecycle, BodyRemovedInPostTickCallbackLetsTheBoxesAboveFall) { removeMiddleBoxFromTickCallback(GetParam(), false); }

TEST_P(Lifecycle, JointRemovedInTickCallbacksDropsTheBoxItHeld)
{
	for (bool preTick : {true, false})
	{
		harness::Trial run(plugin(GetParam()), "single_box", {});
		btRigidBody* ground = run.scene().ground();
		// A second box hung 3 m up from the static ground by a point-to-point joint 0.5 m above it.
		btCollisionShape* shape = run.scene().addShape(new btBoxShape(btVector3(btScalar(0.25), btScalar(0.25), btScalar(0.25))));
		btRigidBody* hung = run.scene().addBody(shape, 1, btTransform(btQuaternion::getIdentity(), btVector3(5, 3, 0)), 0.6f);
		btTypedConstraint* joint = run.scene().addConstraint(
			new btPoint2PointConstraint(*hung, *ground, btVector3(0, btScalar(0.5), 0), btVector3(5, btScalar(3.5) + btScalar(0.5), 0)));
		TickAction action;
		action.stepsLeft = 60;
		action.constraintToRemove = joint;
		run.simulation().world().setInternalTickCallback(actOnTick, &action, preTick);
		run.run(0.9);
		EXPECT_NEAR(hung->getCenterOfMassPosition().y(), 3.0, 0.05) << "the joint holds until it is removed";
		run.run(1.6);
		ASSERT_TRUE(action.done);
		EXPECT_EQ(run.simulation().world().getNumConstraints(), 0);
		// Fell 3 m onto the ground: rests with its centre at its half height, 0.25 m.
		EXPECT_NEAR(hung->getCenterOfMassPosition().y(), 0.25, 0.02);
		EXPECT_FALSE(harness::anyNonFinite({hung}));
		run.simulation().world().setInternalTickCallback(nullptr);
		run.simulation().world().addConstraint(joint);  // back, so the scene removes it as usual
	}
}

TEST_P(Lifecycle, SwitchingSolversEverySecondKeepsTheTowerStanding)
{
	// Two plugin solvers with different weightings take turns; warm-start caches carry over.
	harness::Trial run(plugin(GetParam()), "tower", {{"n", 10}});
	btShockPropagationConstraintSolver first, second;
	first.setWeighting(btScalar(0.1));
	second.setWeighting(btScalar(0.25));
	for (int second_ = 0; second_ < 10; ++second_)
	{
		run.simulation().world().setConstraintSolver(second_ % 2 ? &second : &first);
		run.run(1.0);
	}
	EXPECT_LT(run.drift().maxDrift(), kStandingDriftMeters);
	EXPECT_FALSE(harness::anyNonFinite(run.bodies()));
	run.simulation().world().setConstraintSolver(run.simulation().shockSolver());  // the harness deletes its own solver
}

TEST_P(Lifecycle, ChangingTheWeightingEveryStepKeepsTheTowerStanding)
{
	harness::Trial run(plugin(GetParam()), "tower", {{"n", 10}});
	const btScalar weightings[] = {btScalar(0.1), btScalar(0), btScalar(0.25), btScalar(0.5)};
	for (int step = 0; step < 600; ++step)
	{
		run.simulation().shockSolver()->setWeighting(weightings[step % 4]);
		run.simulation().step();
	}
	EXPECT_LT(run.drift().maxDrift(), kStandingDriftMeters);
	EXPECT_FALSE(harness::anyNonFinite(run.bodies()));
}

TEST_P(Lifecycle, WorldWithOnlyStaticBodiesLeavesThemExactlyInPlace)
{
	harness::Simulation sim(plugin(GetParam()), kTimeStepSeconds);
	btBoxShape shape(btVector3(1, 1, 1));
	std::vector<std::unique_ptr<btRigidBody>> statics;
	for (int i = 0; i < 3; ++i)
	{
		statics.emplace_back(new btRigidBody(0, nullptr, &shape));
		// Overlapping each other: static pairs must still be ignored.
		statics.back()->getWorldTransform().setOrigin(btVector3(btScalar(1.5 * i), 0, 0));
		sim.world().addRigidBody(statics.back().get());
	}
	for (int i = 0; i < 60; ++i) sim.step();
	for (int i = 0; i < 3; ++i)
	{
		EXPECT_EQ(statics[i]->getWorldTransform().getOrigin(), btVector3(btScalar(1.5 * i), 0, 0));
		EXPECT_TRUE(statics[i]->getLinearVelocity().isZero());
	}
	EXPECT_EQ(sim.shockSolver()->getStatistics().m_numLayers, 0);
	for (auto& body : statics) sim.world().removeRigidBody(body.get());
}

TEST_P(Lifecycle, BodyWithDisableSimulationStaysPutWhileTheTowerBesideItStands)
{
	harness::Trial run(plugin(GetParam()), "tower", {{"n", 5}});
	btCollisionShape* shape = run.scene().addShape(new btBoxShape(btVector3(btScalar(0.25), btScalar(0.25), btScalar(0.25))));
	const btVector3 where(4, 3, 0);  // in mid-air: would fall 2.75 m if simulated
	btRigidBody* frozen = run.scene().addBody(shape, 1, btTransform(btQuaternion::getIdentity(), where), 0.6f);
	frozen->forceActivationState(DISABLE_SIMULATION);
	run.run(2.0);
	EXPECT_EQ(frozen->getWorldTransform().getOrigin(), where);
	EXPECT_LT(run.drift().maxDrift(), kStandingDriftMeters);
	EXPECT_FALSE(harness::anyNonFinite(run.bodies()));
}

INSTANTIATE_TEST_SUITE_P(Robustness, Lifecycle, ::testing::Values(harness::SolverKind::ShockWorld, harness::SolverKind::ShockSolverOnly),
						 kindName);

// Destruction order, when the world was given a solver it does not own. The world must not touch
// the solver in its destructor, so either order is valid (ASan reports any use after free).

namespace
{
struct Rig
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher{&configuration};
	btDbvtBroadphase broadphase;
};

/// A 3-box tower in `world`, stepped 1 s; returns the largest drift. The scene is removed again.
double standTowerOfThree(btDiscreteDynamicsWorld& world)
{
	world.setGravity(btVector3(0, btScalar(-9.81), 0));
	std::unique_ptr<scenes::SceneContent> scene = scenes::createScene(world, "tower", {{"n", 3}});
	harness::DriftTracker drift(scene->dynamicBodies());
	for (int i = 0; i < 60; ++i) world.stepSimulation(btScalar(kTimeStepSeconds), 1, btScalar(kTimeStepSeconds));
	return drift.maxDrift();
}
}  // namespace

TEST(LifecycleDestruction, ShockWorldDestroyedBeforeItsSolver)
{
	Rig rig;
	std::unique_ptr<btShockPropagationConstraintSolver> solver(new btShockPropagationConstraintSolver);
	std::unique_ptr<btShockPropagationDynamicsWorld> world(
		new btShockPropagationDynamicsWorld(&rig.dispatcher, &rig.broadphase, solver.get(), &rig.configuration));
	EXPECT_LT(standTowerOfThree(*world), kStandingDriftMeters);
	world.reset();
	EXPECT_EQ(solver->getSettings().m_weighting, btShockPropagationSettings().m_weighting);  // still alive and intact
}

TEST(LifecycleDestruction, SolverDestroyedBeforeTheShockWorld)
{
	Rig rig;
	std::unique_ptr<btShockPropagationConstraintSolver> solver(new btShockPropagationConstraintSolver);
	std::unique_ptr<btShockPropagationDynamicsWorld> world(
		new btShockPropagationDynamicsWorld(&rig.dispatcher, &rig.broadphase, solver.get(), &rig.configuration));
	EXPECT_LT(standTowerOfThree(*world), kStandingDriftMeters);
	solver.reset();
	world.reset();  // must not touch the deleted solver
}

TEST(LifecycleDestruction, SolverDestroyedBeforeTheStockWorldItWasGivenTo)
{
	Rig rig;
	std::unique_ptr<btShockPropagationConstraintSolver> solver(new btShockPropagationConstraintSolver);
	std::unique_ptr<btDiscreteDynamicsWorld> world(new btDiscreteDynamicsWorld(&rig.dispatcher, &rig.broadphase, solver.get(), &rig.configuration));
	EXPECT_LT(standTowerOfThree(*world), kStandingDriftMeters);
	solver.reset();
	world.reset();
}

TEST(LifecycleDestruction, WorldThatOwnsItsSolverFreesItWhenGivenAnother)
{
	// Created with nullptr, the world owns its solver; replacing it must destroy the old one
	// completely (its buffers too: LeakSanitizer checks), and the new one must carry on.
	Rig rig;
	btShockPropagationConstraintSolver replacement;
	{
		btShockPropagationDynamicsWorld world(&rig.dispatcher, &rig.broadphase, nullptr, &rig.configuration);
		EXPECT_LT(standTowerOfThree(world), kStandingDriftMeters);  // the owned solver has grown its buffers
		world.setConstraintSolver(&replacement);
		EXPECT_EQ(world.getShockPropagationSolver(), &replacement);
		EXPECT_LT(standTowerOfThree(world), kStandingDriftMeters);
	}
	EXPECT_EQ(replacement.getSettings().m_weighting, btShockPropagationSettings().m_weighting);  // not deleted by the world
}
