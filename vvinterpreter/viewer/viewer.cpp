#include "viewer/viewer.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <memory>
#include <string>

#include <model/viewer_keys.hpp>

#include "app/files.hpp"
#include "render/image.hpp"
#include "render/scene.hpp"
#include "runner/fault_guard.hpp"
#include "runner/model_runner.hpp"
#include "runner/parameter_source.hpp"
#include "runner/plots.hpp"
#include "viewer/file_watch.hpp"
#include "viewer/function_editor.hpp"
#include "viewer/inspection.hpp"
#include "viewer/picking.hpp"
#include "viewer/model_worker.hpp"
#include "viewer/panel.hpp"
#include "viewer/script.hpp"

namespace vvi {

namespace {

std::string glfw_error;
void on_glfw_error(int, const char* description) { glfw_error = description ? description : "unknown error"; }

double now_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

// A job runs this long before the window shows it as running, with Stop.
constexpr double long_job_seconds = 0.5;

class viewer {
 public:
  viewer(const options& o, const viewer_resume& r) : o_(o), resume_(r), runner_(o) {
    replay_ = r.replay;
    color_by_ = o.color_by;
    script_pos_ = r.script_pos;
    screenshots_ = r.screenshots;
    if (r.restarted) {
      error_ = r.error;
      message_ = r.note;
      keep_error_once_ = true;
      if (cam_.restore(r.camera)) camera_set_ = true;
    }
  }

  int run() {
    if (!open_window()) return 1;
    if (!o_.script.empty() && !load_script()) {
      close_window();
      return 1;
    }
    tell_supervisor("up", "");
    start_build(false);
    while (!glfwWindowShouldClose(window_)) frame();
    tell_supervisor("quitting", "");  // whatever happens now, no restart
    if (busy()) {  // closed while the model runs: it cannot be closed cleanly
      std::fflush(nullptr);
      _exit(0);
    }
    drawing_.release();
    runner_.close();
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
    int w = resume_.window[2] > 0 ? resume_.window[2] : 1100, h = resume_.window[3] > 0 ? resume_.window[3] : 800;
    window_ = glfwCreateWindow(w, h, ("vv - " + o_.model).c_str(), nullptr, nullptr);
    if (!window_) {
      std::fprintf(stderr, "vvinterpreter: cannot open a window (%s); use --batch to run without one\n",
                   glfw_error.c_str());
      glfwTerminate();
      return false;
    }
    if (resume_.window[2] > 0) glfwSetWindowPos(window_, resume_.window[0], resume_.window[1]);
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window_, this);
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* win, int button, int action, int mods) {
      static_cast<viewer*>(glfwGetWindowUserPointer(win))->on_button(button, action, mods);
    });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* win, double x, double y) {
      static_cast<viewer*>(glfwGetWindowUserPointer(win))->on_move(x, y);
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* win, double, double dy) {
      static_cast<viewer*>(glfwGetWindowUserPointer(win))->on_scroll(dy);
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* win, int key, int, int action, int mods) {
      static_cast<viewer*>(glfwGetWindowUserPointer(win))->on_key(key, action, mods);
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

  // ---- building ----
  void start_build(bool force) {
    if (building_) return;
    building_ = true;
    status_ = force ? "recompiling ..." : "compiling ...";
    // What the files are now: a save during the build is a change after it.
    std::vector<std::string> known = watch_.paths();
    if (known.empty()) known.push_back(o_.model);
    stamps_before_build_ = watch_.stamps_of(known);
    const model_runner* runner = &runner_;
    std::string model = o_.model;
    // Said once the sources are read: an edit after this line is one the
    // build does not have.
    auto compiling = [model] {
      std::printf("compiling %s ...\n", model.c_str());
      std::fflush(stdout);
    };
    build_ = std::async(std::launch::async, [runner, force, compiling] { return runner->build(force, compiling); });
  }

  void finish_build() {
    if (!building_ || build_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    building_ = false;
    build_result b = build_.get();
    if (!b.sources.empty()) watch_.watch(b.sources, stamps_before_build_);
    if (!b.ok) {
      // The last good model keeps running.
      show_error(b.details.empty() ? b.error : b.details, b.error);
      status_ = runner_.model() || pending_load_ ? "running the last model that compiled" : "no model";
      return;
    }
    warnings_ = b.warnings;
    pending_load_ = true;
    pending_plugin_ = b.plugin;
    pending_cached_ = b.cached;
    // After a restart: a build that crashed on its way in is not loaded
    // again as it is; the model that ran before comes back.
    if (!resume_used_ && resume_.restarted) {
      resume_used_ = true;
      pending_steps_ = resume_.good_steps;
      if (b.plugin == resume_.bad_plugin) {
        if (resume_.good_plugin.empty()) pending_load_ = false;
        pending_plugin_ = resume_.good_plugin;
      }
      return;
    }
    pending_steps_ = replay_ && runner_.model() ? runner_.model()->steps_done() : 0;
  }

  // ---- the model, on the worker thread ----
  bool busy() const { return worker_.busy(); }

  void submit_load(const std::string& plugin, unsigned steps, const std::string& verb) {
    tell_supervisor("trying", plugin);
    session* before = runner_.model();
    job_ = [this, before, plugin, verb] {
      bool fresh = runner_.model() != before || runner_.plugin_path() == plugin;
      if (!fresh) {  // load failed: the running model stays
        tell_supervisor("tried", "");
        show_error(runner_.error(), runner_.error());
        return;
      }
      if (!resume_.no_render_plugin.empty() && plugin == resume_.no_render_plugin) render_failed_ = true;
      else render_failed_ = false;
      std::string e;
      if (!render_failed_ && !init_rendering(runner_.model(), e)) render_failed_ = true, show_error(e, e);
      animating_ = false;
      run_left_ = 0;
      status_ = "running";
      if (!runner_.error().empty()) show_error(runner_.error(), runner_.error());
      else if (keep_error_once_) keep_error_once_ = false;  // the crash that caused the restart stays shown
      else error_.clear();
      refresh_drawing();
      if (!camera_set_) {
        fit_view();
        camera_set_ = true;  // later reloads keep the view
      }
      say(verb + " " + o_.model + (pending_cached_ && verb != "rewound" ? " (cached)" : ""));
      tell_model_state();
    };
    std::string what = steps ? "loading and running to step " + std::to_string(steps) : "loading";
    worker_.submit([this, plugin, steps] { runner_.load(plugin, steps); }, what);
  }

  void submit_step() {
    job_ = [this] {
      if (runner_.error().empty()) {
        refresh_drawing();
        if (runner_.model()->run_settings().record_frame) record_frame_ = true;
      } else {
        show_error(runner_.error(), runner_.error());
        animating_ = false;
        run_left_ = 0;
      }
      tell_model_state();
    };
    runner_.clear_error();
    worker_.submit([this] { runner_.step(); }, "step " + std::to_string(runner_.model()->steps_done() + 1));
  }

  void submit_simple(const std::string& what, bool (model_runner::*op)(), bool refresh) {
    job_ = [this, refresh] {
      if (!runner_.error().empty()) show_error(runner_.error(), runner_.error());
      if (refresh) refresh_drawing();
    };
    runner_.clear_error();
    worker_.submit([this, op] { (runner_.*op)(); }, what);
  }

  // "Reread files", or a file a file object reads was saved: the model
  // keeps its step; a file that does not read keeps its last good values.
  void submit_reread() {
    bool on_save = reread_on_save_;
    reread_on_save_ = false;
    job_ = [this, on_save] {
      if (!runner_.error().empty()) return show_error(runner_.error(), runner_.error());
      std::string files;
      for (const std::string& f : file_objects_) files += (files.empty() ? "" : ", ") + f;
      if (on_save || !files.empty()) say("reread " + (files.empty() ? std::string("(no files)") : files));
      refresh_drawing();
    };
    runner_.clear_error();
    worker_.submit([this] { runner_.reread(); }, "reread");
  }

  // When a job ended: its follow-up on this (the GL) thread.
  void finish_job() {
    if (!worker_.take_finished() || !job_) return;
    std::function<void()> f = std::move(job_);
    job_ = nullptr;
    f();
    drawn_since_job_ = false;
    std::fflush(stdout);  // what the model printed shows now, also through a pipe
  }

  // The next thing to run, when the worker is free.
  void next_job(double t) {
    // Each state a job leaves is drawn (and recorded) once before the next.
    if (busy() || !drawn_since_job_) return;
    if (pending_load_) {
      pending_load_ = false;
      bool first = !runner_.model();
      submit_load(pending_plugin_, pending_steps_, first ? "loaded" : "reloaded");
    } else if (rewind_requested_) {
      rewind_requested_ = false;
      if (!runner_.plugin_path().empty()) submit_load(runner_.plugin_path(), 0, "rewound");
    } else if (!runner_.model()) {
      run_left_ = 0;
    } else if (end_requested_) {
      end_requested_ = false;
      submit_simple("end", &model_runner::end, true);
    } else if (reread_requested_) {
      reread_requested_ = false;
      submit_reread();
    } else if (run_left_ > 0) {
      --run_left_;
      submit_step();
    } else if (animating_ && t - last_animated_ >= runner_.model()->run_settings().delay_msec / 1000.0) {
      last_animated_ = t;
      submit_step();
    }
  }

  // Stop: a job cannot be cut short inside this process, so the window
  // asks its supervisor to start it again at the last good state.
  void stop() {
    animating_ = false;
    run_left_ = 0;
    if (!busy()) return;
    char secs[32];
    std::snprintf(secs, sizeof secs, "%.1f", worker_.busy_seconds());
    std::string what = worker_.what();
    std::string activity = what.rfind("step", 0) == 0 ? "step" : what.rfind("loading", 0) == 0 ? "loading" : what;
    fault_guard::report_activity_stack();  // the supervisor names the line it was stopped at
    tell_supervisor("stopped", activity + " " + what + " was stopped after " + secs + " s");
    std::fflush(nullptr);
    _exit(viewer_restart_code);  // the worker may be anywhere: no clean-up
  }

  // The drawing also gives the view its bounds, so it is kept up to date
  // when the model draws itself too.
  void refresh_drawing() {
    if (!runner_.model()) return;
    vv_geometry g{};
    std::string e = runner_.geometry(g, color_by_);
    if (e.empty() && !color_by_.empty() && !g.values) {
      std::string numeric = g.numeric_fields ? g.numeric_fields : "";
      e = "colour by " + color_by_ + ": the vertices have no numeric property " + color_by_ +
          (numeric.empty() ? " (they have none)" : " (they have " + numeric + ")");
      color_by_.clear();
      show_error(e, e);
      e = runner_.geometry(g);
    }
    if (!e.empty()) return show_error(e, e);
    drawing_.update(g, style_.flat);
    inspect_.update(g);
    if (std::string pe = inspect_.describe(runner_); !pe.empty()) show_error(pe, pe);
    if (auto_fit_ && !camera_moved_ && camera_set_) fit_view();
    refresh_model_views();
  }

  // What the panel shows of the model's state, read while the model is
  // idle (the panel is drawn every frame, also while a step runs).
  void refresh_model_views() {
    parameters_.clear();
    plots_.clear();
    if (!runner_.model()) return;
    for (const vv_param_entry* p : parameters_of(*runner_.model()))
      parameters_.push_back({p->name, p->type, parameter_text(*p), parameter_number(*p), p->has_range != 0, p->lo,
                             p->hi, p->line});
    for (const vv_plot_series& series : runner_.model()->plots()) {
      plot_view v;
      v.name = series.name;
      v.values.assign(series.values, series.values + series.count);
      if (series.count) v.first_step = series.steps[0], v.last_step = series.steps[series.count - 1];
      if (series.count) v.last = series.values[series.count - 1];
      plots_.push_back(std::move(v));
    }
    std::vector<std::string> files = runner_.file_objects();
    if (files != file_objects_) file_objects_ = files, objects_watch_.watch(files);
  }

  // ---- looking into the model ----
  void set_parameter(const std::string& name, const std::string& text) {
    if (busy() || !runner_.model()) return;
    std::string e = runner_.set_parameter(name, text);
    if (!e.empty()) return show_error(e, e);
    say("set " + name + " = " + text);
    if (rewind_on_change_) {
      submit_load(runner_.plugin_path(), runner_.model()->steps_done(), "rewound");
      return;
    }
    refresh_model_views();
  }

  void save_parameters() {
    if (busy() || !runner_.model()) return;
    // Only what the user set: the other values stay as the file writes them.
    std::vector<parameter_value_at> values;
    for (const parameter_setting& set : runner_.parameter_settings())
      if (const vv_param_entry* p = find_parameter(*runner_.model(), set.name))
        values.push_back({p->name, parameter_text(*p), p->line});
    if (values.empty()) return say("no parameter was changed: nothing to save");
    std::string e = save_parameter_values(o_.model, values);
    if (e.empty()) say("saved the parameters in " + o_.model);
    else show_error(e, e);
  }

  void pick(unsigned label) {
    if (busy() || !runner_.model()) return;
    inspect_.pick_label(label);
    if (std::string e = inspect_.describe(runner_); !e.empty()) return show_error(e, e);
    std::printf("%s", inspect_.text().c_str());
    std::fflush(stdout);
  }

  void pick_at(double x, double y) {
    int w = 0, h = 0;
    glfwGetWindowSize(window_, &w, &h);
    scene_area scene = scene_in_window(w);
    long index = pick_vertex(inspect_.positions(), cam_, scene.width, h, x - scene.left, y);
    inspect_.pick_index(index);
    if (inspect_.picked_label()) pick(inspect_.picked_label());
  }

  void set_style(const display_style& style) {
    bool rebuild = style.flat != style_.flat;
    style_ = style;
    if (rebuild && !busy()) refresh_drawing();
  }

  void colour_by(const std::string& field) {
    color_by_ = field;
    if (!busy()) refresh_drawing();
  }

  void show(const std::string& what, bool on) {
    display_style st = style_;
    if (what == "faces") st.faces = on;
    else if (what == "edges") st.edges = on;
    else if (what == "points") st.points = on;
    else if (what == "flat") st.flat = on;
    else if (what == "back-faces") st.back_faces = on;
    else if (what == "auto-fit") auto_fit_ = on, camera_moved_ = false;
    set_style(st);
  }

  void write_plots_to(const std::string& path) {
    if (!runner_.model()) return show_error("plots " + path + ": no model is loaded", "plots: no model is loaded");
    std::string e = write_plots(path, runner_.model()->plots());
    if (e.empty()) say("wrote " + path);
    else show_error(e, e);
  }

  // ---- one frame ----
  void frame() {
    bool idle = !building_ && !busy() && !animating_ && run_left_ == 0 && script_pos_ >= script_.size() &&
                !pending_load_;
    if (idle) glfwWaitEventsTimeout(0.25);  // wake for events and to watch the files
    else if (busy()) glfwWaitEventsTimeout(0.02);
    else glfwPollEvents();
    double t = now_seconds();
    if (t - last_watch_ >= 0.25) {
      last_watch_ = t;
      if (!building_ && watch_.changed()) start_build(false);
      // A file a file object reads was saved: reread it, keeping the step.
      if (objects_watch_.changed() && runner_.model()) reread_requested_ = reread_on_save_ = true;
    }
    finish_build();
    finish_job();
    run_script();
    next_job(t);

    // The panel first (Dear ImGui draws nothing yet): the scene is placed
    // beside the panel as it is on this frame.
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    panel_actions a = draw_panel(panel());
    panel_right_ = a.panel_collapsed ? 0 : a.panel_right;
    edit_functions();

    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    if (w > 0 && h > 0) {
      std::string e;
      // While the model's code runs, its state is not to be read: draw the
      // last drawing without the model's render blocks.
      session* model = busy() || render_failed_ ? nullptr : runner_.model();
      bar_strip_ = double(colour_bar_strip(model, &drawing_, w)) / w;
      display_style style = style_;
      style.picked = inspect_.picked_index();
      style.neighbours = inspect_.neighbours();
      auto draw = [&](int left) {
        if (!draw_frame(model, &drawing_, cam_, w, h, e, style, left)) {
          render_failed_ = true;  // once: the same error would repeat every frame
          show_error(e, e);
        }
      };
      // Screenshots frame the model in the whole picture; the window shows
      // it beside the panel.
      if (!busy() && (record_frame_ || !shot_path_.empty())) {
        draw(0);
        capture(w, h);
      }
      int window_w = 0, window_h = 0;
      glfwGetWindowSize(window_, &window_w, &window_h);
      draw(window_w > 0 ? static_cast<int>(std::lround(double(scene_in_window(window_w).left) * w / window_w)) : 0);
      if (!busy()) drawn_since_job_ = true;
    }
    ImGui::Render();
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    if (!window_shot_path_.empty() && w > 0 && h > 0) {
      save(window_shot_path_, w, h);
      window_shot_path_.clear();
    }
    glfwSwapBuffers(window_);
    act(a);
    tell_view_state();
  }

  // Screenshots read the frame before the panel is drawn over it.
  void capture(int w, int h) {
    if (record_frame_ && runner_.model()) {
      record_frame_ = false;
      std::error_code ec;
      std::filesystem::create_directories(o_.frames, ec);
      char name[32];
      std::snprintf(name, sizeof name, "/frame_%05u.png", runner_.model()->steps_done());
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
    if (a.run && runner_.model() && !busy()) run_left_ += runner_.model()->run_settings().steps;
    if (a.animate && runner_.model() && !busy() && !runner_.model()->run_settings().no_animate) animating_ = true;
    if (a.stop) stop();
    if (a.rewind) rewind_requested_ = true;
    if (a.end) end_requested_ = true;
    if (a.reread) reread_requested_ = true;
    if (a.recompile) start_build(true);
    if (a.fit) fit();
    if (a.screenshot) shot_path_ = next_screenshot_name();
    if (a.toggle_replay) replay_ = !replay_;
    for (const auto& [name, text] : a.set_parameters) set_parameter(name, text);
    if (a.save_parameters) save_parameters();
    if (a.toggle_rewind_on_change) rewind_on_change_ = !rewind_on_change_;
    if (a.style_changed) set_style(a.style);
    if (a.toggle_auto_fit) {
      auto_fit_ = !auto_fit_;
      camera_moved_ = false;
      if (auto_fit_) fit();
    }
    if (a.color_by_changed) colour_by(a.color_by);
    if (a.clear_pick) inspect_.clear();
  }

  void fit() {
    if (!busy()) fit_view();
  }

  // The whole model in view, seen from a little above and to the side when
  // it is not flat (a pyramid face-on is a flat diamond); a flat model in
  // the xy-plane is seen face-on.
  void fit_view() {
    box b = view_box(runner_.model(), &drawing_);
    cam_.fit(b);
    glm::dvec3 size = b.max - b.min;
    if (!b.empty && size.z > 0.01 * glm::length(size)) cam_.look_from(30, 25);
  }

  // The function editor's Save writes the file; the file watch then has
  // the model reread it.
  void edit_functions() {
    std::string said, error;
    editor_.draw(file_objects_, said, error);
    if (!said.empty()) say(said);
    if (!error.empty()) show_error(error, error);
  }

  // Where the scene is drawn in a window w pixels wide: right of the panel
  // when that leaves it room enough (else the panel, which folds away,
  // floats over it), and left of the colour bar's strip (as draw_frame
  // drew the last frame).
  struct scene_area {
    int left, width;
  };
  scene_area scene_in_window(int w) const {
    int right = w - static_cast<int>(std::lround(bar_strip_ * w));
    int left = static_cast<int>(panel_right_) + 6;
    if (right - left < std::max(300, w / 3)) left = 0;
    return {left, std::max(1, right - left)};
  }

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
    s.has_model = runner_.model() != nullptr;
    s.busy = busy();
    if (busy() && worker_.busy_seconds() >= long_job_seconds) {
      char secs[32];
      std::snprintf(secs, sizeof secs, "%.1f", worker_.busy_seconds());
      s.running = worker_.what() + " running for " + secs + " s";
    }
    if (runner_.model() && !busy()) {
      s.steps = runner_.model()->steps_done();
      s.last_step_ms = runner_.model()->last_step_ms();
      s.run_steps = runner_.model()->run_settings().steps;
      s.can_animate = !runner_.model()->run_settings().no_animate;
      for (const vv_mesh_entry* m : runner_.model()->meshes()) s.meshes.emplace_back(m->name, m->vertex_count());
    }
    s.animating = animating_;
    s.replay = replay_;
    s.error = error_;
    s.warnings = warnings_;
    s.message = message_;
    s.parameters = parameters_;
    s.rewind_on_change = rewind_on_change_;
    s.plots = plots_;
    s.style = style_;
    s.auto_fit = auto_fit_ && !camera_moved_;
    s.color_by = color_by_;
    s.numeric_fields = inspect_.numeric_fields();
    s.has_values = drawing_.has_values();
    s.value_min = drawing_.value_min();
    s.value_max = drawing_.value_max();
    s.counts = inspect_.counts();
    s.picked = inspect_.text();
    s.picked_label = inspect_.picked_label();
    s.file_objects = file_objects_;
    return s;
  }

  // ---- what the supervisor needs after a crash ----
  void tell_model_state() {
    if (!runner_.model()) return;
    tell_supervisor("model", std::to_string(runner_.model()->steps_done()) + " " + runner_.plugin_path());
  }

  void tell_view_state() {
    std::string c = cam_.save();
    if (c != told_camera_) tell_supervisor("camera", told_camera_ = c);
    int x = 0, y = 0, w = 0, h = 0;
    glfwGetWindowPos(window_, &x, &y);
    glfwGetWindowSize(window_, &w, &h);
    std::string win = std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(w) + " " + std::to_string(h);
    if (win != told_window_) tell_supervisor("window", told_window_ = win);
    if (script_pos_ != told_script_) tell_supervisor("script", std::to_string(told_script_ = script_pos_));
    if (screenshots_ != told_shots_) tell_supervisor("shots", std::to_string(told_shots_ = screenshots_));
    if (replay_ != told_replay_) tell_supervisor("replay", (told_replay_ = replay_) ? "1" : "0");
  }

  // ---- input ----
  void on_button(int button, int action, int mods) {
    if (ImGui::GetIO().WantCaptureMouse && action == GLFW_PRESS) return;
    if (action == GLFW_PRESS && button == GLFW_MOUSE_BUTTON_LEFT && (mods & GLFW_MOD_CONTROL)) {
      glfwGetCursorPos(window_, &mouse_x_, &mouse_y_);
      pick_at(mouse_x_, mouse_y_);
      return;
    }
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
      else cam_.pan(x - mouse_x_, y - mouse_y_, scene_in_window(w).width, h);
      camera_moved_ = true;  // the user's view: auto-fit stops
    }
    mouse_x_ = x, mouse_y_ = y;
  }

  void on_scroll(double dy) {
    if (!ImGui::GetIO().WantCaptureMouse) cam_.zoom(dy > 0 ? 1.15 : 1 / 1.15), camera_moved_ = true;
  }

  void on_key(int key, int action, int mods) {
    if (ImGui::GetIO().WantCaptureKeyboard || (action != GLFW_PRESS && action != GLFW_REPEAT)) return;
    panel_actions a;
    // Letters and digits: the list vvc checks actions' keys against.
    const char c = key >= GLFW_KEY_A && key <= GLFW_KEY_Z   ? static_cast<char>('a' + (key - GLFW_KEY_A))
                   : key >= GLFW_KEY_0 && key <= GLFW_KEY_9 ? static_cast<char>('0' + (key - GLFW_KEY_0))
                                                            : '\0';
    if (const vv::model::viewer_key* k = c ? vv::model::find_viewer_key(c) : nullptr) {
      switch (k->command) {
        case vv::model::viewer_command::run: a.run = true; break;
        case vv::model::viewer_command::animate_or_stop: (animating_ ? a.stop : a.animate) = true; break;
        case vv::model::viewer_command::rewind: a.rewind = true; break;
        case vv::model::viewer_command::end: a.end = true; break;
        case vv::model::viewer_command::fit: a.fit = true; break;
        case vv::model::viewer_command::screenshot: a.screenshot = true; break;
      }
      return act(a);
    }
    switch (key) {
      case GLFW_KEY_SPACE: a.step = true; break;
      case GLFW_KEY_HOME: cam_.reset(); break;
      case GLFW_KEY_LEFT: cam_.rotate_degrees(-5, 0); break;
      case GLFW_KEY_RIGHT: cam_.rotate_degrees(5, 0); break;
      case GLFW_KEY_UP: cam_.rotate_degrees(0, -5); break;
      case GLFW_KEY_DOWN: cam_.rotate_degrees(0, 5); break;
      case GLFW_KEY_EQUAL:
      case GLFW_KEY_KP_ADD: cam_.zoom(1.15); break;
      case GLFW_KEY_MINUS:
      case GLFW_KEY_KP_SUBTRACT: cam_.zoom(1 / 1.15); break;
      case GLFW_KEY_ESCAPE: a.stop = true; break;  // a running step, or the animation
      case GLFW_KEY_Q:
        if (mods & GLFW_MOD_CONTROL) glfwSetWindowShouldClose(window_, 1);
        break;
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
  // screenshots, builds). A command waits for the model's job to end,
  // except `stop`, which ends a job that has run for half a second.
  void run_script() {
    while (script_pos_ < script_.size()) {
      const script_command& c = script_[script_pos_];
      if (c.kind == script_command::stop && busy()) {
        if (worker_.busy_seconds() < long_job_seconds) return;
        ++script_pos_;
        tell_supervisor("script", std::to_string(told_script_ = script_pos_));
        stop();
      }
      // Waiting and a picture of the window go on beside a running job.
      bool beside_job = c.kind == script_command::wait || c.kind == script_command::window_screenshot;
      if (building_ || (busy() && !beside_job) || pending_load_ || run_left_ > 0 || rewind_requested_ ||
          end_requested_ || reread_requested_ || now_seconds() < wait_until_ || !shot_path_.empty() ||
          !window_shot_path_.empty())
        return;
      ++script_pos_;
      switch (c.kind) {
        case script_command::step: run_left_ += static_cast<unsigned>(c.count); return;
        case script_command::run: if (runner_.model()) run_left_ += runner_.model()->run_settings().steps; return;
        case script_command::rewind: rewind_requested_ = true; return;
        case script_command::end: end_requested_ = true; return;
        case script_command::reread: reread_requested_ = true; return;
        case script_command::recompile: start_build(true); return;
        case script_command::fit: fit(); break;
        case script_command::screenshot: shot_path_ = c.path; return;
        case script_command::window_screenshot: window_shot_path_ = c.path; return;
        case script_command::export_mesh: export_from_script(c); break;
        case script_command::rotate: cam_.rotate_degrees(c.a, c.b); break;
        case script_command::zoom: cam_.zoom(c.a); break;
        case script_command::wait: wait_until_ = now_seconds() + c.count / 1000.0; return;
        case script_command::stop: stop(); break;
        case script_command::quit: glfwSetWindowShouldClose(window_, 1); return;
        case script_command::pick: pick(static_cast<unsigned>(c.count)); break;
        case script_command::set: set_parameter(c.name, c.value); return;
        case script_command::save_params: save_parameters(); break;
        case script_command::color_by: colour_by(c.name); break;
        case script_command::show: show(c.name, c.value == "on"); break;
        case script_command::plots: write_plots_to(c.path); break;
      }
    }
  }

  void export_from_script(const script_command& c) {
    std::string e = runner_.export_to(c.path, {c.mesh});
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
  viewer_resume resume_;
  bool resume_used_ = false, keep_error_once_ = false;
  GLFWwindow* window_ = nullptr;
  model_runner runner_;
  model_worker worker_;
  std::function<void()> job_;  // the follow-up of the running job
  bool drawn_since_job_ = true;
  mesh_drawing drawing_;
  camera cam_;
  bool camera_set_ = false;
  display_style style_;
  float panel_right_ = 0;  // where the open panel ends, in window pixels
  double bar_strip_ = 0;  // the colour bar's strip, as a fraction of the window's width
  bool auto_fit_ = true, camera_moved_ = false;  // auto-fit until the user moves the view
  std::string color_by_;
  inspection inspect_;
  function_editor editor_;
  std::vector<parameter_view> parameters_;
  bool rewind_on_change_ = false;
  std::vector<plot_view> plots_;
  file_watch objects_watch_;  // the files the model's file objects read
  std::vector<std::string> file_objects_;
  file_watch watch_;
  std::vector<file_watch::stamp> stamps_before_build_;
  std::future<build_result> build_;
  bool building_ = false;
  bool pending_load_ = false, pending_cached_ = false;
  std::string pending_plugin_;
  unsigned pending_steps_ = 0;
  bool rewind_requested_ = false, end_requested_ = false, reread_requested_ = false, reread_on_save_ = false;
  bool replay_ = true;
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
  std::string told_camera_, told_window_;
  std::size_t told_script_ = static_cast<std::size_t>(-1);
  int told_shots_ = -1;
  bool told_replay_ = true;
};

}  // namespace

int run_viewer_window(const options& o, const viewer_resume& resume) { return viewer(o, resume).run(); }

}  // namespace vvi
