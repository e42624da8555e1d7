// The window's picture of the model: the drawing (vertex buffers), the
// camera, how it is drawn (display toggles, colour by a property), and the
// inspected vertex. It reads the model only while the model is idle, after
// each job; between, it draws what it kept. The view commands of the
// controller (fit, rotate, zoom, reset-view, show, color-by, pick) end here.
#pragma once

#include <string>

#include "control/command.hpp"
#include "control/state_record.hpp"
#include "render/camera.hpp"
#include "render/scene.hpp"
#include "viewer/inspection.hpp"

namespace vvi {

class model_runner;
class session;

//! Where errors and notes go (the panel, standard output and error).
class messages {
 public:
  virtual ~messages() = default;
  virtual void say(const std::string& m) = 0;
  virtual void show_error(const std::string& shown, const std::string& line) = 0;
};

class scene_view {
 public:
  scene_view(const view_record& from, messages& m);
  scene_view(const scene_view&) = delete;
  scene_view& operator=(const scene_view&) = delete;

  //! A fresh instance was loaded: its render_init block (unless its render
  //! blocks are off), then its drawing; the first model is fitted into view.
  void loaded(const model_runner& r, bool render_blocks);
  //! The model changed: read it again.
  void refresh(const model_runner& r);
  //! A view command; `busy`: the model's code runs (it cannot be read).
  //! False: not now.
  bool carry_out(const command& c, const model_runner& r, bool busy);

  //! Draws the scene in a w x h picture, right of `left` pixels; `model`
  //! draws itself (its render blocks) unless null.
  void draw(session* model, int w, int h, int left);
  //! The label of the vertex drawn nearest (x, y) in a w x h scene (0: none).
  unsigned label_at(double x, double y, int w, int h) const;
  //! The colour bar's strip at the right of a w-pixel picture.
  int bar_strip(session* model, int w) const;

  // The mouse.
  void drag_rotate(double x0, double y0, double x1, double y1, int w, int h);
  void pan(double dx, double dy, int w, int h);
  void zoom(double factor);

  //! While a series is recorded its pictures keep one framing: the view
  //! does not follow the model (auto-fit) while held.
  void hold_framing(bool on) { hold_framing_ = on; }

  //! How the view shows the model, for the state record.
  view_record record(const view_record& base) const;
  bool render_failed() const { return render_failed_; }

  // For the panel.
  const display_style& style() const { return style_; }
  bool auto_fit() const { return auto_fit_ && !camera_moved_; }
  const std::string& color_by() const { return color_by_; }
  const mesh_drawing& drawing() const { return drawing_; }
  const inspection& inspected() const { return inspect_; }
  void release() { drawing_.release(); }

 private:
  void fit_view(session* model);
  void show(const std::string& what, bool on, const model_runner& r, bool busy);
  void inspect(unsigned label, const model_runner& r);

  messages& say_;
  mesh_drawing drawing_;
  camera cam_;
  bool camera_set_ = false;
  display_style style_;
  bool auto_fit_ = true, camera_moved_ = false;  // auto-fit until the user moves the view
  bool hold_framing_ = false;
  std::string color_by_;
  inspection inspect_;
  bool render_failed_ = false;
};

}  // namespace vvi
