// bsp_sweep: the measurements behind the charts of docs/measurements.md (demos/charts.sh runs it, then plots).
//   bsp_sweep pareto  --out DIR [--scenes a,b] [--solvers "si,sp f=0.5"] [--iterations 1,10] [--duration S] [--no-reference]
//   bsp_sweep towers  --out DIR [--heights 2,4] [--max-iterations N] [--duration S]
//   bsp_sweep scaling --out DIR [--bases 10,20] [--steps N]
// Writes DIR/<study>.csv and DIR/<study>.json. Exit code 2 on bad arguments.
#include "Studies.h"

#include <harness/CommandLine.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
[[noreturn]] void fail(const std::string& message)
{
	std::cerr << "bsp_sweep: " << message << "\n"
			  << "usage: bsp_sweep pareto|towers|scaling --out DIR [options] (see the comment at the top of demos/sweep/main.cpp)\n";
	std::exit(2);
}

/// A whole number from 1 to 1e6.
int positiveInt(const std::string& text)
{
	const int v = harness::parseInteger(text);
	if (v < 1 || v > 1000000) fail("not a positive integer (1..1e6): '" + text + "'");
	return v;
}

/// Comma-separated whole numbers from 1 to 1e6.
std::vector<int> positiveList(const std::string& text, const std::string& what)
{
	std::vector<int> out;
	for (const std::string& item : harness::splitList(text, what)) out.push_back(positiveInt(item));
	return out;
}
}  // namespace

int main(int argc, char** argv)
{
	if (argc < 2) fail("missing study");
	const std::string study = argv[1];
	if (study != "pareto" && study != "towers" && study != "scaling") fail("unknown study '" + study + "'");
	std::string outDir;
	sweep::ParetoOptions pareto;
	sweep::TowerOptions towers;
	sweep::ScalingOptions scaling;
	try
	{
		for (int i = 2; i < argc; ++i)
		{
			const std::string a = argv[i];
			auto value = [&]() -> std::string {
				if (i + 1 >= argc) fail("missing value after " + a);
				return argv[++i];
			};
			if (a == "--out") outDir = value();
			else if (a == "--scenes")
			{
				const std::vector<std::string> wanted = harness::splitList(value(), "scene");
				std::vector<sweep::SceneCase> chosen;
				for (const std::string& w : wanted)
				{
					bool found = false;
					for (const sweep::SceneCase& c : sweep::sweepScenes())
						if (c.label == w) { chosen.push_back(c); found = true; }
					if (!found) fail("unknown sweep scene '" + w + "'");
				}
				pareto.scenes = chosen;
			}
			else if (a == "--solvers")
			{
				pareto.variants.clear();
				const std::vector<std::string> labels = harness::splitList(value(), "solver");
				for (const std::string& l : labels) pareto.variants.push_back(sweep::findVariant(l));
				towers.variants = scaling.variants = labels;
			}
			else if (a == "--iterations") pareto.iterations = positiveList(value(), "iteration");
			else if (a == "--duration") pareto.durationSeconds = towers.durationSeconds = harness::parseNumber(value());
			else if (a == "--no-reference") pareto.reference = false;
			else if (a == "--heights") towers.heights = positiveList(value(), "height");
			else if (a == "--max-iterations") towers.maxIterations = positiveInt(value());
			else if (a == "--bases") scaling.bases = positiveList(value(), "base");
			else if (a == "--steps") scaling.measuredSteps = positiveInt(value());
			else fail("unknown option '" + a + "'");
		}
		if (outDir.empty()) fail("--out DIR is required");
		if (!(pareto.durationSeconds > 0)) fail("--duration must be > 0 seconds");

		sweep::ResultTable table;
		std::vector<std::pair<std::string, std::string>> notes;
		if (study == "pareto")
		{
			// Scene by scene, written after each: a long sweep leaves its finished scenes behind.
			sweep::ParetoOptions one = pareto;
			for (const sweep::SceneCase& scene : pareto.scenes)
			{
				one.scenes = {scene};
				std::vector<std::pair<std::string, std::string>> sceneNotes;
				sweep::runPareto(one, table, sceneNotes);
				notes = sceneNotes;
				table.writeCsv(outDir + "/" + study + ".csv");
				table.writeJson(outDir + "/" + study + ".json", notes);
			}
			return 0;
		}
		if (study == "towers") sweep::runTowers(towers, table, notes);
		else sweep::runScaling(scaling, table, notes);
		table.writeCsv(outDir + "/" + study + ".csv");
		table.writeJson(outDir + "/" + study + ".json", notes);
	}
	catch (const std::invalid_argument& e)
	{
		fail(e.what());
	}
	catch (const std::runtime_error& e)
	{
		std::cerr << "bsp_sweep: " << e.what() << "\n";
		return 1;
	}
	return 0;
}
