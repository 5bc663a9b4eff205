// Weight feeling (issue 7, decision D13): with it, the plugin's contact forces are the forces of
// statics while the stacks still stand. Expectations come from statics (total weight, symmetry,
// the lever rule), not from recorded runs. Each force is averaged over the last second of a run.
#include "Fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>


namespace
{
constexpr double kGravity = 9.81;

double weightOf(const btRigidBody* body)
{
	return kGravity / body->getInvMass();
}

/// Runs `seconds`, then averages `measure()` over one more second.
template <class Measure>
double averageOverLastSecond(harness::Trial& run, double seconds, Measure measure)
{
	run.run(seconds);
	const int steps = int(1.0 / spec::kTimeStepSeconds + 0.5);
	double sum = 0;
	for (int i = 0; i < steps; ++i)
	{
		run.run(spec::kTimeStepSeconds);
		sum += measure();
	}
	return sum / steps;
}

double groundOverWeight(harness::Trial& run)
{
	return harness::groundReactionOverWeight(*run.simulation().world().getDispatcher(), run.scene().ground(), run.bodies(),
											 spec::kTimeStepSeconds, kGravity);
}

struct SupportForces
{
	double left = 0;   ///< N
	double right = 0;  ///< N
};

/// Runs 2 s, then averages the vertical forces of `left` and `right` on `upper` over one more second.
SupportForces averageSupportForces(harness::Trial& run, const btRigidBody* upper, const btRigidBody* left, const btRigidBody* right)
{
	btDispatcher& dispatcher = *run.simulation().world().getDispatcher();
	SupportForces sum;
	const double steps = std::round(1.0 / spec::kTimeStepSeconds);
	averageOverLastSecond(run, 2.0, [&] {
		sum.left += harness::supportForce(dispatcher, upper, left, spec::kTimeStepSeconds) / steps;
		sum.right += harness::supportForce(dispatcher, upper, right, spec::kTimeStepSeconds) / steps;
		return 0.0;
	});
	return sum;
}

struct Mode
{
	harness::SolverSpec solver;
	const char* name;
};

class WeightFeeling : public ::testing::TestWithParam<Mode>
{
};

std::string modeName(const ::testing::TestParamInfo<Mode>& info)
{
	return info.param.name;
}

harness::SolverSpec solverOnlyWeightFeeling()
{
	harness::SolverSpec s = spec::weightFeeling();
	s.kind = harness::SolverKind::ShockSolverOnly;
	return s;
}
}  // namespace

TEST_P(WeightFeeling, GroundCarriesTheWholeTowerOf10And40)
{
	for (int n : {10, 40})
	{
		harness::Trial run(GetParam().solver, "tower", {{"n", n}});
		const double ground = averageOverLastSecond(run, 2.0, [&] { return groundOverWeight(run); });
		EXPECT_NEAR(ground, 1.0, 0.05) << "tower of " << n << ": ground reaction / total weight";
		EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters) << "tower of " << n;
	}
}

TEST_P(WeightFeeling, LintelOnEqualColumnsPutsHalfItsWeightOnEach)
{
	// Column tops 0.1 m wide at +-1.25 m: where on a top the lintel presses moves the split by at
	// most 4% (wide tops would make it statically indeterminate).
	harness::Trial run(GetParam().solver, "door", {{"left", 2}, {"right", 2}, {"size", 0.1}});
	const btRigidBody* lintel = run.named("lintel");
	const SupportForces forces = averageSupportForces(run, lintel, run.named("leftTop"), run.named("rightTop"));
	const double half = weightOf(lintel) / 2;
	EXPECT_NEAR(forces.left, half, 0.1 * half) << "N on the left column";
	EXPECT_NEAR(forces.right, half, 0.1 * half) << "N on the right column";
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

TEST_P(WeightFeeling, PlankSharesAnOffCentreLoadByTheLeverRule)
{
	harness::Trial run(GetParam().solver, "loaded_plank");
	const btRigidBody* plank = run.named("plank");
	const double rightShare = run.scene().facts.at("rightShare");
	ASSERT_GT(rightShare, 0.6) << "the scene should load the right support more";
	const SupportForces forces = averageSupportForces(run, plank, run.named("leftSupport"), run.named("rightSupport"));
	const double load = weightOf(run.named("load"));
	const double expectedLeft = weightOf(plank) / 2 + load * (1 - rightShare);
	const double expectedRight = weightOf(plank) / 2 + load * rightShare;
	EXPECT_NEAR(forces.left, expectedLeft, 0.1 * expectedLeft) << "N on the left support";
	EXPECT_NEAR(forces.right, expectedRight, 0.1 * expectedRight) << "N on the right support";
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

TEST_P(WeightFeeling, SeesawTipsToTheHeavySideAndRestsThere)
{
	// Two cubes on the heavy end: the default five topple off the tipped plank (their centre of mass
	// is over the edge at its 14 degrees) and the light cube then tips it back, as physics says; an
	// edge 0.28 m high tips the plank by 5 degrees only, so two cubes stay on it after it lands.
	harness::Trial run(GetParam().solver, "seesaw", {{"stack", 2}, {"fulcrumSize", 0.2}});
	const btRigidBody* plank = run.named("plank");
	run.run(6.0);
	const double rise = plank->getWorldTransform().getBasis().getColumn(0).y();  // > 0: +x end up
	EXPECT_GT(rise, std::sin(0.05)) << "the heavy (-x) end should be down (it rests at 5.4 degrees)";
	EXPECT_LT(harness::kineticEnergy(run.bodies()), 1e-3) << "J: the seesaw should have come to rest";
}

// The door's standing without an energy spike is HardCase.DoorWithUnequalColumnsStandsWithoutJamming,
// which runs with weight feeling too; here, its weight reaches the ground.
TEST_P(WeightFeeling, DoorWithUnequalColumnsPassesItsWeightToTheGround)
{
	harness::Trial run(GetParam().solver, "door");
	const double ground = averageOverLastSecond(run, 2.0, [&] { return groundOverWeight(run); });
	EXPECT_NEAR(ground, 1.0, 0.05);
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}

TEST_P(WeightFeeling, MassRatio1000TowerStandsAndWeighsRight)
{
	harness::Trial run(GetParam().solver, "mass_ratio_tower");
	const double ground = averageOverLastSecond(run, 2.0, [&] { return groundOverWeight(run); });
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
	EXPECT_NEAR(ground, 1.0, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Modes, WeightFeeling,
						 ::testing::Values(Mode{spec::weightFeeling(), "World"},
										   Mode{solverOnlyWeightFeeling(), "SolverOnly"}),
						 modeName);

// The classic order (no down pass, f = 0: no corrector sweeps) delivers every withheld reaction
// too, so the ground carries the whole tower as statics says. (The layered passes' classic mode
// withheld the weight of the boxes above: 0.24 of it.)
TEST(WithoutWeightFeeling, GroundCarriesTheWholeTower)
{
	harness::Trial run(spec::classic(10, 0.0), "tower", {{"n", 10}});
	const double ground = averageOverLastSecond(run, 2.0, [&] { return groundOverWeight(run); });
	EXPECT_NEAR(ground, 1.0, 0.05) << "ground reaction / total weight";
	EXPECT_LT(run.maxDrift(), harness::kStandingDriftMeters);
}
