// Hostile worlds (scenes/HostileScene.h) under the plugin, seed after seed: what must hold
// whatever an application throws at the world.
//
// Per seed, 120 steps at 60 Hz, after every step:
//  - the world holds exactly the bodies and constraints the generator says it added;
//  - no body that was never poisoned has a NaN or Inf transform or velocity (bodies jointed to or
//    touching a poisoned body included: the plugin leaves non-finite bodies, their manifolds
//    and their joints out of every pass);
//  - the kinetic energy of those bodies stays within the energy budget below, and no such body
//    moves faster than the speed cap below.
//
// Energy budget (J). Contacts have restitution 0 and the plugin removes penetration by moving
// positions, not by adding velocity, so kinetic energy can only come from
//   (a) the bodies' initial kinetic energy E0_i,
//   (b) gravity: m_i g (highest_i - y_i), where highest_i is the highest the body's centre has
//       been (placed, teleported, or lifted out of an overlap) and y_i where it is now, both
//       measured less the height its teleports lifted it by (HostileBody::liftedBy): a teleport
//       keeps the velocity, so a body falling 0.9 m to 4.1 m/s and teleported up keeps the energy
//       of that fall (without this, clean seed 134 and poisoned seeds 409, 450, 542, 742, 785 and
//       807 were reported over the budget, stock and plugin alike),
//   (c) the kinematic bodies: an inelastic push brings a body at most to the pusher's speed v_k;
//       allowing for rotation and a second push, 1/2 m_i (2 v_k)^2 per body,
//   (d) joints: a correction that moves a jointed body by up to one body extent e (1.1 m here)
//       leaves a joint error that Bullet's joint ERP removes at erp e / dt (13 m/s at erp 0.2,
//       60 Hz; the plugin scales the joint ERP of each pass to the pass's share of the step, so
//       it asks for the same speed as a stock step): 1/2 m_i v_j^2 per jointed body.
// A body moving under several of these has |v|^2 <= 2 |v_b|^2 + 2 |v_cd|^2, hence
//   KE(healthy) <= 2 * sum_i [E0_i + m_i g (highest_i - y_i) + 1/2 m_i (2 v_k)^2 + 1/2 m_i v_j^2].
// A poisoned body counts with what it had released when it was poisoned (it is frozen after).
// Speed cap (m/s): no body is accelerated by more than g for the t seconds simulated, pushed faster
// than 2 v_k, pulled by a joint faster than v_j, or started faster than v0; twice that allows
// lever effects between bodies:  |v| <= 2 (v0 + g t + 2 v_k + v_j).
// The energy budget catches a heavy body gaining energy; the speed cap catches a light one (a
// 1e-3 kg body thrown at 1 km/s is 500 J, invisible next to a 1e6 kg body's budget).
//
// Count and finiteness must hold for every seed. The budget or the cap is exceeded today in
// 0.5-0.8% of seeds (1,000 seeds, world / solver-only: 5 / 5 in float, 7 / 8 in double;
// docs/design.md, sections 10 and 12), almost all by the speed cap: light bodies squeezed under
// bodies 1e5-1e8 times their mass. Stock Bullet exceeds the same bounds in 0.6-0.8% of the same
// worlds without poison (it spreads NaN when poisoned), and the comparison test checks that the
// plugin does not do so much more often. The test fails if more than kMaxSeedsOverBoundPercent of
// the seeds exceed them, and prints the ones that do.
//
// 100 seeds per mode run by default; BSP_HOSTILE_SEEDS=<n> runs n (ctest -L long: 1,000), and
// BSP_FIRST=<k> starts at seed k (to rerun one seed a failure printed).

#include "../behavior/Fixture.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <harness/Metrics.h>
#include <harness/Simulation.h>
#include <scenes/HostileScene.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using spec::kTimeStepSeconds;
constexpr double kGravity = 9.81;  // m/s^2, harness::Simulation's default
constexpr int kStepsPerSeed = 120;
constexpr int kDefaultSeeds = 100;
constexpr int kComparisonSeeds = 400;  // the plugin against stock without poison (see that test)
constexpr int kMaxReportedFailures = 20;
constexpr double kMaxSeedsOverBoundPercent = 1;  // measured 0.5-0.8 over 1,000 seeds (see above)

int seedCount()
{
	const char* text = std::getenv("BSP_HOSTILE_SEEDS");
	if (!text) return kDefaultSeeds;
	const int n = std::atoi(text);
	return n > 0 ? n : kDefaultSeeds;
}

bool isFinite(const btRigidBody& body)
{
	const btTransform& t = body.getWorldTransform();
	double sum = double(t.getOrigin().x()) + t.getOrigin().y() + t.getOrigin().z();
	for (int i = 0; i < 3; ++i) sum += double(t.getBasis()[i].x()) + t.getBasis()[i].y() + t.getBasis()[i].z();
	const btVector3& v = body.getLinearVelocity();
	const btVector3& w = body.getAngularVelocity();
	sum += double(v.x()) + v.y() + v.z() + w.x() + w.y() + w.z();
	return std::isfinite(sum);
}

double massOf(const btRigidBody& body) { return body.getInvMass() > 0 ? 1.0 / double(body.getInvMass()) : 0.0; }

/// Largest values seen over all seeds of one run, for the test log.
struct Extremes
{
	double energyOverBudget = 0;
	double speedOverCap = 0;
	int poisonedBodies = 0;
	int bodiesMade = 0;
};

/// Runs one seed; appends what went wrong to `broken` (count or finiteness) or to `overBound`
/// (energy budget or speed cap), at most one line per seed.
void runSeed(const harness::SolverSpec& solver, const scenes::HostileParams& params, std::uint32_t seed, std::vector<std::string>& broken, std::vector<std::string>& overBound,
			 Extremes& extremes)
{
	harness::Simulation sim(solver, kTimeStepSeconds, kGravity);
	scenes::HostileScene scene(sim.world(), seed, params);  // destroyed before the world
	btDiscreteDynamicsWorld& world = sim.world();
	const double jointSpeed = world.getSolverInfo().m_erp * scenes::HostileScene::largestExtent() / kTimeStepSeconds;
	std::map<const btRigidBody*, double> highest;  // m, highest centre height seen while healthy
	auto report = [&](std::vector<std::string>& list, int step, const std::string& what) {
		std::ostringstream out;
		out << "seed " << seed << ", step " << step << ": " << what;
		list.push_back(out.str());
	};
	auto fail = [&](int step, const std::string& what) { report(broken, step, what); };
	bool overReported = false;
	auto exceed = [&](int step, const std::string& what) {
		if (!overReported) report(overBound, step, what);
		overReported = true;
	};
	for (int step = 1; step <= kStepsPerSeed; ++step)
	{
		scene.beforeStep(kTimeStepSeconds);
		sim.step();

		if (world.getNumCollisionObjects() != scene.expectedCollisionObjects())
			return fail(step, "world holds " + std::to_string(world.getNumCollisionObjects()) + " bodies, generator added " +
								  std::to_string(scene.expectedCollisionObjects()));
		if (world.getNumConstraints() != scene.expectedConstraints())
			return fail(step, "world holds " + std::to_string(world.getNumConstraints()) + " constraints, generator added " +
								  std::to_string(scene.expectedConstraints()));

		double kinetic = 0, budget = 0;
		const double pushSpeed = 2 * scene.kinematicSpeed();
		const double speedCap = 2 * (scene.maxStartSpeed() + kGravity * scene.elapsedTime() + pushSpeed + jointSpeed);
		for (const scenes::HostileBody& record : scene.bodies())
		{
			const btRigidBody& body = *record.body;
			const double mass = massOf(body);
			if (record.isStatic || record.kinematic || mass == 0) continue;
			if (record.poisoned)
			{
				const double top = std::max(highest.count(&body) ? highest[&body] : record.highestY, record.highestY);
				budget += record.startKineticEnergy + mass * kGravity * (top - (record.yWhenPoisoned - record.liftedBy));
				continue;
			}
			if (!isFinite(body))
				return fail(step, "a body that was never poisoned became non-finite");
			const double y = body.getWorldTransform().getOrigin().y() - record.liftedBy;  // budget frame, (b)
			double& top = highest.emplace(&body, record.highestY).first->second;
			top = std::max(std::max(top, y), record.highestY);
			budget += record.startKineticEnergy + mass * kGravity * (top - y) + 0.5 * mass * pushSpeed * pushSpeed;
			if (scene.isJointed(&body)) budget += 0.5 * mass * jointSpeed * jointSpeed;
			kinetic += harness::kineticEnergy({const_cast<btRigidBody*>(&body)});
			const double speed = body.getLinearVelocity().length();
			extremes.speedOverCap = std::max(extremes.speedOverCap, speed / speedCap);
			if (speed > speedCap)
				exceed(step, "a healthy body moves at " + std::to_string(speed) + " m/s, cap " + std::to_string(speedCap) + " m/s");
		}
		budget *= 2;
		if (budget > 0) extremes.energyOverBudget = std::max(extremes.energyOverBudget, kinetic / budget);
		if (kinetic > budget)
			exceed(step, "kinetic energy " + std::to_string(kinetic) + " J exceeds the budget " + std::to_string(budget) + " J");
	}
	for (const scenes::HostileBody& record : scene.bodies()) extremes.poisonedBodies += record.poisoned ? 1 : 0;
	extremes.bodiesMade += int(scene.bodies().size());
}

/// Runs the seeds; checks counts and finiteness (always) and, if `boundPercent` >= 0, that at most
/// that share of the seeds exceed the bounds. Returns how many seeds exceeded them.
int runSeeds(const harness::SolverSpec& solver, const scenes::HostileParams& params = scenes::HostileParams(),
			 double boundPercent = kMaxSeedsOverBoundPercent, int seeds = seedCount())
{
	std::vector<std::string> broken, overBound;
	Extremes extremes;
	const int first = std::getenv("BSP_FIRST") ? std::atoi(std::getenv("BSP_FIRST")) : 0;
	for (int seed = first; seed < first + seeds; ++seed) runSeed(solver, params, std::uint32_t(seed), broken, overBound, extremes);
	std::ostringstream log;
	log << seeds << " seeds x " << kStepsPerSeed << " steps, " << extremes.bodiesMade << " bodies (" << extremes.poisonedBodies
		<< " poisoned); " << overBound.size() << " seeds over the energy budget or speed cap; largest kinetic energy / budget "
		<< extremes.energyOverBudget << ", largest speed / cap " << extremes.speedOverCap;
	std::printf("%s\n", log.str().c_str());
	for (const std::string& line : overBound) std::printf("  over: %s\n", line.c_str());
	::testing::Test::RecordProperty("summary", log.str());
	for (size_t i = 0; i < broken.size() && i < size_t(kMaxReportedFailures); ++i) ADD_FAILURE() << broken[i];
	EXPECT_EQ(broken.size(), 0u) << broken.size() << " of " << seeds << " seeds lost count or finiteness";
	if (boundPercent >= 0)
	{
		EXPECT_LE(100.0 * double(overBound.size()) / seeds, boundPercent) << overBound.size() << " of " << seeds << " seeds exceeded the bounds";
	}
	return int(overBound.size());
}

using spec::plugin;
}  // namespace

TEST(HostileWorld, ShockWorldKeepsCountsAndHealthyBodiesFiniteAndBounded)
{
	runSeeds(plugin(harness::SolverKind::ShockWorld));
}

TEST(HostileWorld, SolverOnlyKeepsCountsAndHealthyBodiesFiniteAndBounded)
{
	runSeeds(plugin(harness::SolverKind::ShockSolverOnly));
}

TEST(HostileWorld, WithoutPoisonThePluginExceedsTheBoundsNoMoreOftenThanStock)
{
	// Stock Bullet spreads NaN from poisoned bodies (it fails the finiteness check in most seeds),
	// so the comparison runs the same worlds without poison. Stock exceeds the same bounds too
	// (1,000 seeds, world mode: stock 8, plugin 11 in float; stock 6, plugin 13 in double); the
	// plugin may not do so much more often. At under 1% a run of 100 seeds sees stock over in 0
	// or 1 of them and the comparison is noise (double, seeds 0-99: stock 0, plugin 1), so it
	// runs at least 400 (double: stock 2, plugin 3; float: stock 3, plugin 5).
	scenes::HostileParams clean;
	clean.poisonFraction = 0;
	const int seeds = std::max(seedCount(), kComparisonSeeds);
	const int stockOver = runSeeds(spec::stock(), clean, -1, seeds);
	const int pluginOver = runSeeds(plugin(harness::SolverKind::ShockWorld), clean, -1, seeds);
	EXPECT_LE(pluginOver, 2 * stockOver + seeds / 100) << "plugin " << pluginOver << " seeds over the bounds, stock " << stockOver;
}

TEST(HostileWorld, AHeavyBodyLandingOnALightOneDoesNotSpinItUp)
{
	// Clean seed 2218: a 313 t body lands on a stack resting on a 10 g cube. The layered passes
	// this step replaced handed the cube 2.7e8 rad/s there and, once, 3.5e5 m/s in double
	// (5,458 times the speed cap; docs/history.md, D28). Judged here in the build's precision.
	scenes::HostileParams clean;
	clean.poisonFraction = 0;
	harness::SolverSpec solver = plugin(harness::SolverKind::ShockWorld);
	std::vector<std::string> broken, overBound;
	Extremes extremes;
	runSeed(solver, clean, 2218, broken, overBound, extremes);
	std::printf("seed 2218: largest speed / cap %.3g\n", extremes.speedOverCap);
	EXPECT_TRUE(broken.empty());
	EXPECT_LT(extremes.speedOverCap, 2.0) << "the fastest healthy body against the speed cap";
}

TEST(HostileWorld, AGroupThatComesApartIsNotWarmStartedFromTheConvergingStepsLoads)
{
	// docs/design.md, groups without stacks. Poisoned seed 876, world mode: a column of
	// 367 t, 19.8 t and 72 kg boxes stood on an 18 g box; once the column's contact with it was
	// gone the 18 g box was alone on the floor, a group without stacks, solved by Bullet's own
	// solve, which warm started its floor points from the column's load the predictor had
	// left there (3.7e4 N s) and threw it at 1,689 m/s, 36.5 times the speed cap. Bullet's solve
	// now starts from its own impulses only: the seed stays within its bounds.
	harness::SolverSpec solver = spec::shock();
	std::vector<std::string> broken, overBound;
	Extremes extremes;
	runSeed(solver, scenes::HostileParams(), 876, broken, overBound, extremes);
	std::printf("seed 876: largest speed / cap %.3g, kinetic energy / budget %.3g\n", extremes.speedOverCap, extremes.energyOverBudget);
	EXPECT_TRUE(broken.empty());
	EXPECT_LT(extremes.speedOverCap, 1.0) << "the fastest healthy body against the speed cap";
	EXPECT_LT(extremes.energyOverBudget, 1.0) << "kinetic energy against the budget";
}
