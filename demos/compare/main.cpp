// bsp_demo: one registry scene under several solvers, side by side in lockstep, with a
// comparison table (and CSV / JSON for charts). The main demo of BulletShockPropagation.
#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <harness/Metrics.h>
#include <harness/Simulation.h>
#include <scenes/Registry.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
const double kStandingDriftMeters = 0.01;  // a body that moved more than this has "fallen"

struct Options
{
	std::string scene = "wall";
	std::vector<std::string> solvers{"si", "sp"};
	std::vector<int> iterations{10};
	std::vector<double> weightings{btShockPropagationSettings().m_weighting};
	double duration = 10.0;
	double timeStep = 1.0 / 60.0;
	std::vector<std::pair<std::string, double>> params;
	std::string csvPath, jsonPath, seriesPath;
	bool progress = true;
	int fixationMode = -1;
	bool globalSecondCorrection = false;
};

struct Run
{
	harness::SolverSpec spec;
	std::unique_ptr<harness::Simulation> sim;
	std::unique_ptr<scenes::SceneContent> scene;
	std::vector<btRigidBody*> bodies;
	std::unique_ptr<harness::DriftTracker> drift;
	double weight = 0;
	// results
	double collapseTime = -1;
	double maxDrift = 0, maxPenetration = 0;
	double keSum = 0, reactionSum = 0;
	int lastSecondSteps = 0;
	double seconds = 0;
	int layers = 0;
	bool nonFinite = false;
	std::vector<double> seriesDrift, seriesPenetration, seriesKE, seriesReaction;
};

[[noreturn]] void fail(const std::string& message)
{
	std::cerr << "bsp_demo: " << message << "\n(run bsp_demo --help for usage)\n";
	std::exit(2);
}

template <class T>
std::vector<T> parseList(const std::string& text, const char* what, T (*convert)(const std::string&))
{
	std::vector<T> out;
	std::stringstream in(text);
	std::string item;
	while (std::getline(in, item, ','))
	{
		if (item.empty()) fail(std::string("empty entry in ") + what + " list '" + text + "'");
		out.push_back(convert(item));
	}
	if (out.empty()) fail(std::string("empty ") + what + " list");
	return out;
}

double toDouble(const std::string& s)
{
	char* end = nullptr;
	const double v = std::strtod(s.c_str(), &end);
	if (s.empty() || *end != '\0' || !std::isfinite(v)) fail("not a number: '" + s + "'");
	return v;
}

int toInt(const std::string& s)
{
	const double v = toDouble(s);
	if (v != std::floor(v)) fail("not an integer: '" + s + "'");
	return int(v);
}

std::string toString(const std::string& s) { return s; }

void usage()
{
	std::cout << "usage: bsp_demo [options]\n"
				 "  --scene NAME          registry scene (default wall); --list shows them\n"
				 "  --solvers A,B,...     " << harness::solverKindNames() << "\n"
				 "                        (default si,sp)\n"
				 "  --iterations N,M,...  PGS iterations, each run for every solver (default 10)\n"
				 "  --f F,G,...           plugin weighting values in [0,1] (default 0.5)\n"
				 "  --duration S          simulated seconds (default 10)\n"
				 "  --dt S                time step in seconds (default 1/60)\n"
				 "  --param NAME=VALUE    scene parameter (repeatable); --list shows them\n"
				 "  --csv FILE            summary table as CSV\n"
				 "  --json FILE           summary and per-step series as JSON\n"
				 "  --fixation MODE       plugin fixation: linear (default), keep, zero\n"
				 "  --global-correction   plugin: the paper's un-layered second correction\n"
				 "  --no-progress         no progress bar\n";
}

void listScenes()
{
	for (const scenes::SceneEntry& e : scenes::registry())
	{
		std::cout << e.category << "/" << e.name << ": " << e.description << "\n";
		for (const scenes::Param& p : e.defaults)
			std::cout << "    " << p.name << " = " << p.value << " " << p.unit << "  " << p.description << "\n";
	}
}

Options parse(int argc, char** argv)
{
	Options o;
	for (int i = 1; i < argc; ++i)
	{
		const std::string a = argv[i];
		auto value = [&]() -> std::string {
			if (i + 1 >= argc) fail("missing value after " + a);
			return argv[++i];
		};
		if (a == "--help" || a == "-h") { usage(); std::exit(0); }
		else if (a == "--list") { listScenes(); std::exit(0); }
		else if (a == "--scene") o.scene = value();
		else if (a == "--solvers") o.solvers = parseList<std::string>(value(), "solver", toString);
		else if (a == "--iterations") o.iterations = parseList<int>(value(), "iteration", toInt);
		else if (a == "--f") o.weightings = parseList<double>(value(), "f", toDouble);
		else if (a == "--duration") o.duration = toDouble(value());
		else if (a == "--dt") o.timeStep = toDouble(value());
		else if (a == "--param")
		{
			const std::string kv = value();
			const auto eq = kv.find('=');
			if (eq == std::string::npos) fail("--param wants NAME=VALUE, got '" + kv + "'");
			o.params.push_back({kv.substr(0, eq), toDouble(kv.substr(eq + 1))});
		}
		else if (a == "--csv") o.csvPath = value();
		else if (a == "--json") o.jsonPath = value();
		else if (a == "--no-progress") o.progress = false;
		else if (a == "--global-correction") o.globalSecondCorrection = true;
		else if (a == "--fixation")
		{
			const std::string m = value();
			if (m == "keep") o.fixationMode = BT_FIXATION_KEEP_VELOCITY;
			else if (m == "zero") o.fixationMode = BT_FIXATION_ZERO_VELOCITY;
			else if (m == "linear") o.fixationMode = BT_FIXATION_KEEP_LINEAR_VELOCITY;
			else fail("unknown fixation mode '" + m + "'; valid: linear, keep, zero");
		}
		else fail("unknown option '" + a + "'");
	}
	if (!scenes::findScene(o.scene)) fail("unknown scene '" + o.scene + "'; valid scenes: " + scenes::sceneNames());
	if (!(o.duration > 0)) fail("--duration must be > 0 seconds");
	if (!(o.timeStep > 0 && o.timeStep <= 1)) fail("--dt must be in (0, 1] seconds");
	for (int n : o.iterations)
		if (n < 1) fail("--iterations must be >= 1");
	for (double f : o.weightings)
		if (!(f >= 0 && f <= 1)) fail("--f values must be in [0, 1]");
	for (const std::string& path : {o.csvPath, o.jsonPath})
	{
		if (path.empty()) continue;
		std::ofstream probe(path, std::ios::app);
		if (!probe) fail("cannot write output file '" + path + "'");
	}
	return o;
}

std::vector<harness::SolverSpec> expand(const Options& o)
{
	std::vector<harness::SolverSpec> specs;
	for (const std::string& name : o.solvers)
	{
		harness::SolverSpec base;
		std::string error;
		if (!harness::parseSolverKind(name, base, error)) fail(error);
		const bool shock = base.kind == harness::SolverKind::ShockWorld || base.kind == harness::SolverKind::ShockSolverOnly;
		for (int n : o.iterations)
		{
			for (size_t k = 0; k < (shock ? o.weightings.size() : 1); ++k)
			{
				harness::SolverSpec s = base;
				s.iterations = n;
				s.weighting = o.weightings[k];
				s.fixationMode = o.fixationMode;
				s.globalSecondCorrection = o.globalSecondCorrection;
				specs.push_back(s);
			}
		}
	}
	return specs;
}

void progressBar(double fraction)
{
	const int width = 40;
	const int filled = int(fraction * width + 0.5);
	std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "========================================", width - filled, "", int(fraction * 100 + 0.5));
	std::fflush(stderr);
}
}  // namespace

int main(int argc, char** argv)
{
	const Options opt = parse(argc, argv);
	std::vector<std::unique_ptr<Run>> runs;
	for (const harness::SolverSpec& spec : expand(opt))
	{
		std::unique_ptr<Run> r(new Run);
		r->spec = spec;
		r->sim.reset(new harness::Simulation(spec, opt.timeStep));
		try
		{
			r->scene = scenes::createScene(r->sim->world(), opt.scene, opt.params);
		}
		catch (const std::exception& e)
		{
			fail(e.what());
		}
		r->bodies = r->scene->dynamicBodies();
		r->drift.reset(new harness::DriftTracker(r->bodies));
		runs.push_back(std::move(r));
	}

	const int steps = int(opt.duration / opt.timeStep + 0.5);
	const int lastSecondFrom = steps - int(1.0 / opt.timeStep + 0.5);
	const bool showProgress = opt.progress && isatty(2);
	for (int step = 0; step < steps; ++step)
	{
		for (std::unique_ptr<Run>& r : runs)
		{
			const auto t0 = std::chrono::steady_clock::now();
			r->sim->step();
			r->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
			btDispatcher& dispatcher = *r->sim->world().getDispatcher();
			const double drift = r->drift->maxDrift();
			const double penetration = harness::maxPenetration(dispatcher);
			const double ke = harness::kineticEnergy(r->bodies);
			const double reaction = harness::groundReactionOverWeight(dispatcher, r->scene->ground(), r->bodies, opt.timeStep, r->sim->gravity());
			r->maxDrift = std::max(r->maxDrift, drift);
			r->maxPenetration = std::max(r->maxPenetration, penetration);
			if (r->collapseTime < 0 && drift > kStandingDriftMeters) r->collapseTime = r->sim->time();
			if (step >= lastSecondFrom)
			{
				r->keSum += ke;
				r->reactionSum += reaction;
				++r->lastSecondSteps;
			}
			if (r->sim->shockSolver()) r->layers = std::max(r->layers, r->sim->shockSolver()->getStatistics().m_numLayers);
			r->nonFinite = r->nonFinite || harness::anyNonFinite(r->bodies);
			r->seriesDrift.push_back(drift);
			r->seriesPenetration.push_back(penetration);
			r->seriesKE.push_back(ke);
			r->seriesReaction.push_back(reaction);
		}
		if (showProgress && (step % 10 == 0 || step == steps - 1)) progressBar(double(step + 1) / steps);
	}
	if (showProgress) std::fprintf(stderr, "\n");

	const scenes::SceneEntry* entry = scenes::findScene(opt.scene);
	std::printf("scene %s (%zu dynamic bodies), %.1f s at dt %.4f s; drift and collapse threshold %.0f cm\n", entry->name.c_str(),
				runs.front()->bodies.size(), opt.duration, opt.timeStep, kStandingDriftMeters * 100);
	std::printf("%-22s %-12s %10s %10s %10s %12s %9s %9s %10s %7s\n", "solver", "standing", "maxdrift", "rmsdrift", "maxpen", "KE(last 1s)", "ground/W", "ms/step", "ratio", "layers");
	const double baseMs = runs.front()->seconds * 1e3 / steps;
	for (const std::unique_ptr<Run>& r : runs)
	{
		char standing[32];
		if (r->nonFinite) std::snprintf(standing, sizeof standing, "NaN");
		else if (r->collapseTime < 0) std::snprintf(standing, sizeof standing, "yes");
		else std::snprintf(standing, sizeof standing, "moved@%.2fs", r->collapseTime);
		const double ms = r->seconds * 1e3 / steps;
		std::printf("%-22s %-12s %8.2fcm %8.2fcm %8.2fmm %10.3g J %9.3f %9.3f %9.2fx %7d\n", r->spec.label().c_str(), standing, r->maxDrift * 100,
					r->drift->rmsDrift() * 100, r->maxPenetration * 1e3, r->keSum / std::max(1, r->lastSecondSteps), r->reactionSum / std::max(1, r->lastSecondSteps), ms,
					ms / baseMs, r->layers);
	}
	std::printf("ratio = ms/step relative to the first row, measured side by side in this run\n");

	if (!opt.csvPath.empty())
	{
		std::ofstream csv(opt.csvPath);
		csv << "scene,solver,iterations,f,substeps,standing,collapse_s,max_drift_m,rms_drift_m,max_penetration_m,ke_last_second_j,ground_over_weight,ms_per_step,layers\n";
		for (const std::unique_ptr<Run>& r : runs)
			csv << opt.scene << "," << r->spec.label().substr(0, r->spec.label().find(' ')) << "," << r->spec.iterations << "," << r->spec.weighting << "," << r->spec.substeps << ","
				<< (r->collapseTime < 0 && !r->nonFinite) << "," << r->collapseTime << "," << r->maxDrift << "," << r->drift->rmsDrift() << "," << r->maxPenetration << ","
				<< r->keSum / std::max(1, r->lastSecondSteps) << "," << r->reactionSum / std::max(1, r->lastSecondSteps) << "," << r->seconds * 1e3 / steps << "," << r->layers << "\n";
	}
	if (!opt.jsonPath.empty())
	{
		std::ofstream js(opt.jsonPath);
		js << "{\"scene\":\"" << opt.scene << "\",\"dt\":" << opt.timeStep << ",\"duration\":" << opt.duration << ",\"runs\":[";
		for (size_t i = 0; i < runs.size(); ++i)
		{
			const Run& r = *runs[i];
			auto series = [&](const char* name, const std::vector<double>& v) {
				js << ",\"" << name << "\":[";
				for (size_t k = 0; k < v.size(); ++k) js << (k ? "," : "") << v[k];
				js << "]";
			};
			js << (i ? "," : "") << "{\"solver\":\"" << r.spec.label() << "\",\"iterations\":" << r.spec.iterations << ",\"f\":" << r.spec.weighting
			   << ",\"substeps\":" << r.spec.substeps << ",\"standing\":" << (r.collapseTime < 0 && !r.nonFinite ? "true" : "false") << ",\"collapse_s\":" << r.collapseTime
			   << ",\"max_drift_m\":" << r.maxDrift << ",\"rms_drift_m\":" << r.drift->rmsDrift() << ",\"max_penetration_m\":" << r.maxPenetration
			   << ",\"ms_per_step\":" << r.seconds * 1e3 / steps << ",\"layers\":" << r.layers;
			series("drift_m", r.seriesDrift);
			series("penetration_m", r.seriesPenetration);
			series("kinetic_energy_j", r.seriesKE);
			series("ground_over_weight", r.seriesReaction);
			js << "}";
		}
		js << "]}\n";
	}
	return 0;
}
