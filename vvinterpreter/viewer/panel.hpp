// The viewer's control panel (Dear ImGui): buttons in, actions out. It
// only shows state; the viewer decides what the actions do.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace vvi {

struct panel_state {
  std::string model;
  std::string status;  // "running", "compiling ...", ...
  unsigned steps = 0;
  unsigned run_steps = 0;  // proxy.steps
  double last_step_ms = 0;
  std::vector<std::pair<std::string, std::size_t>> meshes;  // name, vertices
  bool animating = false;
  bool can_animate = true;  // !proxy.no_animate
  bool has_model = false;
  bool busy = false;        // the model's code is running
  std::string running;      // "step 3 running for 2.1 s", once a job runs long
  bool replay = true;       // reloads and restarts run the model again to its step
  std::string error;
  std::string warnings;
  std::string message;  // the last thing done ("wrote shot.png")
};

struct panel_actions {
  bool step = false, run = false, animate = false, stop = false, rewind = false, end = false;
  bool reread = false, recompile = false, fit = false, screenshot = false;
  bool toggle_replay = false;
};

panel_actions draw_panel(const panel_state& s);

}  // namespace vvi
