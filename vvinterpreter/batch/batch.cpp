#include "batch/batch.hpp"

#include <chrono>
#include <cstdio>
#include <string.h>
#include <unistd.h>

#include "render/image.hpp"
#include "render/offscreen.hpp"
#include "runner/crash_report.hpp"
#include "runner/model_runner.hpp"
#include "runner/output_file.hpp"
#include "runner/plots.hpp"
#include "runner/supervisor.hpp"
#include "render/scene.hpp"

namespace vvi {

namespace {

int fail(const std::string& why) {
  std::fprintf(stderr, "vvinterpreter: %s\n", why.c_str());
  return 1;
}

void report_build(const options& o, const build_result& b) {
  if (!b.warnings.empty()) std::fprintf(stderr, "%s", b.warnings.c_str());
  if (o.quiet) return;
  if (b.cached) std::printf("%s: compiled model found in the cache\n", o.model.c_str());
  else std::printf("%s: translated in %.0f ms, compiled in %.2f s\n", o.model.c_str(), b.translate_ms, b.compile_ms / 1000);
}

// "step 12/100, 3.4 s" on one line, only when a person watches standard error.
class progress {
 public:
  progress(unsigned total, bool quiet) : total_(total), on_(!quiet && isatty(STDERR_FILENO) && total > 1) {}
  void update(unsigned done) {
    if (!on_) return;
    auto now = std::chrono::steady_clock::now();
    if (done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    double s = std::chrono::duration<double>(now - start_).count();
    std::fprintf(stderr, "\rstep %u/%u, %.1f s", done, total_, s);
    if (done == total_) std::fprintf(stderr, "\n");
  }

 private:
  unsigned total_;
  bool on_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_{};
};

std::string no_such_property(const options& o, const vv_geometry& g) {
  std::string numeric = g.numeric_fields ? g.numeric_fields : "";
  return o.model + ": --color-by " + o.color_by + ": the vertices have no numeric property " + o.color_by +
         (numeric.empty() ? " (they have none)" : " (they have " + numeric + ")");
}

std::string screenshot(const options& o, model_runner& runner) {
  std::string error;
  std::unique_ptr<offscreen> gl = offscreen::create(o.width, o.height, error);
  if (!gl) return error;
  session* model = runner.model();
  if (model) model->announce_drawing(true);  // its render blocks are supervised like the others
  if (!init_rendering(model, error)) return error;
  mesh_drawing drawing;  // drawn unless the model draws itself; its bounds fit the view
  vv_geometry g{};
  error = runner.geometry(g, o.color_by);
  if (!error.empty()) return error;
  if (!o.color_by.empty() && !g.values) return no_such_property(o, g);
  if (!g.positions && !(model && model->has_block(&vv_plugin::render)))
    return o.screenshot + ": nothing to draw: the vertices of the model's mesh have no 'pos' property "
                          "(give them one, or draw them in a render block)";
  drawing.update(g);
  camera cam;
  cam.fit(view_box(model, &drawing));
  cam.rotate_degrees(o.view_yaw, o.view_pitch);
  if (!draw_frame(model, &drawing, cam, o.width, o.height, error)) return error;
  std::vector<std::uint8_t> pixels = read_pixels(o.width, o.height);
  std::string written =
      write_output(o.screenshot, [&](const std::string& to) { return write_png(to, o.width, o.height, pixels); });
  drawing.release();
  return written;
}

// --list-params: the parameters as the file and --set give them, before
// start (which does not run).
int list_parameters(const options& o, const build_result& b) {
  if (!b.warnings.empty()) std::fprintf(stderr, "%s", b.warnings.c_str());
  std::string error;
  std::unique_ptr<session> model = session::load(b.plugin, session_settings_for(o), error);
  if (!model) return fail(error);
  model->skip_close();  // it never started
  std::vector<parameter_setting> settings;
  for (const auto& [name, text] : o.parameter_values) settings.push_back({name, "", text});
  std::string refused = apply_parameter_settings(*model, settings, o.model);
  if (!refused.empty()) return fail(refused);
  for (const vv_param_entry* p : parameters_of(*model)) std::printf("%s\n", parameter_line(*p).c_str());
  return 0;
}

// The batch run itself, in the supervised child process.
int run_model_headless(const options& o) {
  model_runner runner(o);
  build_result b = runner.build(false);
  if (!b.ok) return fail(b.error);
  if (o.list_params) return list_parameters(o, b);
  report_build(o, b);
  if (!runner.load(b.plugin)) return fail(runner.error());
  progress bar(o.steps, o.quiet);
  auto t0 = std::chrono::steady_clock::now();
  for (unsigned i = 0; i < o.steps; ++i) {
    if (!runner.step()) return fail(runner.error());
    bar.update(i + 1);
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (o.end_block && !runner.end()) return fail(runner.error());
  session& model = *runner.model();
  if (!o.quiet) {
    std::printf("%u steps in %.3f s\n", o.steps, seconds);
    for (const vv_mesh_entry* mesh : model.meshes()) std::printf("mesh %s: %zu vertices\n", mesh->name, mesh->vertex_count());
  }
  if (!o.export_path.empty()) {
    std::string e = runner.export_to(o.export_path);
    if (!e.empty()) return fail(e);
    if (!o.quiet) std::printf("wrote %s\n", o.export_path.c_str());
  }
  for (unsigned label : o.picks) {
    std::string text;
    std::string e = runner.describe_vertex(label, text);
    if (!e.empty()) return fail(e);
    std::printf("%s", text.c_str());
  }
  if (!o.plots_path.empty()) {
    std::string e = write_plots(o.plots_path, model.plots());
    if (!e.empty()) return fail(e);
    if (!o.quiet) std::printf("wrote %s\n", o.plots_path.c_str());
  }
  if (!o.screenshot.empty()) {
    std::string e = screenshot(o, runner);
    if (!e.empty()) return fail(e);
    if (!o.quiet) std::printf("wrote %s\n", o.screenshot.c_str());
  }
  runner.close();
  if (!runner.error().empty()) return fail(runner.error());
  return 0;
}

// While a block runs long, where it is (the supervisor asks the model).
void tell_long_activity(const options& o, const long_activity& a) {
  std::fprintf(stderr, "vvinterpreter: %s\n", describe_long_activity(a, o.model, o.step_timeout).c_str());
  std::fflush(stderr);
}

int report_end(const crash_text& t) {
  std::fprintf(stderr, "vvinterpreter: %s\n%s", t.line.c_str(), t.stack.c_str());
  return 1;
}

}  // namespace

int run_compile_only(const options& o) {
  build_result b = model_runner(o).build(false);
  if (!b.ok) {
    // The whole diagnosis is this mode's output; the reason is one line.
    if (!o.quiet) std::printf("%s", b.details.c_str());
    return fail(b.error);
  }
  report_build(o, b);
  if (!o.quiet) std::printf("%s\n", b.plugin.c_str());
  return 0;
}

int run_batch(const options& o) {
  // The model runs in a child process: a crash or a step past its time
  // limit ends the run with a message, not with this process.
  // --debug, --in-process: a debugger or profiler is the supervisor, and
  // it must see the model in this process.
  if (o.debug || o.in_process) return run_model_headless(o);
  supervision s;
  s.activity_timeout = o.step_timeout;
  s.notice_after = seconds_from_environment("VV_NOTICE_AFTER", 10);
  s.on_long_activity = [&](const long_activity& a) { tell_long_activity(o, a); };
  child_end end = run_supervised([&] { return run_model_headless(o); }, s);
  int status = end.exit_code;
  if (end.kind == child_end::interrupted) {
    const char* name = sigabbrev_np(end.signal);
    fail(std::string("interrupted (SIG") + (name ? name : "?") + "); the files being written were removed");
    status = 128 + end.signal;
  } else if (end.kind == child_end::exited) {
    // Inside a block the model ended the process itself: its steps and
    // files are missing, whatever the status said.
    if (!end.activity.what.empty()) status = report_end(describe_exit(end, o.model));
  } else {
    status = report_end(describe_crash(end, o.model));
  }
  remove_module_copies(end);
  return status;
}

}  // namespace vvi
