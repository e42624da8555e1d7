// The command line (DESIGN.md, "Command-line contracts"). What each option
// means is said once, where it is registered (options.cpp); --help prints
// those descriptions.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "control/command.hpp"
#include "experiment/sweep_options.hpp"

namespace vvi {

struct options {
  std::string model;
  bool batch = false;
  bool compile_only = false;
  unsigned steps = 0;
  std::string export_path;
  std::vector<std::string> meshes;
  bool end_block = false;
  double step_timeout = 0;
  bool debug = false;
  bool in_process = false;
  std::size_t max_face = 0;
  std::string screenshot;
  int width = 800, height = 600;
  double view_yaw = 0, view_pitch = 0;
  unsigned long every = 0;   // --every K: a time series (0: none)
  std::vector<double> frame;  // --frame XMIN YMIN ZMIN XMAX YMAX ZMAX, or none
  unsigned fps = 10;          // of a --screenshot movie
  std::uint64_t seed = 0;
  bool strict = false;
  unsigned threads = 0;  // 0: the machine's cores
  bool check = false;
  std::vector<std::pair<std::string, std::string>> parameter_values;  // --set, in order
  bool list_params = false;
  std::string plots_path;
  std::vector<unsigned> picks;
  //! --action NAME@STEP and --pick-action LABEL@STEP, in order: after step STEP.
  std::vector<std::pair<unsigned long, command>> events_at;
  std::string replay;
  std::string checkpoint;  // --checkpoint: the state after the steps
  std::string resume;      // --resume: go on from a checkpoint instead of start
  std::string color_by;
  std::string script;
  std::string frames = "frames";
  std::string cache;
  int optimization = 1;
  bool rebuild = false;
  bool expect_edits = false;  // --expect-edits: the declarations' part from the first build
  unsigned build_cores = 0;   // $VV_BUILD_CORES: the most idle cores a new model's build counts (0: no limit)
  bool quiet = false;
  sweep_options sweep;
};

struct parse_result {
  bool ok = false;
  bool exit_now = false;  // --help / --version answered
  std::string message;    // the text to print (usage error, help, version)
  options opts;
};

parse_result parse_options(int argc, const char* const* argv);

//! The usage and every option with what it does (from their registration).
std::string usage_text();

}  // namespace vvi
