#include "batch/batch_view.hpp"

#include <unistd.h>

#include <cstdio>

#include "control/model_controller.hpp"
#include "render/image.hpp"
#include "render/offscreen.hpp"
#include "render/scene.hpp"
#include "runner/fault_guard.hpp"
#include "runner/output_file.hpp"
#include "series/step_names.hpp"

namespace vvi {

batch_view::batch_view(const options& o) : o_(o), bar_(o.steps, o.quiet) {
  if (o.frame.size() == 6) {
    box b;
    b.add({o.frame[0], o.frame[1], o.frame[2]});
    b.add({o.frame[3], o.frame[4], o.frame[5]});
    frame_ = b;
  }
}

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
  if (c.kind == model_change::loaded) rendering_of_ = nullptr;  // a fresh instance: its render_init
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
    std::vector<std::uint8_t> pixels;
    e = picture(c.path, pixels);
    if (e.empty())
      e = write_output(c.path, [&](const std::string& to) { return write_png(to, o_.width, o_.height, pixels); });
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

std::string batch_view::record_picture(const std::string& file, unsigned long step) {
  const model_runner& runner = controller_->runner();
  if (measuring_) {
    vv_geometry g{};
    if (std::string e = runner.geometry(g); !e.empty()) return e;
    box b = view_box(runner.model(), geometry_bounds(g));
    measured_.add(b.min);
    measured_.add(b.max);
    return "";
  }
  std::vector<std::uint8_t> pixels;
  if (std::string e = picture(file, pixels); !e.empty()) return e;
  if (series_file_of(file) != series_file::movie) {
    std::string e = write_output(file, [&](const std::string& to) { return write_png(to, o_.width, o_.height, pixels); });
    if (e.empty()) wrote(file);
    return e;
  }
  std::unique_ptr<movie_writer>& movie = movies_[file];
  std::string e;
  if (!movie) movie = movie_writer::open(file, o_.width, o_.height, o_.fps, e);
  if (!movie) {
    movies_.erase(file);
    return e;
  }
  return movie->add(step, std::move(pixels), o_.width, o_.height);
}

std::string batch_view::end_movie(const std::string& file, bool keep) {
  auto m = movies_.find(file);
  if (m == movies_.end()) return "";
  std::string e = keep ? m->second->finish() : "";
  if (keep && e.empty()) wrote(file);
  movies_.erase(m);  // an unfinished movie's temporary goes
  return e;
}

namespace {

std::string no_such_property(const options& o, const vv_geometry& g) {
  std::string numeric = g.numeric_fields ? g.numeric_fields : "";
  return o.model + ": --color-by " + o.color_by + ": the vertices have no numeric property " + o.color_by +
         (numeric.empty() ? " (they have none)" : " (they have " + numeric + ")");
}

}  // namespace

// The context is made at the first picture and kept for the others (a
// series draws many); a model instance's render_init runs once in it.
std::string batch_view::picture(const std::string& path, std::vector<std::uint8_t>& pixels) {
  const options& o = o_;
  const model_runner& runner = controller_->runner();
  const box* frame = frame_ ? &*frame_ : nullptr;
  std::string error;
  if (!gl_) gl_ = offscreen::create(o.width, o.height, error);
  if (!gl_) return error;
  session* model = runner.model();
  if (model) model->announce_drawing(true);  // its render blocks are supervised like the others
  if (rendering_of_ != model || !model) {
    if (!init_rendering(model, error)) return error;
    rendering_of_ = model;
  }
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
  cam.fit(frame ? *frame : view_box(model, &drawing));
  cam.rotate_degrees(o.view_yaw, o.view_pitch);
  if (!draw_frame(model, &drawing, cam, o.width, o.height, error)) return error;
  pixels = read_pixels(o.width, o.height);
  drawing.release();
  return "";
}

}  // namespace vvi
