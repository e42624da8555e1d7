#include "batch/batch_view.hpp"

#include <unistd.h>

#include <cstdio>

#include "control/model_controller.hpp"
#include "render/image.hpp"
#include "render/offscreen.hpp"
#include "render/scene.hpp"
#include "runner/fault_guard.hpp"
#include "runner/output_file.hpp"

namespace vvi {

progress::progress(unsigned total, bool quiet) : total_(total), on_(!quiet && isatty(STDERR_FILENO) && total > 1) {}

void progress::update(unsigned done) {
  if (!on_) return;
  auto now = std::chrono::steady_clock::now();
  if (done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  double s = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, "\rstep %u/%u, %.1f s", done, total_, s);
  if (done == total_) std::fprintf(stderr, "\n");
}

void batch_view::model_changed(const model_change& c) {
  if (c.kind == model_change::stepped) bar_.update(controller_->facts().steps - first_step_);
}

bool batch_view::view(const command& c) {
  const model_runner& runner = controller_->runner();
  std::string e;
  if (c.kind == command::inspect) {
    std::string text;
    e = runner.describe_vertex(static_cast<unsigned>(c.number), text);
    if (e.empty()) std::printf("%s", text.c_str());
  } else if (c.kind == command::screenshot) {
    e = batch_screenshot(o_, c.path, runner);
    if (e.empty()) wrote(c.path);
  }
  if (!e.empty() && failure_.empty()) failure_ = e;
  return true;
}

void batch_view::wrote(const std::string& path) {
  if (!o_.quiet) std::printf("wrote %s\n", path.c_str());
}

void batch_view::show_error(const std::string&, const std::string& line) {
  if (failure_.empty()) failure_ = line;
}

void batch_view::record_changed(const state_record& r) { fault_guard::send(record_line(r)); }

namespace {

std::string no_such_property(const options& o, const vv_geometry& g) {
  std::string numeric = g.numeric_fields ? g.numeric_fields : "";
  return o.model + ": --color-by " + o.color_by + ": the vertices have no numeric property " + o.color_by +
         (numeric.empty() ? " (they have none)" : " (they have " + numeric + ")");
}

}  // namespace

std::string batch_screenshot(const options& o, const std::string& path, const model_runner& runner) {
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
    return path + ": nothing to draw: the vertices of the model's mesh have no 'pos' property "
                  "(give them one, or draw them in a render block)";
  drawing.update(g);
  camera cam;
  cam.fit(view_box(model, &drawing));
  cam.rotate_degrees(o.view_yaw, o.view_pitch);
  if (!draw_frame(model, &drawing, cam, o.width, o.height, error)) return error;
  std::vector<std::uint8_t> pixels = read_pixels(o.width, o.height);
  std::string written =
      write_output(path, [&](const std::string& to) { return write_png(to, o.width, o.height, pixels); });
  drawing.release();
  return written;
}

}  // namespace vvi
