#include "run_model.hpp"

#include "files.hpp"
#include "scene.hpp"

namespace vvi {

build_settings settings_for(const options& o, bool force) {
  build_settings s;
  s.cache_dir = o.cache.empty() ? default_cache_dir() : o.cache;
  s.optimization = o.optimization;
  s.force = force;
  return s;
}

loaded_model load_model(const options& o, bool force) {
  loaded_model m;
  m.build = build_model(o.model, settings_for(o, force));
  if (!m.build.ok) {
    m.error = m.build.error;
    return m;
  }
  session_settings s;
  // A plugin given on its own knows the folder it was translated from.
  if (!is_plugin_file(o.model)) s.model_dir = folder_of(o.model);
  s.seed = o.seed;
  s.strict = o.strict;
  m.model = session::load(m.build.plugin, s, m.error);
  return m;
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

std::size_t max_face_of(const options& o, session& model) {
  return o.max_face ? o.max_face : model.proxy().max_face;
}

std::string update_drawing(session& model, const std::string& mesh_name, std::size_t max_face,
                           mesh_drawing& drawing) {
  const vv_mesh_entry* m = model.mesh(mesh_name);
  if (!m) {
    if (!mesh_name.empty()) return "the model has no global mesh named " + mesh_name;
    vv_geometry none{};
    drawing.update(none);
    return "";
  }
  vv_geometry g{};
  if (const char* e = m->geometry(max_face, &g)) return e;
  drawing.update(g);
  return "";
}

}  // namespace vvi
