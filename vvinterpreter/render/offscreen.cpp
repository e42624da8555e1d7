#include "render/offscreen.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdio>

namespace vvi {

namespace {
std::string egl_error(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", eglGetError());
  return std::string(what) + " failed (EGL error " + code + ")";
}
}  // namespace

std::unique_ptr<offscreen> offscreen::create(int width, int height, std::string& error) {
  std::unique_ptr<offscreen> o(new offscreen);
  auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  EGLDisplay d = get_display ? get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)
                             : EGL_NO_DISPLAY;
  if (d == EGL_NO_DISPLAY) {
    error = "no offscreen OpenGL: EGL has no surfaceless platform (Mesa's libegl-mesa0)";
    return nullptr;
  }
  o->display_ = d;
  EGLint major = 0, minor = 0;
  if (!eglInitialize(d, &major, &minor)) {
    error = "no offscreen OpenGL: " + egl_error("eglInitialize");
    o->display_ = nullptr;
    return nullptr;
  }
  // Desktop OpenGL, compatibility profile: render blocks may use legacy GL.
  if (!eglBindAPI(EGL_OPENGL_API)) {
    error = "no offscreen OpenGL: " + egl_error("eglBindAPI");
    return nullptr;
  }
  const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint found = 0;
  eglChooseConfig(d, attributes, &config, 1, &found);
  o->context_ = eglCreateContext(d, found ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, nullptr);
  if (!o->context_ || !eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, o->context_)) {
    error = "no offscreen OpenGL: " + egl_error("creating a context");
    return nullptr;
  }
  glGenFramebuffers(1, &o->framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, o->framebuffer_);
  glGenRenderbuffers(1, &o->color_);
  glBindRenderbuffer(GL_RENDERBUFFER, o->color_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, o->color_);
  glGenRenderbuffers(1, &o->depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, o->depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, o->depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "no offscreen OpenGL: cannot make a " + std::to_string(width) + "x" + std::to_string(height) +
            " framebuffer";
    return nullptr;
  }
  return o;
}

offscreen::~offscreen() {
  if (context_) {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (color_) glDeleteRenderbuffers(1, &color_);
    if (depth_) glDeleteRenderbuffers(1, &depth_);
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }
  if (display_) eglTerminate(display_);
}

}  // namespace vvi
