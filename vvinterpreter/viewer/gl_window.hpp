// The GLFW window with its OpenGL context (a compatibility profile: render
// blocks of vv programs use legacy GL) and Dear ImGui on it. Input goes to
// an input_handler after Dear ImGui has seen it.
#pragma once

#include <string>

struct GLFWwindow;

namespace vvi {

class input_handler {
 public:
  virtual ~input_handler() = default;
  virtual void on_button(int button, int action, int mods) = 0;
  virtual void on_move(double x, double y) = 0;
  virtual void on_scroll(double dy) = 0;
  virtual void on_key(int key, int action, int mods) = 0;
};

class gl_window {
 public:
  gl_window() = default;
  gl_window(const gl_window&) = delete;
  gl_window& operator=(const gl_window&) = delete;

  //! Opens the window at `place` (x y width height; width 0: the default
  //! size, placed by the system); false, with one line on standard error,
  //! when there is no display.
  bool open(const std::string& title, const int place[4]);
  void close();
  void set_input(input_handler* input);

  bool should_close() const;
  void request_close();
  //! Waits for events at most `seconds` (0: only takes what is there).
  //! Waits for input, for `seconds` at most (0: takes what came, at once).
  void wait_events(double seconds);
  //! Ends a wait_events, from any thread, while the window is open.
  static void wake();
  void swap();
  //! The window's size in screen coordinates, and its framebuffer's in pixels.
  void size(int& w, int& h) const;
  void framebuffer_size(int& w, int& h) const;
  void cursor(double& x, double& y) const;
  //! x y width height, for the state record.
  void place(int out[4]) const;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace vvi
