// Draws one trial's world into one viewport with OpenGL 3.3: shaded bodies with dark edges,
// a checkered ground, translucent static bodies (pit walls, ramps), optionally contact points and
// normal forces. The same code draws the
// interactive window and the offscreen pictures.
#pragma once

#include "viewer/BodyColours.h"
#include "viewer/Camera.h"

#include <harness/Trial.h>

#include <vector>

namespace viewer
{
/// A rectangle in framebuffer pixels, origin at the bottom left (OpenGL's convention).
struct Viewport
{
	int x = 0, y = 0, width = 1, height = 1;
	double aspect() const { return double(width) / double(height > 0 ? height : 1); }
};

struct DrawOptions
{
	ColourMode colours = ColourMode::StackLayer;
	bool contacts = false;       ///< contact points and normal-force lines
	/// Length of a contact's normal-force line (m) per mean body weight of the scene; the line
	/// starts at the contact point and points into the upper body (the one it supports).
	double forceScale = 0.25;
};

/// Background colour of every viewport (linear RGB), for tests that look for "not blank".
Rgb backgroundColour();
/// Colour of the ground's lighter checker squares before shading.
Rgb groundColour();

class Renderer
{
public:
	/// Needs a current OpenGL 3.3 core context; throws std::runtime_error if a shader fails.
	Renderer();
	~Renderer();
	Renderer(const Renderer&) = delete;
	Renderer& operator=(const Renderer&) = delete;

	/// Clears `viewport` and draws every collision object of the trial's world into it.
	void drawTrial(harness::Trial& trial, const OrbitCamera& camera, const Viewport& viewport, const DrawOptions& options);

private:
	void drawBody(const btCollisionObject& object, const Rgb& colour, int mode);
	void drawContacts(harness::Trial& trial, const DrawOptions& options);
	void drawLines(const std::vector<float>& xyz, const Rgb& colour, unsigned primitive);

	unsigned m_program = 0;
	unsigned m_cubeVao = 0, m_cubeVbo = 0, m_cubeEbo = 0;
	unsigned m_dynamicVao = 0, m_dynamicVbo = 0;  // hulls and lines, refilled per draw
	int m_uViewProj = -1, m_uModel = -1, m_uScale = -1, m_uColour = -1, m_uMode = -1, m_uEdges = -1, m_uAlpha = -1;
};
}  // namespace viewer
