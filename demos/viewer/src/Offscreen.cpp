#include "viewer/Offscreen.h"

#include "Gl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace viewer
{
namespace
{
std::string eglErrorText(const char* what)
{
	char code[16];
	std::snprintf(code, sizeof(code), "0x%04x", unsigned(eglGetError()));
	return std::string(what) + " failed (EGL error " + code + ")";
}

bool hasExtension(const char* list, const char* name)
{
	if (!list) return false;
	const size_t n = std::strlen(name);
	for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name))
		if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
	return false;
}

std::string glRendererName()
{
	const GLubyte* renderer = glGetString(GL_RENDERER);
	const GLubyte* version = glGetString(GL_VERSION);
	return std::string(renderer ? reinterpret_cast<const char*>(renderer) : "?") + ", OpenGL " +
		   (version ? reinterpret_cast<const char*>(version) : "?");
}
}  // namespace

std::unique_ptr<OffscreenContext> OffscreenContext::create(std::string& error)
{
	std::unique_ptr<OffscreenContext> context(new OffscreenContext());
	std::string eglError = "skipped (BSP_VIEWER_NO_EGL is set)";
	const char* noEgl = std::getenv("BSP_VIEWER_NO_EGL");
	if (!(noEgl && *noEgl && std::strcmp(noEgl, "0") != 0) && context->tryEgl(eglError)) return context;
	std::string windowError;
	if (context->tryHiddenWindow(windowError)) return context;
	error = "no offscreen OpenGL 3.3 context: EGL " + eglError + "; hidden window " + windowError +
			". Install Mesa's EGL (libegl1, libegl-mesa0, libgl1-mesa-dri; tests/install-deps.sh does) or run under xvfb-run.";
	return nullptr;
}

bool OffscreenContext::tryEgl(std::string& error)
{
	const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
	auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
	if (!getPlatformDisplay || !hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
	{
		error = "has no surfaceless platform (EGL_MESA_platform_surfaceless; is Mesa's libegl-mesa0 installed?)";
		return false;
	}
	EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
	EGLint major = 0, minor = 0;
	if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
	{
		error = eglErrorText("eglInitialize on the surfaceless platform");
		return false;
	}
	m_eglDisplay = display;
	if (!eglBindAPI(EGL_OPENGL_API))
	{
		error = eglErrorText("eglBindAPI(OpenGL)");
		return false;
	}
	const EGLint configAttributes[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
	EGLConfig config = nullptr;
	EGLint numConfigs = 0;
	eglChooseConfig(display, configAttributes, &config, 1, &numConfigs);
	const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
										EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
	EGLContext context = eglCreateContext(display, numConfigs > 0 ? config : EGLConfig(nullptr), EGL_NO_CONTEXT, contextAttributes);
	if (context == EGL_NO_CONTEXT)
	{
		error = eglErrorText("eglCreateContext(OpenGL 3.3 core)");
		return false;
	}
	m_eglContext = context;
	if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
	{
		error = eglErrorText("eglMakeCurrent without a surface");
		return false;
	}
	m_description = "EGL surfaceless, " + glRendererName();
	return true;
}

bool OffscreenContext::tryHiddenWindow(std::string& error)
{
	const char* display = std::getenv("DISPLAY");
	const char* wayland = std::getenv("WAYLAND_DISPLAY");
	if (!(display && *display) && !(wayland && *wayland))
	{
		error = "needs a display and there is none (DISPLAY and WAYLAND_DISPLAY are unset)";
		return false;
	}
	if (!glfwInit())
	{
		const char* description = nullptr;
		glfwGetError(&description);
		error = std::string("failed: GLFW cannot start (") + (description ? description : "unknown error") + ")";
		return false;
	}
	glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
	glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
	glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
	glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
	GLFWwindow* window = glfwCreateWindow(64, 64, "bsp_viewer offscreen", nullptr, nullptr);
	if (!window)
	{
		const char* description = nullptr;
		glfwGetError(&description);
		error = std::string("failed: no OpenGL 3.3 core window (") + (description ? description : "unknown error") + ")";
		glfwTerminate();
		return false;
	}
	m_window = window;
	glfwMakeContextCurrent(window);
	m_description = "hidden GLFW window, " + glRendererName();
	return true;
}

OffscreenContext::~OffscreenContext()
{
	if (m_eglDisplay)
	{
		EGLDisplay display = static_cast<EGLDisplay>(m_eglDisplay);
		eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
		if (m_eglContext) eglDestroyContext(display, static_cast<EGLContext>(m_eglContext));
		// No eglTerminate: it unloads Mesa's driver, which leaves two small allocations of its
		// own unreachable (LeakSanitizer reports them); the display is the process's anyway.
		eglReleaseThread();
	}
	if (m_window)
	{
		glfwDestroyWindow(static_cast<GLFWwindow*>(m_window));
		glfwTerminate();
	}
}

Framebuffer::Framebuffer(int width, int height, int samples) : m_width(width), m_height(height)
{
	if (width <= 0 || height <= 0) throw std::runtime_error("framebuffer size must be positive");
	GLint maxSamples = 0;
	glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
	samples = std::max(0, std::min(samples, int(maxSamples)));

	glGenRenderbuffers(1, &m_colour);
	glBindRenderbuffer(GL_RENDERBUFFER, m_colour);
	glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
	glGenRenderbuffers(1, &m_depth);
	glBindRenderbuffer(GL_RENDERBUFFER, m_depth);
	glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
	glGenFramebuffers(1, &m_fbo);
	glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
	glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_colour);
	glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_depth);
	const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;

	glGenRenderbuffers(1, &m_resolveColour);
	glBindRenderbuffer(GL_RENDERBUFFER, m_resolveColour);
	glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
	glGenFramebuffers(1, &m_resolveFbo);
	glBindFramebuffer(GL_FRAMEBUFFER, m_resolveFbo);
	glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_resolveColour);
	const bool resolveComplete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
	glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
	if (!complete || !resolveComplete) throw std::runtime_error("the OpenGL driver cannot make a " + std::to_string(width) + " x " + std::to_string(height) + " framebuffer");
}

Framebuffer::~Framebuffer()
{
	glDeleteFramebuffers(1, &m_fbo);
	glDeleteFramebuffers(1, &m_resolveFbo);
	glDeleteRenderbuffers(1, &m_colour);
	glDeleteRenderbuffers(1, &m_depth);
	glDeleteRenderbuffers(1, &m_resolveColour);
}

void Framebuffer::bind()
{
	glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
}

Image Framebuffer::read()
{
	glBindFramebuffer(GL_READ_FRAMEBUFFER, m_fbo);
	glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_resolveFbo);
	glBlitFramebuffer(0, 0, m_width, m_height, 0, 0, m_width, m_height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
	glBindFramebuffer(GL_READ_FRAMEBUFFER, m_resolveFbo);
	Image image;
	image.width = m_width;
	image.height = m_height;
	std::vector<unsigned char> bottomUp(size_t(m_width) * size_t(m_height) * 3);
	glPixelStorei(GL_PACK_ALIGNMENT, 1);
	glReadPixels(0, 0, m_width, m_height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
	image.rgb.resize(bottomUp.size());
	const size_t row = size_t(m_width) * 3;
	for (int y = 0; y < m_height; ++y)
		std::memcpy(&image.rgb[size_t(y) * row], &bottomUp[size_t(m_height - 1 - y) * row], row);
	glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
	return image;
}
}  // namespace viewer
