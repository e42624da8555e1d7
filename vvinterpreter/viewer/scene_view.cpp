#include "viewer/scene_view.hpp"

#include <cstdio>

#include "runner/model_runner.hpp"
#include "viewer/picking.hpp"

namespace vvi {

scene_view::scene_view(const view_record& from, messages& m) : say_(m) {
  if (!from.camera.empty() && cam_.restore(from.camera)) camera_set_ = true;
  style_.faces = from.faces, style_.edges = from.edges, style_.points = from.points;
  style_.flat = from.flat, style_.back_faces = from.back_faces, style_.auto_hide_edges = from.auto_hide_edges;
  auto_fit_ = from.auto_fit;
  color_by_ = from.color_by;
  if (from.picked) inspect_.pick_label(from.picked);
}

void scene_view::loaded(const model_runner& r, bool render_blocks) {
  render_failed_ = !render_blocks;
  std::string e;
  if (!render_failed_ && !init_rendering(r.model(), e)) render_failed_ = true, say_.show_error(e, e);
  refresh(r);
  if (!camera_set_) {
    fit_view(r.model());
    camera_set_ = true;  // later reloads keep the view
  }
}

// The drawing also gives the view its bounds, so it is kept up to date
// when the model draws itself too.
void scene_view::refresh(const model_runner& r) {
  if (!r.model()) return;
  vv_geometry g{};
  std::string e = r.geometry(g, color_by_);
  if (e.empty() && !color_by_.empty() && !g.values) {
    std::string numeric = g.numeric_fields ? g.numeric_fields : "";
    e = "colour by " + color_by_ + ": the vertices have no numeric property " + color_by_ +
        (numeric.empty() ? " (they have none)" : " (they have " + numeric + ")");
    color_by_.clear();
    say_.show_error(e, e);
    e = r.geometry(g);
  }
  if (!e.empty()) return say_.show_error(e, e);
  drawing_.update(g, style_.flat);
  inspect_.update(g);
  if (std::string pe = inspect_.describe(r); !pe.empty()) say_.show_error(pe, pe);
  if (auto_fit_ && !camera_moved_ && camera_set_ && !hold_framing_) fit_view(r.model());
}

bool scene_view::carry_out(const command& c, const model_runner& r, bool busy) {
  switch (c.kind) {
    case command::fit:
      if (busy) return false;
      fit_view(r.model());
      return true;
    case command::rotate: cam_.rotate_degrees(c.x, c.y); return true;
    case command::zoom: cam_.zoom(c.x); return true;
    case command::reset_view: cam_.reset(); return true;
    case command::show: show(c.name, c.on, r, busy); return true;
    case command::color_by:
      color_by_ = c.name;
      if (!busy) refresh(r);
      return true;
    case command::inspect:
      if (busy) return false;
      inspect(static_cast<unsigned>(c.number), r);
      return true;
    default: return true;
  }
}

void scene_view::show(const std::string& what, bool on, const model_runner& r, bool busy) {
  bool flat = style_.flat;
  if (what == "faces") style_.faces = on;
  else if (what == "edges") style_.edges = on;
  else if (what == "points") style_.points = on;
  else if (what == "flat") style_.flat = on;
  else if (what == "back-faces") style_.back_faces = on;
  else if (what == "auto-hide-edges") style_.auto_hide_edges = on;
  else if (what == "auto-fit") {
    auto_fit_ = on, camera_moved_ = false;
    if (on && !busy) fit_view(r.model());
  }
  if (style_.flat != flat && !busy) refresh(r);  // flat shading has its own buffers
}

void scene_view::inspect(unsigned label, const model_runner& r) {
  if (!label) return inspect_.clear();
  if (!r.model()) return;
  inspect_.pick_label(label);
  if (std::string e = inspect_.describe(r); !e.empty()) return say_.show_error(e, e);
  std::printf("%s", inspect_.text().c_str());
  std::fflush(stdout);
}

// The whole model in view, seen from a little above and to the side when
// it is not flat (a pyramid face-on is a flat diamond); a flat model in
// the xy-plane is seen face-on.
void scene_view::fit_view(session* model) {
  box b = view_box(model, &drawing_);
  cam_.fit(b);
  glm::dvec3 size = b.max - b.min;
  if (!b.empty && size.z > 0.01 * glm::length(size)) cam_.look_from(30, 25);
}

void scene_view::draw(session* model, int w, int h, int left) {
  std::string e;
  display_style style = style_;
  style.picked = inspect_.picked_index();
  style.neighbours = inspect_.neighbours();
  if (!draw_frame(render_failed_ ? nullptr : model, &drawing_, cam_, w, h, e, style, left)) {
    render_failed_ = true;  // once: the same error would repeat every frame
    say_.show_error(e, e);
  }
}

unsigned scene_view::label_at(double x, double y, int w, int h) const {
  return inspect_.label_of(pick_vertex(inspect_.positions(), cam_, w, h, x, y));
}

int scene_view::bar_strip(session* model, int w) const {
  return colour_bar_strip(render_failed_ ? nullptr : model, &drawing_, w);
}

void scene_view::drag_rotate(double x0, double y0, double x1, double y1, int w, int h) {
  cam_.drag_rotate(x0, y0, x1, y1, w, h);
  camera_moved_ = true;  // the user's view: auto-fit stops
}

void scene_view::pan(double dx, double dy, int w, int h) {
  cam_.pan(dx, dy, w, h);
  camera_moved_ = true;
}

void scene_view::zoom(double factor) {
  cam_.zoom(factor);
  camera_moved_ = true;
}

view_record scene_view::record(const view_record& base) const {
  view_record v = base;
  v.camera = cam_.save();
  v.faces = style_.faces, v.edges = style_.edges, v.points = style_.points;
  v.flat = style_.flat, v.back_faces = style_.back_faces, v.auto_hide_edges = style_.auto_hide_edges;
  v.auto_fit = auto_fit_ && !camera_moved_;
  v.color_by = color_by_;
  v.picked = inspect_.picked_label();
  return v;
}

}  // namespace vvi
