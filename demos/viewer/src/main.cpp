// bsp_viewer: one registry scene under several solvers, side by side in lockstep - live in a
// window, or headless into a PNG (a grid of viewports: columns = solvers, rows = times).
#include "Interactive.h"

#include "viewer/Labels.h"
#include "viewer/Offscreen.h"
#include "viewer/Pictures.h"
#include "viewer/Renderer.h"

#include <BulletShockPropagation/btShockPropagationSettings.h>
#include <harness/CommandLine.h>
#include <scenes/Registry.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
struct Options
{
	viewer::ComparisonSetup setup;
	std::vector<std::string> solvers{"si", "si", "sp"};
	std::vector<int> iterations;  // empty: 10,100,10 for the default solvers, else 10
	harness::PluginFlags plugin;  // --f, --fixation, ...: one value each, for every plugin viewport
	viewer::DrawOptions draw;
	bool colourGiven = false;
	bool headless = false;
	bool palette = false;
	std::string out;
	std::vector<double> times;
	std::vector<int> frames;
	int cellWidth = 320, cellHeight = 240;
	viewer::OrbitCamera camera;  // yaw and pitch of the pictures
	double frameTime = -1;       // s; -1: frame the start
};

[[noreturn]] void fail(const std::string& message)
{
	std::cerr << "bsp_viewer: " << message << "\n(run bsp_viewer --help for usage)\n";
	std::exit(2);
}

void usage()
{
	std::cout << "usage: bsp_viewer [options]\n"
				 "One registry scene under several solvers side by side, in lockstep: in a window, or\n"
				 "with --headless offscreen into a PNG (no display needed).\n"
				 "  --scene NAME           registry scene (default wall); --list shows them\n"
				 "  --param NAME=VALUE     scene parameter (repeatable)\n"
				 "  --solvers A,B,...      one viewport each (default si,si,sp); valid:\n"
				 "                         " << harness::solverKindNames() << "\n"
				 "  --iterations N,M,...   one value for every viewport or one per solver\n"
				 "                         (default 10,100,10 with the default solvers, else 10)\n"
				 "  --dt S                 time step in seconds (default 1/60)\n"
				 "  --colour MODE          body colours: layers = stack layer (default in the window),\n"
				 "                         drift = red as a body moves up to 1 cm, plain (default headless)\n"
				 "  --contacts             draw contact points and normal forces\n"
				 "headless:\n"
				 "  --headless             render offscreen (EGL) and write a PNG instead of a window\n"
				 "  --out FILE             the PNG to write (required with --headless)\n"
				 "  --times S,T,...        one row per simulated time in seconds (default 4)\n"
				 "  --frames N,M,...       one row per frame number (steps) instead\n"
				 "  --size WxH             pixels per viewport (default 320x240)\n"
				 "  --palette              write a 256-colour PNG (about 40% of the bytes)\n"
				 "  --yaw DEG, --pitch DEG camera direction (default 26, 17: from the front right, above)\n"
				 "  --frame-at S           frame the bodies as they lie at S seconds (last solver), not\n"
				 "                         as they start (for piles that settle)\n"
				 "In the window: left drag orbits, right drag pans, the wheel zooms, a middle click or\n"
				 "shift + left click shoots a box; space pauses, S steps, R resets, F frames the scene.\n"
				 "plugin settings (one value each):\n";
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
		if (a == "--scene") o.setup.scene = value();
		else if (a == "--param") o.setup.params.push_back(harness::parseSceneParam(value()));
		else if (a == "--solvers") o.solvers = harness::splitList(value(), "solver");
		else if (a == "--iterations")
			o.iterations = harness::parseIntegerList(value(), "iteration");
		else if (a == "--dt") o.setup.timeStep = harness::parseNumber(value());
		else if (a == "--colour" || a == "--color")
		{
			const std::string mode = value();
			if (mode == "layers") o.draw.colours = viewer::ColourMode::StackLayer;
			else if (mode == "drift") o.draw.colours = viewer::ColourMode::Drift;
			else if (mode == "plain") o.draw.colours = viewer::ColourMode::Plain;
			else fail("unknown colour mode '" + mode + "'; valid: layers, drift, plain");
			o.colourGiven = true;
		}
		else if (a == "--contacts") o.draw.contacts = true;
		else if (a == "--headless") o.headless = true;
		else if (a == "--out") o.out = value();
		else if (a == "--palette") o.palette = true;
		else if (a == "--times")
			o.times = harness::parseNumberList(value(), "time");
		else if (a == "--frames")
			o.frames = harness::parseIntegerList(value(), "frame");
		else if (a == "--yaw") o.camera.yaw = harness::parseNumber(value()) * M_PI / 180;
		else if (a == "--pitch")
		{
			o.camera.pitch = harness::parseNumber(value()) * M_PI / 180;
			if (!(std::fabs(o.camera.pitch) <= 85 * M_PI / 180)) fail("--pitch must be within -85..85 degrees");
		}
		else if (a == "--frame-at")
		{
			o.frameTime = harness::parseNumber(value());
			if (!(o.frameTime >= 0 && o.frameTime <= 3600)) fail("--frame-at must be in [0, 3600] seconds");
		}
		else if (a == "--size")
		{
			const std::string size = value();
			const auto x = size.find('x');
			if (x == std::string::npos) fail("--size wants WxH, e.g. 320x240, got '" + size + "'");
			o.cellWidth = harness::parseInteger(size.substr(0, x));
			o.cellHeight = harness::parseInteger(size.substr(x + 1));
			if (o.cellWidth < 16 || o.cellHeight < 16 || o.cellWidth > 4096 || o.cellHeight > 4096)
				fail("--size: each side must be 16..4096 pixels");
		}
		else fail("unknown option '" + a + "'");
	}
	if (!scenes::findScene(o.setup.scene)) fail("unknown scene '" + o.setup.scene + "'; valid scenes: " + scenes::sceneNames());
	if (!(o.setup.timeStep > 0 && o.setup.timeStep <= 1)) fail("--dt must be in (0, 1] seconds");
	if (o.iterations.empty())
		o.iterations = o.solvers == std::vector<std::string>{"si", "si", "sp"} ? std::vector<int>{10, 100, 10} : std::vector<int>{10};
	if (o.iterations.size() != 1 && o.iterations.size() != o.solvers.size())
		fail("--iterations wants one value or one per solver (" + std::to_string(o.solvers.size()) + ")");
	for (int n : o.iterations)
		if (n < 1 || n > 10000) fail("--iterations must be 1..10000");
	for (size_t k = 0; k < o.solvers.size(); ++k)
	{
		harness::SolverSpec spec;
		std::string error;
		if (!harness::parseSolverKind(o.solvers[k], spec, error)) fail(error);
		spec.iterations = o.iterations.size() == 1 ? o.iterations[0] : o.iterations[k];
		const std::vector<btShockPropagationSettings> settings = o.plugin.expand(spec.settings);
		if (settings.size() != 1) fail("plugin flags take one value each here (one viewport per solver)");
		spec.settings = settings.front();
		o.setup.solvers.push_back(spec);
	}
	if (o.solvers.size() > 8) fail("at most 8 solvers (viewports)");
	if (!o.headless && (!o.out.empty() || !o.times.empty() || !o.frames.empty() || o.palette))
		fail("--out, --times, --frames and --palette need --headless");
	if (!std::isfinite(o.camera.yaw)) fail("--yaw must be finite");
	if (o.headless)
	{
		if (o.out.empty()) fail("--headless needs --out FILE.png");
		if (!o.times.empty() && !o.frames.empty()) fail("give --times or --frames, not both");
		if (o.times.empty() && o.frames.empty()) o.times = {4};
		for (double t : o.times)
			if (!(t >= 0 && t <= 3600)) fail("--times must be in [0, 3600] seconds");
		for (int f : o.frames)
			if (f < 0 || f > 1000000) fail("--frames must be >= 0");
		if (!o.colourGiven) o.draw.colours = viewer::ColourMode::Plain;
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

int runHeadless(const Options& o)
{
	std::string error;
	std::unique_ptr<viewer::OffscreenContext> context = viewer::OffscreenContext::create(error);
	if (!context)
	{
		std::cerr << "bsp_viewer: cannot render headless: " << error << "\n";
		return 1;
	}
	viewer::StripOptions strip;
	strip.cellWidth = o.cellWidth;
	strip.cellHeight = o.cellHeight;
	strip.colours = o.draw.colours;
	strip.contacts = o.draw.contacts;
	strip.framesNotSeconds = !o.frames.empty();
	strip.yaw = o.camera.yaw;
	if (o.frameTime >= 0) strip.frameSteps = int(std::lround(o.frameTime / o.setup.timeStep));
	strip.pitch = o.camera.pitch;
	if (strip.framesNotSeconds)
		strip.checkpoints = o.frames;
	else
		for (double t : o.times) strip.checkpoints.push_back(int(std::lround(t / o.setup.timeStep)));
	for (size_t k = 1; k < strip.checkpoints.size(); ++k)
		if (strip.checkpoints[k] < strip.checkpoints[k - 1]) fail("--times / --frames must be ascending");

	viewer::Comparison comparison(o.setup);
	viewer::Renderer renderer;
	viewer::OffscreenText text;
	const viewer::Image image = viewer::renderStrip(comparison, strip, renderer, text);
	if (!viewer::writePng(o.out, image, error, o.palette))
	{
		std::cerr << "bsp_viewer: " << error << "\n";
		return 1;
	}
	std::cout << o.out << ": " << image.width << " x " << image.height << " (" << context->description() << ")\n";
	return 0;
}
}  // namespace

int main(int argc, char** argv)
{
	const Options o = parse(argc, argv);
	try
	{
		// Scene parameters are checked here, with the scene's own message (exit 2).
		viewer::Comparison probe(viewer::ComparisonSetup{o.setup.scene, o.setup.params, {o.setup.solvers.front()}, o.setup.timeStep});
	}
	catch (const std::invalid_argument& e)
	{
		fail(e.what());
	}
	try
	{
		return o.headless ? runHeadless(o) : viewer::runInteractive(o.setup, o.draw, o.camera);
	}
	catch (const std::exception& e)
	{
		std::cerr << "bsp_viewer: " << e.what() << "\n";
		return 1;
	}
}
