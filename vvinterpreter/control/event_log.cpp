#include "control/event_log.hpp"

#include <algorithm>

#include "control/command_text.hpp"

namespace vvi {

void set_setting(std::vector<parameter_setting>& settings, const std::string& name, const std::string& text) {
  for (parameter_setting& s : settings)
    if (s.name == name) {
      s.text = text;
      return;
    }
  settings.push_back({name, "", text});
}

void event_log::append(const command& event) {
  if (event.kind == command::step && !events.empty() && events.back().kind == command::step) {
    events.back().number += event.number;
    return;
  }
  command e = event;
  e.line = 0;
  events.push_back(e);
}

unsigned long event_log::steps() const { return steps_before(events.size()); }

unsigned long event_log::steps_before(std::size_t index) const {
  unsigned long n = 0;
  for (std::size_t i = 0; i < index && i < events.size(); ++i)
    if (events[i].kind == command::step) n += events[i].number;
  return n;
}

event_log event_log::up_to(std::size_t index, unsigned long extra_steps) const {
  event_log out;
  out.initial = initial;
  out.resumed_from = resumed_from;
  for (std::size_t i = 0; i < index && i < events.size(); ++i) out.events.push_back(events[i]);
  if (extra_steps > 0 && index < events.size() && events[index].kind == command::step)
    out.append(command::steps(std::min(extra_steps, events[index].number)));
  return out;
}

std::vector<parameter_setting> event_log::settings_after() const {
  std::vector<parameter_setting> s = initial;
  for (const command& e : events)
    if (e.kind == command::set) set_setting(s, e.name, e.value);
  return s;
}

std::string event_log::text() const {
  std::string out;
  for (const parameter_setting& s : initial) out += command_text(command::named(command::set, s.name, s.text)) + "\n";
  if (!resumed_from.empty()) out += command_text(command::with_path(command::resume, resumed_from)) + "\n";
  else if (!initial.empty()) out += "rewind\n";
  for (const command& e : events) out += command_text(e) + "\n";
  return out;
}

bool event_log::parse(const std::string& text, const std::string& name, event_log& out, std::string& error) {
  std::vector<command> commands = parse_commands(text, name, error);
  if (!error.empty()) return false;
  event_log log;
  for (const command& c : commands) {
    if (c.kind == command::rewind || c.kind == command::resume) {
      log.initial = log.settings_after();
      log.events.clear();
      log.resumed_from = c.kind == command::resume ? c.path : "";
    } else if (is_event(c.kind)) {
      log.append(c);
    } else {
      error = name + ":" + std::to_string(c.line) + ": '" + command_word(c.kind) +
              "' is not one of the model's events (step, end, reread, set, action, pick-action), rewind or resume";
      return false;
    }
  }
  out = log;
  return true;
}

bool operator==(const event_log& a, const event_log& b) {
  if (a.initial.size() != b.initial.size() || a.events != b.events || a.resumed_from != b.resumed_from) return false;
  for (std::size_t i = 0; i < a.initial.size(); ++i)
    if (a.initial[i].name != b.initial[i].name || a.initial[i].text != b.initial[i].text) return false;
  return true;
}

}  // namespace vvi
