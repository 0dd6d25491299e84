/*
 * sss_osmesa_shim: a tiny shared library that makes a process whose VTK was
 * built for GLX + system GLEW usable with OSMesa.
 *
 * GLEW resolves every post-1.1 GL entry point through glXGetProcAddressARB.
 * In a glvnd system that symbol comes from libGLX and returns dispatch stubs
 * that only reach contexts made current through glvnd (GLX/EGL), never an
 * OSMesa context. This library exports glXGetProcAddressARB and
 * glXGetProcAddress forwarding to OSMesaGetProcAddress. It has to be found
 * before libGLX/libGL in the global symbol scope, i.e. loaded with
 * LD_PRELOAD (together with libOSMesa, which then also provides the GL 1.x
 * symbols VTK links directly), or linked into the executable ahead of the
 * VTK libraries. vtkOSMesaRenderWindow::EnsureProcessIsOSMesaReady() does
 * the LD_PRELOAD re-exec automatically.
 */
#include <GL/osmesa.h>

#define SSS_SHIM_EXPORT __attribute__((visibility("default")))

typedef void (*sss_gl_proc)(void);

SSS_SHIM_EXPORT sss_gl_proc glXGetProcAddressARB(const GLubyte* name)
{
  return name ? (sss_gl_proc)OSMesaGetProcAddress((const char*)name) : (sss_gl_proc)0;
}

SSS_SHIM_EXPORT sss_gl_proc glXGetProcAddress(const GLubyte* name)
{
  return glXGetProcAddressARB(name);
}

/* Lets tools check that the shim is present in a process (dlsym). */
SSS_SHIM_EXPORT int sss_osmesa_shim_version(void)
{
  return 1;
}
