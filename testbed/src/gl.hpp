// OpenGL 3.3 core entry points. Linux's libGL exports them, so the prototypes of glcorearb.h
// are enough and no loader is needed.
#ifndef EDYN_TESTBED_GL_HPP
#define EDYN_TESTBED_GL_HPP

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#define GLFW_INCLUDE_GLCOREARB
#include <GLFW/glfw3.h>

#endif // EDYN_TESTBED_GL_HPP
