#include "viewer/gl_window.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>

#include <cstdio>

namespace vvi {

namespace {

std::string glfw_error;
void on_glfw_error(int, const char* description) { glfw_error = description ? description : "unknown error"; }

input_handler* input_of(GLFWwindow* w) { return static_cast<input_handler*>(glfwGetWindowUserPointer(w)); }

void no_window() {
  std::fprintf(stderr, "vvinterpreter: cannot open a window (%s); use --batch to run without one\n",
               glfw_error.c_str());
}

}  // namespace

bool gl_window::open(const std::string& title, const int place[4]) {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) return no_window(), false;
  // No profile hints: a compatibility context, so render blocks may use legacy GL.
  int w = place[2] > 0 ? place[2] : 1100, h = place[2] > 0 ? place[3] : 800;
  window_ = glfwCreateWindow(w, h, title.c_str(), nullptr, nullptr);
  if (!window_) {
    no_window();
    glfwTerminate();
    return false;
  }
  if (place[2] > 0) glfwSetWindowPos(window_, place[0], place[1]);
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* win, int button, int action, int mods) {
    if (input_handler* in = input_of(win)) in->on_button(button, action, mods);
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* win, double x, double y) {
    if (input_handler* in = input_of(win)) in->on_move(x, y);
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* win, double, double dy) {
    if (input_handler* in = input_of(win)) in->on_scroll(dy);
  });
  glfwSetKeyCallback(window_, [](GLFWwindow* win, int key, int, int action, int mods) {
    if (input_handler* in = input_of(win)) in->on_key(key, action, mods);
  });
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
  ImGui_ImplGlfw_InitForOpenGL(window_, true);  // chains to the callbacks above
  ImGui_ImplOpenGL2_Init();
  return true;
}

void gl_window::close() {
  ImGui_ImplOpenGL2_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
  window_ = nullptr;
}

void gl_window::set_input(input_handler* input) { glfwSetWindowUserPointer(window_, input); }
bool gl_window::should_close() const { return glfwWindowShouldClose(window_); }
void gl_window::request_close() { glfwSetWindowShouldClose(window_, 1); }

void gl_window::wait_events(double seconds) {
  if (seconds > 0) glfwWaitEventsTimeout(seconds);
  else glfwPollEvents();
}

void gl_window::wake() { glfwPostEmptyEvent(); }

void gl_window::swap() { glfwSwapBuffers(window_); }
void gl_window::size(int& w, int& h) const { glfwGetWindowSize(window_, &w, &h); }
void gl_window::framebuffer_size(int& w, int& h) const { glfwGetFramebufferSize(window_, &w, &h); }
void gl_window::cursor(double& x, double& y) const { glfwGetCursorPos(window_, &x, &y); }

void gl_window::place(int out[4]) const {
  glfwGetWindowPos(window_, &out[0], &out[1]);
  glfwGetWindowSize(window_, &out[2], &out[3]);
}

}  // namespace vvi
