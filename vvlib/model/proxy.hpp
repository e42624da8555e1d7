// The program's view of its host (`proxy`, docs/language.md section 5): run
// settings the program writes and the host reads (through the descriptor's
// run_settings, plot_count and plot_series: model/abi.hpp), file objects to
// reread, and the plots.
#pragma once

#include <string>
#include <vector>

#include "file_object.hpp"

namespace vv {

//! A quantity a program records over steps (proxy.plot): values[i] was
//! recorded at steps[i].
struct plot_series {
  std::string name;
  std::vector<unsigned> steps;
  std::vector<double> values;
};

struct proxy {
  unsigned steps = 0;         //!< steps the host's "run" command performs
  unsigned delay_msec = 0;    //!< pause between animated steps
  bool no_animate = false;    //!< the host ignores "animate"
  bool record_frame = false;  //!< the host saves a PNG after each step
  //! Face orbits longer than this are holes or boundaries, not faces, when
  //! the host draws or exports the model (0: no limit; --max-face overrides).
  unsigned max_face = 0;
  void* viewer = nullptr;     //!< the host's canvas, opaque to programs

  //! The box the view must show (set by setViewVolume).
  bool has_view_volume = false;
  double view_min[3] = {0, 0, 0};
  double view_max[3] = {0, 0, 0};

  //! File-backed objects, by kind, re-read on the host's command together
  //! with the registered ones (model/file_registry.hpp).
  std::vector<file_object*> materials, palettes, functions, contours;

  //! Series recorded by plot(), in the order first recorded.
  std::vector<plot_series> plots;
  //! The step being run (0 in start), set by the host before each block.
  unsigned plot_step = 0;

  //! `proxy.plot("cells", n)`: records the value for the current step (a
  //! second value in the same step replaces the first).
  void plot(const std::string& name, double value) {
    plot_series* s = nullptr;
    for (plot_series& p : plots)
      if (p.name == name) s = &p;
    if (!s) s = &plots.emplace_back(plot_series{name, {}, {}});
    if (!s->steps.empty() && s->steps.back() == plot_step) {
      s->values.back() = value;
      return;
    }
    s->steps.push_back(plot_step);
    s->values.push_back(value);
  }

  void setViewVolume(double maxx, double maxy, double maxz, double minx, double miny,
                     double minz) noexcept {
    has_view_volume = true;
    view_max[0] = maxx, view_max[1] = maxy, view_max[2] = maxz;
    view_min[0] = minx, view_min[1] = miny, view_min[2] = minz;
  }
};

}  // namespace vv
