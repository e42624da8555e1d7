#include "runner/session.hpp"

#include <execinfo.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <thread>

#include "compile/shared_declarations.hpp"
#include "runner/crash_report.hpp"
#include "runner/fault_guard.hpp"
#include "runner/throw_points.hpp"

namespace vvi {

std::unique_ptr<session> session::load(const std::string& plugin_path, const session_settings& s,
                                       std::string& error) {
  std::unique_ptr<plugin> p = plugin::open(plugin_path, error);
  if (!p) return nullptr;
  vv_plugin_settings settings{};
  settings.model_dir = s.model_dir.c_str();
  settings.seed = s.seed;
  settings.strict_old_state = s.strict ? 1 : 0;
  settings.check = s.check ? 1 : 0;
  settings.threads = s.threads ? s.threads : std::max(1u, std::thread::hardware_concurrency());
  p->model().configure(&settings);
  return std::unique_ptr<session>(new session(std::move(p), s.model, s.check));
}

namespace {

std::vector<std::string> own_maps() {
  std::ifstream in("/proc/self/maps");
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

// The block running with no supervisor to hear of an exit() inside it.
struct unsupervised_block {
  const session* running = nullptr;
  const char* block = nullptr;
  unsigned step = 0;
};
unsupervised_block unsupervised;

}  // namespace

// An error raised without a source location (`v->pos` on the null vertex)
// came with the addresses it was raised at: its .vvp line is the innermost
// frame of the model's own source.
std::string session::locate(const std::string& raw) const {
  // Raised in a shared declarations' part: its file named in the model's folder.
  const std::string message = message_of_build(raw, plugin_->path());
  std::size_t n = 0;
  const void* const* frames = plugin_->model().error_frames(&n);
  if (n == 0) return message;
  std::vector<std::uintptr_t> calls;
  for (std::size_t i = 0; i < n; ++i) calls.push_back(reinterpret_cast<std::uintptr_t>(frames[i]) - 1);
  std::vector<source_frame> found =
      model_frames(calls, own_maps(), {{plugin_->loaded_copy(), plugin_->path()}});
  if (found.empty()) return message;
  return found.front().file + ":" + std::to_string(found.front().line) + ": " + message;
}

// Said as batch's supervisor says it (runner/crash_report.hpp:
// describe_exit), from the stack of the exit() call, which is still there;
// the status is batch's too: the run is not done.
void session::say_exit_in_block(int status, void*) {
  unsupervised_block b = unsupervised;
  if (!b.running) return;
  child_end end;
  end.kind = child_end::exited;
  end.exit_code = status;
  end.activity = {b.block, b.step};
  end.sample.why = "exit";
  void* frames[128];
  int n = backtrace(frames, 128);
  for (int i = 0; i < n; ++i) end.sample.frames.push_back(reinterpret_cast<std::uintptr_t>(frames[i]));
  end.sample.maps = own_maps();
  end.modules[b.running->plugin_->loaded_copy()] = b.running->plugin_->path();
  crash_text t = describe_exit(end, b.running->model_);
  std::fflush(nullptr);  // what the model printed comes first
  std::fprintf(stderr, "vvinterpreter: %s\n%s", t.line.c_str(), t.stack.c_str());
  std::fflush(stderr);
  _exit(1);
}

bool session::run(const char* block, plugin::block_fn fn, unsigned step, bool announce) {
  // A block the program lacks: nothing to draw, but start, step, end and
  // close are still announced (a step without a step block still counts).
  if (!fn && !announce) return true;
  fault_guard::begin(block, step, announce);
  // Supervised, the child's exit is reported by the supervisor.
  const bool unsupervised_run = fault_guard::report_fd() < 0 && fn;
  if (unsupervised_run) {
    static const bool registered = on_exit(say_exit_in_block, nullptr) == 0;
    if (registered) unsupervised = {this, block, step};
  }
  throw_points::keep(true);
  const char* e = fn ? fn() : nullptr;
  if (unsupervised_run) unsupervised = {};
  throw_points::keep(false);
  fault_guard::finish(announce);
  if (e) {
    error_ = locate(e);
    // Always said, even when the message happens to contain the word.
    error_ += " (in " + (step ? std::string(block) + " " + std::to_string(step) : std::string(block)) + ")";
    return false;
  }
  return true;
}

// An action or a pick runs on the state the last step left: proxy.plot
// records against that step, and the step count stays.
template <class Call>
bool session::run_between_steps(const std::string& what, Call call) {
  plugin_->model().set_plot_step(steps_);
  fault_guard::begin(what.c_str());
  throw_points::keep(true);
  const char* e = call();
  throw_points::keep(false);
  fault_guard::finish();
  if (e) {
    error_ = locate(e) + " (in " + what + ")";
    return false;
  }
  return check_neighbourhoods(what);
}

bool session::run_action(const std::string& name) {
  const vv_action_entry* a = action(name);
  if (!a) {
    std::string known;
    for (const vv_action_entry* k : actions()) known += (known.empty() ? "\"" : ", \"") + std::string(k->name) + "\"";
    error_ = "the model has no action \"" + name + "\"" + (known.empty() ? " (it has none)" : " (it has " + known + ")");
    return false;
  }
  return run_between_steps("action \"" + name + "\"", [a] { return a->run(); });
}

bool session::run_pick(unsigned label) {
  const vv_plugin& m = plugin_->model();
  if (!m.pick) {
    error_ = "the model has no pick block (pick of vertex " + std::to_string(label) + ")";
    return false;
  }
  return run_between_steps("pick of vertex " + std::to_string(label), [&m, label] { return m.pick(label); });
}

bool session::resume(const std::string& state, unsigned step) {
  const vv_plugin& m = plugin_->model();
  fault_guard::begin("resume");
  const char* e = m.restore_state(state.data(), state.size());
  fault_guard::finish();
  if (e) {
    error_ = std::string("the checkpoint does not fit the model: ") + e;
    return false;
  }
  steps_ = step;
  return check_neighbourhoods("resume");
}

std::string session::save_state(std::string& out) const {
  const vv_plugin& m = plugin_->model();
  std::string unsaveable;
  for (std::size_t i = 0; i < m.global_count; ++i) {
    const vv_global_entry& g = m.globals[i];
    if (g.kept != VV_GLOBAL_UNSAVEABLE) continue;
    unsaveable += "\n" + model_ + ":" + std::to_string(g.line) + ": " + g.name + " (" + g.type + "): " +
                  (g.why ? g.why : "cannot be saved");
  }
  if (!unsaveable.empty())
    return model_ + ": a checkpoint cannot hold the model's whole state: these globals cannot be saved" + unsaveable;
  const void* data = nullptr;
  std::size_t size = 0;
  if (const char* e = m.save_state(&data, &size)) return model_ + ": a checkpoint cannot hold the model: " + e;
  out.assign(static_cast<const char*>(data), size);
  return "";
}

bool session::check_neighbourhoods(const std::string& after) {
  if (!check_) return true;
  const char* broken = plugin_->model().check();
  if (!broken) return true;
  error_ = std::string(broken) + " (after " + after + ")";
  return false;
}

// proxy.plot records against the step running: 0 in start, N in step N,
// the last step's number in end.
bool session::start() {
  plugin_->model().set_plot_step(0);
  return run("start", plugin_->model().start) && check_neighbourhoods("start");
}
bool session::end() {
  plugin_->model().set_plot_step(steps_);
  return run("end", plugin_->model().end);
}
bool session::reread() { return run("reread", plugin_->model().reread); }
// The viewer draws every frame: its drawing is not announced (the pipe
// would carry 60 lines a second). Batch draws once, supervised like any block.
bool session::render_init() { return run("render_init", plugin_->model().render_init, 0, announce_drawing_); }
bool session::render() { return run("render", plugin_->model().render, 0, announce_drawing_); }
bool session::render_screen() {
  return run("render_screen", plugin_->model().render_screen, 0, announce_drawing_);
}

bool session::step() {
  plugin_->model().set_plot_step(steps_ + 1);
  auto t = std::chrono::steady_clock::now();
  bool ok = run("step", plugin_->model().step, steps_ + 1);
  last_step_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
  if (ok) ++steps_;
  return ok && check_neighbourhoods("step " + std::to_string(steps_));
}

void session::close() {
  if (closed_) return;
  closed_ = true;
  run("close", plugin_->model().close);
}

session::~session() { close(); }

vv_run_settings session::run_settings() const {
  vv_run_settings s{};
  plugin_->model().run_settings(&s);
  return s;
}

std::vector<vv_plot_series> session::plots() const {
  const vv_plugin& m = plugin_->model();
  std::vector<vv_plot_series> out(m.plot_count());
  for (std::size_t i = 0; i < out.size(); ++i) m.plot_series(i, &out[i]);
  return out;
}

std::vector<const vv_action_entry*> session::actions() const {
  const vv_plugin& m = plugin_->model();
  std::vector<const vv_action_entry*> out;
  for (std::size_t i = 0; i < m.action_count; ++i) out.push_back(&m.actions[i]);
  return out;
}

const vv_action_entry* session::action(const std::string& name) const {
  for (const vv_action_entry* a : actions())
    if (name == a->name) return a;
  return nullptr;
}

std::vector<const vv_mesh_entry*> session::meshes() const {
  const vv_plugin& m = plugin_->model();
  std::vector<const vv_mesh_entry*> out;
  for (std::size_t i = 0; i < m.mesh_count; ++i) out.push_back(&m.meshes[i]);
  return out;
}

const vv_mesh_entry* session::mesh(const std::string& name) const {
  for (const vv_mesh_entry* m : meshes())
    if (name.empty() || name == m->name) return m;
  return nullptr;
}

}  // namespace vvi
