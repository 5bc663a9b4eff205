#include "Studies.h"

#include <harness/Trial.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace sweep
{
namespace
{
/// 1, 2, 3, 5, 7, 10, 15, 20, 30, 50, 70, 100, 150, ... up to `limit`.
std::vector<int> ladder(int limit)
{
	std::vector<int> counts;
	for (int decade = 1; decade <= limit; decade *= 10)
		for (int tenths : {10, 15, 20, 30, 50, 70})
		{
			const int k = decade * tenths / 10;
			if (k <= limit && (counts.empty() || k > counts.back())) counts.push_back(k);
		}
	return counts;
}

/// Steps the tower until a body passes 1 cm or the duration ends; true if it stood throughout.
bool stands(const harness::SolverSpec& spec, int height, double duration, double& msPerStep)
{
	harness::Trial trial(spec, "tower", {{"n", double(height)}});
	const int steps = int(duration / trial.simulation().timeStep() + 0.5);
	for (int i = 0; i < steps; ++i)
	{
		trial.step();
		if (trial.series().drift.back() > harness::kStandingDriftMeters || harness::anyNonFinite(trial.bodies())) break;
	}
	msPerStep = trial.summary().msPerStep;
	return trial.summary().standing && trial.steps() == steps;
}
}  // namespace

void runTowers(const TowerOptions& o, ResultTable& out, std::vector<std::pair<std::string, std::string>>& notes)
{
	const auto start = std::chrono::steady_clock::now();
	const std::vector<int> counts = ladder(o.maxIterations);
	for (const std::string& label : o.variants)
	{
		const Variant v = findVariant(label);
		for (int n : o.heights)
		{
			int needed = -1;
			int tried = 0;
			double ms = 0;
			for (int k : counts)
			{
				harness::SolverSpec spec = v.spec;
				spec.iterations = k;
				++tried;
				if (stands(spec, n, o.durationSeconds, ms))
				{
					needed = k;
					break;
				}
			}
			out.newRow();
			out.add("solver", v.label);
			out.add("boxes", n);
			out.add("iterations_needed", needed > 0 ? double(needed) : NAN);  // empty: none up to the limit
			out.add("max_iterations_tried", counts[std::min<size_t>(tried, counts.size()) - 1]);
			out.add("ms_per_step", needed > 0 ? ms : NAN);
			std::fprintf(stderr, "towers: %-10s n=%3d needs %d\n", v.label.c_str(), n, needed);
		}
	}
	notes.push_back({"rule", "smallest count of the ladder 1,2,3,5,7,10,15,20,30,50,70,100,150,... up to " + std::to_string(o.maxIterations) +
								 " whose run keeps every box within 1 cm of its start for the whole duration; a run stops at the first "
								 "body past 1 cm; empty iterations_needed: none up to the limit"});
	notes.push_back({"towers_seconds", std::to_string(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count())});
}
}  // namespace sweep
