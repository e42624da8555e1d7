#include "runner/model_runner.hpp"

#include <vv/io/output_file.hpp>

#include "app/files.hpp"
#include "app/joined_names.hpp"
#include "runner/checkpoint_file.hpp"
#include "runner/mesh_export.hpp"
#include "runner/output_file.hpp"

namespace vvi {

build_settings build_settings_for(const options& o, bool force) {
  build_settings s;
  s.cache_dir = o.cache.empty() ? default_cache_dir() : o.cache;
  s.optimization = o.optimization;
  s.debug = o.debug;
  s.force = force || o.rebuild;  // --rebuild: batch and --compile-only build once
  // The viewer is there to edit the model (compile/build_history.hpp).
  s.part_from_the_first_build = o.expect_edits || !(o.batch || o.compile_only);
  s.declarations_header_ahead = o.expect_edits || (!(o.batch || o.compile_only) && o.script.empty());
  s.build_cores = o.build_cores;
  return s;
}

session_settings session_settings_for(const options& o) {
  session_settings s;
  s.model = o.model;
  // A plugin given on its own knows the folder it was translated from.
  if (!is_plugin_file(o.model)) s.model_dir = absolute_folder_of(o.model);
  s.seed = o.seed;
  s.strict = o.strict;
  s.threads = o.threads;
  s.check = o.check;
  return s;
}

model_runner::model_runner(const options& o) : o_(o) {
  for (const auto& [name, text] : o.parameter_values) settings_.push_back({name, "", text});
}

build_result model_runner::build(bool force, std::function<void()> compiling, build_kind kind,
                                 const std::atomic<bool>* stop) const {
  build_settings s = build_settings_for(o_, force);
  s.cancel = stop;
  s.compiling = std::move(compiling);
  s.quick = kind == build_kind::quick_first;
  s.in_background = kind == build_kind::behind_quick;
  return build_model(o_.model, s);
}

bool model_runner::load(const std::string& plugin_path, unsigned steps, const std::string& resume) {
  std::string error;
  std::unique_ptr<session> fresh = session::load(plugin_path, session_settings_for(o_), error);
  if (!fresh) {
    error_ = error;
    return false;
  }
  if (!resume.empty()) {
    // The checkpoint's state in place of start; the user's values after it.
    checkpoint c;
    error = read_checkpoint(resume, c);
    const vv_plugin& m = fresh->model();
    if (error.empty()) error = check_checkpoint_program(resume, c, m.program_name, m.program_hash);
    if (error.empty() && !fresh->resume(c.state, c.step)) error = resume + ": " + fresh->error();
    if (!error.empty()) {
      fresh->skip_close();  // not started, or half restored: its close block must not run
      error_ = error;
      return false;
    }
  }
  // The user's values replace the file's before start reads them.
  std::vector<parameter_setting> kept = settings_;
  std::string refused = apply_parameter_settings(*fresh, kept, o_.model);
  if (!refused.empty()) {
    error_ = refused;
    return false;
  }
  settings_ = kept;
  if (resume.empty() && !fresh->start()) {
    error_ = fresh->error();
    return false;  // `fresh` closes and unloads; the running model stays
  }
  if (model_) model_->close();  // the old instance's close block, on the old instance
  model_ = std::move(fresh);
  plugin_ = plugin_path;
  error_.clear();
  cancel = false;
  while (model_->steps_done() < steps && !cancel)
    if (!step()) break;
  return true;
}

std::string model_runner::set_parameter(const std::string& name, const std::string& text) {
  if (!model_) return "no model is loaded";
  const vv_param_entry* p = find_parameter(*model_, name);
  if (!p) return "the model has no parameter " + name;
  std::string why = vvi::set_parameter(*p, text);
  if (!why.empty()) return why;
  for (parameter_setting& g : settings_)
    if (g.name == name) {
      g = {name, p->type, text};
      return "";
    }
  settings_.push_back({name, p->type, text});
  return "";
}

bool model_runner::step() {
  if (!model_) return false;
  if (model_->step()) return true;
  error_ = model_->error();
  return false;
}

bool model_runner::end() {
  if (!model_) return false;
  if (model_->end()) return true;
  error_ = model_->error();
  return false;
}

bool model_runner::reread() {
  if (!model_) return false;
  if (model_->reread()) return true;
  error_ = model_->error();
  return false;
}

bool model_runner::run_action(const std::string& name) {
  if (!model_) {
    error_ = "no model is loaded";
    return false;
  }
  if (model_->run_action(name)) return true;
  // An unknown name is the user's mistake, not the program's: name the model.
  error_ = model_->action(name) ? model_->error() : o_.model + ": " + model_->error();
  return false;
}

bool model_runner::run_pick(unsigned label) {
  if (!model_) {
    error_ = "no model is loaded";
    return false;
  }
  if (model_->run_pick(label)) return true;
  error_ = model_->model().pick ? model_->error() : o_.model + ": " + model_->error();
  return false;
}

void model_runner::close() {
  if (!model_) return;
  model_->close();
  if (!model_->error().empty()) error_ = model_->error();
  model_.reset();
}

std::size_t model_runner::max_face() const {
  return o_.max_face ? o_.max_face : model_ ? model_->run_settings().max_face : 0;
}

namespace {

std::vector<const char*> c_names(const std::vector<std::string>& names) {
  std::vector<const char*> out;
  for (const std::string& n : names) out.push_back(n.c_str());
  return out;
}

// "" when every name is a global mesh of the model, else the error.
std::string unknown_mesh(const session& model, const std::string& path, const std::vector<std::string>& names) {
  std::string known;
  for (const vv_mesh_entry* m : model.meshes()) known += (known.empty() ? "" : ", ") + std::string(m->name);
  for (const std::string& n : names)
    if (!model.mesh(n))
      return path + ": the model has no global mesh named " + n +
             (known.empty() ? " (it has none)" : " (it has " + known + ")");
  return "";
}

}  // namespace

std::string model_runner::geometry(vv_geometry& out, const std::string& value_field) const {
  out = vv_geometry{};
  out.value_field = value_field.c_str();
  if (!model_) return "";
  const std::vector<std::string>& names = o_.meshes;
  if (std::string e = unknown_mesh(*model_, o_.model, names); !e.empty()) return e;
  if (names.size() > 1) {
    std::vector<const char*> c = c_names(names);
    const char* e = model_->model().union_geometry(c.data(), c.size(), max_face(), &out);
    return e ? e : "";
  }
  const vv_mesh_entry* m = model_->mesh(names.empty() ? "" : names[0]);
  if (!m) return "";
  const char* e = m->geometry(max_face(), &out);
  return e ? e : "";
}

std::string model_runner::describe_vertex(unsigned label, std::string& text) const {
  if (!model_) return "no model is loaded";
  const char* described = nullptr;
  if (const char* e = model_->model().describe_vertex(label, &described)) return o_.model + ": pick " + std::to_string(label) + ": " + e;
  text = described;
  return "";
}

std::vector<std::string> model_runner::file_objects() const {
  std::vector<std::string> out;
  if (!model_) return out;
  std::string lines = model_->model().file_objects();
  for (std::size_t at = 0, end; (end = lines.find('\n', at)) != std::string::npos; at = end + 1)
    out.push_back(lines.substr(at, end - at));
  return out;
}

std::string model_runner::save_checkpoint(const std::string& path) const {
  if (!model_) return "checkpoint " + path + ": no model is loaded";
  checkpoint c;
  if (std::string e = model_->save_state(c.state); !e.empty()) return e;
  const vv_plugin& m = model_->model();
  c.program = m.program_name;
  c.program_hash = m.program_hash;
  c.step = model_->steps_done();
  c.seed = o_.seed;
  for (const vv_param_entry* p : parameters_of(*model_)) c.parameters.emplace_back(p->name, parameter_text(*p));
  const std::string text = checkpoint_text(c);
  return write_output(path, [&](const std::string& to) -> std::string {
    try {
      vv::io::write_text_file(to, text);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  });
}

std::string model_runner::export_to(const std::string& path) const { return export_to(path, o_.meshes); }

std::string model_runner::export_to(const std::string& path, const std::vector<std::string>& names) const {
  if (!model_) return "no model is loaded";
  if (std::string e = unknown_mesh(*model_, o_.model, names); !e.empty()) return e;
  return write_output(path, [&](const std::string& to) { return write_meshes(to, names); });
}

std::string model_runner::write_meshes(const std::string& path, const std::vector<std::string>& names) const {
  if (names.size() > 1) {
    std::vector<const char*> c = c_names(names);
    if (is_written_by_model(path)) {
      const char* e = model_->model().union_file(c.data(), c.size(), max_face(), path.c_str());
      return e ? e : "";
    }
    vv_geometry g{};
    if (const char* e = model_->model().union_geometry(c.data(), c.size(), max_face(), &g)) return e;
    return export_polygons(g, path, "meshes " + joined_names(names));
  }
  const vv_mesh_entry* m = model_->mesh(names.empty() ? "" : names[0]);
  if (!m) return o_.model + ": the model has no global mesh to export";
  if (is_written_by_model(path)) {
    const char* e = m->write_file(path.c_str(), max_face());
    return e ? e : "";
  }
  vv_geometry g{};
  if (const char* e = m->geometry(max_face(), &g)) return e;
  return export_polygons(g, path, std::string("mesh ") + m->name);
}

}  // namespace vvi
