// The interactive window of bsp_viewer (GLFW + OpenGL 3.3 + Dear ImGui). Private to the program.
#pragma once

#include "viewer/Comparison.h"
#include "viewer/Renderer.h"

namespace viewer
{
/// Opens the window and runs until it is closed. Returns the process exit code: 0, or 1 with a
/// message on stderr when no window can be opened (no display), pointing to --headless.
int runInteractive(const ComparisonSetup& setup, const DrawOptions& draw, const OrbitCamera& camera);
}  // namespace viewer
