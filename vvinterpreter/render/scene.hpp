// Drawing a model with OpenGL (compatibility profile: render blocks of vv
// programs use legacy GL). The same code draws the window and the batch
// screenshots, so both show the same picture.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vv/plugin.hpp>

#include "render/camera.hpp"

namespace vvi {

class session;

//! A mesh's faces (smooth-shaded) and edges in vertex buffers, for drawing
//! meshes of millions of triangles at interactive rates.
class mesh_drawing {
 public:
  mesh_drawing() = default;
  mesh_drawing(const mesh_drawing&) = delete;
  mesh_drawing& operator=(const mesh_drawing&) = delete;
  ~mesh_drawing();

  //! New geometry (call with the GL context current).
  void update(const vv_geometry& g);
  void draw() const;
  const box& bounds() const { return bounds_; }
  std::size_t triangles() const { return triangle_indices_ / 3; }
  //! Frees the GL buffers (before the context goes away).
  void release();

 private:
  unsigned vertex_buffer_ = 0, triangle_buffer_ = 0, line_buffer_ = 0;
  std::size_t triangle_indices_ = 0, line_indices_ = 0;
  box bounds_;
};

//! One frame: clear, the model's render block (or the default drawing of
//! `fallback`), then its render_screen block in pixel coordinates. Returns
//! false with `error` set when a render block failed.
bool draw_frame(session* model, const mesh_drawing* fallback, const camera& cam, int width,
                int height, std::string& error);

//! The box the view must show: the proxy's view volume when the program set
//! one, else the drawing's bounds, else the unit cube.
box view_box(session* model, const mesh_drawing* drawing);

//! Calls the model's render_init block (a GL context was created).
bool init_rendering(session* model, std::string& error);

//! The current framebuffer's pixels, top row first, RGBA.
std::vector<std::uint8_t> read_pixels(int width, int height);

}  // namespace vvi
