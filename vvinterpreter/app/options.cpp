#include "app/options.hpp"

#include <cstdlib>
#include <string>

#include "build/build_config.hpp"
#include "viewer/script.hpp"

namespace vvi {

const char* usage_text =
    "usage: vvinterpreter [options] MODEL.vvp\n"
    "       vvinterpreter --batch [--steps N] [--end] [--export FILE] [--mesh NAME[,NAME...]]\n"
    "                     [--max-face N] [--screenshot FILE.png --size WxH] [--seed S]\n"
    "                     [--step-timeout SECONDS] [--set NAME=VALUE ...] [--plots FILE.csv]\n"
    "                     [--pick LABEL ...] [--color-by NAME] MODEL.vvp\n"
    "       vvinterpreter --list-params [--set NAME=VALUE ...] MODEL.vvp\n"
    "       vvinterpreter --compile-only MODEL.vvp\n"
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
    "  --export FILE      write a mesh after the steps: .vvm .obj .off .ply .stl\n"
    "  --mesh NAME[,NAME] the global meshes to export or draw, as one (default: the first)\n"
    "  --step-timeout S   end a step that runs longer than S seconds, as an error (batch)\n"
    "  --max-face N       face orbits longer than N are holes, not faces\n"
    "  --screenshot FILE  render a PNG after the steps (batch: offscreen)\n"
    "  --size WxH         the screenshot's size (default 800x600)\n"
    "  --view YAW PITCH   turn the screenshot's view by these degrees (default 0 0)\n"
    "  --seed S           seed of the model's random numbers (default 0)\n"
    "  --strict           reading the old state of a never-synchronised vertex is an error\n"
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
    "  --debug            build the model with -g -O0 and run it in this process, for gdb\n"
    "  --in-process       batch: run the model in this process, unsupervised (a crash\n"
    "                     then ends the interpreter; for profilers and debuggers)\n"
    "  --quiet            no progress or summary lines\n"
    "  --help, --version\n";

namespace {

bool to_unsigned(const std::string& s, unsigned long long& out) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 19) return false;
  out = std::strtoull(s.c_str(), nullptr, 10);
  return true;
}

// The options that take a text (a path).
std::string* text_option(options& o, const std::string& name) {
  if (name == "--export") return &o.export_path;
  if (name == "--screenshot") return &o.screenshot;
  if (name == "--script") return &o.script;
  if (name == "--plots") return &o.plots_path;
  if (name == "--color-by") return &o.color_by;
  if (name == "--frames") return &o.frames;
  if (name == "--cache") return &o.cache;
  return nullptr;
}

}  // namespace

parse_result parse_options(int argc, const char* const* argv) {
  parse_result r;
  options& o = r.opts;
  auto fail = [&](const std::string& msg) {
    r.ok = false;
    r.message = "vvinterpreter: " + msg + "\n" + usage_text;
    return r;
  };
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    auto number = [&](unsigned long long& out) {
      std::string v;
      return value(v) && to_unsigned(v, out);
    };
    unsigned long long n = 0;
    std::string v;
    if (a == "--help" || a == "-h") {
      r.ok = r.exit_now = true;
      r.message = std::string(usage_text) + "\nscript commands (--script FILE):\n" + script_help;
      return r;
    } else if (a == "--version") {
      r.ok = r.exit_now = true;
      r.message = std::string("vvinterpreter ") + config::version + "\n";
      return r;
    } else if (a == "--batch") {
      o.batch = true;
    } else if (a == "--compile-only") {
      o.compile_only = true;
    } else if (a == "--strict") {
      o.strict = true;
    } else if (a == "--list-params") {
      o.list_params = true;
    } else if (a == "--set") {
      std::size_t eq = std::string::npos;
      if (!value(v) || (eq = v.find('=')) == std::string::npos || eq == 0)
        return fail("--set needs NAME=VALUE, e.g. --set rate=0.5");
      o.parameter_values.emplace_back(v.substr(0, eq), v.substr(eq + 1));
    } else if (a == "--check") {
      o.check = true;
    } else if (a == "--quiet") {
      o.quiet = true;
    } else if (a == "--end") {
      o.end_block = true;
    } else if (a == "--debug") {
      o.debug = true;
    } else if (a == "--in-process") {
      o.in_process = true;
    } else if (a == "--step-timeout") {
      char* end = nullptr;
      if (!value(v)) return fail("--step-timeout needs a number of seconds");
      o.step_timeout = std::strtod(v.c_str(), &end);
      if (v.empty() || *end || !(o.step_timeout > 0) || o.step_timeout > 1e6)
        return fail("--step-timeout needs a number of seconds greater than 0");
    } else if (a == "--mesh") {
      if (!value(v) || v.empty()) return fail("--mesh needs a value");
      o.meshes.clear();
      std::size_t from = 0;
      for (std::size_t comma; from <= v.size(); from = comma + 1) {
        comma = v.find(',', from);
        if (comma == std::string::npos) comma = v.size();
        if (comma == from) return fail("--mesh needs names separated by commas, e.g. --mesh J,C");
        o.meshes.push_back(v.substr(from, comma - from));
      }
    } else if (a == "--pick") {
      if (!number(n) || n == 0 || n > 0xffffffffull) return fail("--pick needs a vertex label (1 or more)");
      o.picks.push_back(static_cast<unsigned>(n));
    } else if (a == "--steps") {
      if (!number(n) || n > 100000000) return fail("--steps needs a count");
      o.steps = static_cast<unsigned>(n);
    } else if (a == "--max-face") {
      if (!number(n) || n < 3) return fail("--max-face needs a number of corners (3 or more)");
      o.max_face = n;
    } else if (a == "--seed") {
      if (!number(n)) return fail("--seed needs a non-negative number");
      o.seed = n;
    } else if (a == "--opt") {
      if (!number(n) || n > 3) return fail("--opt needs a level from 0 to 3");
      o.optimization = static_cast<int>(n);
    } else if (a == "--size") {
      if (!value(v)) return fail("--size needs WIDTHxHEIGHT");
      std::size_t x = v.find('x');
      unsigned long long w = 0, h = 0;
      if (x == std::string::npos || !to_unsigned(v.substr(0, x), w) || !to_unsigned(v.substr(x + 1), h) ||
          w < 1 || h < 1 || w > 16384 || h > 16384)
        return fail("--size needs WIDTHxHEIGHT, e.g. 800x600 (at most 16384 each way)");
      o.width = static_cast<int>(w), o.height = static_cast<int>(h);
    } else if (a == "--view") {
      std::string y, p;
      char* end1 = nullptr;
      char* end2 = nullptr;
      if (!value(y) || !value(p)) return fail("--view needs two angles in degrees");
      o.view_yaw = std::strtod(y.c_str(), &end1);
      o.view_pitch = std::strtod(p.c_str(), &end2);
      if (*end1 || *end2 || y.empty() || p.empty()) return fail("--view needs two angles in degrees");
    } else if (std::string* text = text_option(o, a)) {
      if (!value(v) || v.empty()) return fail(a + " needs a value");
      *text = v;
    } else if (!a.empty() && a[0] == '-') {
      return fail("unknown option " + a);
    } else if (o.model.empty()) {
      o.model = a;
    } else {
      return fail("more than one model (" + o.model + " and " + a + ")");
    }
  }
  if (o.model.empty()) return fail("no model given");
  if (o.list_params) o.batch = true;  // headless, and supervised like a batch run
  if (o.batch && !o.script.empty()) return fail("--script drives the viewer; it cannot be used with --batch");
  r.ok = true;
  return r;
}

}  // namespace vvi
