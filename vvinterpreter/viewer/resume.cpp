#include "viewer/resume.hpp"

#include <sstream>

#include "runner/fault_guard.hpp"

namespace vvi {

void viewer_state::hear(const std::string& line) {
  std::istringstream in(line);
  std::string state, key;
  if (!(in >> state >> key) || state != "state") return;
  std::string rest;
  std::getline(in >> std::ws, rest);
  std::istringstream words(rest);
  if (key == "up") {
    up = true;
  } else if (key == "quitting") {
    quitting = true;
  } else if (key == "model") {
    words >> model_steps;
    std::getline(words >> std::ws, model_plugin);
    trying_plugin.clear();
  } else if (key == "trying") {
    trying_plugin = rest;
  } else if (key == "tried") {
    trying_plugin.clear();
  } else if (key == "camera") {
    camera = rest;
  } else if (key == "window") {
    words >> window[0] >> window[1] >> window[2] >> window[3];
  } else if (key == "script") {
    words >> script_pos;
  } else if (key == "shots") {
    words >> screenshots;
  } else if (key == "replay") {
    words >> replay;
  } else if (key == "stopped") {
    words >> stopped_activity;
    std::getline(words >> std::ws, stopped);
  }
}

void tell_supervisor(const std::string& key, const std::string& value) {
  fault_guard::send("state " + key + (value.empty() ? "" : " " + value));
}

}  // namespace vvi
