// Stacking specs on real Bullet worlds: where stock SI fails and shock propagation holds.
#include "Fixture.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <ostream>
#include <string>


TEST(Stacking, VerticalStackOf20DriftsLessThan1cmIn10s)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 20}});
	run.run(10.0);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
	EXPECT_FALSE(harness::anyNonFinite(run.bodies()));
}

TEST(Stacking, VerticalStackOf40DriftsLessThan1cmIn10s)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 40}});
	run.run(10.0);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

TEST(Stacking, StockSequentialImpulseAt10IterationsLetsStackOf20Fall)
{
	// The other side of the first spec: the same scene and iteration count with stock Bullet.
	harness::Trial run(spec::stock(10), "tower", {{"n", 20}});
	run.run(10.0);
	EXPECT_GT(run.drift().drift(run.named("top")), 0.5) << "stock SI was expected to lose the tower";
}

TEST(Stacking, SolverOnlyDropInKeepsStackOf20Up)
{
	// The one-line swap into a stock btDiscreteDynamicsWorld, default settings (README, "Swap it
	// into an existing Bullet app"; measured in docs/history.md, section 10, "Solver-only mode").
	harness::Trial run(spec::shockSolverOnly(), "tower", {{"n", 20}});
	run.run(10.0);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

TEST(Stacking, PyramidWithBase20DriftsLessThan1cmIn10s)
{
	harness::Trial run(spec::shock(), "pyramid", {{"base", 20}});
	run.run(10.0);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

TEST(Stacking, FlushEndedBrickWallOf200DriftsLessThan1cmIn10s)
{
	// Running bond with half bricks closing the short rows: every piece rests on its support.
	// (The default wall's overhanging end bricks need weight from the rows above: docs/history.md,
	// section 10, "Weighting f".)
	harness::Trial run(spec::shock(), "wall", {{"halfBricks", 1}, {"length", 12}});
	ASSERT_EQ(run.bodies().size(), 200u);
	run.run(10.0);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

class MassRatio : public ::testing::TestWithParam<double>
{
};

TEST_P(MassRatio, HeavyTopOnFourBoxTowerDriftsLessThan1cmIn10s)
{
	harness::Trial run(spec::shock(), "mass_ratio_tower", {{"ratio", GetParam()}});
	run.run(10.0);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

INSTANTIATE_TEST_SUITE_P(Stacking, MassRatio, ::testing::Values(100.0, 1000.0));

TEST(Stacking, SingleRestingBoxBehavesAsUnderStockSI)
{
	harness::Trial shock(spec::shock(), "single_box");
	harness::Trial stock(spec::stock(), "single_box");
	shock.run(10.0);
	stock.run(10.0);
	const btVector3 a = shock.named("box")->getCenterOfMassPosition();
	const btVector3 b = stock.named("box")->getCenterOfMassPosition();
	EXPECT_LT((a - b).length(), 1e-3);
	EXPECT_LT(shock.maxDrift(), 1e-3);
	EXPECT_LT(shock.named("box")->getLinearVelocity().length(), 1e-3);
}

TEST(Stacking, LeaningStackWithCentreOfMassOutsideBaseStillFalls)
{
	// No over-stability from fixation: each cube overhangs the one below by more than half its
	// width, so its centre of mass is outside its support and the stack must topple. (A stack that
	// is stable box by box but not as a whole: the truth suite's offset stacks, tests/truth; it needs
	// the top-down pass, D16 in docs/history.md.)
	harness::Trial run(spec::shock(), "leaning_tower", {{"n", 4}, {"shift", 0.55}});
	run.run(5.0);
	EXPECT_GT(run.drift().drift(run.named("top")), 0.5);
}

TEST(Friction, SlidingBoxDeceleratesAtMuG)
{
	harness::Trial run(spec::shock(), "sliding_box");
	const double mu = run.scene().facts.at("mu");
	const double v0 = run.scene().facts.at("v0");
	const double stopTime = v0 / (mu * 9.81);
	run.run(0.5 * stopTime);  // still sliding
	const double v = run.named("box")->getLinearVelocity().x();
	const double deceleration = (v0 - v) / run.simulation().time();
	EXPECT_NEAR(deceleration, mu * 9.81, 0.05 * mu * 9.81);
}

TEST(FreeFall, BodyWithoutContactsIsUntouched)
{
	// Exactly Bullet's own integration: gravity applied once per step, nothing else.
	harness::Trial shock(spec::shock(), "free_fall");
	harness::Trial stock(spec::stock(), "free_fall");
	shock.run(1.0);
	stock.run(1.0);
	const btRigidBody* a = shock.named("box");
	const btRigidBody* b = stock.named("box");
	EXPECT_EQ(a->getCenterOfMassPosition().y(), b->getCenterOfMassPosition().y());
	EXPECT_EQ(a->getLinearVelocity().y(), b->getLinearVelocity().y());
	EXPECT_NEAR(a->getLinearVelocity().y(), -9.81 * shock.simulation().time(), 1e-3);
}

TEST(Impulses, AppliedImpulseIsTheStepsTotal)
{
	// Two boxes, f = 0.5: the top box rests, so the impulses on it over one step sum to m g dt.
	// Each row holds one impulse for the whole step (predictor and corrector), written back once;
	// one stage's share alone would be less than that.
	harness::Trial run(spec::shock(10, 0.5), "tower", {{"n", 2}});
	run.run(1.0);
	const btRigidBody* top = run.named("top");
	double upward = 0;
	btDispatcher* dispatcher = run.simulation().world().getDispatcher();
	for (int i = 0; i < dispatcher->getNumManifolds(); ++i)
	{
		const btPersistentManifold* m = dispatcher->getManifoldByIndexInternal(i);
		if (m->getBody0() != top && m->getBody1() != top) continue;
		const double sign = m->getBody0() == top ? 1.0 : -1.0;  // normal points from B to A
		for (int j = 0; j < m->getNumContacts(); ++j)
			upward += sign * m->getContactPoint(j).m_normalWorldOnB.y() * m->getContactPoint(j).m_appliedImpulse;
	}
	const double weightImpulse = 9.81 * spec::kTimeStepSeconds / top->getInvMass();
	EXPECT_NEAR(upward, weightImpulse, 0.05 * weightImpulse);
}

TEST(Statistics, TowerOf20HasTwentyLayersAndNineteenFixations)
{
	harness::Trial run(spec::shock(), "tower", {{"n", 20}});
	run.run(0.1);
	const btShockPropagationStatistics& stats = run.simulation().shockSolver()->getStatistics();
	EXPECT_EQ(stats.m_numLayers, 20);
	EXPECT_EQ(stats.m_largestLayer, 1);
	EXPECT_EQ(stats.m_numFixatedBodies, 19);
	EXPECT_EQ(stats.m_numLayeredGroups, 1);
}

TEST(Statistics, GroundOnlyScenesSkipTheLayeredSolve)
{
	harness::Trial run(spec::shock(), "single_box");
	run.run(0.1);
	const btShockPropagationStatistics& stats = run.simulation().shockSolver()->getStatistics();
	EXPECT_EQ(stats.m_numLayers, 1);
	EXPECT_EQ(stats.m_numLayeredGroups, 0);
}

// The read-only layer record (for viewers): every box of a tower at its height from the ground,
// in both modes; a stock solver has none.
TEST(Statistics, LayeredBodiesListEveryTowerBoxAtItsHeightFromTheGround)
{
	for (harness::SolverKind kind : {harness::SolverKind::ShockWorld, harness::SolverKind::ShockSolverOnly})
	{
		harness::Trial run(spec::plugin(kind), "tower", {{"n", 5}});
		run.run(0.1);
		const btShockPropagationConstraintSolver& solver = *run.simulation().shockSolver();
		ASSERT_EQ(solver.getNumLayeredBodies(), 5);
		for (int i = 0; i < solver.getNumLayeredBodies(); ++i)
		{
			const btCollisionObject* body = solver.getLayeredBody(i);
			// Boxes 0.5 m tall from y = 0: the centre at 0.25 + 0.5 k is height k + 1.
			const int expected = int(body->getWorldTransform().getOrigin().y() / 0.5) + 1;
			EXPECT_EQ(solver.getLayeredBodyHeight(i), expected) << "box at y = " << body->getWorldTransform().getOrigin().y();
		}
	}
}

// Known failure (docs/design.md, section 12): round towers of other proportions than the registry's
// 16 bricks a ring at mu 0.6. Each brick rests on two below it, half a brick on each, so the tower
// stands (statics), and the converged reference stands: stock SI with 8 sub-steps x 100 iterations
// drifts 0.36 cm (ring of 12) and 0.51 cm (ring of 16, mu 0.9) in 10 s. The plugin collapses both
// in world and solver-only mode (at 2.5 s and 9.1 s); solver-only, the other 16 of the 18 rings of
// 10-20 bricks at mu 0.6, 0.9 and 1.2 stand. Traced (docs/history.md, section 4ah): after about 140 steps at rest, one
// step's first predictor cycle hands a brick, through the down pass's delivery, a load its own
// supports cannot hold; its layer visit ends unconverged, the coupled residual rises above its
// value before the passes (0.16 -> 0.31 m/s), the cycles stop there and the corrector's 5 sweeps
// leave the brick tipping; from then on every step gains energy. Run with
// --gtest_also_run_disabled_tests (the reference takes about 40 s a case).
namespace
{
struct RoundTowerCase
{
	int ring;
	double mu;
};

void PrintTo(const RoundTowerCase& c, std::ostream* os) { *os << "ring " << c.ring << ", mu " << c.mu; }

class RoundTowerVariant : public ::testing::TestWithParam<RoundTowerCase>
{
};

double roundTowerDrift(const harness::SolverSpec& solver, const RoundTowerCase& c)
{
	harness::Trial run(solver, "round_tower", {{"ring", double(c.ring)}, {"mu", c.mu}});
	run.run(10.0);
	return run.maxDrift();
}
}  // namespace

TEST_P(RoundTowerVariant, DISABLED_StandsAsTheReferenceDoes)
{
	harness::SolverSpec reference = spec::stock(100);
	reference.substeps = 8;
	const double referenceDrift = roundTowerDrift(reference, GetParam());
	const double world = roundTowerDrift(spec::shock(), GetParam());
	const double solverOnly = roundTowerDrift(spec::shockSolverOnly(), GetParam());
	std::printf("ROUND TOWER | ring %d mu %.1f | reference %.3g cm | world %.3g cm | solver-only %.3g cm\n", GetParam().ring, GetParam().mu,
				referenceDrift * 100, world * 100, solverOnly * 100);
	ASSERT_LT(referenceDrift, harness::kStandingDriftMeters) << "the reference must stand, else the case says nothing";
	EXPECT_LT(world, harness::kStandingDriftMeters);
	EXPECT_LT(solverOnly, harness::kStandingDriftMeters);
}

INSTANTIATE_TEST_SUITE_P(KnownFailure, RoundTowerVariant, ::testing::Values(RoundTowerCase{12, 0.6}, RoundTowerCase{16, 0.9}),
						 [](const ::testing::TestParamInfo<RoundTowerCase>& info) {
							 return "Ring" + std::to_string(info.param.ring) + "Mu" + std::to_string(int(info.param.mu * 10 + 0.5));
						 });
