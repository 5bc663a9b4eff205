// The truth suite (demos/truth): every case of truth::truthCases() under the plugin's defaults, in
// world mode and solver-only mode, at the app's 5, 10 and 20 iterations, must hold its physics
// statement. Each case prints
//   TRUTH | <case> | <config>: <PASS/FAIL/SKIP> <figure> <unit> (expected <expected>) | ...
// With BSP_TRUTH_STOCK=1 in the environment stock Bullet (SI at 10 and 100 iterations, SI with 4
// sub-steps, MLCP) runs too, for the report line only (bsp_truth reports every configuration; in
// CI they would only cost time: MLCP on the ragdoll ensemble alone takes a minute). With
// BSP_TRUTH_DETAIL=1 each configuration's detail line is printed as well.
#include <truth/TruthCase.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
struct Config
{
	const char* label;
	harness::SolverKind kind;
	int iterations;
	int substeps;
	bool asserted;  ///< the plugin's default: must pass
};

const Config kConfigs[] = {
	{"sp-5", harness::SolverKind::ShockWorld, 5, 1, true},
	{"sp", harness::SolverKind::ShockWorld, 10, 1, true},
	{"sp-20", harness::SolverKind::ShockWorld, 20, 1, true},
	{"sp-solver-5", harness::SolverKind::ShockSolverOnly, 5, 1, true},
	{"sp-solver", harness::SolverKind::ShockSolverOnly, 10, 1, true},
	{"sp-solver-20", harness::SolverKind::ShockSolverOnly, 20, 1, true},
	{"si-10", harness::SolverKind::StockSI, 10, 1, false},
	{"si-100", harness::SolverKind::StockSI, 100, 1, false},
	{"si-sub4", harness::SolverKind::StockSI, 10, 4, false},
	{"mlcp", harness::SolverKind::MLCPDantzig, 10, 1, false},
};

/// Truths the plugin's default does not hold yet (they would be listed in docs/design.md, section
/// 12, known limits). They run and print like the others, and the test is reported as skipped with
/// the plugin's figures (and whether it held in this build: a marginal case may hold in double
/// and not in float). None: the converging step holds all 26.
const std::vector<std::string> kOpenTruths = {};

bool isOpen(const std::string& name)
{
	for (const std::string& open : kOpenTruths)
		if (name == open) return true;
	return false;
}

bool skipped(const truth::Verdict& v) { return v.detail.rfind("skipped", 0) == 0; }

std::string reportEntry(const Config& config, const truth::Verdict& v)
{
	char buffer[256];
	if (skipped(v))
		std::snprintf(buffer, sizeof buffer, "%s: SKIP (%s)", config.label, v.detail.c_str());
	else
		std::snprintf(buffer, sizeof buffer, "%s: %s %.4g %s (expected %.4g)", config.label, v.pass ? "PASS" : "FAIL", v.figure,
					  v.unit.c_str(), v.expected);
	return buffer;
}
}  // namespace

class Truth : public ::testing::TestWithParam<size_t>
{
};

TEST_P(Truth, HoldsUnderThePluginDefault)
{
	const truth::TruthCase& c = truth::truthCases().at(GetParam());
	std::string line = "TRUTH | " + c.name;
	const bool open = isOpen(c.name);
	std::string openFigures;
	bool openHolds = true;
	for (const Config& config : kConfigs)
	{
		if (!config.asserted && !std::getenv("BSP_TRUTH_STOCK")) continue;
		harness::SolverSpec spec;  // the plugin's defaults: no plugin-only field is touched
		spec.kind = config.kind;
		spec.iterations = config.iterations;
		spec.substeps = config.substeps;
		const truth::Verdict v = c.run(spec);
		line += " | " + reportEntry(config, v);
		if (std::getenv("BSP_TRUTH_DETAIL"))
			std::printf("  %s / %s: %s (%.3f ms/step)\n", c.name.c_str(), config.label, v.detail.c_str(), v.msPerStep);
		if (config.asserted && !open)
			EXPECT_TRUE(v.pass) << c.name << " under " << config.label << " (" << c.statement << "): " << v.detail;
		if (config.asserted && open)
		{
			openHolds = openHolds && v.pass;
			openFigures += std::string(" ") + config.label + ": " + v.detail + ";";
		}
	}
	std::printf("%s\n", line.c_str());
	std::fflush(stdout);
	if (open)
	{
		// Reported, not asserted: a marginal case may hold in one build and not the other (the
		// ragdoll pile did, before D17), so an open truth that holds in this build only says so.
		GTEST_SKIP() << "open truth (docs/design.md, section 12)" << (openHolds ? ", holds in this build:" : ":") << openFigures;
	}
}

INSTANTIATE_TEST_SUITE_P(Cases, Truth, ::testing::Range(size_t(0), truth::truthCases().size()),
						 [](const ::testing::TestParamInfo<size_t>& info) { return truth::truthCases().at(info.param).name; });

TEST(ConvergingStep, APushedStackSlidesAsOneBody)
{
	// Coulomb: 5 boxes pushed at the bottom with F = 1.4 mu W slide together at (F - mu W) / M =
	// 1.962 m/s^2, the box-box friction (mu 1) holding the boxes above with room to spare: no box
	// moves relative to the bottom one. The predictor's down pass carries them as a welded
	// composite; its weld rows are settled after the transfer (btWeldedComposites.cpp, settleWelds).
	// Without that the boxes parted by 0.8 to 8.6 mm in 2 s whenever a corner of a weld let go
	// (float; the truth suite's bound is 1 cm), with it 0.015 mm. Stock SI parts them by 1.1 m.
	for (harness::SolverKind kind : {harness::SolverKind::ShockWorld, harness::SolverKind::ShockSolverOnly})
		for (int iterations : {5, 10, 20})
		{
			harness::SolverSpec spec;
			spec.kind = kind;
			spec.iterations = iterations;
			const truth::PushedStack p = truth::measurePushedStack(spec, 1.4);
			std::printf("PUSHED | %s, %d iterations: boxes apart %.2e m, a %.4f m/s^2 (Coulomb %.4f)\n",
						kind == harness::SolverKind::ShockWorld ? "world" : "solver-only", iterations, p.apart, p.acceleration, p.expected);
			EXPECT_LT(p.apart, 1e-3) << iterations << " iterations";
			EXPECT_NEAR(p.acceleration, p.expected, 0.02 * p.expected) << iterations << " iterations";
			EXPECT_FALSE(p.nonFinite);
		}
	harness::SolverSpec stock;
	stock.kind = harness::SolverKind::StockSI;
	stock.iterations = 10;
	const truth::PushedStack p = truth::measurePushedStack(stock, 1.4);
	std::printf("PUSHED | stock SI, 10 iterations: boxes apart %.2e m\n", p.apart);
	EXPECT_GT(p.apart, 1e-2);  // the scene tells a solver that lets the boxes slip from one that does not
}

