// The functions behind the descriptor's members (model/abi.hpp) that are
// the same for every program: the generated code passes its model object
// (model/program.hpp) and its global meshes, and points the descriptor at
// small functions that call these. Each returns NULL or the error.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <vv/faces.hpp>
#include <vv/inspect.hpp>
#include <vv/io/mesh_io.hpp>
#include <vv/io/positions.hpp>
#include <vv/io/vvm.hpp>
#include <vv/mesh.hpp>
#include <vv/neighbourhood_check.hpp>
#include <vv/polylines.hpp>

#include "abi.hpp"
#include "program.hpp"
#include "state.hpp"

namespace vv::model {

//! The export options of a host's max_face (0: no limit).
inline export_options export_options_for(std::size_t max_face) {
  export_options opt;
  if (max_face) opt.max_face = max_face;
  return opt;
}

//! vv_mesh_entry::write_file: .vvm or .vtp by the extension.
template <class Tr>
const char* write_file(program<Tr>& p, const mesh<Tr>& m, const char* path, std::size_t max_face) noexcept {
  return p.run([&] { vv::write_mesh(m, path, export_options_for(max_face)); });
}

template <class Tr>
const char* geometry(program<Tr>& p, const mesh<Tr>& m, std::size_t max_face, vv_geometry* out) noexcept {
  exchange& x = p.host_exchange();
  return p.run([&] {
    x.positions.clear();
    x.face_offsets.assign(1, 0u);
    x.face_vertices.clear();
    x.line_offsets.assign(1, 0u);
    x.line_vertices.clear();
    x.labels.clear();
    using VP = typename Tr::vertex_props;
    if constexpr (detail::has_pos<VP>::value) {
      for (std::uint32_t id : m.slots()) {
        if (!id) continue;
        auto pos = detail::xyz_of(m.ctx()->props(id).pos);
        x.positions.insert(x.positions.end(), pos.begin(), pos.end());
      }
    }
    std::size_t limit = max_face ? max_face : std::numeric_limits<std::size_t>::max();
    if (is_curve(m)) {
      for (const auto& line : polylines(m)) {
        x.line_vertices.insert(x.line_vertices.end(), line.begin(), line.end());
        x.line_offsets.push_back(static_cast<std::uint32_t>(x.line_vertices.size()));
      }
    } else {
      for (const auto& face : orbits(m, limit).faces) {
        if (face.size() < 3) continue;
        x.face_vertices.insert(x.face_vertices.end(), face.begin(), face.end());
        x.face_offsets.push_back(static_cast<std::uint32_t>(x.face_vertices.size()));
      }
    }
    out->vertex_count = m.size();
    out->positions = detail::has_pos<VP>::value ? x.positions.data() : nullptr;
    out->face_count = x.face_offsets.size() - 1;
    out->face_offsets = x.face_offsets.data();
    out->face_vertices = x.face_vertices.data();
    out->line_count = x.line_offsets.size() - 1;
    out->line_offsets = x.line_offsets.data();
    out->line_vertices = x.line_vertices.data();
    std::vector<std::uint32_t> ids;
    for (std::uint32_t id : m.slots())
      if (id) ids.push_back(id), x.labels.push_back(m.ctx()->label(id));
    out->labels = x.labels.data();
    x.numeric_fields = numeric_vertex_fields<Tr>();
    out->numeric_fields = x.numeric_fields.c_str();
    bool wanted = out->value_field && *out->value_field;
    out->values = wanted && numeric_field_values(*m.ctx(), ids, out->value_field, x.values) ? x.values.data() : nullptr;
  });
}

//! One global mesh of the program, by name (for unions, checks, picks).
template <class Tr>
struct named_mesh {
  const char* name;
  const mesh<Tr>* m;
};

//! The union of the named meshes; throws naming an unknown one.
template <class Tr, std::size_t N>
mesh<Tr> union_of(const named_mesh<Tr> (&all)[N], const char* const* names, std::size_t count) {
  mesh<Tr> u(*all[0].m->ctx());
  for (std::size_t i = 0; i < count; ++i) {
    const mesh<Tr>* found = nullptr;
    for (const named_mesh<Tr>& n : all)
      if (std::string(n.name) == names[i]) found = n.m;
    if (!found) throw std::runtime_error(std::string("the model has no global mesh named ") + names[i]);
    u.merge(*found);
  }
  return u;
}

template <class Tr, std::size_t N>
const char* union_file(program<Tr>& p, const named_mesh<Tr> (&all)[N], const char* const* names, std::size_t count,
                       std::size_t max_face, const char* path) noexcept {
  return p.run([&] { vv::write_mesh(union_of(all, names, count), path, export_options_for(max_face)); });
}

template <class Tr, std::size_t N>
const char* union_geometry(program<Tr>& p, const named_mesh<Tr> (&all)[N], const char* const* names,
                           std::size_t count, std::size_t max_face, vv_geometry* out) noexcept {
  // The union lives in the exchange until the next call: the geometry
  // points into data computed from it.
  exchange& x = p.host_exchange();
  const char* e = p.run([&] { x.union_mesh = std::make_shared<mesh<Tr>>(union_of(all, names, count)); });
  if (e) return e;
  return geometry(p, *std::static_pointer_cast<mesh<Tr>>(x.union_mesh), max_face, out);
}

//! The vertex with this label in any of the global meshes; 0 when none holds it.
template <class Tr, std::size_t N>
std::uint32_t slot_in(const named_mesh<Tr> (&all)[N], unsigned label) {
  std::vector<const mesh<Tr>*> meshes;
  for (const named_mesh<Tr>& n : all) meshes.push_back(n.m);
  return slot_of_label(*all[0].m->ctx(), meshes, label);
}

//! vv_plugin::describe_vertex over the global meshes.
template <class Tr, std::size_t N>
const char* describe_vertex(program<Tr>& p, const named_mesh<Tr> (&all)[N], unsigned label,
                            const char** text) noexcept {
  exchange& x = p.host_exchange();
  return p.run([&] {
    std::vector<const mesh<Tr>*> meshes;
    std::vector<std::string> names;
    for (const named_mesh<Tr>& n : all) meshes.push_back(n.m), names.push_back(n.name);
    std::uint32_t id = slot_in(all, label);
    if (!id) throw std::runtime_error("no global mesh holds a vertex " + std::to_string(label));
    x.text = vv::describe_vertex(*all[0].m->ctx(), meshes, names, id);
    *text = x.text.c_str();
  });
}

//! vv_plugin::pick: runs the pick block with the vertex of this label.
template <class Tr, std::size_t N, class Block>
const char* pick(program<Tr>& p, const named_mesh<Tr> (&all)[N], unsigned label, Block block) noexcept {
  std::uint32_t id = slot_in(all, label);
  if (!id) return refuse(p.host_exchange(), "no global mesh holds a vertex " + std::to_string(label));
  return p.run([&] { block(vertex<Tr>::from_slot(all[0].m->ctx(), id)); });
}

//! vv_plugin::run_settings: what the program set in its proxy.
inline void run_settings(const vv::proxy& p, vv_run_settings* out) noexcept {
  *out = vv_run_settings{};
  out->steps = p.steps;
  out->delay_msec = p.delay_msec;
  out->no_animate = p.no_animate ? 1 : 0;
  out->record_frame = p.record_frame ? 1 : 0;
  out->max_face = p.max_face;
  out->has_view_volume = p.has_view_volume ? 1 : 0;
  for (int i = 0; i < 3; ++i) out->view_min[i] = p.view_min[i], out->view_max[i] = p.view_max[i];
}

//! vv_plugin::plot_series: series i of the proxy's plots (an empty series
//! past the end).
inline void plot_series(const vv::proxy& p, std::size_t i, vv_plot_series* out) noexcept {
  *out = vv_plot_series{};
  if (i >= p.plots.size()) return;
  const vv::plot_series& s = p.plots[i];
  out->name = s.name.c_str();
  out->count = s.values.size();
  out->steps = s.steps.data();
  out->values = s.values.data();
}

//! vv_plugin::file_objects: the registered objects' files and those of the
//! objects the program put into the proxy's lists, one per line.
template <class Tr>
const char* file_object_paths(program<Tr>& p) noexcept {
  exchange& x = p.host_exchange();
  const char* e = p.run([&] {
    std::vector<std::string> paths = p.files().paths();
    const vv::proxy& h = p.host();
    for (const auto* list : {&h.materials, &h.palettes, &h.functions, &h.contours})
      for (const file_object* f : *list)
        if (f && !f->path().empty() && std::find(paths.begin(), paths.end(), f->path()) == paths.end())
          paths.push_back(f->path());
    x.text.clear();
    for (const std::string& path : paths) x.text += path + "\n";
  });
  return e ? "" : x.text.c_str();
}

//! vv_plugin::save_state: the bytes stay in the exchange until the next call.
template <class Tr>
const char* save_state_entry(program<Tr>& p, global_slot<Tr>* globals, std::size_t n, const void** data,
                             std::size_t* size) noexcept {
  exchange& x = p.host_exchange();
  return p.run([&] {
    x.state = save_state(p, globals, n);
    *data = x.state.data();
    *size = x.state.size();
  });
}

//! vv_plugin::restore_state.
template <class Tr>
const char* restore_state_entry(program<Tr>& p, global_slot<Tr>* globals, std::size_t n, const void* data,
                                std::size_t size) noexcept {
  return p.run([&] { restore_state(p, globals, n, data, size); });
}

//! vv_plugin::check: a mesh that was symmetric at the last check must still
//! be (a model may keep one-way neighbourhoods, as cell centres to walls).
template <class Tr, std::size_t N>
const char* check(program<Tr>& p, const named_mesh<Tr> (&all)[N]) noexcept {
  exchange& x = p.host_exchange();
  std::string found;
  const char* e = p.run([&] {
    x.was_symmetric.resize(N, 0);
    for (std::size_t i = 0; i < N && found.empty(); ++i) {
      broken_neighbourhood broken = first_broken_neighbourhood(*all[i].m, x.was_symmetric[i] != 0);
      if (!broken.problem.empty()) {
        if (broken.at.file) found = std::string(broken.at.file) + ":" + std::to_string(broken.at.line) + ": ";
        found += std::string("check: mesh ") + all[i].name + ": " + broken.problem;
      }
      x.was_symmetric[i] = broken.problem.empty() && is_symmetric(*all[i].m);
    }
  });
  if (e || found.empty()) return e;
  return refuse(x, found);
}

}  // namespace vv::model
