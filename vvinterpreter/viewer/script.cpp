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
};

}  // namespace

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
