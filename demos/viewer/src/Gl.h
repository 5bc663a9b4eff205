// OpenGL 3.3 core entry points, straight from the GL dispatch library (libOpenGL, libglvnd):
// they reach whichever context is current, an EGL one offscreen or GLFW's window. Private.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
