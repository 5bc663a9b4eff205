// bsp_bench: Google Benchmark microbenchmarks over the registry scenes (not run in CI, only built).
//   GraphAndLayers/<scene>   the plugin's contact graph + stack layers from a settled world's manifolds
//   Step/<scene>/<solver>    one 60 Hz step of each solver, timed over 300 steps (5 s) after 10
//                            settling steps; counters: drift_mm (largest body displacement from
//                            the settled state over those 5 s), pen_mm (deepest contact at the end),
//                            bodies. Accuracy next to time: a fast configuration that lets the
//                            scene fall shows it here.
// Filter with --benchmark_filter, e.g. 'Step/wall/'.
#include <BulletShockPropagation/btContactGraph.h>
#include <BulletShockPropagation/btShockPropagationSettings.h>
#include <BulletShockPropagation/btStackLayers.h>
#include <harness/Metrics.h>
#include <harness/Trial.h>
#include <scenes/Registry.h>

#include <benchmark/benchmark.h>

#include <memory>
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

/// A registry scene under the named solver (bsp_demo's names), settled for kSettleSteps frames.
std::unique_ptr<harness::Trial> settledTrial(const std::string& solver, const std::string& scene)
{
	harness::SolverSpec spec;
	std::string error;
	if (!harness::parseSolverKind(solver, spec, error)) throw std::invalid_argument(error);
	std::unique_ptr<harness::Trial> trial(new harness::Trial(spec, scene));
	for (int i = 0; i < kSettleSteps; ++i) trial->simulation().step();
	return trial;
}

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
			graph.addManifold(list.entries[i].manifold, list.entries[i].nodeA, list.entries[i].nodeB, int(i), up, settings.m_supportAngle);
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
	for (auto _ : state) w->simulation().step();  // the step alone: no metrics in the timed loop
	state.counters["drift_mm"] = drift.maxDrift() * 1e3;
	state.counters["pen_mm"] = harness::maxPenetration(*w->simulation().world().getDispatcher()) * 1e3;
	state.counters["bodies"] = double(bodies.size());
}
}  // namespace

int main(int argc, char** argv)
{
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
