#include "render/scene.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "render/colour_ramp.hpp"
#include "runner/session.hpp"

namespace vvi {

namespace {

struct vertex_record {
  float position[3];
  float normal[3];
  float colour[3];
};

const rgb plain_colour = {0.62f, 0.72f, 0.86f};

glm::dvec3 position_of(const vv_geometry& g, std::uint32_t v) {
  return glm::dvec3(g.positions[3 * v], g.positions[3 * v + 1], g.positions[3 * v + 2]);
}

void put(float (&to)[3], const glm::dvec3& v) { to[0] = float(v.x), to[1] = float(v.y), to[2] = float(v.z); }
void put(float (&to)[3], const rgb& c) { to[0] = c[0], to[1] = c[1], to[2] = c[2]; }

// Each edge once, as index pairs: the faces' sides (a side shared by two
// faces appears twice) and the segments of the polylines.
std::vector<std::uint32_t> unique_edges(const vv_geometry& g) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  auto add = [&](std::uint32_t a, std::uint32_t b) { pairs.emplace_back(std::min(a, b), std::max(a, b)); };
  for (std::size_t f = 0; f < g.face_count; ++f) {
    const std::uint32_t* c = g.face_vertices + g.face_offsets[f];
    std::size_t k = g.face_offsets[f + 1] - g.face_offsets[f];
    for (std::size_t i = 0; i < k; ++i) add(c[i], c[(i + 1) % k]);
  }
  for (std::size_t l = 0; l < g.line_count; ++l)
    for (std::uint32_t i = g.line_offsets[l]; i + 1 < g.line_offsets[l + 1]; ++i)
      add(g.line_vertices[i], g.line_vertices[i + 1]);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<std::uint32_t> lines;
  lines.reserve(2 * pairs.size());
  for (const auto& p : pairs) lines.push_back(p.first), lines.push_back(p.second);
  return lines;
}

void upload(unsigned target, unsigned buffer, std::size_t bytes, const void* data) {
  glBindBuffer(target, buffer);
  glBufferData(target, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
  glBindBuffer(target, 0);
}

void point_at(unsigned buffer) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glVertexPointer(3, GL_FLOAT, sizeof(vertex_record), reinterpret_cast<void*>(offsetof(vertex_record, position)));
  glNormalPointer(GL_FLOAT, sizeof(vertex_record), reinterpret_cast<void*>(offsetof(vertex_record, normal)));
  glColorPointer(3, GL_FLOAT, sizeof(vertex_record), reinterpret_cast<void*>(offsetof(vertex_record, colour)));
}

}  // namespace

mesh_drawing::~mesh_drawing() { release(); }

void mesh_drawing::release() {
  bar_.release();
  unsigned buffers[] = {vertex_buffer_, triangle_buffer_, line_buffer_, flat_buffer_};
  if (vertex_buffer_) glDeleteBuffers(4, buffers);
  vertex_buffer_ = triangle_buffer_ = line_buffer_ = flat_buffer_ = 0;
  vertex_count_ = triangle_indices_ = line_indices_ = flat_corners_ = 0;
}

void mesh_drawing::update(const vv_geometry& g, bool flat) {
  bounds_ = box();
  mean_edge_ = 0;
  has_values_ = false;
  std::size_t n = g.positions ? g.vertex_count : 0;
  std::vector<vertex_record> vertices(n);
  std::vector<std::uint32_t> triangles, lines;
  std::vector<vertex_record> corners;  // flat: three per triangle
  if (n) {
    std::vector<rgb> colours(n, plain_colour);
    if (g.values) {
      has_values_ = true;
      value_min_ = 0, value_max_ = 0;
      bool any = false;
      for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(g.values[i])) {
          value_min_ = any ? std::min(value_min_, g.values[i]) : g.values[i];
          value_max_ = any ? std::max(value_max_, g.values[i]) : g.values[i];
          any = true;
        }
      double span = value_max_ - value_min_;
      for (std::size_t i = 0; i < n; ++i)
        colours[i] = colour_ramp(!std::isfinite(g.values[i]) ? std::nan("")
                                 : span > 0                  ? (g.values[i] - value_min_) / span
                                                             : 0.5);
      bar_.set(value_min_, value_max_, g.value_field ? g.value_field : "");
    }
    std::vector<glm::dvec3> normals(n, glm::dvec3(0));
    bounds_ = geometry_bounds(g);
    for (std::size_t f = 0; f < g.face_count; ++f) {
      const std::uint32_t* c = g.face_vertices + g.face_offsets[f];
      std::size_t k = g.face_offsets[f + 1] - g.face_offsets[f];
      glm::dvec3 face_normal(0);
      for (std::size_t i = 1; i + 1 < k; ++i) {  // a fan of triangles
        triangles.insert(triangles.end(), {c[0], c[i], c[i + 1]});
        // Unnormalised: larger triangles count more (area weighting).
        face_normal += glm::cross(position_of(g, c[i]) - position_of(g, c[0]),
                                  position_of(g, c[i + 1]) - position_of(g, c[0]));
      }
      for (std::size_t i = 0; i < k; ++i) normals[c[i]] += face_normal;
      if (!flat) continue;
      double len = glm::length(face_normal);
      glm::dvec3 unit = len > 0 ? face_normal / len : glm::dvec3(0, 0, 1);
      for (std::size_t i = 1; i + 1 < k; ++i)
        for (std::uint32_t v : {c[0], c[i], c[i + 1]}) {
          vertex_record r{};
          put(r.position, position_of(g, v)), put(r.normal, unit), put(r.colour, colours[v]);
          corners.push_back(r);
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
      double len = glm::length(normals[i]);
      put(vertices[i].position, position_of(g, std::uint32_t(i)));
      put(vertices[i].normal, len > 0 ? normals[i] / len : glm::dvec3(0, 0, 1));
      put(vertices[i].colour, colours[i]);
    }
    lines = unique_edges(g);
    double total = 0;
    for (std::size_t i = 0; i < lines.size(); i += 2)
      total += glm::length(position_of(g, lines[i]) - position_of(g, lines[i + 1]));
    mean_edge_ = lines.empty() ? 0 : total / double(lines.size() / 2);
  }
  if (!vertex_buffer_) {
    unsigned buffers[4];
    glGenBuffers(4, buffers);
    vertex_buffer_ = buffers[0], triangle_buffer_ = buffers[1], line_buffer_ = buffers[2], flat_buffer_ = buffers[3];
  }
  upload(GL_ARRAY_BUFFER, vertex_buffer_, vertices.size() * sizeof(vertex_record), vertices.data());
  upload(GL_ELEMENT_ARRAY_BUFFER, triangle_buffer_, triangles.size() * 4, triangles.data());
  upload(GL_ELEMENT_ARRAY_BUFFER, line_buffer_, lines.size() * 4, lines.data());
  upload(GL_ARRAY_BUFFER, flat_buffer_, corners.size() * sizeof(vertex_record), corners.data());
  vertex_count_ = n;
  triangle_indices_ = triangles.size();
  line_indices_ = lines.size();
  flat_corners_ = corners.size();
}

void mesh_drawing::draw(const display_style& style, bool edges_visible) const {
  if (!vertex_buffer_ || !vertex_count_) return;
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  if (style.faces && triangle_indices_) {
    // Faces, pushed back a little so the edges drawn on them stay visible.
    glEnable(GL_LIGHTING);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1, 1);
    if (!style.back_faces) glEnable(GL_CULL_FACE), glCullFace(GL_BACK);
    if (style.flat && flat_corners_) {
      point_at(flat_buffer_);
      glDrawArrays(GL_TRIANGLES, 0, GLsizei(flat_corners_));
    } else {
      point_at(vertex_buffer_);
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangle_buffer_);
      glDrawElements(GL_TRIANGLES, GLsizei(triangle_indices_), GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_CULL_FACE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_LIGHTING);
  }
  point_at(vertex_buffer_);
  glDisableClientState(GL_NORMAL_ARRAY);
  // A curve (no faces) is all lines: they are always drawn, coloured when
  // the drawing is coloured.
  bool curve = !triangle_indices_;
  if (!curve || !has_values_) glDisableClientState(GL_COLOR_ARRAY);
  if (edges_visible || curve) {
    glColor3f(0.15f, 0.17f, 0.22f);
    if (curve) glLineWidth(2);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, line_buffer_);
    glDrawElements(GL_LINES, GLsizei(line_indices_), GL_UNSIGNED_INT, nullptr);
    glLineWidth(1);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  if (style.points) {
    glEnableClientState(GL_COLOR_ARRAY);
    if (!has_values_) glDisableClientState(GL_COLOR_ARRAY), glColor3f(0.1f, 0.1f, 0.1f);
    glPointSize(4);
    glDrawArrays(GL_POINTS, 0, GLsizei(vertex_count_));
  }
  glDisableClientState(GL_COLOR_ARRAY);
  glPointSize(1);
  glDisableClientState(GL_VERTEX_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void mesh_drawing::draw_pick(const display_style& style) const {
  if (!vertex_buffer_ || style.picked < 0 || std::size_t(style.picked) >= vertex_count_) return;
  // A model's render block may leave any state behind: set all that counts.
  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_POINT_BIT);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);  // on top of everything
  glDisable(GL_POINT_SMOOTH);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glEnableClientState(GL_VERTEX_ARRAY);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);  // the neighbours' indices are in memory
  point_at(vertex_buffer_);
  glPointSize(8);
  glColor3f(pick_colours::neighbour[0], pick_colours::neighbour[1], pick_colours::neighbour[2]);
  glDrawElements(GL_POINTS, GLsizei(style.neighbours.size()), GL_UNSIGNED_INT, style.neighbours.data());
  glPointSize(12);
  glColor3f(pick_colours::picked[0], pick_colours::picked[1], pick_colours::picked[2]);
  glDrawArrays(GL_POINTS, GLint(style.picked), 1);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glPopClientAttrib();
  glPopAttrib();
}

bool edges_visible(const mesh_drawing& d, const display_style& style, const camera& cam, int width, int height) {
  constexpr double fewest_pixels = 6;  // shorter edges would fill the picture with lines
  return style.edges &&
         (!style.auto_hide_edges || d.mean_edge_length() * cam.pixels_per_unit(width, height) >= fewest_pixels);
}

namespace {

// Pixel coordinates, origin at the bottom left, drawn over the scene.
void use_pixel_coordinates(int width, int height) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, width, 0, height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
}

bool shows_colour_bar(session* model, const mesh_drawing* fallback) {
  return fallback && fallback->has_values() && !(model && model->has_block(&vv_plugin::render));
}

}  // namespace

int colour_bar_strip(session* model, const mesh_drawing* fallback, int width) {
  return shows_colour_bar(model, fallback) ? fallback->bar().strip_width(width) : 0;
}

box view_box(session* model, const mesh_drawing* drawing) {
  return view_box(model, drawing ? drawing->bounds() : box());
}

box geometry_bounds(const vv_geometry& g) {
  box b;
  std::size_t n = g.positions ? g.vertex_count : 0;
  for (std::size_t i = 0; i < n; ++i) b.add(position_of(g, std::uint32_t(i)));
  return b;
}

box view_box(session* model, const box& drawing_bounds) {
  box b;
  vv_run_settings p{};
  if (model) p = model->run_settings();
  if (p.has_view_volume) {
    b.add({p.view_min[0], p.view_min[1], p.view_min[2]});
    b.add({p.view_max[0], p.view_max[1], p.view_max[2]});
  } else if (!drawing_bounds.empty) {
    b = drawing_bounds;
  } else {
    b.add({-1, -1, -1});
    b.add({1, 1, 1});
  }
  return b;
}

bool init_rendering(session* model, std::string& error) {
  if (!model || model->render_init()) return true;
  error = model->error();
  return false;
}

bool draw_frame(session* model, const mesh_drawing* fallback, const camera& cam, int width,
                int height, std::string& error, const display_style& style, int left) {
  glViewport(0, 0, width, height);
  glClearColor(0.93f, 0.94f, 0.96f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // The scene keeps left of the colour bar's strip, whatever the view.
  int strip = colour_bar_strip(model, fallback, width);
  left = std::clamp(left, 0, std::max(width - strip - 1, 0));
  int scene_width = std::max(width - strip - left, 1);
  if (strip || left) {
    glViewport(left, 0, scene_width, height);
    glScissor(left, 0, scene_width, height);  // wide lines and points too
    glEnable(GL_SCISSOR_TEST);
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glShadeModel(GL_SMOOTH);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(glm::value_ptr(cam.projection(double(scene_width) / std::max(height, 1))));
  glMatrixMode(GL_MODELVIEW);
  // A headlight: placed in eye coordinates before the view is loaded.
  glLoadIdentity();
  const float light_position[] = {0.3f, 0.4f, 1.0f, 0.0f};
  const float light_diffuse[] = {0.85f, 0.85f, 0.85f, 1.0f};
  const float light_ambient[] = {0.25f, 0.25f, 0.25f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, light_diffuse);
  glLightfv(GL_LIGHT0, GL_AMBIENT, light_ambient);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_NORMALIZE);
  glLoadMatrixd(glm::value_ptr(cam.view()));

  bool ok = true;
  if (model && model->has_block(&vv_plugin::render)) {
    if (!model->render()) error = model->error(), ok = false;
  } else if (fallback) {
    fallback->draw(style, edges_visible(*fallback, style, cam, scene_width, height));
  }
  if (ok && fallback) {
    // In the camera's view again: a render block may have changed it.
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(glm::value_ptr(cam.projection(double(scene_width) / std::max(height, 1))));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(glm::value_ptr(cam.view()));
    fallback->draw_pick(style);
  }
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, width, height);
  if (ok && model && model->has_block(&vv_plugin::render_screen)) {
    use_pixel_coordinates(width, height);
    if (!model->render_screen()) error = model->error(), ok = false;
  }
  if (ok && strip) {
    use_pixel_coordinates(width, height);
    fallback->bar().draw(width, height);
    glEnable(GL_DEPTH_TEST);
  }
  glDisable(GL_LIGHTING);
  return ok;
}

std::vector<std::uint8_t> read_pixels(int width, int height) {
  std::vector<std::uint8_t> pixels(std::size_t(width) * std::size_t(height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  // GL's rows run bottom to top; images run top to bottom.
  std::size_t row = std::size_t(width) * 4;
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(pixels.begin() + long(y * row), pixels.begin() + long((y + 1) * row),
                     pixels.begin() + long((height - 1 - y) * row));
  return pixels;
}

}  // namespace vvi
