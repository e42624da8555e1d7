#include "control/command_text.hpp"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace vvi {

namespace {

// What follows a command's word.
enum class args {
  none,
  count_or_one,   // [N], N >= 1
  count,          // N >= 0
  label,          // LABEL >= 1
  label_or_none,  // LABEL >= 1, or "none" (0)
  angles,         // DX DY
  factor,         // F > 0
  path,           // FILE
  mesh_path,      // MESH FILE
  assignment,     // NAME=VALUE
  name,           // NAME (quoted when it has spaces)
  field_or_none,  // NAME, or "none" ("")
  show,           // WHAT on|off
  on_off,         // on|off
  record,         // K FILE [DIGITS], or "off"
};

struct command_spec {
  const char* word;
  command::kind_t kind;
  args arguments;
  const char* usage;
  const char* help;
};

// The language, in the order the help lists it.
const command_spec specs[] = {
    {"step", command::step, args::count_or_one, "step [N]", "run N steps (default 1)"},
    {"run", command::run, args::none, "run", "run the proxy's number of steps"},
    {"animate", command::animate, args::none, "animate", "step continuously, proxy.delay_msec apart"},
    {"stop", command::stop, args::none, "stop",
     "end a step that runs long (the model restarts at its last good state), or the animation"},
    {"rewind", command::rewind, args::none, "rewind", "start again from a fresh instance"},
    {"resume", command::resume, args::path, "resume FILE",
     "go on from a checkpoint: a fresh instance with its state, instead of start"},
    {"end", command::end, args::none, "end", "run the end block"},
    {"reread", command::reread, args::none, "reread", "reread the model's files (util::Function, Palette, ...)"},
    {"action", command::action, args::name, "action NAME", "run the model's action NAME (quoted if it has spaces)"},
    {"pick-action", command::pick_action, args::label, "pick-action LABEL",
     "run the model's pick block on the vertex with this label"},
    {"set", command::set, args::assignment, "set NAME=VALUE", "set a parameter (a `param` of the program)"},
    {"reload", command::reload, args::none, "reload", "build the model if its files changed, and reload it"},
    {"recompile", command::recompile, args::none, "recompile", "rebuild and reload the model"},
    {"pick", command::inspect, args::label_or_none, "pick LABEL|none",
     "select the vertex with this label and print it to stdout"},
    {"export", command::export_mesh, args::mesh_path, "export MESH FILE",
     "write a global mesh (.vvm .obj .off .ply .stl .vtp)"},
    {"plots", command::plots, args::path, "plots FILE.csv", "write the proxy.plot series"},
    {"save-params", command::save_params, args::none, "save-params",
     "write the parameters' values into their lines of the .vvp"},
    {"save-session", command::save_session, args::path, "save-session FILE",
     "write the model's events, for --replay FILE"},
    {"checkpoint", command::checkpoint, args::path, "checkpoint FILE",
     "save the model's whole state, to go on from it later (resume FILE, --resume FILE)"},
    {"record", command::record, args::record, "record K FILE [DIGITS]",
     "write FILE (a mesh, .png, .mp4) now and at each step that is a multiple of K, {step} in it the step "
     "(DIGITS wide, default 5); record off: the last state, and stop"},
    {"screenshot", command::screenshot, args::path, "screenshot FILE.png", "save the view without the panel"},
    {"window-screenshot", command::window_screenshot, args::path, "window-screenshot F",
     "save the whole window, panel included"},
    {"fit", command::fit, args::none, "fit", "fit the view to the model"},
    {"rotate", command::rotate, args::angles, "rotate DX DY", "turn the view by degrees"},
    {"zoom", command::zoom, args::factor, "zoom F", "come closer by the factor F"},
    {"reset-view", command::reset_view, args::none, "reset-view", "the view as it was at first"},
    {"show", command::show, args::show, "show WHAT on|off",
     "faces, edges, points, flat, back-faces, auto-hide-edges, auto-fit"},
    {"color-by", command::color_by, args::field_or_none, "color-by NAME|none",
     "colour by a numeric vertex property, or not"},
    {"replay", command::replay, args::on_off, "replay on|off",
     "after a reload, restart or error, run the model again through its events"},
    {"rewind-on-change", command::rewind_on_change, args::on_off, "rewind-on-change on|off",
     "a parameter change runs the model again from start"},
    {"wait", command::wait, args::count, "wait MS", "pause, beside a running step"},
    {"quit", command::quit, args::none, "quit", "close the window"},
};

const char* const shown_things[] = {"faces", "edges", "points", "flat", "back-faces", "auto-hide-edges", "auto-fit"};

const command_spec* spec_of(command::kind_t k) {
  for (const command_spec& s : specs)
    if (s.kind == k) return &s;
  return nullptr;
}

// The words of a line: quoted words may hold spaces; a '#' that starts an
// unquoted word starts a comment. False on an unterminated quote.
bool split_words(const std::string& line, std::vector<std::string>& words) {
  for (std::size_t i = 0; i < line.size();) {
    if (std::isspace(static_cast<unsigned char>(line[i]))) {
      ++i;
      continue;
    }
    if (line[i] == '#') return true;
    std::string w;
    if (line[i] == '"') {
      for (++i;; ++i) {
        if (i >= line.size()) return false;
        if (line[i] == '"') break;
        if (line[i] == '\\' && i + 1 < line.size() && (line[i + 1] == '"' || line[i + 1] == '\\')) ++i;
        w += line[i];
      }
      ++i;
    } else {
      while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) w += line[i++];
    }
    words.push_back(w);
  }
  return true;
}

bool whole_number(const std::string& s, unsigned long long lo, unsigned long& out) {
  if (s.empty() || s.size() > 12 || s.find_first_not_of("0123456789") != std::string::npos) return false;
  unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  out = static_cast<unsigned long>(v);
  return v >= lo && v <= 0xffffffffull;
}

bool real_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return *end == '\0';
}

bool on_off(const std::string& s, bool& on) {
  on = s == "on";
  return s == "on" || s == "off";
}

// The arguments into the command; false when they do not fit.
bool read_arguments(args a, const std::vector<std::string>& w, command& c) {
  std::size_t n = w.size();
  switch (a) {
    case args::none: return n == 0;
    case args::count_or_one: return n == 0 || (n == 1 && whole_number(w[0], 1, c.number));
    case args::count: return n == 1 && whole_number(w[0], 0, c.number);
    case args::label: return n == 1 && whole_number(w[0], 1, c.number);
    case args::label_or_none:
      if (n == 1 && w[0] == "none") return c.number = 0, true;
      return n == 1 && whole_number(w[0], 1, c.number);
    case args::angles: return n == 2 && real_number(w[0], c.x) && real_number(w[1], c.y);
    case args::factor: return n == 1 && real_number(w[0], c.x) && c.x > 0;
    case args::path: return n == 1 && !w[0].empty() && (c.path = w[0], true);
    case args::mesh_path: return n == 2 && !w[1].empty() && (c.name = w[0], c.path = w[1], true);
    case args::assignment: {
      std::size_t eq = n == 1 ? w[0].find('=') : std::string::npos;
      if (eq == std::string::npos || eq == 0) return false;
      c.name = w[0].substr(0, eq), c.value = w[0].substr(eq + 1);
      return true;
    }
    case args::name: return n == 1 && !w[0].empty() && (c.name = w[0], true);
    case args::field_or_none: return n == 1 && (c.name = w[0] == "none" ? "" : w[0], true);
    case args::show: {
      if (n != 2 || !on_off(w[1], c.on)) return false;
      c.name = w[0];
      for (const char* thing : shown_things)
        if (c.name == thing) return true;
      return false;
    }
    case args::on_off: return n == 1 && on_off(w[0], c.on);
    case args::record: {
      if (n == 1 && w[0] == "off") return c.on = false, true;
      unsigned long digits = 0;
      if ((n != 2 && n != 3) || !whole_number(w[0], 1, c.number) || w[1].empty()) return false;
      if (n == 3 && (!whole_number(w[2], 1, digits) || digits > 20)) return false;
      c.path = w[1];
      c.digits = static_cast<unsigned>(digits);
      return true;
    }
  }
  return false;
}

// A word as the parser reads it back.
std::string word_text(const std::string& w) {
  bool plain = !w.empty() && w[0] != '#' && w[0] != '"';
  for (char ch : w) plain = plain && !std::isspace(static_cast<unsigned char>(ch));
  if (plain) return w;
  std::string q = "\"";
  for (char ch : w) q += (ch == '"' || ch == '\\') ? std::string("\\") + ch : std::string(1, ch);
  return q + "\"";
}

// The shortest text that reads back as v.
std::string number_text(double v) {
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string argument_text(args a, const command& c) {
  switch (a) {
    case args::none: return "";
    case args::count_or_one:
    case args::count:
    case args::label: return " " + std::to_string(c.number);
    case args::label_or_none: return c.number ? " " + std::to_string(c.number) : " none";
    case args::angles: return " " + number_text(c.x) + " " + number_text(c.y);
    case args::factor: return " " + number_text(c.x);
    case args::path: return " " + word_text(c.path);
    case args::mesh_path: return " " + word_text(c.name) + " " + word_text(c.path);
    case args::assignment: return " " + word_text(c.name + "=" + c.value);
    case args::name: return " " + word_text(c.name);
    case args::field_or_none: return " " + (c.name.empty() ? std::string("none") : word_text(c.name));
    case args::show: return " " + c.name + (c.on ? " on" : " off");
    case args::on_off: return c.on ? " on" : " off";
    case args::record:
      if (!c.on) return " off";
      return " " + std::to_string(c.number) + " " + word_text(c.path) + (c.digits ? " " + std::to_string(c.digits) : "");
  }
  return "";
}

}  // namespace

std::string command_help() {
  std::string out;
  for (const command_spec& s : specs) {
    std::string usage = s.usage;
    out += "  " + usage + std::string(usage.size() < 22 ? 22 - usage.size() : 0, ' ') + " " + s.help + "\n";
  }
  return out;
}

bool parse_command_line(const std::string& line, bool& found, command& out, std::string& error) {
  found = false;
  std::vector<std::string> words;
  if (!split_words(line, words)) {
    error = "a quoted word is not closed";
    return false;
  }
  if (words.empty()) return true;
  const command_spec* spec = nullptr;
  for (const command_spec& s : specs)
    if (words[0] == s.word) spec = &s;
  if (!spec) {
    error = "unknown command '" + words[0] + "'";
    return false;
  }
  command c = command::of(spec->kind);
  std::vector<std::string> rest(words.begin() + 1, words.end());
  if (!read_arguments(spec->arguments, rest, c)) {
    error = "bad arguments for '" + words[0] + "' (it takes: " + spec->usage + ")";
    if (spec->arguments == args::name && rest.size() > 1)
      error += "; a name with spaces is quoted: " + std::string(spec->word) + " \"" + rest[0] + " " + rest[1] + "\"";
    return false;
  }
  out = c;
  found = true;
  return true;
}

std::vector<command> parse_commands(const std::string& text, const std::string& name, std::string& error) {
  std::vector<command> out;
  std::istringstream lines(text);
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    bool found = false;
    command c;
    std::string problem;
    if (!parse_command_line(line, found, c, problem)) {
      error = name + ":" + std::to_string(n) + ": " + problem;
      return {};
    }
    if (!found) continue;
    c.line = n;
    out.push_back(c);
  }
  return out;
}

std::string command_text(const command& c) {
  const command_spec* spec = spec_of(c.kind);
  return spec ? spec->word + argument_text(spec->arguments, c) : "";
}

const char* command_word(command::kind_t k) {
  const command_spec* spec = spec_of(k);
  return spec ? spec->word : "";
}

}  // namespace vvi
