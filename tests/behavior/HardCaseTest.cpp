// Expectations of the registry's hard cases (issue 3), from statics and kinematics rather than
// from recorded runs. Each runs under the plugin (default settings, 10 iterations) and, where
// stock Bullet gets the physics right, under stock SI as well.
#include "Fixture.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>


namespace
{
/// Angle (radians) between a body's local y axis and the world's y axis.
double tilt(const btRigidBody* body)
{
	const btVector3 up = body->getWorldTransform().getBasis().getColumn(1);
	return std::acos(std::max(-1.0, std::min(1.0, double(up.y()))));
}

class HardCase : public ::testing::TestWithParam<harness::SolverSpec>
{
};

std::string solverName(const ::testing::TestParamInfo<harness::SolverSpec>& info)
{
	if (info.param.kind == harness::SolverKind::StockSI) return "StockSI";
	return info.param.settings.m_weightFeeling ? "ShockPropagation" : "ShockPropagationClassic";
}
}  // namespace

TEST_P(HardCase, SeesawTipsToTheHeavySideFirst)
{
	// The first clear tilt (3 degrees) must lower the -x end, under the stack. Later the stack may
	// slide off the tipped plank and the light box tip it back (stock SI does), which is physics too.
	harness::Trial run(GetParam(), "seesaw");
	ASSERT_LT(run.scene().facts.at("heavySide"), 0);
	const btRigidBody* plank = run.named("plank");
	double rise = 0;  // y of the plank's +x axis: > 0 when the +x end is higher
	for (int i = 0; i < 240 && std::fabs(rise) < std::sin(0.05); ++i)
	{
		run.simulation().step();
		rise = plank->getWorldTransform().getBasis().getColumn(0).y();
	}
	EXPECT_GT(rise, std::sin(0.05)) << "the plank did not tip towards the heavy stack within 4 s";
}

TEST_P(HardCase, RampBoxesSlideBelowTanAngleAndStickAbove)
{
	harness::Trial run(GetParam(), "friction_ramp");
	const int count = int(run.scene().facts.at("count"));
	const double tanAngle = run.scene().facts.at("tanAngle");
	run.run(1.5);
	for (int k = 0; k < count; ++k)
	{
		const btRigidBody* box = run.named("box" + std::to_string(k));
		const double mu = run.scene().facts.at("mu" + std::to_string(k));
		const double moved = run.drift().drift(box);
		if (mu < tanAngle - 0.05)
		{
			EXPECT_GT(moved, 0.5) << "box with mu " << mu << " < tan(angle) " << tanAngle << " should slide";
		}
		else if (mu > tanAngle + 0.05)
		{
			EXPECT_LT(moved, 0.01) << "box with mu " << mu << " > tan(angle) " << tanAngle << " should stick";
		}
	}
}

TEST_P(HardCase, OverlapRecoveryEndsSeparatedWithoutFlinging)
{
	harness::Trial run(GetParam(), "overlap_recovery");
	const double size = run.scene().facts.at("size");
	const double overlap = run.scene().facts.at("overlapDepth");
	double fastest = 0;
	for (int i = 0; i < 120; ++i)
	{
		run.simulation().step();
		fastest = std::max(fastest, harness::maxSpeed(run.bodies()));
	}
	EXPECT_LT(harness::maxPenetration(*run.simulation().world().getDispatcher()), 0.005) << "m, still overlapping after 2 s";
	// Separating needs each body to move by at most the overlaps below it; nothing should fly.
	EXPECT_LT(fastest, 2.0) << "m/s: a body was flung";
	EXPECT_LT(harness::maxSpeed(run.bodies()), 0.05) << "m/s: the pile should be at rest";
	for (const btRigidBody* b : run.bodies()) EXPECT_LT(run.drift().drift(b), 4 * overlap + size) << "a body left the pile";
}

TEST_P(HardCase, DoorWithUnequalColumnsStandsWithoutJamming)
{
	harness::Trial run(GetParam(), "door");
	double peakEnergy = 0;
	for (int i = 0; i < 300; ++i)
	{
		run.simulation().step();
		peakEnergy = std::max(peakEnergy, harness::kineticEnergy(run.bodies()));
	}
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
	// A jammed lintel is violent (BFS-only layering measured 145 J); stock SI's settling, 0.018 J.
	EXPECT_LT(peakEnergy, 0.05) << "J: the lintel jammed or jumped";
	EXPECT_LT(harness::maxPenetration(*run.simulation().world().getDispatcher()), 0.005);
}

TEST_P(HardCase, DominoRowTopplesToTheLast)
{
	harness::Trial run(GetParam(), "domino_row");
	run.run(5.0);
	EXPECT_GT(tilt(run.named("first")), 0.5);
	EXPECT_GT(tilt(run.named("last")), 0.5) << "rad: the chain reaction stopped before the last domino";
}

// The same row made of convex hulls (with and without polyhedral features) and of compounds: the
// chain topples to the last domino and each comes to rest leaning on the next, as stock's does
// (stock in the same test: its row ends at 1.37 rad for every domino but the last). Before D33
// measured a rim's distance to the other part's face along that face (docs/design.md, section 11),
// a domino leaning on the next by its top edge, their faces 11 degrees apart, was given points at
// the other's face corners 1 m away (read as 7.6 mm deep, 19 cm apart in truth) and the row stopped
// half-fallen: the last domino did not move, the others hung at 0.5-1.2 rad.
TEST(DominoShapes, HullAndCompoundRowsToppleAsStocks)
{
	for (int shape : {1, 2, 5})
	{
		harness::Trial stock(spec::stock(), "domino_row", {{"shape", double(shape)}});
		stock.run(5.0);
		for (const harness::SolverSpec& solver : {spec::shock(), spec::shockSolverOnly()})
		{
			harness::Trial run(solver, "domino_row", {{"shape", double(shape)}});
			run.run(5.0);
			const std::string label = "shape " + std::to_string(shape) + (solver.kind == harness::SolverKind::ShockWorld ? " world" : " solver-only");
			EXPECT_GT(tilt(run.named("last")), 0.5) << label << ": the chain reaction stopped before the last domino";
			for (size_t i = 0; i + 1 < run.bodies().size(); ++i)
				EXPECT_NEAR(tilt(run.bodies()[i]), tilt(stock.bodies()[i]), 0.1) << label << ", domino " << i;
		}
	}
}

TEST_P(HardCase, HingeBridgeSagsToRestAndItsJointsHold)
{
	harness::Trial run(GetParam(), "hinge_bridge");
	const double deckHeight = run.scene().facts.at("deckHeight");
	run.run(5.0);
	EXPECT_LT(run.named("middlePlank")->getCenterOfMassPosition().y(), deckHeight) << "the bridge must sag";
	EXPECT_GT(run.named("middlePlank")->getCenterOfMassPosition().y(), 0.0) << "the bridge must not reach the ground";
	for (btTypedConstraint* c : run.scene().constraints())
	{
		btHingeConstraint* hinge = dynamic_cast<btHingeConstraint*>(c);
		ASSERT_NE(hinge, nullptr);
		const btVector3 a = hinge->getRigidBodyA().getWorldTransform() * hinge->getFrameOffsetA().getOrigin();
		const btVector3 b = hinge->getRigidBodyB().getWorldTransform() * hinge->getFrameOffsetB().getOrigin();
		// Bullet's hinges are soft (erp 0.2): at 10 iterations under this load, after 5 s, stock SI
		// and the plugin in both modes open them by up to 3.83 cm. A hinge that lets go opens
		// without bound.
		EXPECT_LT((a - b).length(), 0.09) << "m: a hinge came apart";
	}
	EXPECT_LT(harness::maxSpeed(run.bodies()), 0.2) << "m/s: the bridge should have settled";
}

TEST_P(HardCase, LeaningStackWhoseBoxesOverhangHalfTopples)
{
	// Every box overhangs the one below by more than half its edge: each one tips on its own.
	harness::Trial run(GetParam(), "leaning_tower", {{"n", 4}, {"shift", 0.55}});
	ASSERT_EQ(run.scene().facts.at("expectFalls"), 1);
	run.run(3.0);
	EXPECT_GT(run.drift().drift(run.named("top")), 0.5);
}

INSTANTIATE_TEST_SUITE_P(Registry, HardCase, ::testing::Values(spec::shock(), spec::classic(), spec::stock(10)), solverName);

// Where stock SI fails, the plugin's expectation alone.

TEST(HardCaseShock, LeaningTowerWithCentreOfMassOutsideTheBaseFallsUnderStockSI)
{
	// The registry default: boxes shifted 0.3 of an edge, each stable on the one below, the stack as
	// a whole not. Stock SI topples it. Without weight feeling the plugin does not (every layer sees
	// only the box above it); issue 7 asserts the plugin on this scene.
	harness::Trial run(spec::stock(10), "leaning_tower");
	ASSERT_EQ(run.scene().facts.at("expectFalls"), 1);
	run.run(4.0);
	EXPECT_GT(run.drift().drift(run.named("top")), 0.5);
}

TEST(HardCaseShock, LargeSlabOnTwoSmallCubesStands)
{
	// Mass ratio 100; stock SI at 10 iterations lets the slab sink and slide (24 cm).
	harness::Trial run(spec::shock(), "large_on_small");
	run.run(5.0);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

TEST(HardCaseShock, CardHouseStands)
{
	// 10 g cards leaning at 25 degrees: the top card may settle by the cards' bedding in (measured
	// 1.9 cm), but the house must stand: the top card stays within 5 cm and everything comes to
	// rest. Stock SI at 10 iterations collapses it (95 cm).
	harness::Trial run(spec::shock(), "card_house");
	run.run(5.0);
	EXPECT_LT(run.drift().drift(run.named("top")), 0.05) << "m";
	EXPECT_LT(harness::maxSpeed(run.bodies()), 0.01) << "m/s";
}

TEST(HardCaseShock, MassRatioTowerOfRatio1000Stands)
{
	harness::Trial run(spec::shock(), "mass_ratio_tower", {{"ratio", 1000}});
	run.run(5.0);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

TEST(HardCaseShock, BfsLayersHoldTheDoorOnceFixationAsksWhetherThePushIsCarried)
{
	// The failure the support ordering was made for (docs/design.md, D12): with plain BFS layers the
	// right column's top box lies in a layer below the lintel and was fixated against it, clamped
	// between the fixated lintel and the fixated box below (the classic method lost the door: 62 cm
	// in 2 s). A row is one-sided only where the fixated body's supports carry its push
	// (btShockPredictor::pushCarried, docs/design.md 4.2): the lintel's supports push it up, and a
	// push up from the box under it is in none of their friction cones, so that row is solved with
	// both bodies free and the door holds without the ordering.
	harness::Trial run(spec::classic(), "door");
	btShockPropagationSettings settings = run.simulation().shockSolver()->getSettings();
	settings.m_diagnostics.m_supportOrdering = false;
	run.simulation().shockSolver()->setSettings(settings);
	run.run(2.0);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters) << "m: BFS-only layers, classic order";
}

namespace
{
struct PitResult
{
	std::vector<double> deepest;  // m, deepest penetration of each pile (seeds 1..kPiles)
	double fastestLate = 0;       // m/s, fastest body in the last 5 s of any pile
};

constexpr int kPiles = 12;

/// The deepest penetration of each of twelve piles (seeds 1-12), and the fastest body late in any
/// of them. A pile is chaotic: any change to a solver reorders its impacts, and one seed's depth
/// moves by 30-50% between two equally good solvers (docs/history.md, D23, D26), so the piles are
/// compared seed by seed, as a paired sample.
PitResult dropIntoPit(const harness::SolverSpec& solver)
{
	PitResult r;
	for (int seed = 1; seed <= kPiles; ++seed)
	{
		harness::Trial run(solver, "dense_random", {{"seed", double(seed)}});
		double deepest = 0;
		for (int i = 0; i < 600; ++i)
		{
			run.simulation().step();
			deepest = std::max(deepest, harness::maxPenetration(*run.simulation().world().getDispatcher()));
			if (i >= 300) r.fastestLate = std::max(r.fastestLate, harness::maxSpeed(run.bodies()));
		}
		r.deepest.push_back(deepest);
	}
	return r;
}
}  // namespace

TEST(HardCaseShock, CubesDroppedIntoAPitAreStoppedAtTheirContacts)
{
	// 100 cubes dropped into a pit: every landing is stopped at its contact (since D15 speculative
	// contacts use the step's own dt; D11's approach stop is retired), so the piles are no deeper
	// than stock SI's, and they settle. Same seeds, paired: the plugin's mean excess over stock must
	// be within two standard errors of zero (not significantly deeper). Measured (float, 10 s, seeds
	// 1-24, deepest penetration of a 0.5 m cube): stock 0.157 m, plugin 0.140 m (0.136 m with D26
	// off); seeds 1-12: mean excess -0.016 m, two standard errors 0.034 m. Seeds 1-6 alone, the
	// earlier test's sample, read 0.170 m against stock's 0.158 m. A plugin whose landings were not
	// stopped at the contact (D11's era: 0.22 m against 0.16) fails this.
	const PitResult stock = dropIntoPit(spec::stock(10));
	const PitResult plugin = dropIntoPit(spec::shock());
	double mean = 0, squares = 0;
	for (int i = 0; i < kPiles; ++i) mean += (plugin.deepest[i] - stock.deepest[i]) / kPiles;
	for (int i = 0; i < kPiles; ++i) squares += (plugin.deepest[i] - stock.deepest[i] - mean) * (plugin.deepest[i] - stock.deepest[i] - mean);
	const double standardError = std::sqrt(squares / (kPiles - 1) / kPiles);
	EXPECT_LE(mean, 2 * standardError) << "m: the piles are deeper than stock SI's (mean excess over " << kPiles << " seeds)";
	EXPECT_LT(plugin.fastestLate, std::sqrt(2 * 9.81 * 2.0)) << "m/s: faster than a fall from 2 m after the pile settled";
}
