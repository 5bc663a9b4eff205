// Headless pictures: a comparison drawn offscreen as a grid of viewports (columns = solvers,
// rows = moments in time), each labelled with its solver, time and drift, like the seed's figures.
#pragma once

#include "viewer/BodyColours.h"
#include "viewer/Camera.h"
#include "viewer/Comparison.h"
#include "viewer/Png.h"

#include <string>
#include <vector>

namespace viewer
{
class Renderer;
class OffscreenText;

struct StripOptions
{
	std::vector<int> checkpoints;          ///< frames (steps since reset), ascending; one row each
	bool framesNotSeconds = false;         ///< label rows "frame N" instead of "t = S s"
	int cellWidth = 320, cellHeight = 240; ///< pixels per viewport (its label band comes on top)
	ColourMode colours = ColourMode::Plain;
	bool contacts = false;
	int samples = 4;                       ///< multisampling
	double yaw = OrbitCamera().yaw;        ///< rad, camera direction about the vertical
	double pitch = OrbitCamera().pitch;    ///< rad above the horizontal (higher to look into a pit)
	/// Frame the bodies as they are after this many steps under the last solver (a throwaway run),
	/// for scenes that start spread out and settle (dense_random); -1: as they start.
	int frameSteps = -1;
};

/// Steps `comparison` to each checkpoint in turn and draws every trial there; the camera frames
/// the bodies as they are when this is called (the start, for a fresh comparison). Needs a
/// current OpenGL 3.3 context (OffscreenContext).
Image renderStrip(Comparison& comparison, const StripOptions& options, Renderer& renderer, OffscreenText& text);

/// The camera every picture uses for this comparison: the options' yaw and pitch, framing the
/// dynamic bodies of the first trial now, or of a throwaway run after options.frameSteps (and
/// the ground under them).
OrbitCamera pictureCamera(Comparison& comparison, const StripOptions& options, double aspect);
}  // namespace viewer
