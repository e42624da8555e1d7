#include "batch.hpp"

#include <chrono>
#include <cstdio>
#include <unistd.h>

#include "image.hpp"
#include "mesh_export.hpp"
#include "offscreen.hpp"
#include "run_model.hpp"
#include "scene.hpp"

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

std::string screenshot(const options& o, session& model) {
  std::string error;
  std::unique_ptr<offscreen> gl = offscreen::create(o.width, o.height, error);
  if (!gl) return error;
  if (!init_rendering(&model, error)) return error;
  mesh_drawing drawing;  // drawn unless the model draws itself; its bounds fit the view
  error = update_drawing(model, o.mesh, max_face_of(o, model), drawing);
  if (!error.empty()) return error;
  camera cam;
  cam.fit(view_box(&model, &drawing));
  cam.rotate_degrees(o.view_yaw, o.view_pitch);
  if (!draw_frame(&model, &drawing, cam, o.width, o.height, error)) return error;
  std::string written = write_png(o.screenshot, o.width, o.height, read_pixels(o.width, o.height));
  drawing.release();
  return written;
}

}  // namespace

int run_compile_only(const options& o) {
  build_result b = build_model(o.model, settings_for(o));
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
  loaded_model m = load_model(o);
  if (!m.model) return fail(m.error);
  report_build(o, m.build);
  session& model = *m.model;
  if (!model.start()) return fail(model.error());
  progress bar(o.steps, o.quiet);
  auto t0 = std::chrono::steady_clock::now();
  for (unsigned i = 0; i < o.steps; ++i) {
    if (!model.step()) return fail(model.error());
    bar.update(i + 1);
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!o.quiet) {
    std::printf("%u steps in %.3f s\n", o.steps, seconds);
    for (const vv_mesh_entry* mesh : model.meshes()) std::printf("mesh %s: %zu vertices\n", mesh->name, mesh->vertex_count());
  }
  if (!o.export_path.empty()) {
    const vv_mesh_entry* mesh = model.mesh(o.mesh);
    if (!mesh)
      return fail(o.mesh.empty() ? o.model + ": the model has no global mesh to export"
                                 : o.model + ": the model has no global mesh named " + o.mesh);
    std::string e = export_mesh(*mesh, o.export_path, max_face_of(o, model));
    if (!e.empty()) return fail(e);
    if (!o.quiet) std::printf("wrote %s\n", o.export_path.c_str());
  }
  if (!o.screenshot.empty()) {
    std::string e = screenshot(o, model);
    if (!e.empty()) return fail(e);
    if (!o.quiet) std::printf("wrote %s\n", o.screenshot.c_str());
  }
  model.close();
  if (!model.error().empty()) return fail(model.error());
  return 0;
}

}  // namespace vvi
