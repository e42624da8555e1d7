#include "render/scene.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cstring>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "runner/session.hpp"

namespace vvi {

namespace {

struct vertex_record {
  float position[3];
  float normal[3];
};

}  // namespace

mesh_drawing::~mesh_drawing() { release(); }

void mesh_drawing::release() {
  unsigned buffers[] = {vertex_buffer_, triangle_buffer_, line_buffer_};
  if (vertex_buffer_) glDeleteBuffers(3, buffers);
  vertex_buffer_ = triangle_buffer_ = line_buffer_ = 0;
  triangle_indices_ = line_indices_ = 0;
}

void mesh_drawing::update(const vv_geometry& g) {
  bounds_ = box();
  std::vector<vertex_record> vertices(g.positions ? g.vertex_count : 0);
  std::vector<std::uint32_t> triangles, lines;
  if (g.positions) {
    for (std::size_t i = 0; i < g.vertex_count; ++i) {
      glm::dvec3 p(g.positions[3 * i], g.positions[3 * i + 1], g.positions[3 * i + 2]);
      bounds_.add(p);
      vertices[i] = {{float(p.x), float(p.y), float(p.z)}, {0, 0, 0}};
    }
    std::vector<glm::dvec3> normals(g.vertex_count, glm::dvec3(0));
    for (std::size_t f = 0; f < g.face_count; ++f) {
      const std::uint32_t* c = g.face_vertices + g.face_offsets[f];
      std::size_t k = g.face_offsets[f + 1] - g.face_offsets[f];
      for (std::size_t i = 0; i < k; ++i) {  // each boundary edge once per face
        std::uint32_t a = c[i], b = c[(i + 1) % k];
        lines.push_back(std::min(a, b));
        lines.push_back(std::max(a, b));
      }
      for (std::size_t i = 1; i + 1 < k; ++i) {  // a fan of triangles
        triangles.insert(triangles.end(), {c[0], c[i], c[i + 1]});
        auto at = [&](std::uint32_t v) {
          return glm::dvec3(g.positions[3 * v], g.positions[3 * v + 1], g.positions[3 * v + 2]);
        };
        // Unnormalised: larger triangles count more (area weighting).
        glm::dvec3 n = glm::cross(at(c[i]) - at(c[0]), at(c[i + 1]) - at(c[0]));
        normals[c[0]] += n, normals[c[i]] += n, normals[c[i + 1]] += n;
      }
    }
    for (std::size_t i = 0; i < g.vertex_count; ++i) {
      double len = glm::length(normals[i]);
      glm::dvec3 n = len > 0 ? normals[i] / len : glm::dvec3(0, 0, 1);
      vertices[i].normal[0] = float(n.x), vertices[i].normal[1] = float(n.y), vertices[i].normal[2] = float(n.z);
    }
    for (std::size_t l = 0; l < g.line_count; ++l)  // a curve: its polylines' segments
      for (std::uint32_t i = g.line_offsets[l]; i + 1 < g.line_offsets[l + 1]; ++i) {
        std::uint32_t a = g.line_vertices[i], b = g.line_vertices[i + 1];
        lines.push_back(std::min(a, b));
        lines.push_back(std::max(a, b));
      }
    // Edges shared by two faces appear twice: keep one.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    pairs.reserve(lines.size() / 2);
    for (std::size_t i = 0; i < lines.size(); i += 2) pairs.emplace_back(lines[i], lines[i + 1]);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    lines.clear();
    for (const auto& p : pairs) lines.push_back(p.first), lines.push_back(p.second);
  }
  if (!vertex_buffer_) {
    unsigned buffers[3];
    glGenBuffers(3, buffers);
    vertex_buffer_ = buffers[0], triangle_buffer_ = buffers[1], line_buffer_ = buffers[2];
  }
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(vertex_record)), vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangle_buffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(triangles.size() * 4), triangles.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, line_buffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(lines.size() * 4), lines.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  triangle_indices_ = triangles.size();
  line_indices_ = lines.size();
}

void mesh_drawing::draw() const {
  if (!vertex_buffer_ || (!triangle_indices_ && !line_indices_)) return;
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof(vertex_record), reinterpret_cast<void*>(offsetof(vertex_record, position)));
  glNormalPointer(GL_FLOAT, sizeof(vertex_record), reinterpret_cast<void*>(offsetof(vertex_record, normal)));
  // Faces, pushed back a little so the edges drawn on them stay visible.
  glEnable(GL_LIGHTING);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1, 1);
  glColor3f(0.62f, 0.72f, 0.86f);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangle_buffer_);
  glDrawElements(GL_TRIANGLES, GLsizei(triangle_indices_), GL_UNSIGNED_INT, nullptr);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_LIGHTING);
  glDisableClientState(GL_NORMAL_ARRAY);
  glColor3f(0.15f, 0.17f, 0.22f);
  if (!triangle_indices_) glLineWidth(2);  // a curve: its lines are all there is
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, line_buffer_);
  glDrawElements(GL_LINES, GLsizei(line_indices_), GL_UNSIGNED_INT, nullptr);
  glLineWidth(1);
  glDisableClientState(GL_VERTEX_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

box view_box(session* model, const mesh_drawing* drawing) {
  box b;
  if (model && model->proxy().has_view_volume) {
    const vv::proxy& p = model->proxy();
    b.add({p.view_min[0], p.view_min[1], p.view_min[2]});
    b.add({p.view_max[0], p.view_max[1], p.view_max[2]});
  } else if (drawing && !drawing->bounds().empty) {
    b = drawing->bounds();
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
                int height, std::string& error) {
  glViewport(0, 0, width, height);
  glClearColor(0.93f, 0.94f, 0.96f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glShadeModel(GL_SMOOTH);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(glm::value_ptr(cam.projection(double(width) / std::max(height, 1))));
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
  if (model && model->has_block("render")) {
    if (!model->render()) error = model->error(), ok = false;
  } else if (fallback) {
    fallback->draw();
  }
  if (ok && model && model->has_block("render_screen")) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, width, 0, height, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    if (!model->render_screen()) error = model->error(), ok = false;
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
