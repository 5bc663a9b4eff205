// Rendering without a window: an OpenGL 3.3 core context from EGL (Mesa's surfaceless platform,
// no display needed), or as a fallback a hidden GLFW window when a display exists (xvfb-run), and
// a multisampled framebuffer object to draw into and read back.
#pragma once

#include "viewer/Png.h"

#include <memory>
#include <string>

namespace viewer
{
class OffscreenContext
{
public:
	/// Makes the context current, or returns nullptr with `error` saying what was tried and why it
	/// failed. Setting BSP_VIEWER_NO_EGL=1 skips EGL (to test the fallback and the message).
	static std::unique_ptr<OffscreenContext> create(std::string& error);
	~OffscreenContext();
	OffscreenContext(const OffscreenContext&) = delete;
	OffscreenContext& operator=(const OffscreenContext&) = delete;

	/// How the context was made and by which renderer, e.g. "EGL surfaceless, llvmpipe (...)".
	const std::string& description() const { return m_description; }

private:
	OffscreenContext() = default;
	bool tryEgl(std::string& error);
	bool tryHiddenWindow(std::string& error);

	std::string m_description;
	void* m_eglDisplay = nullptr;
	void* m_eglContext = nullptr;
	void* m_window = nullptr;  // GLFWwindow
};

/// A framebuffer object with depth and `samples`-fold multisampling; needs a current context.
class Framebuffer
{
public:
	/// Throws std::runtime_error if the driver cannot make it.
	Framebuffer(int width, int height, int samples = 4);
	~Framebuffer();
	Framebuffer(const Framebuffer&) = delete;
	Framebuffer& operator=(const Framebuffer&) = delete;

	int width() const { return m_width; }
	int height() const { return m_height; }
	/// Draw into this framebuffer from now on.
	void bind();
	/// Resolves the samples and reads the pixels back (rows top to bottom).
	Image read();

private:
	int m_width, m_height;
	unsigned m_fbo = 0, m_colour = 0, m_depth = 0;
	unsigned m_resolveFbo = 0, m_resolveColour = 0;
};
}  // namespace viewer
