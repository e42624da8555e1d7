#include "viewer.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <future>
#include <memory>
#include <string>

#include "files.hpp"
#include "file_watch.hpp"
#include "image.hpp"
#include "mesh_export.hpp"
#include "panel.hpp"
#include "run_model.hpp"
#include "scene.hpp"
#include "script.hpp"

namespace vvi {

namespace {

std::string glfw_error;
void on_glfw_error(int, const char* description) { glfw_error = description ? description : "unknown error"; }

double now_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

class viewer {
 public:
  explicit viewer(const options& o) : o_(o) {}

  int run() {
    if (!open_window()) return 1;
    if (!o_.script.empty() && !load_script()) {
      close_window();
      return 1;
    }
    start_build(false);
    while (!glfwWindowShouldClose(window_)) frame();
    drawing_.release();
    model_.reset();
    close_window();
    return 0;
  }

 private:
  // ---- window ----
  bool open_window() {
    glfwSetErrorCallback(on_glfw_error);
    if (!glfwInit()) {
      std::fprintf(stderr, "vvinterpreter: cannot open a window (%s); use --batch to run without one\n",
                   glfw_error.c_str());
      return false;
    }
    // No profile hints: a compatibility context, so render blocks may use legacy GL.
    window_ = glfwCreateWindow(1100, 800, ("vv - " + o_.model).c_str(), nullptr, nullptr);
    if (!window_) {
      std::fprintf(stderr, "vvinterpreter: cannot open a window (%s); use --batch to run without one\n",
                   glfw_error.c_str());
      glfwTerminate();
      return false;
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window_, this);
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int mods) {
      static_cast<viewer*>(glfwGetWindowUserPointer(w))->on_button(button, action, mods);
    });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
      static_cast<viewer*>(glfwGetWindowUserPointer(w))->on_move(x, y);
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
      static_cast<viewer*>(glfwGetWindowUserPointer(w))->on_scroll(dy);
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
      static_cast<viewer*>(glfwGetWindowUserPointer(w))->on_key(key, action, mods);
    });
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
    ImGui_ImplGlfw_InitForOpenGL(window_, true);  // chains to the callbacks above
    ImGui_ImplOpenGL2_Init();
    return true;
  }

  void close_window() {
    ImGui_ImplOpenGL2_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
  }

  // ---- building and loading ----
  void start_build(bool force) {
    if (building_) return;
    building_ = true;
    status_ = force ? "recompiling ..." : "compiling ...";
    options o = o_;
    build_ = std::async(std::launch::async, [o, force] { return build_model(o.model, settings_for(o, force)); });
  }

  void finish_build() {
    if (!building_ || build_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    building_ = false;
    build_result b = build_.get();
    if (!b.sources.empty()) watch_.watch(b.sources);
    if (!b.ok) {
      // The last good model keeps running.
      show_error(b.details.empty() ? b.error : b.details, b.error);
      status_ = model_ ? "running the last model that compiled" : "no model";
      return;
    }
    warnings_ = b.warnings;
    bool first = !model_;
    if (load(b.plugin)) {
      plugin_path_ = b.plugin;
      say((first ? "loaded " : "reloaded ") + o_.model + (b.cached ? " (cached)" : ""));
    }
  }

  // Loads a plugin and starts it; on failure the current model stays.
  bool load(const std::string& plugin_path) {
    session_settings s;
    s.model_dir = folder_of(o_.model);
    s.seed = o_.seed;
    s.strict = o_.strict;
    std::string error;
    std::unique_ptr<session> fresh = session::load(plugin_path, s, error);
    if (!fresh) {
      show_error(error, error);
      return false;
    }
    if (!fresh->start()) {
      show_error(fresh->error(), fresh->error());
      return false;
    }
    std::string init_error;
    if (!init_rendering(fresh.get(), init_error)) show_error(init_error, init_error);
    model_ = std::move(fresh);  // the old model's close block runs here
    error_.clear();
    render_failed_ = false;
    animating_ = false;
    run_left_ = 0;
    status_ = "running";
    refresh_drawing();
    if (!camera_set_) {
      cam_.fit(view_box(model_.get(), &drawing_));
      camera_set_ = true;  // later reloads keep the view
    }
    return true;
  }

  void rewind() {
    if (plugin_path_.empty()) return;
    std::string path = plugin_path_;
    drawing_.release();
    model_.reset();  // close and unload: the model's state goes with it
    if (load(path)) say("rewound " + o_.model);
  }

  // ---- running ----
  bool step() {
    if (!model_) {
      run_left_ = 0;
      return false;
    }
    if (!model_->step()) {
      show_error(model_->error(), model_->error());
      animating_ = false;
      run_left_ = 0;
      return false;
    }
    refresh_drawing();
    if (model_->proxy().record_frame) record_frame_ = true;
    return true;
  }

  // The drawing also gives the view its bounds, so it is kept up to date
  // when the model draws itself too.
  void refresh_drawing() {
    if (!model_) return;
    std::string e = update_drawing(*model_, o_.mesh, max_face_of(o_, *model_), drawing_);
    if (!e.empty()) show_error(e, e);
  }

  // ---- one frame ----
  void frame() {
    bool busy = building_ || animating_ || run_left_ > 0 || script_pos_ < script_.size();
    if (busy) glfwPollEvents();
    else glfwWaitEventsTimeout(0.25);  // idle: wake for events and to watch the files
    double t = now_seconds();
    if (t - last_watch_ >= 0.25) {
      last_watch_ = t;
      if (!building_ && watch_.changed()) start_build(false);
    }
    finish_build();
    run_script();
    if (run_left_ > 0) {
      if (step()) --run_left_;
    } else if (animating_ && model_ && t - last_animated_ >= model_->proxy().delay_msec / 1000.0) {
      last_animated_ = t;
      step();
    }

    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    if (w > 0 && h > 0) {
      std::string e;
      if (!render_failed_ && !draw_frame(model_.get(), &drawing_, cam_, w, h, e)) {
        render_failed_ = true;  // once: the same error would repeat every frame
        show_error(e, e);
      } else if (render_failed_) {
        draw_frame(nullptr, &drawing_, cam_, w, h, e);
      }
      capture(w, h);
    }
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    panel_actions a = draw_panel(panel());
    ImGui::Render();
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    if (!window_shot_path_.empty() && w > 0 && h > 0) {
      save(window_shot_path_, w, h);
      window_shot_path_.clear();
    }
    glfwSwapBuffers(window_);
    act(a);
  }

  // Screenshots read the frame before the panel is drawn over it.
  void capture(int w, int h) {
    if (record_frame_ && model_) {
      record_frame_ = false;
      std::error_code ec;
      std::filesystem::create_directories(o_.frames, ec);
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%05u.png", model_->steps_done());
      save(o_.frames + name, w, h);
    }
    if (!shot_path_.empty()) {
      save(shot_path_, w, h);
      shot_path_.clear();
    }
  }

  void save(const std::string& path, int w, int h) {
    std::string e = write_png(path, w, h, read_pixels(w, h));
    if (e.empty()) say("wrote " + path);
    else show_error(e, e);
  }

  void act(const panel_actions& a) {
    if (a.step) run_left_ += 1;
    if (a.run && model_) run_left_ += model_->proxy().steps;
    if (a.animate && model_ && !model_->proxy().no_animate) animating_ = true;
    if (a.stop) animating_ = false, run_left_ = 0;
    if (a.rewind) rewind();
    if (a.end && model_ && !model_->end()) show_error(model_->error(), model_->error());
    if (a.end) refresh_drawing();
    if (a.reread && model_ && !model_->reread()) show_error(model_->error(), model_->error());
    if (a.recompile) start_build(true);
    if (a.fit) fit();
    if (a.screenshot) shot_path_ = next_screenshot_name();
  }

  void fit() { cam_.fit(view_box(model_.get(), &drawing_)); }

  std::string next_screenshot_name() {
    for (;;) {
      char name[40];
      std::snprintf(name, sizeof name, "vv_screenshot_%03d.png", ++screenshots_);
      if (!std::filesystem::exists(name)) return name;
    }
  }

  panel_state panel() const {
    panel_state s;
    s.model = o_.model;
    s.status = status_;
    s.has_model = model_ != nullptr;
    if (model_) {
      s.steps = model_->steps_done();
      s.last_step_ms = model_->last_step_ms();
      s.run_steps = model_->proxy().steps;
      s.can_animate = !model_->proxy().no_animate;
      for (const vv_mesh_entry* m : model_->meshes()) s.meshes.emplace_back(m->name, m->vertex_count());
    }
    s.animating = animating_;
    s.error = error_;
    s.warnings = warnings_;
    s.message = message_;
    return s;
  }

  // ---- input ----
  void on_button(int button, int action, int mods) {
    if (ImGui::GetIO().WantCaptureMouse && action == GLFW_PRESS) return;
    if (action == GLFW_PRESS) {
      dragging_ = (button == GLFW_MOUSE_BUTTON_LEFT && !(mods & GLFW_MOD_SHIFT)) ? 1 : 2;
      glfwGetCursorPos(window_, &mouse_x_, &mouse_y_);
    } else {
      dragging_ = 0;
    }
  }

  void on_move(double x, double y) {
    if (dragging_) {
      int w = 0, h = 0;
      glfwGetWindowSize(window_, &w, &h);
      if (dragging_ == 1) cam_.drag_rotate(mouse_x_, mouse_y_, x, y, w, h);
      else cam_.pan(x - mouse_x_, y - mouse_y_, h);
    }
    mouse_x_ = x, mouse_y_ = y;
  }

  void on_scroll(double dy) {
    if (!ImGui::GetIO().WantCaptureMouse) cam_.zoom(dy > 0 ? 1.15 : 1 / 1.15);
  }

  void on_key(int key, int action, int) {
    if (ImGui::GetIO().WantCaptureKeyboard || (action != GLFW_PRESS && action != GLFW_REPEAT)) return;
    panel_actions a;
    switch (key) {
      case GLFW_KEY_SPACE: a.step = true; break;
      case GLFW_KEY_R: a.run = true; break;
      case GLFW_KEY_A: (animating_ ? a.stop : a.animate) = true; break;
      case GLFW_KEY_W: a.rewind = true; break;
      case GLFW_KEY_E: a.end = true; break;
      case GLFW_KEY_F: a.fit = true; break;
      case GLFW_KEY_S: a.screenshot = true; break;
      case GLFW_KEY_HOME: cam_.reset(); break;
      case GLFW_KEY_LEFT: cam_.rotate_degrees(-5, 0); break;
      case GLFW_KEY_RIGHT: cam_.rotate_degrees(5, 0); break;
      case GLFW_KEY_UP: cam_.rotate_degrees(0, -5); break;
      case GLFW_KEY_DOWN: cam_.rotate_degrees(0, 5); break;
      case GLFW_KEY_EQUAL:
      case GLFW_KEY_KP_ADD: cam_.zoom(1.15); break;
      case GLFW_KEY_MINUS:
      case GLFW_KEY_KP_SUBTRACT: cam_.zoom(1 / 1.15); break;
      case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window_, 1); break;
      default: break;
    }
    act(a);
  }

  // ---- --script ----
  bool load_script() {
    std::optional<std::string> text = read_file(o_.script);
    std::string error;
    if (!text) error = o_.script + ": cannot read the script";
    else script_ = parse_script(*text, o_.script, error);
    if (!error.empty()) {
      std::fprintf(stderr, "vvinterpreter: %s\n", error.c_str());
      return false;
    }
    return true;
  }

  // Runs script commands until one needs frames to pass (steps, waits,
  // screenshots, builds).
  void run_script() {
    while (script_pos_ < script_.size()) {
      if (building_ || run_left_ > 0 || now_seconds() < wait_until_ || !shot_path_.empty() ||
          !window_shot_path_.empty())
        return;
      const script_command& c = script_[script_pos_++];
      switch (c.kind) {
        case script_command::step: run_left_ += static_cast<unsigned>(c.count); return;
        case script_command::run: if (model_) run_left_ += model_->proxy().steps; return;
        case script_command::rewind: rewind(); break;
        case script_command::end: act(end_action()); break;
        case script_command::reread: if (model_ && !model_->reread()) show_error(model_->error(), model_->error()); break;
        case script_command::recompile: start_build(true); return;
        case script_command::fit: fit(); break;
        case script_command::screenshot: shot_path_ = c.path; return;
        case script_command::window_screenshot: window_shot_path_ = c.path; return;
        case script_command::export_mesh: export_from_script(c); break;
        case script_command::rotate: cam_.rotate_degrees(c.a, c.b); break;
        case script_command::zoom: cam_.zoom(c.a); break;
        case script_command::wait: wait_until_ = now_seconds() + c.count / 1000.0; return;
        case script_command::quit: glfwSetWindowShouldClose(window_, 1); return;
      }
    }
  }

  static panel_actions end_action() {
    panel_actions a;
    a.end = true;
    return a;
  }

  void export_from_script(const script_command& c) {
    const vv_mesh_entry* m = model_ ? model_->mesh(c.mesh) : nullptr;
    std::string e = !model_ ? "no model is loaded" : !m ? "the model has no global mesh named " + c.mesh
                                                          : export_mesh(*m, c.path, max_face_of(o_, *model_));
    if (e.empty()) say("wrote " + c.path);
    else show_error(e, e);
  }

  // ---- messages ----
  void say(const std::string& m) {
    message_ = m;
    std::printf("%s\n", m.c_str());
    std::fflush(stdout);
  }
  void show_error(const std::string& shown, const std::string& line) {
    error_ = shown;
    std::fprintf(stderr, "vvinterpreter: %s\n", line.c_str());
    std::fflush(stderr);
  }

  options o_;
  GLFWwindow* window_ = nullptr;
  std::unique_ptr<session> model_;
  std::string plugin_path_;
  mesh_drawing drawing_;
  camera cam_;
  bool camera_set_ = false;
  file_watch watch_;
  std::future<build_result> build_;
  bool building_ = false;
  std::string status_ = "starting", error_, warnings_, message_;
  bool animating_ = false, render_failed_ = false, record_frame_ = false;
  unsigned run_left_ = 0;
  double last_animated_ = 0, last_watch_ = 0, wait_until_ = 0;
  std::string shot_path_, window_shot_path_;
  int screenshots_ = 0;
  int dragging_ = 0;
  double mouse_x_ = 0, mouse_y_ = 0;
  std::vector<script_command> script_;
  std::size_t script_pos_ = 0;
};

}  // namespace

int run_viewer(const options& o) { return viewer(o).run(); }

}  // namespace vvi
