#include "control/state_record.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "runner/report_words.hpp"

namespace vvi {

bool operator==(const view_record& a, const view_record& b) {
  for (int i = 0; i < 4; ++i)
    if (a.window[i] != b.window[i]) return false;
  return a.camera == b.camera && a.faces == b.faces && a.edges == b.edges && a.points == b.points &&
         a.flat == b.flat && a.back_faces == b.back_faces && a.auto_hide_edges == b.auto_hide_edges &&
         a.auto_fit == b.auto_fit && a.color_by == b.color_by && a.picked == b.picked &&
         a.screenshots == b.screenshots;
}

namespace {

// Every field, by the name it has on the line: f(name, field) for each.
template <class Record, class F>
void each_field(Record& r, F&& f) {
  f("plugin", r.plugin);
  f("log", r.log);
  f("trying", r.trying);
  f("replaying", r.replaying);
  f("bad", r.bad_plugin);
  f("no-render", r.no_render_plugin);
  f("replay", r.replay);
  f("rewind-on-change", r.rewind_on_change);
  f("camera", r.view.camera);
  f("window", r.view.window);
  f("faces", r.view.faces);
  f("edges", r.view.edges);
  f("points", r.view.points);
  f("flat", r.view.flat);
  f("back-faces", r.view.back_faces);
  f("auto-hide-edges", r.view.auto_hide_edges);
  f("auto-fit", r.view.auto_fit);
  f("color-by", r.view.color_by);
  f("picked", r.view.picked);
  f("screenshots", r.view.screenshots);
  f("script", r.script_pos);
  f("up", r.up);
  f("quitting", r.quitting);
  f("stopped", r.stopped);
  f("stopped-activity", r.stopped_activity);
  f("restarted", r.restarted);
  f("error", r.error);
  f("note", r.note);
}

// A value in a word: '%', spaces, control characters and '=' as %XX.
std::string escaped(const std::string& s) {
  std::string out;
  for (unsigned char ch : s) {
    if (ch <= ' ' || ch == '%' || ch == '=' || ch == 0x7f) {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", ch);
      out += hex;
    } else {
      out += static_cast<char>(ch);
    }
  }
  return out;
}

std::string unescaped(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size()) {
      out += static_cast<char>(std::strtol(s.substr(i + 1, 2).c_str(), nullptr, 16));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

std::string text_of(const std::string& v) { return v; }
std::string text_of(bool v) { return v ? "1" : "0"; }
std::string text_of(long v) { return std::to_string(v); }
std::string text_of(int v) { return std::to_string(v); }
std::string text_of(unsigned v) { return std::to_string(v); }
std::string text_of(std::size_t v) { return std::to_string(v); }
std::string text_of(const event_log& v) { return v.text(); }
std::string text_of(const int (&v)[4]) {
  return std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + " " + std::to_string(v[3]);
}

void read(const std::string& t, std::string& v) { v = t; }
void read(const std::string& t, bool& v) { v = t == "1"; }
void read(const std::string& t, long& v) { v = std::strtol(t.c_str(), nullptr, 10); }
void read(const std::string& t, int& v) { v = static_cast<int>(std::strtol(t.c_str(), nullptr, 10)); }
void read(const std::string& t, unsigned& v) { v = static_cast<unsigned>(std::strtoul(t.c_str(), nullptr, 10)); }
void read(const std::string& t, std::size_t& v) { v = std::strtoull(t.c_str(), nullptr, 10); }
void read(const std::string& t, event_log& v) {
  std::string error;
  event_log::parse(t, "the state record", v, error);  // written by record_line: it reads
}
void read(const std::string& t, int (&v)[4]) {
  std::istringstream in(t);
  in >> v[0] >> v[1] >> v[2] >> v[3];
}

}  // namespace

std::string record_line(const state_record& r) {
  std::string line = report_words::state;
  each_field(r, [&](const char* name, const auto& value) { line += std::string(" ") + name + "=" + escaped(text_of(value)); });
  return line;
}

bool read_record_line(const std::string& line, state_record& out) {
  std::istringstream words(line);
  std::string word;
  if (!(words >> word) || word != report_words::state) return false;
  state_record r;
  while (words >> word) {
    std::size_t eq = word.find('=');
    if (eq == std::string::npos) continue;
    std::string key = word.substr(0, eq), value = unescaped(word.substr(eq + 1));
    each_field(r, [&](const char* name, auto& field) {
      if (key == name) read(value, field);
    });
  }
  out = r;
  return true;
}

}  // namespace vvi
