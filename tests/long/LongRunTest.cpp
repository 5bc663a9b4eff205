// Long runs (ctest -L long; not in tests/run.sh): a 9,870-box pyramid (registry "pyramid", base
// 140) simulated for 10 s keeps its resident memory flat after a 1 s warm-up, in the world mode
// and the solver-only mode. Prints the figures, e.g.
//   build/float/tests/bsp_long_tests --gtest_filter=LongRun.*
// Linux only (reads VmRSS from /proc/self/status); elsewhere the tests are skipped.

#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <harness/Metrics.h>
#include <harness/Simulation.h>
#include <scenes/Registry.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

namespace
{
constexpr double kTimeStepSeconds = 1.0 / 60.0;
constexpr int kPyramidBase = 140;        // 140 * 141 / 2 = 9,870 boxes
constexpr int kWarmUpSteps = 60;         // 1 s: every contact and buffer has been created
constexpr int kRunSteps = 600;           // 10 s
/// Allowed growth of resident memory after the warm-up (kB). The steps allocate nothing through
/// Bullet once warm (tests/robustness/MemoryTest.cpp), so this only absorbs allocator noise; a
/// per-step leak of even 100 bytes per body would be 9,870 * 540 * 100 B = 530 MB.
constexpr long kMaxGrowthKb = 4096;

/// Resident set size of this process (kB), or -1 if unknown.
long residentKb()
{
	std::ifstream status("/proc/self/status");
	std::string key;
	while (status >> key)
	{
		if (key == "VmRSS:")
		{
			long kb = -1;
			status >> kb;
			return kb;
		}
		std::getline(status, key);
	}
	return -1;
}

void runPyramid(harness::SolverKind kind, const char* label)
{
	if (residentKb() < 0) GTEST_SKIP() << "no /proc/self/status: resident memory unknown";
	harness::SolverSpec spec;
	spec.kind = kind;
	harness::Simulation sim(spec, kTimeStepSeconds);
	std::unique_ptr<scenes::SceneContent> scene = scenes::createScene(sim.world(), "pyramid", {{"base", kPyramidBase}});
	const std::vector<btRigidBody*> bodies = scene->dynamicBodies();
	ASSERT_EQ(bodies.size(), size_t(kPyramidBase * (kPyramidBase + 1) / 2));
	const long beforeKb = residentKb();
	for (int i = 0; i < kWarmUpSteps; ++i) sim.step();
	const long warmKb = residentKb();
	long peakKb = warmKb;
	for (int i = kWarmUpSteps; i < kRunSteps; ++i)
	{
		sim.step();
		if (i % 60 == 0) peakKb = std::max(peakKb, residentKb());
	}
	const long endKb = residentKb();
	peakKb = std::max(peakKb, endKb);
	std::printf("%s: %zu bodies, RSS %ld kB after building, %ld kB after 1 s, %ld kB after 10 s (peak %ld kB, growth %ld kB)\n", label,
				bodies.size(), beforeKb, warmKb, endKb, peakKb, endKb - warmKb);
	::testing::Test::RecordProperty("rss_after_warmup_kb", std::to_string(warmKb));
	::testing::Test::RecordProperty("rss_at_end_kb", std::to_string(endKb));
	EXPECT_LE(peakKb - warmKb, kMaxGrowthKb);
	EXPECT_FALSE(harness::anyNonFinite(bodies));
	scene.reset();
}
}  // namespace

TEST(LongRun, PyramidOf9870BoxesKeepsResidentMemoryFlatFor10sInShockWorld) { runPyramid(harness::SolverKind::ShockWorld, "world"); }

TEST(LongRun, PyramidOf9870BoxesKeepsResidentMemoryFlatFor10sSolverOnly) { runPyramid(harness::SolverKind::ShockSolverOnly, "solver only"); }
