#include "app/options.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>

#include "compile/build_config.hpp"
#include "control/command_text.hpp"
#include "experiment/sweep_options.hpp"
#include "series/step_names.hpp"

namespace vvi {

namespace {

const char* const synopsis =
    "usage: vvinterpreter [options] MODEL.vvp\n"
    "       vvinterpreter --batch [options] MODEL.vvp\n"
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
    "MODEL may also be a plugin (.so) built earlier.\n";

// The sections of --help, in order; each option names its own.
const char* const sections[] = {"modes", "batch", "model", "viewer", "building", "experiments"};

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

// An option with one value: its name, the value's name, its section and
// what it does. `take` runs at each occurrence, in command-line order (a
// later one wins, or adds, as take decides); a missing value reaches it as
// "" so that each option says itself what it needs.
void with_value(CLI::App& app, const std::string& name, const std::string& value, const char* section,
                const std::string& what, std::function<void(const std::string&)> take) {
  app.add_option_function<std::string>(name, std::move(take), what)
      ->expected(0, 1)
      ->trigger_on_parse()
      ->option_text(value)
      ->group(section);
}

void flag(CLI::App& app, const std::string& name, const char* section, const std::string& what, bool& set) {
  app.add_flag_callback(name, [&set] { set = true; }, what)->trigger_on_parse()->group(section);
}

// An option naming a file or a folder (any text but "").
void text(CLI::App& app, const std::string& name, const std::string& value, const char* section,
          const std::string& what, std::string& out) {
  with_value(app, name, value, section, what, [name, &out](const std::string& v) {
    if (v.empty()) throw usage_error{name + " needs a value"};
    out = v;
  });
}

// "WHAT@STEP" of --action and --pick-action: the step after the last '@'.
unsigned long at_step(const std::string& v, const std::string& option, std::string& what) {
  std::size_t at = v.rfind('@');
  std::string need = option + " needs " + (option == "--action" ? "NAME" : "LABEL") + "@STEP, e.g. " + option +
                     (option == "--action" ? " Divide@3" : " 17@3");
  if (at == std::string::npos || at == 0) throw usage_error{need};
  what = v.substr(0, at);
  return static_cast<unsigned long>(number(v.substr(at + 1), 0, 100000000, need.c_str()));
}

void answers(CLI::App& app) {
  app.set_help_flag();  // usage_text() is the help: it has the sections and the script commands
  app.add_flag_callback("--help,-h", [] {
       throw answered{usage_text() + "\nscript commands (--script FILE):\n" + command_help()};
     }, "this text")->trigger_on_parse()->group("modes");
  app.add_flag_callback("--version", [] {
       throw answered{std::string("vvinterpreter ") + config::version + "\n"};
     }, "the version")->trigger_on_parse()->group("modes");
}

void modes(CLI::App& app, options& o) {
  flag(app, "--batch", "modes", "run without a window", o.batch);
  flag(app, "--list-params", "modes", "print the parameters (name, type, value, range) and exit", o.list_params);
  flag(app, "--compile-only", "modes", "translate and compile, then exit", o.compile_only);
}

void batch_options(CLI::App& app, options& o) {
  with_value(app, "--steps", "N", "batch", "steps to run in batch mode (default 0)", [&o](const std::string& v) {
    o.steps = static_cast<unsigned>(number(v, 0, 100000000, "--steps needs a count"));
  });
  flag(app, "--end", "batch", "run the end block after the last step", o.end_block);
  with_value(app, "--action", "NAME@STEP", "batch", "run the model's action NAME after step STEP (0: after start)",
             [&o](const std::string& v) {
               std::string name;
               unsigned long step = at_step(v, "--action", name);
               o.events_at.emplace_back(step, command::named(command::action, name));
             });
  with_value(app, "--pick-action", "LABEL@STEP", "batch",
             "run the model's pick block on the vertex LABEL after step STEP", [&o](const std::string& v) {
               std::string label;
               unsigned long step = at_step(v, "--pick-action", label);
               unsigned long n = number(label, 1, 0xffffffffull, "--pick-action needs a vertex label (1 or more)");
               o.events_at.emplace_back(step, command::labelled(command::pick_action, n));
             });
  text(app, "--replay", "FILE", "batch", "run the events of a session the viewer saved, before the steps", o.replay);
  text(app, "--checkpoint", "FILE", "batch",
       "after the steps (before the end block), save the model's whole state to go on from it later", o.checkpoint);
  text(app, "--resume", "FILE", "batch",
       "go on from a checkpoint instead of running start: --steps N then runs N more steps (also the viewer)",
       o.resume);
  text(app, "--export", "FILE", "batch",
       "write a mesh after the steps: .vvm .obj .off .ply .stl .vtp ({step} in FILE: the step's number)",
       o.export_path);
  text(app, "--screenshot", "FILE", "batch",
       "render a PNG after the steps (offscreen), or with --every a movie FILE.mp4 (ffmpeg)", o.screenshot);
  with_value(app, "--every", "K", "batch",
             "write --export and --screenshot after start, after every step that is a multiple of K and at the "
             "last, {step} in their names the step's number; a .vtp series is listed in a ParaView .pvd beside it",
             [&o](const std::string& v) { o.every = number(v, 1, 100000000, "--every needs a number of steps (1 or more)"); });
  app.add_option_function<std::vector<std::string>>("--frame", [&o](const std::vector<std::string>& v) {
       const char* need = "--frame needs six numbers: XMIN YMIN ZMIN XMAX YMAX ZMAX";
       if (v.size() != 6) throw usage_error{need};
       o.frame.clear();
       for (const std::string& n : v) {
         char* end = nullptr;
         double x = std::strtod(n.c_str(), &end);
         if (n.empty() || *end || !std::isfinite(x)) throw usage_error{need};
         o.frame.push_back(x);
       }
       for (int axis = 0; axis < 3; ++axis)
         if (o.frame[axis + 3] < o.frame[axis])
           throw usage_error{std::string("--frame: ") + "XYZ"[axis] + "MAX is below " + "XYZ"[axis] + "MIN"};
     }, "fit the screenshots to this box rather than to the model (default in a series: the box that holds "
        "every frame's model, found by a first run)")
      ->expected(0, 6)->allow_extra_args(false)->trigger_on_parse()->option_text("X0 Y0 Z0 X1 Y1 Z1")->group("batch");
  with_value(app, "--fps", "N", "batch", "frames a second of a --screenshot movie (default 10)",
             [&o](const std::string& v) { o.fps = static_cast<unsigned>(number(v, 1, 240, "--fps needs a number of frames a second (1 to 240)")); });
  with_value(app, "--size", "WxH", "batch", "the screenshot's size (default 800x600)", [&o](const std::string& v) {
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
     }, "turn the screenshot's view by these degrees (default 0 0)")
      ->expected(0, 2)->allow_extra_args(false)->trigger_on_parse()->option_text("YAW PITCH")->group("batch");
  text(app, "--plots", "FILE.csv", "batch",
       "write what the model recorded with proxy.plot, a column per series (the first: the step)", o.plots_path);
  with_value(app, "--pick", "LABEL", "batch",
             "print the vertex with this label (properties, neighbourhood, half-edge records) after the steps; "
             "repeatable",
             [&o](const std::string& v) {
               o.picks.push_back(static_cast<unsigned>(number(v, 1, 0xffffffffull, "--pick needs a vertex label (1 or more)")));
             });
  with_value(app, "--step-timeout", "S", "batch", "end a block that runs longer than S seconds, as an error",
             [&o](const std::string& v) {
               if (v.empty()) throw usage_error{"--step-timeout needs a number of seconds"};
               char* end = nullptr;
               o.step_timeout = std::strtod(v.c_str(), &end);
               if (*end || !(o.step_timeout > 0) || o.step_timeout > 1e6)
                 throw usage_error{"--step-timeout needs a number of seconds greater than 0"};
             });
  flag(app, "--in-process", "batch",
       "run the model in this process, unsupervised (a crash then ends the interpreter; for profilers)",
       o.in_process);
  flag(app, "--quiet", "batch", "no progress or summary lines", o.quiet);
}

void model_options(CLI::App& app, options& o) {
  with_value(app, "--set", "NAME=VALUE", "model", "give the parameter NAME (a `param` of the program) this value; repeatable",
             [&o](const std::string& v) {
               std::size_t eq = v.find('=');
               if (eq == std::string::npos || eq == 0) throw usage_error{"--set needs NAME=VALUE, e.g. --set rate=0.5"};
               o.parameter_values.emplace_back(v.substr(0, eq), v.substr(eq + 1));
             });
  with_value(app, "--mesh", "NAME[,NAME]", "model", "the global meshes to export or draw, as one (default: the first)",
             [&o](const std::string& v) {
               if (v.empty()) throw usage_error{"--mesh needs a value"};
               o.meshes.clear();
               for (std::size_t from = 0, comma; from <= v.size(); from = comma + 1) {
                 comma = v.find(',', from);
                 if (comma == std::string::npos) comma = v.size();
                 if (comma == from) throw usage_error{"--mesh needs names separated by commas, e.g. --mesh J,C"};
                 o.meshes.push_back(v.substr(from, comma - from));
               }
             });
  with_value(app, "--max-face", "N", "model", "face orbits longer than N are holes, not faces", [&o](const std::string& v) {
    o.max_face = number(v, 3, ~0ull, "--max-face needs a number of corners (3 or more)");
  });
  with_value(app, "--seed", "S", "model", "seed of the model's random numbers (default 0)", [&o](const std::string& v) {
    o.seed = number(v, 0, ~0ull, "--seed needs a non-negative number");
  });
  flag(app, "--strict", "model",
       "reading the old state of a never-synchronised vertex is an error, and a parallel forall runs in order, "
       "checking that each iteration changes only its own vertex's properties",
       o.strict);
  with_value(app, "--threads", "N", "model",
             "threads of a parallel forall (default: the machine's cores); the results do not depend on it",
             [&o](const std::string& v) {
               o.threads = static_cast<unsigned>(number(v, 1, 1024, "--threads needs a number of threads (1 to 1024)"));
             });
  flag(app, "--check", "model",
       "after start and every step, check every global mesh's neighbourhoods and stop at the first broken one, "
       "naming the line that last edited it",
       o.check);
  text(app, "--color-by", "NAME", "model", "colour the drawing by a numeric vertex property (with a colour bar)",
       o.color_by);
}

void viewer_options(CLI::App& app, options& o) {
  text(app, "--script", "FILE", "viewer", "run the commands in FILE, one per line (listed below)", o.script);
  text(app, "--frames", "DIR", "viewer", "where proxy.record_frame writes frame_NNNNN.png (default ./frames)", o.frames);
}

void building_options(CLI::App& app, options& o) {
  text(app, "--cache", "DIR", "building", "compiled models (default $VV_CACHE_DIR or ~/.cache/vv)", o.cache);
  with_value(app, "--opt", "N", "building", "optimisation level for models (0-3, default $VV_OPT or 1)", [&o](const std::string& v) {
    o.optimization = static_cast<int>(number(v, 0, 3, "--opt needs a level from 0 to 3"));
  });
  flag(app, "--rebuild", "building",
       "compile the model even when the cache holds it (batch, --compile-only; the viewer has its Recompile button)",
       o.rebuild);
  flag(app, "--debug", "building", "build the model with -g -O0 and run it in this process, for gdb", o.debug);
  flag(app, "--expect-edits", "building",
       "compile the declarations apart from the first build, as the viewer does, so that the first edit compiles "
       "only the program (batch and --compile-only otherwise do that only on an idle core, or once the file changes)",
       o.expect_edits);
}

// Everything the parser knows, in the order --help lists it.
void register_options(CLI::App& app, options& o, std::vector<std::string>& models) {
  modes(app, o);
  batch_options(app, o);
  model_options(app, o);
  viewer_options(app, o);
  building_options(app, o);
  add_sweep_options(app, o.sweep);  // the section "experiments"
  answers(app);
  app.add_option("model", models);
  app.allow_extras();  // unknown options are named by check_whole
}

// What --every, {step} and a movie need of each other: "" or why not.
std::string series_problem(const options& o) {
  const std::string every = "--every " + std::to_string(o.every);
  bool movie = series_file_of(o.screenshot) == series_file::movie;
  if (movie && has_step_mark(o.screenshot))
    return "--screenshot " + o.screenshot + ": a movie is one file; leave {step} out of its name";
  if (movie && !o.every)
    return "--screenshot " + o.screenshot + ": a movie needs --every K (a frame after start and every K steps)";
  if (!o.every) return "";
  if (!o.batch)
    return every + " is for --batch; the viewer records series with its Record section or the script command "
                   "record";
  if (o.export_path.empty() && o.screenshot.empty())
    return every + " writes the files of --export and --screenshot every " + std::to_string(o.every) +
           " steps; give one of them, with {step} in its name (e.g. --export mesh-{step}.vtp)";
  const std::pair<const char*, const std::string*> files[] = {{"--export", &o.export_path},
                                                              {"--screenshot", &o.screenshot}};
  for (const auto& [option, name] : files)
    if (!name->empty() && !has_step_mark(*name) && !(name == &o.screenshot && movie))
      return every + ": " + option + " " + *name +
             " has no {step} in its name, so each file would replace the one before; write it as " +
             with_step_mark(*name);
  return "";
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
  if (!o.batch && !o.checkpoint.empty())
    throw usage_error{"--checkpoint is for --batch (the viewer saves checkpoints with its panel or the command "
                      "checkpoint FILE)"};
  if (!o.batch && (!o.replay.empty() || !o.events_at.empty()))
    throw usage_error{"--replay, --action and --pick-action are for --batch (the viewer runs a session with --script)"};
  if (std::string why = series_problem(o); !why.empty()) throw usage_error{why};
}

// One option's line(s) of the help: its names and value, then what it does,
// wrapped at 79 columns.
std::string help_line(const CLI::Option& opt) {
  std::string names = opt.get_name(false, true);
  std::string head = "  " + names + (opt.get_option_text().empty() ? "" : " " + opt.get_option_text());
  const std::size_t indent = 22, width = 79;
  std::string out = head;
  std::size_t column = head.size();
  if (column + 1 >= indent) out += "\n" + std::string(indent, ' '), column = indent;
  else out += std::string(indent - column, ' '), column = indent;
  std::string word, what = opt.get_description() + " ";
  bool first = true;
  for (char ch : what) {
    if (ch != ' ') {
      word += ch;
      continue;
    }
    if (!first && column + 1 + word.size() > width) out += "\n" + std::string(indent, ' '), column = indent, first = true;
    out += (first ? "" : " ") + word;
    column += (first ? 0 : 1) + word.size();
    first = false;
    word.clear();
  }
  return out + "\n";
}

}  // namespace

std::string usage_text() {
  CLI::App app("", "vvinterpreter");
  options o;
  std::vector<std::string> models;
  register_options(app, o, models);
  std::string out = synopsis;
  for (const char* section : sections) {
    out += std::string("\n") + section + ":\n";
    for (const CLI::Option* opt : app.get_options())
      if (opt->get_group() == section) out += help_line(*opt);
  }
  return out;
}

parse_result parse_options(int argc, const char* const* argv) {
  parse_result r;
  CLI::App app("", "vvinterpreter");
  std::vector<std::string> models;
  register_options(app, r.opts, models);
  try {
    // $VV_OPT gives the default level (a test suite's quick builds, a
    // cluster profile's); --opt overrides it.
    if (const char* level = std::getenv("VV_OPT"); level && *level)
      r.opts.optimization = static_cast<int>(number(level, 0, 3, "VV_OPT needs a level from 0 to 3"));
    if (const char* cores = std::getenv("VV_BUILD_CORES"); cores && *cores)
      r.opts.build_cores = static_cast<unsigned>(number(cores, 1, 4096, "VV_BUILD_CORES needs a number of cores (1 or more)"));
    app.parse(argc, argv);
    check_whole(app, models, r.opts);
    r.ok = true;
  } catch (const answered& a) {
    r.ok = r.exit_now = true;
    r.message = a.text;
  } catch (const usage_error& e) {
    r.message = "vvinterpreter: " + e.message + "\n" + usage_text();
  } catch (const CLI::ParseError& e) {
    r.message = std::string("vvinterpreter: ") + e.what() + "\n" + usage_text();
  }
  return r;
}

}  // namespace vvi
