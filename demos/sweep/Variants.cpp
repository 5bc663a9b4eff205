#include "Variants.h"

#include <stdexcept>

namespace sweep
{
namespace
{
Variant variant(const std::string& label, const std::string& kind, double f = 0.5, int maxIterations = 1 << 30)
{
	Variant v;
	v.label = label;
	std::string error;
	if (!harness::parseSolverKind(kind, v.spec, error)) throw std::invalid_argument(error);
	v.spec.settings.m_weighting = btScalar(f);
	v.maxIterations = maxIterations;
	return v;
}
}  // namespace

std::vector<Variant> sweepVariants()
{
	return {
		variant("si", "si"),
		variant("si2f", "si2f"),
		variant("si-sub2", "si-sub2"),
		variant("si-sub4", "si-sub4"),
		variant("si-sub8", "si-sub8"),
		variant("nncg", "nncg"),
		variant("mlcp", "mlcp"),
		variant("sp f=0", "sp", 0.0),
		variant("sp f=0.05", "sp", 0.05, 50),
		variant("sp f=0.1", "sp", 0.1, 50),
		variant("sp f=0.25", "sp", 0.25, 50),
		variant("sp f=0.5", "sp", 0.5),
		variant("sp-classic f=0.5", "sp-classic", 0.5, 200),  // Erleben's classic method (no weight feeling)
	};
}

Variant findVariant(const std::string& label)
{
	std::string labels;
	for (const Variant& v : sweepVariants())
	{
		if (v.label == label) return v;
		labels += (labels.empty() ? "" : ", ") + v.label;
	}
	throw std::invalid_argument("unknown solver variant '" + label + "'; valid: " + labels);
}

std::vector<int> sweepIterations() { return {1, 2, 5, 10, 20, 50, 100, 200}; }

std::vector<SceneCase> sweepScenes()
{
	return {
		{"tower_10", "tower", {{"n", 10}}},
		{"tower_20", "tower", {{"n", 20}}},
		{"tower_40", "tower", {{"n", 40}}},
		{"pyramid_20", "pyramid", {{"base", 20}}},
		{"pyramid_30", "pyramid", {{"base", 30}}},
		{"wall", "wall", {}},
		{"round_tower", "round_tower", {}},
		{"mass_ratio_100", "mass_ratio_tower", {{"ratio", 100}}},
		{"mass_ratio_1000", "mass_ratio_tower", {{"ratio", 1000}}},
		{"seesaw", "seesaw", {}},
	};
}
}  // namespace sweep
