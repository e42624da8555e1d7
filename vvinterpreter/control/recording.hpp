// Time series: files written while the model runs (the command `record K
// FILE`, batch's --every K, the viewer's Record). Each series is one file
// name with {step} in it (a movie: one file, a frame per step); its files
// are written when recording starts, after every step whose number is a
// multiple of K, after a load (rewind, reload) that comes back to such a
// step, and, when recording stops, for the state it stops at if that
// changed since they were last written. A .vtp series is listed in a
// ParaView collection (.pvd) beside it, its timesteps the steps.
#pragma once

#include <optional>
#include <string>

#include <vv/io/vtk_files.hpp>

#include "control/command.hpp"
#include "series/step_names.hpp"

namespace vvi {

struct recorded_series {
  unsigned long every = 1;
  std::string pattern;  // the name with {step}; a movie's name
  unsigned digits = 5;
  series_file kind = series_file::mesh;
  std::optional<vv::pvd_series> collection;  // of a .vtp series
  bool changed = true;  // the model changed since the files were last written
};

//! The default width of {step} when the last step is not known (the viewer).
inline constexpr unsigned default_step_digits = 5;

//! Why `record K FILE` cannot record FILE, or "".
std::string recording_refused(const command& c);

}  // namespace vvi
