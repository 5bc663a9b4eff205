#include "viewer/Pictures.h"

#include "viewer/Labels.h"
#include "viewer/Offscreen.h"
#include "viewer/Renderer.h"

#include "Gl.h"

#include <cstdio>
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
		std::snprintf(text, sizeof(text), "t = %.1f s", seconds);
	return text;
}
}  // namespace

OrbitCamera pictureCamera(Comparison& comparison, double aspect)
{
	OrbitCamera camera;
	btVector3 lo, hi;
	if (bodyBounds(comparison.trial(0).bodies(), lo, hi))
	{
		lo.setY(btMin(lo.y(), btScalar(0)));  // keep the ground in view
		camera.frame(lo, hi, aspect);
	}
	return camera;
}

Image renderStrip(Comparison& comparison, const StripOptions& options, Renderer& renderer, OffscreenText& text)
{
	if (options.checkpoints.empty()) throw std::invalid_argument("no moment to draw");
	const int columns = comparison.size(), rows = int(options.checkpoints.size());
	const int width = columns * options.cellWidth + (columns - 1) * kGutter;
	const int height = rows * options.cellHeight + (rows - 1) * kGutter;
	Framebuffer framebuffer(width, height, options.samples);
	framebuffer.bind();
	glViewport(0, 0, width, height);
	glDisable(GL_SCISSOR_TEST);
	glClearColor(1, 1, 1, 1);
	glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

	Viewport cell;
	cell.width = options.cellWidth;
	cell.height = options.cellHeight;
	const OrbitCamera camera = pictureCamera(comparison, cell.aspect());
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
			const int top = r * (options.cellHeight + kGutter);
			cell.y = height - top - options.cellHeight;
			harness::Trial& trial = comparison.trial(c);
			renderer.drawTrial(trial, camera, cell, draw);
			const double drift = trial.steps() ? trial.summary().maxDrift : 0.0;
			labels.push_back({float(cell.x + 4), float(top + 4),
							  {solverTitle(trial.simulation().spec()), rowLabel(options, comparison.steps(), comparison.time()),
							   "max drift " + formatLength(drift)}});
		}
	}
	ImDrawList& list = text.begin(width, height);
	for (const Label& l : labels) drawTextBlock(list, l.x, l.y, l.lines, true);
	text.end();
	return framebuffer.read();
}
}  // namespace viewer
