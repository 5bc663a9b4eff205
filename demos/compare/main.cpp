// bsp_demo: one registry scene under several solvers, side by side in lockstep, with a
// comparison table (and CSV / JSON for charts). The main demo of BulletShockPropagation.
#include "Report.h"
#include "SeedStudies.h"

#include <BulletShockPropagation/btShockPropagationCommon.h>
#include <harness/CommandLine.h>
#include <harness/Trial.h>
#include <scenes/Registry.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
struct Options
{
	std::string scene = "wall";
	std::vector<std::string> solvers{"si", "sp"};
	std::vector<int> iterations{10};
	double duration = 10.0;
	double timeStep = 1.0 / 60.0;
	std::vector<std::pair<std::string, double>> params;
	std::string csvPath, jsonPath;
	bool progress = true;
	harness::PluginFlags plugin;  ///< --f, --fixation, --slop, ...: each combination is one plugin run
	bool seed = false;
};

[[noreturn]] void fail(const std::string& message)
{
	std::cerr << "bsp_demo: " << message << "\n(run bsp_demo --help for usage)\n";
	std::exit(2);
}

void usage()
{
	std::cout << "usage: bsp_demo [options]\n"
				 "  --scene NAME          registry scene (default wall); --list shows them\n"
				 "  --solvers A,B,...     " << harness::solverKindNames() << "\n"
				 "                        (default si,sp)\n"
				 "  --iterations N,M,...  PGS iterations, each run for every solver (default 10)\n"
				 "  --duration S          simulated seconds (default 10)\n"
				 "  --dt S                time step in seconds (default 1/60)\n"
				 "  --param NAME=VALUE    scene parameter (repeatable); --list shows them\n"
				 "  --csv FILE            summary table as CSV\n"
				 "  --json FILE           summary and per-step series as JSON\n"
				 "  --no-progress         no progress bar\n"
				 "  --seed                the source presentation's studies as tables (--csv: every row)\n";
	harness::PluginFlags::printUsage(std::cout);
}

Options parseArguments(int argc, char** argv)
{
	Options o;
	for (int i = 1; i < argc; ++i)
	{
		const std::string a = argv[i];
		auto value = [&] { return harness::optionValue(argc, argv, i); };
		if (harness::parseSharedOption(argc, argv, i, o.plugin, usage)) continue;
		if (a == "--scene") o.scene = value();
		else if (a == "--solvers") o.solvers = harness::splitList(value(), "solver");
		else if (a == "--iterations") o.iterations = harness::parseIntegerList(value(), "iteration");
		else if (a == "--duration") o.duration = harness::parseNumber(value());
		else if (a == "--dt") o.timeStep = harness::parseNumber(value());
		else if (a == "--param") o.params.push_back(harness::parseSceneParam(value()));
		else if (a == "--csv") o.csvPath = value();
		else if (a == "--json") o.jsonPath = value();
		else if (a == "--no-progress") o.progress = false;
		else if (a == "--seed") o.seed = true;
		else fail("unknown option '" + a + "'");
	}
	if (!scenes::findScene(o.scene)) fail("unknown scene '" + o.scene + "'; valid scenes: " + scenes::sceneNames());
	if (!(o.duration > 0)) fail("--duration must be > 0 seconds");
	if (!(o.timeStep > 0 && o.timeStep <= 1)) fail("--dt must be in (0, 1] seconds");
	for (int n : o.iterations)
		if (n < 1) fail("--iterations must be >= 1");
	for (const std::string& path : {o.csvPath, o.jsonPath})
	{
		if (path.empty()) continue;
		std::ofstream probe(path, std::ios::app);
		if (!probe) fail("cannot write output file '" + path + "'");
	}
	return o;
}

Options parse(int argc, char** argv)
{
	try
	{
		return parseArguments(argc, argv);
	}
	catch (const std::invalid_argument& e)
	{
		fail(e.what());
	}
}

std::vector<harness::SolverSpec> expand(const Options& o)
{
	std::vector<harness::SolverSpec> specs;
	for (const std::string& name : o.solvers)
	{
		harness::SolverSpec base;
		std::string error;
		if (!harness::parseSolverKind(name, base, error)) fail(error);
		for (int n : o.iterations)
		{
			for (const btShockPropagationSettings& settings : o.plugin.expand(base.settings))
			{
				harness::SolverSpec s = base;
				s.iterations = n;
				s.settings = settings;
				specs.push_back(s);
				if (!s.isPlugin()) break;  // stock solvers: one run per iteration count
			}
		}
	}
	return specs;
}

}  // namespace

int main(int argc, char** argv)
{
	const Options opt = parse(argc, argv);
	if (opt.seed)
	{
		compare::runSeedStudies(std::cout, opt.csvPath, opt.progress);
		return 0;
	}
	compare::Trials trials;
	for (const harness::SolverSpec& spec : expand(opt))
	{
		try
		{
			trials.emplace_back(new harness::Trial(spec, opt.scene, opt.params, opt.timeStep));
		}
		catch (const std::exception& e)
		{
			fail(e.what());
		}
	}

	const int steps = int(opt.duration / opt.timeStep + 0.5);
	compare::runLockstep(trials, steps, opt.progress);

	std::printf("scene %s (%zu dynamic bodies), %.1f s at dt %.4f s; drift and collapse threshold %.0f cm\n", opt.scene.c_str(),
				trials.front()->bodies().size(), opt.duration, opt.timeStep, harness::kStandingDriftMeters * 100);
	std::fflush(stdout);
	compare::printTable(std::cout, trials);
	std::cout << "ratio = ms/step relative to the first row, measured side by side in this run\n";
	if (!opt.csvPath.empty())
	{
		std::ofstream csv(opt.csvPath);
		compare::writeCsv(csv, opt.scene, trials);
	}
	if (!opt.jsonPath.empty())
	{
		std::ofstream json(opt.jsonPath);
		compare::writeJson(json, opt.scene, opt.timeStep, opt.duration, trials);
	}
	return 0;
}
