#include "viewer/Pictures.h"

#include "viewer/Labels.h"
#include "viewer/Offscreen.h"
#include "viewer/Renderer.h"

#include "Gl.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace viewer
{
namespace
{
/// Pixels between neighbouring viewports (white).
const int kGutter = 2;


struct Label
{
	float x, y;
	std::vector<std::string> lines;
};

std::string rowLabel(const StripOptions& options, int steps, double seconds)
{
	char text[64];
	if (options.framesNotSeconds)
		std::snprintf(text, sizeof(text), "frame %d (%.2f s)", steps, seconds);
	else
		std::snprintf(text, sizeof(text), "t = %g s", std::round(seconds * 1000) / 1000);
	return text;
}
}  // namespace

OrbitCamera pictureCamera(Comparison& comparison, const StripOptions& options, double aspect)
{
	OrbitCamera camera;
	camera.yaw = options.yaw;
	camera.pitch = options.pitch;
	std::unique_ptr<Comparison> settled;
	harness::Trial* framed = &comparison.trial(0);
	if (options.frameSteps >= 0)
	{
		ComparisonSetup setup = comparison.setup();
		setup.solvers = {setup.solvers.back()};
		settled.reset(new Comparison(setup));
		settled->stepTo(options.frameSteps);
		framed = &settled->trial(0);
	}
	btVector3 lo, hi;
	if (bodyBounds(framed->bodies(), lo, hi))
	{
		lo.setY(btMin(lo.y(), btScalar(0)));  // keep the ground in view
		camera.frame(lo, hi, aspect);
	}
	return camera;
}

Image renderStrip(Comparison& comparison, const StripOptions& options, Renderer& renderer, OffscreenText& text)
{
	if (options.checkpoints.empty()) throw std::invalid_argument("no moment to draw");
	// Each cell: a white band with the label (two lines), the viewport below it.
	const int header = int(2 * (text.fontPixels() + 1) + 10);
	const int cellHeight = header + options.cellHeight;
	const int columns = comparison.size(), rows = int(options.checkpoints.size());
	const int width = columns * options.cellWidth + (columns - 1) * kGutter;
	const int height = rows * cellHeight + (rows - 1) * kGutter;
	Framebuffer framebuffer(width, height, options.samples);
	framebuffer.bind();
	glViewport(0, 0, width, height);
	glDisable(GL_SCISSOR_TEST);
	glClearColor(1, 1, 1, 1);
	glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

	Viewport cell;
	cell.width = options.cellWidth;
	cell.height = options.cellHeight;
	const OrbitCamera camera = pictureCamera(comparison, options, cell.aspect());
	DrawOptions draw;
	draw.colours = options.colours;
	draw.contacts = options.contacts;

	std::vector<Label> labels;
	for (int r = 0; r < rows; ++r)
	{
		comparison.stepTo(options.checkpoints[size_t(r)]);
		for (int c = 0; c < columns; ++c)
		{
			cell.x = c * (options.cellWidth + kGutter);
			const int top = r * (cellHeight + kGutter);
			cell.y = height - top - cellHeight;
			harness::Trial& trial = comparison.trial(c);
			renderer.drawTrial(trial, camera, cell, draw);
			const double drift = trial.steps() ? trial.summary().maxDrift : 0.0;
			labels.push_back({float(cell.x), float(top),
							  {solverTitle(trial.simulation().spec()),
							   rowLabel(options, comparison.steps(), comparison.time()) + ", max drift " + formatLength(drift)}});
		}
	}
	ImDrawList& list = text.begin(width, height);
	for (const Label& l : labels) drawTextBlock(list, l.x, l.y, l.lines, true, float(options.cellWidth));
	text.end();
	return framebuffer.read();
}
}  // namespace viewer
