// Runs a translated test program linked into this executable, as the
// interpreter's batch mode will: configure, start, then the steps, actions
// and picks in the order given, end, close.
//
//   driver [--steps N] [--action NAME] [--pick LABEL] ... [--model-dir DIR]
//          [--expect-error TEXT] [--write MESH FILE]
//
// Exits 0 when every CHECK in the program held (and at least one ran) and
// no block failed, or, with --expect-error, when a block failed with a
// message containing TEXT.
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <model/abi.hpp>

#include "vv_check.hpp"

namespace {

// What runs after start, in order.
struct event {
  enum { steps, action, pick } kind;
  std::string argument;
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<event> events;
  std::string model_dir = ".", expected_error, write_mesh, write_path;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--steps" && i + 1 < argc) events.push_back({event::steps, argv[++i]});
    else if (a == "--action" && i + 1 < argc) events.push_back({event::action, argv[++i]});
    else if (a == "--pick" && i + 1 < argc) events.push_back({event::pick, argv[++i]});
    else if (a == "--model-dir" && i + 1 < argc) model_dir = argv[++i];
    else if (a == "--expect-error" && i + 1 < argc) expected_error = argv[++i];
    else if (a == "--write" && i + 2 < argc) write_mesh = argv[++i], write_path = argv[++i];
    else {
      std::cerr << "driver: bad argument " << a << "\n";
      return 2;
    }
  }
  const vv_plugin& model = vv_plugin_descriptor;
  if (model.abi_version != VV_PLUGIN_ABI_VERSION) {
    std::cerr << "driver: plugin ABI " << model.abi_version << ", expected " << VV_PLUGIN_ABI_VERSION << "\n";
    return 2;
  }
  vv_plugin_settings settings{};
  settings.model_dir = model_dir.c_str();
  settings.seed = 42;
  model.configure(&settings);

  std::string error;
  auto run = [&](const char* name, const char* (*block)()) {
    if (!error.empty() || !block) return;
    if (const char* e = block()) error = std::string(name) + ": " + e;
  };
  run("start", model.start);
  unsigned steps_done = 0;
  for (const event& e : events) {
    if (!error.empty()) break;
    if (e.kind == event::steps) {
      for (int i = std::atoi(e.argument.c_str()); i > 0 && error.empty(); --i) {
        model.set_plot_step(++steps_done);
        run("step", model.step);
      }
    } else if (e.kind == event::action) {
      const vv_action_entry* found = nullptr;
      for (std::size_t i = 0; i < model.action_count; ++i)
        if (e.argument == model.actions[i].name) found = &model.actions[i];
      if (!found) error = "no action named " + e.argument;
      else run(("action " + e.argument).c_str(), found->run);
    } else if (!model.pick) {
      error = "the program has no pick block";
    } else if (const char* failed = model.pick(static_cast<unsigned>(std::strtoul(e.argument.c_str(), nullptr, 10)))) {
      error = "pick " + e.argument + ": " + failed;
    }
  }
  run("end", model.end);
  if (!write_mesh.empty() && error.empty()) {
    bool found = false;
    for (std::size_t i = 0; i < model.mesh_count; ++i)
      if (write_mesh == model.meshes[i].name) {
        found = true;
        if (const char* e = model.meshes[i].write_vvm(write_path.c_str())) error = e;
      }
    if (!found) error = "no global mesh named " + write_mesh;
  }
  run("close", model.close);

  if (!expected_error.empty()) {
    if (error.find(expected_error) != std::string::npos) {
      std::cout << "failed as expected: " << error << "\n";
      return vv_check::failures == 0 ? 0 : 1;
    }
    std::cerr << "expected an error containing \"" << expected_error << "\", got "
              << (error.empty() ? std::string("none") : "\"" + error + "\"") << "\n";
    return 1;
  }
  if (!error.empty()) {
    std::cerr << error << "\n";
    return 1;
  }
  std::cout << vv_check::checks << " checks, " << vv_check::failures << " failed\n";
  if (vv_check::checks == 0) {
    std::cerr << "the program ran no CHECK\n";
    return 1;
  }
  return vv_check::failures == 0 ? 0 : 1;
}
