#include "session.hpp"

#include <chrono>

namespace vvi {

std::unique_ptr<session> session::load(const std::string& plugin_path, const session_settings& s,
                                       std::string& error) {
  std::unique_ptr<plugin> p = plugin::open(plugin_path, error);
  if (!p) return nullptr;
  vv_plugin_settings settings{s.model_dir.c_str(), s.seed, s.strict ? 1 : 0};
  p->configure(&settings);
  return std::unique_ptr<session>(new session(std::move(p)));
}

bool session::run(const char* block, plugin::block_fn fn) {
  if (const char* e = fn()) {
    error_ = e;
    if (error_.find(block) == std::string::npos) error_ += std::string(" (in ") + block + ")";
    return false;
  }
  return true;
}

bool session::start() { return run("start", plugin_->start); }
bool session::end() { return run("end", plugin_->end); }
bool session::reread() { return run("reread files", plugin_->reread); }

bool session::step() {
  auto t = std::chrono::steady_clock::now();
  std::string label = "step " + std::to_string(steps_ + 1);
  bool ok = run(label.c_str(), plugin_->step);
  last_step_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
  if (ok) ++steps_;
  return ok;
}

void session::close() {
  if (closed_) return;
  closed_ = true;
  run("close", plugin_->close);
}

session::~session() { close(); }

std::vector<const vv_mesh_entry*> session::meshes() const {
  std::size_t n = 0;
  const vv_mesh_entry* table = plugin_->meshes(&n);
  std::vector<const vv_mesh_entry*> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(&table[i]);
  return out;
}

const vv_mesh_entry* session::mesh(const std::string& name) const {
  for (const vv_mesh_entry* m : meshes())
    if (name.empty() || name == m->name) return m;
  return nullptr;
}

}  // namespace vvi
