// How the viewer colours bodies: by stack layer (the plugin's contact-graph heights of the last
// step, so the layering is visible), by drift (how far each body moved from its start), or plainly.
#pragma once

#include <harness/Trial.h>

#include <unordered_map>

namespace viewer
{
/// Linear RGB in [0, 1].
struct Rgb
{
	float r, g, b;
};

enum class ColourMode
{
	StackLayer,  ///< plugin viewports: colour of each body's stack height; stock ones: plain
	Drift,       ///< plain colour turning red as a body moves up to harness::kStandingDriftMeters
	Plain        ///< every dynamic body in the plain colour
};

/// Number of distinct layer colours; height h >= 1 gets palette entry (h - 1) mod this.
constexpr int kLayerPaletteSize = 8;

/// Colour of stack height `height` (1 = resting on the ground or another static body, ...);
/// BT_STACK_HEIGHT_UNREACHED (a cluster touching nothing static) gets layerlessColour().
Rgb layerColour(int height);
/// Dynamic bodies the solver did not layer (stock solvers, or a body added since the last step).
Rgb layerlessColour();
/// Static bodies other than the ground (ramps, posts).
Rgb staticColour();
/// Drift colouring: layerlessColour() at rest, red from harness::kStandingDriftMeters (the
/// demo's "fallen") on, blended linearly in between.
Rgb driftColour(double driftMetres);

/// Colour of every dynamic body of a trial, by `mode`. Bodies missing from the map are drawn in
/// layerlessColour() (or the static colour).
std::unordered_map<const btCollisionObject*, Rgb> bodyColours(harness::Trial& trial, ColourMode mode);
}  // namespace viewer
