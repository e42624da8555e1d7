#include "app/options.hpp"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <functional>
#include <string>

#include "compile/build_config.hpp"
#include "experiment/sweep_options.hpp"
#include "viewer/script.hpp"

namespace vvi {

const char* usage_text =
    "usage: vvinterpreter [options] MODEL.vvp\n"
    "       vvinterpreter --batch [--steps N] [--end] [--export FILE] [--mesh NAME[,NAME...]]\n"
    "                     [--max-face N] [--screenshot FILE.png --size WxH] [--seed S] [--threads N]\n"
    "                     [--step-timeout SECONDS] [--set NAME=VALUE ...] [--plots FILE.csv]\n"
    "                     [--pick LABEL ...] [--color-by NAME] MODEL.vvp\n"
    "       vvinterpreter --list-params [--set NAME=VALUE ...] MODEL.vvp\n"
    "       vvinterpreter --compile-only MODEL.vvp\n"
    "       vvinterpreter --sweep NAME=V1,V2,... [--sweep NAME=LO:HI:COUNT ...] [--seeds K]\n"
    "                     [--jobs J] [--shard I/N | --slurm N] --out DIR [batch options] MODEL.vvp\n"
    "       vvinterpreter --merge DIR [DIR ...] --out DIR\n"
    "\n"
    "Translates, compiles and runs a vv model: in a window (the default), or\n"
    "headless with --batch: start, N steps, (end), export, screenshot, close.\n"
    "A model that crashes or hangs never takes the viewer down: it is reported\n"
    "with its .vvp line and restarted.\n"
    "MODEL may also be a plugin (.so) built earlier.\n"
    "\n"
    "options:\n"
    "  --batch            run without a window\n"
    "  --steps N          steps to run in batch mode (default 0)\n"
    "  --end              run the end block after the last step (batch)\n"
    "  --export FILE      write a mesh after the steps: .vvm .obj .off .ply .stl .vtp\n"
    "  --mesh NAME[,NAME] the global meshes to export or draw, as one (default: the first)\n"
    "  --step-timeout S   end a step that runs longer than S seconds, as an error (batch)\n"
    "  --max-face N       face orbits longer than N are holes, not faces\n"
    "  --screenshot FILE  render a PNG after the steps (batch: offscreen)\n"
    "  --size WxH         the screenshot's size (default 800x600)\n"
    "  --view YAW PITCH   turn the screenshot's view by these degrees (default 0 0)\n"
    "  --seed S           seed of the model's random numbers (default 0)\n"
    "  --strict           reading the old state of a never-synchronised vertex is an error, and\n"
    "                     a parallel forall runs in order, checking that each iteration changes\n"
    "                     only its own vertex's properties\n"
    "  --threads N        threads of a parallel forall (default: the machine's cores); the\n"
    "                     results do not depend on it\n"
    "  --set NAME=VALUE   give the parameter NAME (a `param` of the program) this value;\n"
    "                     repeatable\n"
    "  --list-params      print the parameters (name, type, value, range) and exit\n"
    "  --plots FILE.csv   batch: write what the model recorded with proxy.plot, a column\n"
    "                     per series (the first column: the step)\n"
    "  --pick LABEL       batch: print the vertex with this label (properties, neighbourhood,\n"
    "                     half-edge records) after the steps; repeatable\n"
    "  --color-by NAME    colour the drawing by a numeric vertex property (with a colour bar)\n"
    "  --check            after start and every step, check every global mesh's neighbourhoods\n"
    "                     and stop at the first broken one, naming the line that last edited it\n"
    "  --script FILE      viewer: run the commands in FILE, one per line (listed below)\n"
    "  --frames DIR       where proxy.record_frame writes frame_NNNNN.png (default ./frames)\n"
    "  --compile-only     translate and compile, then exit\n"
    "  --cache DIR        compiled models (default $VV_CACHE_DIR or ~/.cache/vv)\n"
    "  --opt N            optimisation level for models (0-3, default 1)\n"
    "  --rebuild          compile the model even when the cache holds it (batch,\n"
    "                     --compile-only; the viewer has its Recompile button)\n"
    "  --debug            build the model with -g -O0 and run it in this process, for gdb\n"
    "  --in-process       batch: run the model in this process, unsupervised (a crash\n"
    "                     then ends the interpreter; for profilers and debuggers)\n"
    "  --quiet            no progress or summary lines\n"
    "\n"
    "experiments (docs/experiments.md):\n"
    "  --sweep NAME=V1,V2,...  run the model for each value of the parameter NAME;\n"
    "  --sweep NAME=LO:HI:COUNT  or for COUNT values from LO to HI; repeatable (every\n"
    "                     combination runs)\n"
    "  --seeds K          run each combination with the seeds 1 to K\n"
    "  --jobs J           runs at a time, each in its own process (default: the cores)\n"
    "  --out DIR          the sweep's folder: run-NNNN/ per run, runs.csv, failed.csv\n"
    "  --shard I/N        run only every N-th run from run I (a cluster's job array)\n"
    "  --slurm N          write (and submit with sbatch) a Slurm job array of N shards\n"
    "                     and a job that merges them into DIR\n"
    "  --merge DIR...     join shard folders of one sweep into --out DIR\n"
    "  --help, --version\n";

namespace {

// Thrown by an option that cannot take its value, with the reason.
struct usage_error {
  std::string message;
};
// Thrown by --help and --version, with the text to print.
struct answered {
  std::string text;
};

bool to_unsigned(const std::string& s, unsigned long long& out) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 19) return false;
  out = std::strtoull(s.c_str(), nullptr, 10);
  return true;
}

// The value of a number option, or a usage error saying what it needs.
unsigned long long number(const std::string& v, unsigned long long lo, unsigned long long hi, const char* need) {
  unsigned long long n = 0;
  if (!to_unsigned(v, n) || n < lo || n > hi) throw usage_error{need};
  return n;
}

// An option with one value. `take` runs at each occurrence, in command-line
// order (a later one wins, or adds, as take decides); a missing value
// reaches it as "" so that each option says itself what it needs.
void with_value(CLI::App& app, const std::string& name, std::function<void(const std::string&)> take) {
  app.add_option_function<std::string>(name, std::move(take))->expected(0, 1)->trigger_on_parse();
}

void flag(CLI::App& app, const std::string& name, bool& set) {
  app.add_flag_callback(name, [&set] { set = true; })->trigger_on_parse();
}

// An option naming a file or a folder (any text but "").
void text(CLI::App& app, const std::string& name, std::string& out) {
  with_value(app, name, [name, &out](const std::string& v) {
    if (v.empty()) throw usage_error{name + " needs a value"};
    out = v;
  });
}

void answers(CLI::App& app) {
  app.set_help_flag();  // usage_text is the help: it says more than a generated one would
  app.add_flag_callback("--help,-h", [] {
       throw answered{std::string(usage_text) + "\nscript commands (--script FILE):\n" + script_help};
     })->trigger_on_parse();
  app.add_flag_callback("--version", [] {
       throw answered{std::string("vvinterpreter ") + config::version + "\n"};
     })->trigger_on_parse();
}

void switches(CLI::App& app, options& o) {
  flag(app, "--batch", o.batch);
  flag(app, "--compile-only", o.compile_only);
  flag(app, "--strict", o.strict);
  flag(app, "--list-params", o.list_params);
  flag(app, "--check", o.check);
  flag(app, "--quiet", o.quiet);
  flag(app, "--end", o.end_block);
  flag(app, "--debug", o.debug);
  flag(app, "--in-process", o.in_process);
  flag(app, "--rebuild", o.rebuild);
}

void numbers(CLI::App& app, options& o) {
  with_value(app, "--steps", [&o](const std::string& v) {
    o.steps = static_cast<unsigned>(number(v, 0, 100000000, "--steps needs a count"));
  });
  with_value(app, "--max-face", [&o](const std::string& v) {
    o.max_face = number(v, 3, ~0ull, "--max-face needs a number of corners (3 or more)");
  });
  with_value(app, "--seed", [&o](const std::string& v) { o.seed = number(v, 0, ~0ull, "--seed needs a non-negative number"); });
  with_value(app, "--threads", [&o](const std::string& v) {
    o.threads = static_cast<unsigned>(number(v, 1, 1024, "--threads needs a number of threads (1 to 1024)"));
  });
  with_value(app, "--opt", [&o](const std::string& v) {
    o.optimization = static_cast<int>(number(v, 0, 3, "--opt needs a level from 0 to 3"));
  });
  with_value(app, "--pick", [&o](const std::string& v) {
    o.picks.push_back(static_cast<unsigned>(number(v, 1, 0xffffffffull, "--pick needs a vertex label (1 or more)")));
  });
  with_value(app, "--step-timeout", [&o](const std::string& v) {
    if (v.empty()) throw usage_error{"--step-timeout needs a number of seconds"};
    char* end = nullptr;
    o.step_timeout = std::strtod(v.c_str(), &end);
    if (*end || !(o.step_timeout > 0) || o.step_timeout > 1e6)
      throw usage_error{"--step-timeout needs a number of seconds greater than 0"};
  });
}

void view_options(CLI::App& app, options& o) {
  with_value(app, "--size", [&o](const std::string& v) {
    const char* need = "--size needs WIDTHxHEIGHT, e.g. 800x600 (at most 16384 each way)";
    if (v.empty()) throw usage_error{"--size needs WIDTHxHEIGHT"};
    std::size_t x = v.find('x');
    if (x == std::string::npos) throw usage_error{need};
    o.width = static_cast<int>(number(v.substr(0, x), 1, 16384, need));
    o.height = static_cast<int>(number(v.substr(x + 1), 1, 16384, need));
  });
  // Two values; a negative angle is a value, not an option.
  app.add_option_function<std::vector<std::string>>("--view", [&o](const std::vector<std::string>& v) {
       const char* need = "--view needs two angles in degrees";
       if (v.size() != 2 || v[0].empty() || v[1].empty()) throw usage_error{need};
       char* end1 = nullptr;
       char* end2 = nullptr;
       o.view_yaw = std::strtod(v[0].c_str(), &end1);
       o.view_pitch = std::strtod(v[1].c_str(), &end2);
       if (*end1 || *end2) throw usage_error{need};
     })->expected(0, 2)->allow_extra_args(false)->trigger_on_parse();
}

void model_inputs(CLI::App& app, options& o) {
  with_value(app, "--set", [&o](const std::string& v) {
    std::size_t eq = v.find('=');
    if (eq == std::string::npos || eq == 0) throw usage_error{"--set needs NAME=VALUE, e.g. --set rate=0.5"};
    o.parameter_values.emplace_back(v.substr(0, eq), v.substr(eq + 1));
  });
  with_value(app, "--mesh", [&o](const std::string& v) {
    if (v.empty()) throw usage_error{"--mesh needs a value"};
    o.meshes.clear();
    for (std::size_t from = 0, comma; from <= v.size(); from = comma + 1) {
      comma = v.find(',', from);
      if (comma == std::string::npos) comma = v.size();
      if (comma == from) throw usage_error{"--mesh needs names separated by commas, e.g. --mesh J,C"};
      o.meshes.push_back(v.substr(from, comma - from));
    }
  });
  text(app, "--export", o.export_path);
  text(app, "--screenshot", o.screenshot);
  text(app, "--script", o.script);
  text(app, "--plots", o.plots_path);
  text(app, "--color-by", o.color_by);
  text(app, "--frames", o.frames);
  text(app, "--cache", o.cache);
}

// What the options say together.
void check_whole(const CLI::App& app, const std::vector<std::string>& models, options& o) {
  for (const std::string& a : app.remaining())
    if (!a.empty() && a[0] == '-') throw usage_error{"unknown option " + a};
  if (models.size() > 1) throw usage_error{"more than one model (" + models[0] + " and " + models[1] + ")"};
  if (std::string why = check_sweep_options(o.sweep, !models.empty()); !why.empty()) throw usage_error{why};
  if (o.sweep.merging()) return;  // the folders name their model
  if (models.empty() || models[0].empty()) throw usage_error{"no model given"};
  o.model = models[0];
  if (o.list_params) o.batch = true;  // headless, and supervised like a batch run
  if (o.sweep.sweeping()) o.batch = true;  // each run is a batch run
  if (o.batch && !o.script.empty()) throw usage_error{"--script drives the viewer; it cannot be used with --batch"};
  if (o.rebuild && !o.batch && !o.compile_only)
    throw usage_error{"--rebuild is for --batch and --compile-only (the viewer rebuilds with its Recompile button)"};
}

}  // namespace

parse_result parse_options(int argc, const char* const* argv) {
  parse_result r;
  CLI::App app("", "vvinterpreter");
  std::vector<std::string> models;
  answers(app);
  switches(app, r.opts);
  numbers(app, r.opts);
  view_options(app, r.opts);
  model_inputs(app, r.opts);
  add_sweep_options(app, r.opts.sweep);
  app.add_option("model", models);
  app.allow_extras();  // unknown options are named below, as before
  try {
    app.parse(argc, argv);
    check_whole(app, models, r.opts);
    r.ok = true;
  } catch (const answered& a) {
    r.ok = r.exit_now = true;
    r.message = a.text;
  } catch (const usage_error& e) {
    r.message = "vvinterpreter: " + e.message + "\n" + usage_text;
  } catch (const CLI::ParseError& e) {
    r.message = std::string("vvinterpreter: ") + e.what() + "\n" + usage_text;
  }
  return r;
}

}  // namespace vvi
