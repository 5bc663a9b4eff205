// Determinism: the same scene built twice from scratch in the same process, stepped 600 times
// (10 s at 60 Hz), ends with bit-identical transforms, in the world mode and in the solver-only
// mode. The two runs get different heap addresses, so nothing may depend on pointer values.
// What breaks determinism is listed in docs/design.md, section 14.

#include "../behavior/Fixture.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <harness/Simulation.h>
#include <scenes/HostileScene.h>
#include <scenes/Registry.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{
using spec::kTimeStepSeconds;
constexpr int kSteps = 600;

/// FNV-1a over the bytes of every collision object's transform (origin and basis), in the
/// world's order: equal hashes mean bit-identical transforms (up to a 64-bit collision).
std::uint64_t hashTransforms(const btCollisionWorld& world)
{
	std::uint64_t hash = 14695981039346656037ull;
	auto add = [&hash](const btScalar& x) {
		unsigned char bytes[sizeof(btScalar)];
		std::memcpy(bytes, &x, sizeof(btScalar));
		for (unsigned char b : bytes) hash = (hash ^ b) * 1099511628211ull;
	};
	for (int i = 0; i < world.getNumCollisionObjects(); ++i)
	{
		const btTransform& t = world.getCollisionObjectArray()[i]->getWorldTransform();
		for (int k = 0; k < 3; ++k) add(t.getOrigin()[k]);
		for (int r = 0; r < 3; ++r)
			for (int k = 0; k < 3; ++k) add(t.getBasis()[r][k]);
	}
	return hash;
}

using spec::plugin;

struct Hashes
{
	std::uint64_t start = 0;
	std::uint64_t end = 0;
};

/// Builds `scene` into a fresh world, optionally nudges the first dynamic body by `nudgeMeters`
/// along x, and steps it kSteps times.
Hashes runRegistryScene(harness::SolverKind kind, const std::string& scene, const std::vector<std::pair<std::string, double>>& params,
						double nudgeMeters = 0)
{
	harness::Simulation sim(plugin(kind), kTimeStepSeconds);
	std::unique_ptr<scenes::SceneContent> content = scenes::createScene(sim.world(), scene, params);
	if (nudgeMeters != 0)
	{
		btRigidBody* body = content->dynamicBodies().front();
		btTransform t = body->getWorldTransform();
		t.getOrigin() += btVector3(btScalar(nudgeMeters), 0, 0);
		body->setWorldTransform(t);
	}
	Hashes hashes;
	hashes.start = hashTransforms(sim.world());
	for (int i = 0; i < kSteps; ++i) sim.step();
	hashes.end = hashTransforms(sim.world());
	content.reset();  // the scene removes its bodies while the world exists
	return hashes;
}

class Determinism : public ::testing::TestWithParam<harness::SolverKind>
{
};

std::string kindName(const ::testing::TestParamInfo<harness::SolverKind>& info)
{
	return info.param == harness::SolverKind::ShockWorld ? "ShockWorld" : "SolverOnly";
}
}  // namespace

TEST_P(Determinism, DenseRandomPileTwiceFromScratchGivesIdenticalTransformsAfter600Steps)
{
	// 100 cubes dropped into a pit: many contacts, layers that change from step to step.
	const Hashes first = runRegistryScene(GetParam(), "dense_random", {});
	const Hashes second = runRegistryScene(GetParam(), "dense_random", {});
	EXPECT_NE(first.end, first.start) << "the pile did not move: the comparison would prove nothing";
	EXPECT_EQ(first.start, second.start);
	EXPECT_EQ(first.end, second.end);
}

TEST_P(Determinism, LoadedHingeBridgeTwiceFromScratchGivesIdenticalTransformsAfter600Steps)
{
	// Joints and contacts in one island.
	const Hashes first = runRegistryScene(GetParam(), "hinge_bridge", {});
	const Hashes second = runRegistryScene(GetParam(), "hinge_bridge", {});
	EXPECT_NE(first.end, first.start);
	EXPECT_EQ(first.end, second.end);
}

TEST_P(Determinism, HostileWorldTwiceFromScratchGivesIdenticalTransforms)
{
	// Removals, additions, teleports, NaN bodies: all replayed from the seed.
	auto run = [](harness::SolverKind kind) {
		harness::Simulation sim(plugin(kind), kTimeStepSeconds);
		scenes::HostileScene scene(sim.world(), 7);
		for (int i = 0; i < kSteps; ++i)
		{
			scene.beforeStep(kTimeStepSeconds);
			sim.step();
		}
		return hashTransforms(sim.world());
	};
	EXPECT_EQ(run(GetParam()), run(GetParam()));
}

TEST_P(Determinism, HashSeesA1MicrometreDifference)
{
	// The other side of the specs above: a run that differs by one micrometre at the start
	// hashes differently, so equal hashes do mean equal runs.
	const Hashes plain = runRegistryScene(GetParam(), "dense_random", {});
	const Hashes nudged = runRegistryScene(GetParam(), "dense_random", {}, 1e-6);
	EXPECT_NE(plain.start, nudged.start);
	EXPECT_NE(plain.end, nudged.end);
}

INSTANTIATE_TEST_SUITE_P(Robustness, Determinism, ::testing::Values(harness::SolverKind::ShockWorld, harness::SolverKind::ShockSolverOnly),
						 kindName);
