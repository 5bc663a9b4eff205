// What bsp_sweep compares: the solver variants, the iteration counts and the scenes. Adding a
// solver variant is one line in sweepVariants() (Variants.cpp).
#pragma once

#include <harness/Simulation.h>

#include <string>
#include <utility>
#include <vector>

namespace sweep
{
/// One solver variant: a label for tables and charts, and its settings (iterations set per run).
struct Variant
{
	std::string label;  ///< e.g. "si-sub4", "sp f=0.25"; the family is the text before a space
	harness::SolverSpec spec;
	/// Highest iteration count of the ladder this variant runs at. The plugin's f-sweep stops at
	/// 50: from 20 iterations up every f holds every scene to under 1 mm, and the runs at 100 and
	/// 200 (the plugin's layer passes make them 50-100 ms a step on the round tower) were 30% of
	/// the sweep's time; f = 0 and 0.5 keep the full ladder.
	int maxIterations = 1 << 30;
	bool isMLCP() const { return spec.kind == harness::SolverKind::MLCPDantzig; }
};

/// Every variant of the sweep, in table order.
std::vector<Variant> sweepVariants();

/// The variant with this label; throws std::invalid_argument listing the labels.
Variant findVariant(const std::string& label);

/// Iteration counts of the sweep: 1, 2, 5, 10, 20, 50, 100, 200.
std::vector<int> sweepIterations();

/// A registry scene with parameter overrides, and how charts name it.
struct SceneCase
{
	std::string label;  ///< e.g. "tower_20"
	std::string scene;  ///< registry name
	std::vector<std::pair<std::string, double>> params;
};

/// The sweep's scenes: towers of 10/20/40, pyramids base 20 and 30, the wall, the round tower,
/// mass ratio 100 and 1000, the seesaw.
std::vector<SceneCase> sweepScenes();
}  // namespace sweep
