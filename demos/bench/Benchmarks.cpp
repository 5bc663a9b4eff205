// bsp_bench: Google Benchmark microbenchmarks over the registry scenes (not run in CI, only built).
//   GraphAndLayers/<scene>   the plugin's contact graph + stack layers from a settled world's manifolds
//   Step/<scene>/<solver>    one 60 Hz step of each solver, timed over 300 steps (5 s) after 10
//                            settling steps, at the scene's app iteration count (facts["appIterations"],
//                            e.g. 5 for the BenchmarkDemo ports stack_1000 and boxes_3000; Bullet's
//                            default 10 otherwise); counters: drift_mm (largest body displacement from
//                            the settled state over those 5 s), pen_mm (deepest contact at the end),
//                            bodies, iterations, and per step: coll_ms (Bullet's collision detection,
//                            every call) and, for the plugin, its phases from btShockPropagationStatistics
//                            (graph_ms, setup_ms, predictor_ms, corrector_ms, corr_ms). Accuracy next to time: a
//                            fast configuration that lets the scene fall shows it here.
// Filter with --benchmark_filter, e.g. 'Step/wall/'.
//
// bsp_bench --ratios [--steps N] [--warmup N] [--scenes a,b,...] [--classic] [plugin flags]
//   The cost ratios of issue 16: plugin ms/step over stock SI ms/step, world mode (sp) and solver-only
//   mode (sp-solver), on the registry's towers, pyramids, wall, round tower, a scene without stacks and
//   the BenchmarkDemo ports, each at the scene's app iteration count. The three worlds are stepped in
//   lockstep in one process (one step of each in turn, the order rotating every step), so machine noise
//   hits all three alike. Timed over 2 s after 10 warm-up steps (towers, boxes_3000: 10 s); --steps sets every
//   scene's count. Prints one table, then the per-phase split. bsp_demo's plugin flags (one value
//   each, e.g. --no-support-blocks) set both plugin worlds' settings, --classic runs Erleben's classic
//   method (no weight feeling) in both: the price of a decision.
#include <BulletShockPropagation/btContactGraph.h>
#include <BulletShockPropagation/btShockPropagationConstraintSolver.h>
#include <BulletShockPropagation/btShockPropagationSettings.h>
#include <BulletShockPropagation/btStackLayers.h>
#include <harness/CommandLine.h>
#include <harness/Metrics.h>
#include <harness/Trial.h>
#include <scenes/Registry.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace
{
constexpr int kSettleSteps = 10;  ///< steps before timing: manifolds exist, warm starts are in place
constexpr int kMaxMLCPBodies = 100;  ///< Dantzig is O(rows^3): bigger scenes take seconds per step
/// Steps timed per Step benchmark, the same for every solver (5 s at 60 Hz), so that the drift and
/// penetration counters of two solvers on a scene describe the same simulated time.
constexpr int kMeasuredSteps = 300;

/// Bullet's default m_numIterations, for scenes that record no app iteration count.
constexpr int kDefaultIterations = 10;

using Overrides = std::vector<std::pair<std::string, double>>;

/// The iteration count the scene's app asks for (facts["appIterations"]), else Bullet's default.
int appIterations(const scenes::SceneContent& scene)
{
	const auto found = scene.facts.find("appIterations");
	return found == scene.facts.end() ? kDefaultIterations : int(found->second);
}

/// A registry scene under the named solver (bsp_demo's names) at the scene's app iteration count.
/// The count is set on the world's solver info after the scene is built, as an app sets it; the
/// plugin's sweep counts follow it.
std::unique_ptr<harness::Trial> appTrial(const std::string& solver, const std::string& scene, const Overrides& overrides = {},
										 const btShockPropagationSettings& plugin = btShockPropagationSettings())
{
	harness::SolverSpec spec;
	std::string error;
	if (!harness::parseSolverKind(solver, spec, error)) throw std::invalid_argument(error);
	if (spec.isPlugin())
	{
		const bool weightFeeling = spec.settings.m_weightFeeling;  // the kind's (sp-classic: off)
		spec.settings = plugin;
		spec.settings.m_weightFeeling = weightFeeling && plugin.m_weightFeeling;
	}
	std::unique_ptr<harness::Trial> trial(new harness::Trial(spec, scene, overrides));
	trial->simulation().world().getSolverInfo().m_numIterations = appIterations(trial->scene());
	return trial;
}

/// appTrial() settled for kSettleSteps frames.
std::unique_ptr<harness::Trial> settledTrial(const std::string& solver, const std::string& scene)
{
	std::unique_ptr<harness::Trial> trial = appTrial(solver, scene);
	for (int i = 0; i < kSettleSteps; ++i) trial->simulation().step();
	return trial;
}

/// Per-step costs summed over steps: Bullet's collision detection and the plugin's phases (ms).
struct PhaseSums
{
	int steps = 0;
	double total = 0;  ///< the whole step (ratio mode only; Google Benchmark times Step itself)
	double collision = 0, graph = 0, setup = 0, global = 0, layers = 0, correction = 0;
	double globalSweeps = 0, layerSweeps = 0;  ///< corrector sweeps, predictor sweeps (statistics, summed over the step's groups)

	/// Adds the last step of `sim` (its statistics describe that step).
	void add(harness::Simulation& sim)
	{
		++steps;
		collision += sim.collisionMs();
		if (const btShockPropagationConstraintSolver* solver = sim.shockSolver())
		{
			const btShockPropagationStatistics& st = solver->getStatistics();
			graph += st.m_timeGraphMs;
			setup += st.m_timeSetupMs;
			global += st.m_timeGlobalDynamicsMs;
			layers += st.m_timeLayersMs;
			correction += st.m_timeCorrectionMs;
			globalSweeps += st.m_numGlobalSweeps;
			layerSweeps += st.m_numLayerSweeps;
		}
	}
	double perStep(double sum) const { return steps > 0 ? sum / steps : 0; }
};

/// The world's manifolds with their bodies' node numbers (the scene's dynamic bodies; static ones
/// are roots), as the plugin's solver hands them to btContactGraph.
struct ManifoldList
{
	int numBodies = 0;
	struct Entry
	{
		const btPersistentManifold* manifold;
		int nodeA, nodeB;
	};
	std::vector<Entry> entries;
};

ManifoldList manifoldsOf(harness::Trial& w)
{
	ManifoldList list;
	const std::vector<btRigidBody*>& bodies = w.bodies();
	std::unordered_map<const btCollisionObject*, int> node;
	for (size_t i = 0; i < bodies.size(); ++i) node[bodies[i]] = int(i);
	list.numBodies = int(bodies.size());
	auto nodeOf = [&](const btCollisionObject* o) {
		const auto found = node.find(o);
		return found == node.end() ? int(BT_CONTACT_GRAPH_ROOT) : found->second;
	};
	btDispatcher& dispatcher = *w.simulation().world().getDispatcher();
	for (int i = 0; i < dispatcher.getNumManifolds(); ++i)
	{
		const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
		list.entries.push_back({m, nodeOf(m->getBody0()), nodeOf(m->getBody1())});
	}
	return list;
}

void graphAndLayers(benchmark::State& state, const std::string& scene)
{
	const std::unique_ptr<harness::Trial> w = settledTrial("si", scene);
	const ManifoldList list = manifoldsOf(*w);
	const btShockPropagationSettings settings;
	const btVector3 up(0, 1, 0);
	btContactGraph graph;
	btStackLayers layers;
	for (auto _ : state)
	{
		// The plugin's own edge rule and support test (btContactGraph::addManifold), then the layers.
		graph.reset(list.numBodies);
		for (size_t i = 0; i < list.entries.size(); ++i)
			graph.addManifold(list.entries[i].manifold, list.entries[i].nodeA, list.entries[i].nodeB, int(i), up, settings.m_diagnostics.m_supportAngle);
		graph.buildAdjacency();
		layers.build(graph);
		benchmark::DoNotOptimize(layers.getNumLayers());
	}
	state.counters["bodies"] = list.numBodies;
	state.counters["edges"] = graph.getNumEdges();
	state.counters["layers"] = layers.getNumLayers();
}

void step(benchmark::State& state, const std::string& scene, const std::string& solver)
{
	const std::unique_ptr<harness::Trial> w = settledTrial(solver, scene);
	const std::vector<btRigidBody*>& bodies = w->bodies();
	const harness::DriftTracker drift(bodies);  // from the settled state
	harness::Simulation& sim = w->simulation();
	PhaseSums phases;
	for (auto _ : state)
	{
		sim.step();  // the step alone: no metrics in the timed loop
		phases.add(sim);  // reads a few numbers the step already measured
	}
	state.counters["drift_mm"] = drift.maxDrift() * 1e3;
	state.counters["pen_mm"] = harness::maxPenetration(*sim.world().getDispatcher()) * 1e3;
	state.counters["bodies"] = double(bodies.size());
	state.counters["iterations"] = sim.world().getSolverInfo().m_numIterations;
	state.counters["coll_ms"] = phases.perStep(phases.collision);
	if (sim.shockSolver())
	{
		state.counters["graph_ms"] = phases.perStep(phases.graph);
		state.counters["setup_ms"] = phases.perStep(phases.setup);
		state.counters["predictor_ms"] = phases.perStep(phases.layers);
		state.counters["corrector_ms"] = phases.perStep(phases.global);
		state.counters["corr_ms"] = phases.perStep(phases.correction);
	}
}

// ---------------------------------------------------------------------------------------------------
// --ratios: plugin / stock ms per step, side by side in one process.

struct RatioCase
{
	std::string label;  ///< as printed
	std::string scene;
	Overrides overrides;
	/// Timed steps when --steps is not given (0: RatioOptions::steps). boxes_3000 needs 10 s: its 47
	/// layers fall together and pile up one after another for about 6 s, so 2 s would time free fall.
	/// The towers take 10 s too: at 0.1 ms a step, 2 s is too short a sample against machine noise.
	int steps = 0;
};

/// The scenes issue 16 measures: towers, pyramids, wall, round tower, a scene without stacks (at rest
/// and sliding) and the BenchmarkDemo ports, at the registry's defaults unless the label says otherwise.
std::vector<RatioCase> ratioCases()
{
	return {
		{"tower n=20 (10 s)", "tower", {{"n", 20}}, 600},
		{"tower n=40 (10 s)", "tower", {{"n", 40}}, 600},
		{"pyramid base=20", "pyramid", {{"base", 20}}},
		{"pyramid base=30", "pyramid", {{"base", 30}}},
		{"wall", "wall", {}},
		{"round_tower", "round_tower", {}},
		{"flat_boxes (rest)", "flat_boxes", {}},
		{"flat_boxes v0=3 mu=0.1", "flat_boxes", {{"v0", 3}, {"mu", 0.1}}},
		{"stack_1000", "stack_1000", {}},
		{"boxes_3000 (10 s)", "boxes_3000", {}, 600},
		{"dense_random pile (10 s)", "dense_random", {}, 600},
		{"basic_demo_block (5 s)", "basic_demo_block", {}, 300},
		// Issue 37's shape grid: columns of 10 bodies of other shapes on other grounds.
		{"hull column on heightfield (10 s)", "shape_column", {{"shape", 1}, {"ground", 4}}, 600},
		{"prism column on box (10 s)", "shape_column", {{"shape", 3}, {"ground", 0}}, 600},
		{"cylinder column on mesh (10 s)", "shape_column", {{"shape", 4}, {"ground", 2}}, 600},
		{"compound column on plane (10 s)", "shape_column", {{"shape", 5}, {"ground", 1}}, 600},
	};
}

struct RatioOptions
{
	int warmup = 10;   ///< steps of each world before timing
	int steps = 120;   ///< timed steps of each world (2 s at 60 Hz), unless the case says otherwise
	bool stepsGiven = false;  ///< --steps given: it applies to every case
	std::vector<std::string> only;  ///< labels or scene names to run (empty: all)
	/// The plugin's settings for both plugin worlds: the defaults unless plugin flags were given
	/// (one value each), to price a decision against the same stock steps.
	btShockPropagationSettings plugin;
	std::string pluginLabel;  ///< the non-default flags, as SolverSpec::label() names them
};

struct RatioRow
{
	std::string label;
	int bodies = 0;
	int iterations = 0;
	PhaseSums si, sp, spSolver;
	double siDrift = 0, spDrift = 0, spSolverDrift = 0;  ///< m, largest body displacement from the start at the end
};

RatioRow measureRatio(const RatioCase& c, const RatioOptions& o)
{
	const char* names[3] = {"si", "sp", "sp-solver"};
	std::unique_ptr<harness::Trial> trials[3];
	for (int k = 0; k < 3; ++k) trials[k] = appTrial(names[k], c.scene, c.overrides, o.plugin);
	RatioRow row;
	row.label = c.label;
	row.bodies = int(trials[0]->bodies().size());
	row.iterations = trials[0]->simulation().world().getSolverInfo().m_numIterations;
	PhaseSums* sums[3] = {&row.si, &row.sp, &row.spSolver};
	const int steps = (c.steps > 0 && !o.stepsGiven) ? c.steps : o.steps;
	for (int i = 0; i < o.warmup + steps; ++i)
	{
		// One step of each world, in an order that rotates every step: a slow moment of the machine
		// (another process, a frequency change) lands on all three alike.
		for (int j = 0; j < 3; ++j)
		{
			const int k = (i + j) % 3;
			harness::Simulation& sim = trials[k]->simulation();
			const auto start = std::chrono::steady_clock::now();
			sim.step();
			const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
			if (i < o.warmup) continue;
			sums[k]->total += ms;
			sums[k]->add(sim);
		}
	}
	row.siDrift = trials[0]->drift().maxDrift();
	row.spDrift = trials[1]->drift().maxDrift();
	row.spSolverDrift = trials[2]->drift().maxDrift();
	return row;
}

std::string fixed(double value, int decimals)
{
	char text[64];
	std::snprintf(text, sizeof text, "%.*f", decimals, value);
	return text;
}

void printRatios(const std::vector<RatioRow>& rows, const RatioOptions& o)
{
	std::printf("plugin / stock SI ms per step, side by side (lockstep, %d warm-up + %d timed steps of each world unless the scene says otherwise, 60 Hz)\n",
				o.warmup, o.steps);
	if (!o.pluginLabel.empty()) std::printf("plugin flags:%s\n", o.pluginLabel.c_str());
	std::printf("%-24s %7s %4s %10s %10s %7s %13s %7s   %s\n", "scene", "bodies", "it", "stock ms", "sp ms", "ratio", "sp-solver ms", "ratio",
				"drift at end si / sp / sp-solver (cm)");
	for (const RatioRow& r : rows)
	{
		const double si = r.si.perStep(r.si.total), sp = r.sp.perStep(r.sp.total), sps = r.spSolver.perStep(r.spSolver.total);
		std::printf("%-24s %7d %4d %10.3f %10.3f %6.2fx %13.3f %6.2fx   %s / %s / %s\n", r.label.c_str(), r.bodies, r.iterations, si, sp, sp / si, sps,
					sps / si, fixed(r.siDrift * 100, 1).c_str(), fixed(r.spDrift * 100, 1).c_str(), fixed(r.spSolverDrift * 100, 1).c_str());
	}
	std::printf("\nper-phase ms per step (coll: Bullet's collision detection, every call; the rest from btShockPropagationStatistics)\n");
	std::printf("%-24s %-10s %8s %8s %8s %8s %9s %9s %8s   %s\n", "scene", "solver", "step", "coll", "graph", "setup", "predictor", "corrector", "corr",
				"sweeps per step predictor / corrector");
	for (const RatioRow& r : rows)
	{
		const PhaseSums* sums[3] = {&r.si, &r.sp, &r.spSolver};
		const char* names[3] = {"si", "sp", "sp-solver"};
		for (int k = 0; k < 3; ++k)
		{
			const PhaseSums& p = *sums[k];
			if (k == 0)
				std::printf("%-24s %-10s %8.3f %8.3f %8s %8s %9s %9s %8s\n", r.label.c_str(), names[k], p.perStep(p.total), p.perStep(p.collision), "-", "-", "-", "-", "-");
			else
				std::printf("%-24s %-10s %8.3f %8.3f %8.3f %8.3f %9.3f %9.3f %8.3f   %.1f / %.1f\n", r.label.c_str(), names[k], p.perStep(p.total),
							p.perStep(p.collision), p.perStep(p.graph), p.perStep(p.setup), p.perStep(p.layers), p.perStep(p.global),
							p.perStep(p.correction), p.perStep(p.layerSweeps), p.perStep(p.globalSweeps));
		}
	}
	std::fflush(stdout);
}

int positiveInt(const std::string& text, const std::string& option)
{
	char* end = nullptr;
	const long n = std::strtol(text.c_str(), &end, 10);
	if (text.empty() || *end != '\0' || n < 1 || n > 1000000) throw std::invalid_argument(option + " wants a whole number >= 1, got '" + text + "'");
	return int(n);
}

int runRatios(int argc, char** argv)
{
	RatioOptions o;
	harness::PluginFlags flags;
	bool classic = false;  // Erleben's classic method (no weight feeling) in both plugin worlds
	for (int i = 1; i < argc; ++i)
	{
		const std::string arg = argv[i];
		const bool hasValue = i + 1 < argc;
		if (arg == "--ratios") continue;
		if (flags.parse(argc, argv, i)) continue;
		if (arg == "--classic")
		{
			classic = true;
			continue;
		}
		if (arg == "--steps" && hasValue)
		{
			o.steps = positiveInt(argv[++i], arg);
			o.stepsGiven = true;
		}
		else if (arg == "--warmup" && hasValue) o.warmup = positiveInt(argv[++i], arg);
		else if (arg == "--scenes" && hasValue)
		{
			std::stringstream list(argv[++i]);
			for (std::string name; std::getline(list, name, ',');) o.only.push_back(name);
		}
		else
		{
			std::cerr << "bsp_bench --ratios: unknown option '" << arg
					  << "'; valid: --steps N, --warmup N, --scenes a,b,..., --classic and bsp_demo's plugin flags (one value each)\n";
			return 2;
		}
	}
	const std::vector<btShockPropagationSettings> variants = flags.expand();
	if (variants.size() != 1)
	{
		std::cerr << "bsp_bench --ratios: give each plugin flag one value (got " << variants.size() << " combinations)\n";
		return 2;
	}
	o.plugin = variants[0];
	o.pluginLabel = harness::pluginSettingsLabel(o.plugin);
	if (o.pluginLabel == harness::pluginSettingsLabel(btShockPropagationSettings())) o.pluginLabel.clear();
	if (classic)
	{
		o.plugin.m_weightFeeling = false;
		o.pluginLabel += " classic (no weight feeling)";
	}
	std::vector<RatioRow> rows;
	for (const RatioCase& c : ratioCases())
	{
		bool wanted = o.only.empty();
		for (const std::string& name : o.only) wanted = wanted || name == c.scene || name == c.label;
		if (!wanted) continue;
		std::cerr << "measuring " << c.label << " ...\n";
		rows.push_back(measureRatio(c, o));
	}
	printRatios(rows, o);
	return 0;
}
}  // namespace

int main(int argc, char** argv)
{
	for (int i = 1; i < argc; ++i)
	{
		if (std::strcmp(argv[i], "--ratios") == 0)
		{
			try
			{
				return runRatios(argc, argv);
			}
			catch (const std::invalid_argument& error)
			{
				std::cerr << "bsp_bench --ratios: " << error.what() << "\n";
				return 2;
			}
		}
	}
	const char* solvers[] = {"si", "si2f", "si-sub4", "nncg", "mlcp", "sp", "sp-solver"};
	for (const scenes::SceneEntry& e : scenes::registry())
	{
		benchmark::RegisterBenchmark(("GraphAndLayers/" + e.name).c_str(), graphAndLayers, e.name)->Unit(benchmark::kMicrosecond);
		for (const char* solver : solvers)
		{
			if (std::string(solver) == "mlcp")
			{
				const harness::Trial probe(harness::SolverSpec(), e.name);
				if (int(probe.bodies().size()) > kMaxMLCPBodies) continue;
			}
			benchmark::RegisterBenchmark(("Step/" + e.name + "/" + solver).c_str(), step, e.name, std::string(solver))->Unit(benchmark::kMillisecond)->Iterations(kMeasuredSteps);
		}
	}
	benchmark::Initialize(&argc, argv);
	if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
	benchmark::RunSpecifiedBenchmarks();
	benchmark::Shutdown();
	return 0;
}
