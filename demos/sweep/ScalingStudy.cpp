#include "Studies.h"

#include <BulletShockPropagation/btShockPropagationConstraintSolver.h>
#include <harness/Trial.h>

#include <chrono>
#include <cstdio>
#include <memory>

namespace sweep
{
namespace
{
/// Milliseconds per measured step, split by phase (plugin: its statistics; all: collision detection).
struct Phases
{
	double total = 0, collision = 0, graph = 0, setup = 0, global = 0, layers = 0, correction = 0;
	void add(harness::Simulation& sim, double stepMs)
	{
		total += stepMs;
		collision += sim.collisionMs();  // every performDiscreteCollisionDetection of the step
		if (const btShockPropagationConstraintSolver* s = sim.shockSolver())
		{
			const btShockPropagationStatistics& st = s->getStatistics();
			graph += st.m_timeGraphMs;
			setup += st.m_timeSetupMs;
			global += st.m_timeGlobalDynamicsMs;
			layers += st.m_timeLayersMs;
			correction += st.m_timeCorrectionMs;  // finish and position correction
		}
	}
};
}  // namespace

void runScaling(const ScalingOptions& o, ResultTable& out, std::vector<std::pair<std::string, std::string>>& notes)
{
	const auto start = std::chrono::steady_clock::now();
	for (int base : o.bases)
	{
		std::vector<std::unique_ptr<harness::Trial>> trials;
		std::vector<Variant> variants;
		for (const std::string& label : o.variants)
		{
			Variant v = findVariant(label);
			v.spec.iterations = o.iterations;
			trials.emplace_back(new harness::Trial(v.spec, "pyramid", {{"base", double(base)}}));
			variants.push_back(v);
		}
		std::vector<Phases> phases(trials.size());
		for (int step = 0; step < o.warmupSteps + o.measuredSteps; ++step)
		{
			for (size_t i = 0; i < trials.size(); ++i)
			{
				harness::Simulation& sim = trials[i]->simulation();
				const auto t0 = std::chrono::steady_clock::now();
				sim.step();
				const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
				if (step >= o.warmupSteps) phases[i].add(sim, ms);
			}
		}
		for (size_t i = 0; i < trials.size(); ++i)
		{
			const double n = o.measuredSteps;
			const Phases& p = phases[i];
			out.newRow();
			out.add("solver", variants[i].label);
			out.add("base", base);
			out.add("bodies", double(trials[i]->bodies().size()));
			out.add("ms_per_step", p.total / n);
			out.add("collision_ms", p.collision / n);
			out.add("graph_ms", p.graph / n);
			out.add("setup_ms", p.setup / n);
			out.add("predictor_ms", p.layers / n);
			out.add("corrector_ms", p.global / n);
			out.add("correction_ms", p.correction / n);
			out.add("other_ms", (p.total - p.collision - p.graph - p.setup - p.global - p.layers - p.correction) / n);
			std::fprintf(stderr, "scaling: base %3d %-10s %8.2f ms/step\n", base, variants[i].label.c_str(), p.total / n);
		}
	}
	notes.push_back({"rule", "pyramids in lockstep per base, " + std::to_string(o.warmupSteps) + " untimed steps then " +
								 std::to_string(o.measuredSteps) + " timed ones, " + std::to_string(o.iterations) +
								 " iterations; collision_ms: every collision detection of the step; graph_ms: contact graph and stack "
								 "layers; setup_ms: Bullet's row setup (once per step), rows into layers; predictor_ms: shock propagation "
								 "(up and down passes, cycles); corrector_ms: Bullet's sweeps after it; correction_ms: "
								 "finish and position correction; other_ms: the rest (islands, integration, bookkeeping)"});
	notes.push_back({"scaling_seconds", std::to_string(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count())});
}
}  // namespace sweep
