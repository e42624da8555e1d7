// The command line (DESIGN.md, "Command-line contracts").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "experiment/sweep_options.hpp"

namespace vvi {

struct options {
  std::string model;          // .vvp (or a prebuilt .so)
  bool batch = false;
  bool compile_only = false;
  unsigned steps = 0;
  std::string export_path;    // --export FILE (.vvm .obj .off .ply .stl .vtp)
  std::vector<std::string> meshes;  // --mesh NAME[,NAME...] (default: the first global mesh)
  bool end_block = false;     // --end: run the end block after the last step (batch)
  double step_timeout = 0;    // --step-timeout SECONDS (batch; 0: no limit)
  bool debug = false;         // --debug: build the model with -g -O0 (batch: in this process)
  bool in_process = false;    // --in-process: batch without the supervising process
  std::size_t max_face = 0;   // --max-face N (0: no limit)
  std::string screenshot;     // --screenshot FILE.png
  int width = 800, height = 600;  // --size WxH
  double view_yaw = 0, view_pitch = 0;  // --view YAW PITCH (degrees, batch screenshots)
  std::uint64_t seed = 0;     // --seed S
  bool strict = false;        // --strict
  unsigned threads = 0;       // --threads N (0: the machine's cores)
  bool check = false;         // --check
  //! --set NAME=VALUE, in order (NAME, VALUE).
  std::vector<std::pair<std::string, std::string>> parameter_values;
  bool list_params = false;   // --list-params
  std::string plots_path;     // --plots FILE.csv (batch): the proxy.plot series
  std::vector<unsigned> picks;  // --pick LABEL (batch): describe these vertices
  std::string color_by;       // --color-by NAME: colour by a numeric vertex property
  std::string script;         // --script FILE (viewer)
  std::string frames = "frames";  // --frames DIR (proxy.record_frame)
  std::string cache;          // --cache DIR
  int optimization = 1;       // --opt N
  bool rebuild = false;       // --rebuild: compile even when the cache holds the model (batch, --compile-only)
  bool quiet = false;         // --quiet: no progress, no summary
  sweep_options sweep;        // --sweep, --seeds, --jobs, --shard, --out, --merge, --slurm
};

struct parse_result {
  bool ok = false;
  bool exit_now = false;  // --help / --version answered
  std::string message;    // the text to print (usage error, help, version)
  options opts;
};

parse_result parse_options(int argc, const char* const* argv);
extern const char* usage_text;

}  // namespace vvi
