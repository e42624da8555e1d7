// The program's view of its host (LANGUAGE.md section 8): run settings the
// program writes and the host reads.
#pragma once

#include <string>
#include <vector>

namespace vv {

//! An object whose contents come from a file (a colour palette, a material
//! list, a function graph): the host's "reread files" command calls
//! reread() on every one the program put into the proxy's lists and on
//! every one registered in file_objects.hpp.
class file_object {
 public:
  virtual ~file_object() = default;
  virtual void reread() = 0;
  //! The file, for a host that watches it ("" when there is none).
  virtual const std::string& path() const {
    static const std::string none;
    return none;
  }
};

// Defined in file_objects.hpp, included at the end.
inline void reread_file_objects(std::initializer_list<const std::vector<file_object*>*> proxy_lists);

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

  //! File-backed objects, by kind, re-read on the host's command.
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

  //! Rereads the objects in these lists and the registered ones, each once.
  void reread_files() { reread_file_objects({&materials, &palettes, &functions, &contours}); }

  void setViewVolume(double maxx, double maxy, double maxz, double minx, double miny,
                     double minz) noexcept {
    has_view_volume = true;
    view_max[0] = maxx, view_max[1] = maxy, view_max[2] = maxz;
    view_min[0] = minx, view_min[1] = miny, view_min[2] = minz;
  }
};

}  // namespace vv

#include "../file_objects.hpp"
