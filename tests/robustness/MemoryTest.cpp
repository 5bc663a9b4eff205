// Per-step memory: once a scene has settled, a plugin step allocates nothing through Bullet's
// allocator (btAlignedAlloc: every btAlignedObjectArray of the plugin and of Bullet), so a long
// run keeps its memory flat. The resident-memory figure of a 9,870-box pyramid over 10 s is
// tests/long/LongRunTest.cpp (ctest -L long).
//
// World mode only. In the solver-only mode the same pyramid keeps flickering by a few contact
// points (it drifts 0.23 cm instead of 0.07), and both Bullet's solver setup and btAlignedObjectArray
// ::resize reserve exact sizes, so each new largest layer allocates once (9 times in these 60
// steps; the stock world with stock SI: 12). That is bounded, not a leak: the 10 s run of the
// 9,870-box pyramid in that mode grows its resident memory by 0 kB after the warm-up.

#include "../behavior/Fixture.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <harness/Simulation.h>
#include <scenes/Registry.h>

#include <LinearMath/btAlignedAllocator.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

namespace
{
using spec::kTimeStepSeconds;
constexpr int kWarmUpSteps = 120;  // 2 s: the pyramid has settled and every buffer has grown
constexpr int kCountedSteps = 60;

long gAllocations = 0;
void* countingAlloc(size_t size)
{
	++gAllocations;
	return std::malloc(size);
}
void countingFree(void* memory) { std::free(memory); }

/// Bullet allocations during kCountedSteps steps of a settled 210-box pyramid.
long allocationsOfWarmSteps(harness::SolverKind kind)
{
	harness::SolverSpec spec;
	spec.kind = kind;
	harness::Simulation sim(spec, kTimeStepSeconds);
	std::unique_ptr<scenes::SceneContent> scene = scenes::createScene(sim.world(), "pyramid", {{"base", 20}});
	for (int i = 0; i < kWarmUpSteps; ++i) sim.step();
	// Blocks allocated before the switch are freed through countingFree too: both sides use
	// malloc/free, as Bullet's default allocator does.
	btAlignedAllocSetCustom(countingAlloc, countingFree);
	gAllocations = 0;
	for (int i = 0; i < kCountedSteps; ++i) sim.step();
	const long allocations = gAllocations;
	btAlignedAllocSetCustom(nullptr, nullptr);
	scene.reset();
	return allocations;
}
}  // namespace

TEST(Memory, ShockWorldStepsAllocateNothingOnceThePyramidHasSettled)
{
	EXPECT_EQ(allocationsOfWarmSteps(harness::SolverKind::ShockWorld), 0);
}
