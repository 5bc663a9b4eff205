// Text over the viewports, through Dear ImGui's draw lists and font atlas (which work offscreen
// as well as in the window): the solver's name, the time and the demo program's metrics.
#pragma once

#include <harness/Trial.h>

#include <string>
#include <vector>

struct ImDrawList;
struct ImGuiContext;

namespace viewer
{
/// Human name of a solver, e.g. "stock SI, 10 iterations", "shock propagation, 10 iterations".
std::string solverTitle(const harness::SolverSpec& spec);
/// A length in cm below 1 m, else in m ("0.08 cm", "5.10 m").
std::string formatLength(double metres);
/// The demo program's metrics of a trial now: drift (now and max), penetration, ground
/// reaction / weight, ms/step, stack layers (plugin) - one short line each.
std::vector<std::string> metricLines(harness::Trial& trial);

/// A block of text lines on a light translucent box with its top-left corner at (x, y) (pixels,
/// origin top-left); the first line is bold if `titleFirst`. A block wider than `maxWidth` (if
/// > 0) is drawn with a smaller font so it fits. Returns the block's height.
float drawTextBlock(ImDrawList& list, float x, float y, const std::vector<std::string>& lines, bool titleFirst, float maxWidth = 0);

/// Loads the label font into the current ImGui context: DejaVu Sans at `pixels` if it is
/// installed (fonts-dejavu-core), else ImGui's built-in font.
void loadLabelFont(float pixels);

/// Dear ImGui without a window, for pictures: its own context and OpenGL3 renderer; needs a
/// current OpenGL 3.3 context.
class OffscreenText
{
public:
	explicit OffscreenText(float fontPixels = 15);
	~OffscreenText();
	OffscreenText(const OffscreenText&) = delete;
	OffscreenText& operator=(const OffscreenText&) = delete;

	/// Starts a frame of width x height pixels; draw into the returned list, then end().
	ImDrawList& begin(int width, int height);
	/// Draws what was added since begin() into the bound framebuffer.
	void end();
	float fontPixels() const { return m_fontPixels; }

private:
	float m_fontPixels;
	ImGuiContext* m_context = nullptr;
	ImGuiContext* m_previous = nullptr;
};
}  // namespace viewer
