// Drawing a model with OpenGL (compatibility profile: render blocks of vv
// programs use legacy GL). The same code draws the window and the batch
// screenshots, so both show the same picture.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <model/abi.hpp>

#include "render/camera.hpp"
#include "render/colour_bar.hpp"

namespace vvi {

class session;

//! The colours of the picked vertex and of its neighbours (the panel's
//! inspector names them by these colours too).
namespace pick_colours {
inline constexpr rgb picked = {0.85f, 0.05f, 0.05f};
inline constexpr rgb neighbour = {1.0f, 0.55f, 0.0f};
}  // namespace pick_colours

//! How the default drawing shows a mesh (the viewer's display toggles).
struct display_style {
  bool faces = true, edges = true, points = false;
  bool flat = false;        //!< one normal per face instead of per vertex
  bool back_faces = true;   //!< draw faces seen from behind
  //! Leave out the edges when they would fill the picture (the mean edge
  //! shorter than a few pixels).
  bool auto_hide_edges = true;
  //! Indices into the geometry's vertices: the picked vertex (drawn large)
  //! and its neighbours (drawn smaller).
  long picked = -1;
  std::vector<std::uint32_t> neighbours;
};

//! A mesh's faces and edges in vertex buffers, for drawing meshes of
//! millions of triangles at interactive rates; coloured by the geometry's
//! values when it carries some (its colour bar shows the range).
class mesh_drawing {
 public:
  mesh_drawing() = default;
  mesh_drawing(const mesh_drawing&) = delete;
  mesh_drawing& operator=(const mesh_drawing&) = delete;
  ~mesh_drawing();

  //! New geometry (call with the GL context current); flat: one normal per
  //! face (the faces get their own corners).
  void update(const vv_geometry& g, bool flat = false);
  void draw(const display_style& style, bool edges_visible) const;
  //! The picked vertex and its neighbours, over whatever is drawn (also
  //! over a model that draws itself).
  void draw_pick(const display_style& style) const;
  const box& bounds() const { return bounds_; }
  std::size_t triangles() const { return triangle_indices_ / 3; }
  std::size_t edges() const { return line_indices_ / 2; }
  double mean_edge_length() const { return mean_edge_; }
  //! The range of the values drawn as colours (has_values: there are some).
  bool has_values() const { return has_values_; }
  double value_min() const { return value_min_; }
  double value_max() const { return value_max_; }
  //! The bar of the values' colours, labelled with the range and the
  //! property's name (the geometry's value_field).
  const colour_bar& bar() const { return bar_; }
  //! Frees the GL buffers (before the context goes away).
  void release();

 private:
  unsigned vertex_buffer_ = 0, triangle_buffer_ = 0, line_buffer_ = 0, flat_buffer_ = 0;
  std::size_t vertex_count_ = 0, triangle_indices_ = 0, line_indices_ = 0, flat_corners_ = 0;
  box bounds_;
  double mean_edge_ = 0;
  bool has_values_ = false;
  double value_min_ = 0, value_max_ = 0;
  colour_bar bar_;
};

//! One frame: clear, the model's render block (or the default drawing of
//! `fallback` in `style`), the picked vertex, then its render_screen block
//! in pixel coordinates, and the colour bar when the drawing is coloured.
//! The scene is drawn right of `left` pixels (the viewer's panel) and left
//! of the colour bar's strip. Returns false with `error` set when a render
//! block failed.
bool draw_frame(session* model, const mesh_drawing* fallback, const camera& cam, int width,
                int height, std::string& error, const display_style& style = {}, int left = 0);

//! The width of the colour bar's strip at the right of a picture `width`
//! pixels wide, as draw_frame draws it (0: no bar). The scene takes the
//! rest: picking and panning must see the same.
int colour_bar_strip(session* model, const mesh_drawing* fallback, int width);

//! Whether the edges are drawn: asked for, and (with auto_hide_edges) the
//! mean edge at least a few pixels long in this view.
bool edges_visible(const mesh_drawing& d, const display_style& style, const camera& cam, int width, int height);

//! The box the view must show: the proxy's view volume when the program set
//! one, else the drawing's bounds, else the unit cube.
box view_box(session* model, const mesh_drawing* drawing);
//! The same from the drawing's bounds (geometry_bounds), without GL.
box view_box(session* model, const box& drawing_bounds);
//! The bounds of the geometry's vertices, as a drawing of it has them.
box geometry_bounds(const vv_geometry& g);

//! Calls the model's render_init block (a GL context was created).
bool init_rendering(session* model, std::string& error);

//! The current framebuffer's pixels, top row first, RGBA.
std::vector<std::uint8_t> read_pixels(int width, int height);

}  // namespace vvi
