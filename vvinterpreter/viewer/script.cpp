#include "viewer/script.hpp"

#include <cctype>
#include <map>
#include <sstream>

namespace vvi {

namespace {

// The commands that take no arguments.
const std::map<std::string, script_command::kind_t> plain_commands = {
    {"run", script_command::run},       {"rewind", script_command::rewind},
    {"end", script_command::end},       {"reread", script_command::reread},
    {"recompile", script_command::recompile}, {"fit", script_command::fit},
    {"stop", script_command::stop},     {"quit", script_command::quit},
    {"save-params", script_command::save_params},
};

// What `show` switches.
const char* const shown_things[] = {"faces", "edges", "points", "flat", "back-faces", "auto-fit"};

}  // namespace

const char* const script_help =
    "  step [N]              run N steps (default 1)\n"
    "  run                   run the proxy's number of steps\n"
    "  rewind                start again from a fresh instance\n"
    "  end                   run the end block\n"
    "  reread                reread the model's files (util::Function, Palette, ...)\n"
    "  recompile             rebuild and reload the model\n"
    "  fit                   fit the view to the model\n"
    "  screenshot FILE.png   save the view without the panel\n"
    "  window-screenshot F   save the whole window, panel included\n"
    "  export MESH FILE      write a global mesh (.vvm .obj .off .ply .stl)\n"
    "  rotate DX DY          turn the view by degrees\n"
    "  zoom F                come closer by the factor F\n"
    "  wait MS               pause, beside a running step\n"
    "  stop                  end a step that runs long (the model restarts at its last good state)\n"
    "  pick LABEL            select the vertex with this label and print it to stdout\n"
    "  set NAME=VALUE        set a parameter (a `param` of the program)\n"
    "  save-params           write the parameters' values into their lines of the .vvp\n"
    "  color-by NAME|none    colour by a numeric vertex property, or not\n"
    "  show WHAT on|off      faces, edges, points, flat, back-faces, auto-fit\n"
    "  plots FILE.csv        write the proxy.plot series\n"
    "  quit                  close the window\n";

std::vector<script_command> parse_script(const std::string& text, const std::string& name, std::string& error) {
  std::vector<script_command> out;
  std::istringstream lines(text);
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n) {
    // A '#' that starts a word starts a comment (to the end of the line).
    for (std::size_t at = line.find('#'); at != std::string::npos; at = line.find('#', at + 1))
      if (at == 0 || std::isspace(static_cast<unsigned char>(line[at - 1]))) {
        line.erase(at);
        break;
      }
    std::istringstream words(line);
    std::string word;
    if (!(words >> word)) continue;
    script_command c;
    c.line = n;
    auto bad = [&](const std::string& what) {
      error = name + ":" + std::to_string(n) + ": " + what;
      return std::vector<script_command>();
    };
    bool ok = true;
    if (word == "step") {
      c.kind = script_command::step;
      if (!(words >> c.count)) c.count = 1;
      ok = c.count >= 1;
    } else if (word == "wait") {
      c.kind = script_command::wait;
      ok = static_cast<bool>(words >> c.count) && c.count >= 0;
    } else if (word == "rotate") {
      c.kind = script_command::rotate;
      ok = static_cast<bool>(words >> c.a >> c.b);
    } else if (word == "zoom") {
      c.kind = script_command::zoom;
      ok = static_cast<bool>(words >> c.a) && c.a > 0;
    } else if (word == "screenshot") {
      c.kind = script_command::screenshot;
      ok = static_cast<bool>(words >> c.path);
    } else if (word == "window-screenshot") {
      c.kind = script_command::window_screenshot;
      ok = static_cast<bool>(words >> c.path);
    } else if (word == "export") {
      c.kind = script_command::export_mesh;
      ok = static_cast<bool>(words >> c.mesh >> c.path);
    } else if (word == "pick") {
      c.kind = script_command::pick;
      ok = static_cast<bool>(words >> c.count) && c.count >= 1;
    } else if (word == "set") {
      c.kind = script_command::set;
      std::string assignment;
      std::size_t eq = 0;
      ok = static_cast<bool>(words >> assignment) && (eq = assignment.find('=')) != std::string::npos && eq > 0;
      if (ok) c.name = assignment.substr(0, eq), c.value = assignment.substr(eq + 1);
    } else if (word == "color-by") {
      c.kind = script_command::color_by;
      ok = static_cast<bool>(words >> c.name);
      if (c.name == "none") c.name.clear();
    } else if (word == "show") {
      c.kind = script_command::show;
      ok = static_cast<bool>(words >> c.name >> c.value) && (c.value == "on" || c.value == "off");
      bool known = false;
      for (const char* thing : shown_things) known = known || c.name == thing;
      ok = ok && known;
    } else if (word == "plots") {
      c.kind = script_command::plots;
      ok = static_cast<bool>(words >> c.path);
    } else if (auto plain = plain_commands.find(word); plain != plain_commands.end()) {
      c.kind = plain->second;
    } else {
      return bad("unknown command '" + word + "'");
    }
    std::string extra;
    if (!ok) return bad("bad arguments for '" + word + "'");
    if (words >> extra) return bad("unexpected '" + extra + "' after '" + word + "'");
    out.push_back(c);
  }
  return out;
}

}  // namespace vvi
