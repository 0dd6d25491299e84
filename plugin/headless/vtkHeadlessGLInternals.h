/**
 * Private helpers of vtkHeadlessRenderWindow and its EGL and OSMesa
 * subclasses. Not installed, not part of the public API.
 */
#ifndef vtkHeadlessGLInternals_h
#define vtkHeadlessGLInternals_h

#include "vtk_glew.h"

#include <string>

namespace vtkHeadlessGL
{
/**
 * glewInit() for a context that is not a GLX context.
 *
 * Debian's GLEW 2.2 is built for GLX: glewInit() first loads every GL entry
 * point (glewContextInit) and then runs glxewInit(), which fails with
 * GLEW_ERROR_NO_GLX_DISPLAY ("Unknown error" from glewGetErrorString) because
 * no GLX display is current. vtkOpenGLRenderWindow::OpenGLInitContext() would
 * treat that as fatal, print it and leave the window uninitialized, so the
 * windows call this instead and accept that one code when the GL part is
 * complete. Returns an empty string on success, otherwise the reason.
 */
inline std::string InitGlewWithoutGLX()
{
  const GLenum result = glewInit();
  const bool glPartLoaded = (GLEW_VERSION_3_2 || GLEW_VERSION_3_1) &&
    glGenFramebuffers != nullptr && glBlendFuncSeparate != nullptr && glGetStringi != nullptr;
  if (result == GLEW_OK || (result == GLEW_ERROR_NO_GLX_DISPLAY && glPartLoaded))
  {
    if (glPartLoaded)
    {
      return std::string();
    }
    return "GLEW found no OpenGL 3.2 entry points in this context";
  }
  std::string why = "glewInit failed: ";
  why += reinterpret_cast<const char*>(glewGetErrorString(result));
  if (result == GLEW_ERROR_NO_GL_VERSION)
  {
    why += " (glGetString(GL_VERSION) returned NULL: the GL symbols used by VTK/GLEW do not "
           "reach the current context)";
  }
  return why;
}

/**
 * The headless window (EGL or OSMesa) that last made its context current in
 * this thread. An EGL context stays "current" for EGL even after an OSMesa
 * context took over Mesa's GL dispatch (and vice versa), so the MakeCurrent()
 * fast paths also require that the window is the last owner.
 */
inline const void*& CurrentOwner()
{
  static thread_local const void* owner = nullptr;
  return owner;
}

/**
 * What vtkOpenGLRenderWindow::OpenGLInitContext() computes after glewInit().
 */
inline float QueryMaximumHardwareLineWidth(bool lineSmoothing)
{
  GLfloat range[2] = { 1.0f, 1.0f };
  glGetError();
  glGetFloatv(lineSmoothing ? GL_SMOOTH_LINE_WIDTH_RANGE : GL_ALIASED_LINE_WIDTH_RANGE, range);
  return glGetError() == GL_NO_ERROR ? range[1] : 1.0f;
}
}

#endif
