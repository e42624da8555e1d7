// An OpenGL context without a display (EGL, Mesa's surfaceless platform)
// rendering into a framebuffer object: batch screenshots need no X server.
#pragma once

#include <memory>
#include <string>

namespace vvi {

class offscreen {
 public:
  //! A current context with a width x height colour+depth target, or
  //! nullptr with `error` set.
  static std::unique_ptr<offscreen> create(int width, int height, std::string& error);
  ~offscreen();
  offscreen(const offscreen&) = delete;
  offscreen& operator=(const offscreen&) = delete;

 private:
  offscreen() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
  unsigned framebuffer_ = 0, color_ = 0, depth_ = 0;
};

}  // namespace vvi
