// What the host shows and uses of a model's state: its step, its run
// settings, its meshes' sizes, parameters, plots, files and actions. Read
// while the model is idle, after every job, and kept as they are while the
// next job runs (the model's state is not to be read then): the panel
// always shows the state the last job left.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace vvi {

class session;

//! A parameter as the panel shows it.
struct parameter_view {
  std::string name, type, text;  //!< text: the value as it reads back exactly
  double number = 0;             //!< the value (bool: 0 or 1)
  bool has_range = false;
  double lo = 0, hi = 0;
  int line = 0;
};

//! A proxy.plot series: its values in the order of the steps recorded.
struct plot_view {
  std::string name;
  std::vector<float> values;
  unsigned first_step = 0, last_step = 0;
  double last = 0;
};

//! An action of the program (`action "NAME" key 'k'`), for its button and key.
struct action_view {
  std::string name;
  int key = 0;  //!< 0: none; else a lowercase letter or a digit
  int line = 0;
};

struct model_facts {
  bool loaded = false;
  unsigned steps = 0;            //!< completed steps
  double last_step_ms = 0;
  unsigned run_steps = 0;        //!< proxy.steps: what Run runs
  unsigned delay_msec = 0;       //!< between animated steps
  bool can_animate = true;       //!< !proxy.no_animate
  bool record_frame = false;     //!< proxy.record_frame: a picture after each step
  std::vector<std::pair<std::string, std::size_t>> meshes;  //!< name, vertices
  std::vector<parameter_view> parameters;
  std::vector<plot_view> plots;
  std::vector<std::string> file_objects;  //!< the files its file objects read
  std::vector<action_view> actions;       //!< in source order
  bool has_pick = false;                  //!< the program has a pick block
};

//! The facts of a loaded, idle model (nullptr: none loaded).
model_facts read_facts(const session* model, const std::vector<std::string>& file_objects);

}  // namespace vvi
