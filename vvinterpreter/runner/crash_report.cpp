#include "runner/crash_report.hpp"

#include <signal.h>
#include <string.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "compile/process.hpp"

namespace vvi {

namespace {

struct mapping {
  std::uintptr_t start = 0, end = 0, offset = 0;
  std::string path;
};

std::vector<mapping> parse_maps(const std::vector<std::string>& lines) {
  std::vector<mapping> out;
  for (const std::string& l : lines) {
    mapping m;
    std::istringstream in(l);
    std::string range, perms, offset, dev, inode;
    if (!(in >> range >> perms >> offset >> dev >> inode)) continue;
    std::getline(in >> std::ws, m.path);
    const std::string deleted = " (deleted)";
    if (m.path.size() > deleted.size() && m.path.compare(m.path.size() - deleted.size(), deleted.size(), deleted) == 0)
      m.path.erase(m.path.size() - deleted.size());
    std::size_t dash = range.find('-');
    if (dash == std::string::npos) continue;
    m.start = std::strtoull(range.substr(0, dash).c_str(), nullptr, 16);
    m.end = std::strtoull(range.substr(dash + 1).c_str(), nullptr, 16);
    m.offset = std::strtoull(offset.c_str(), nullptr, 16);
    out.push_back(m);
  }
  return out;
}

bool is_model_source(const std::string& file) {
  return file.size() > 4 && file.compare(file.size() - 4, 4, ".vvp") == 0;
}

// vvc names block bodies vv_block_NAME; the compiler names the code that
// initialises globals after the file.
std::string readable_function(const std::string& f) {
  const std::string block = "vv_block_";
  if (f.rfind(block, 0) == 0) return "the " + f.substr(block.size(), f.find('(') - block.size()) + " block";
  if (f.rfind("_GLOBAL__sub_I", 0) == 0 || f.rfind("__static_initialization_and_destruction", 0) == 0)
    return "a global initialiser";
  return f;
}

// A path the user recognises: relative to the working folder when inside it.
std::string tidy_path(const std::string& file) {
  std::error_code ec;
  std::string cwd = std::filesystem::current_path(ec).string();
  if (!ec && file.rfind(cwd + "/", 0) == 0) return file.substr(cwd.size() + 1);
  return file;
}

// addr2line -a prints each address, then function / file:line pairs (more
// than one when calls were inlined, innermost first).
std::vector<source_frame> lookup(const std::string& file, const std::vector<std::uintptr_t>& addresses) {
  std::vector<std::string> argv = {"addr2line", "-a", "-f", "-C", "-i", "-e", file};
  for (std::uintptr_t a : addresses) {
    char hex[32];
    std::snprintf(hex, sizeof hex, "0x%llx", static_cast<unsigned long long>(a));
    argv.push_back(hex);
  }
  process_result r = run_process(argv);
  std::vector<source_frame> out;
  if (r.status != 0) return out;
  std::istringstream lines(r.output);
  std::string l, function;
  bool want_function = true;
  while (std::getline(lines, l)) {
    if (l.rfind("0x", 0) == 0 && want_function) continue;  // the address line
    if (want_function) {
      function = l;
      want_function = false;
      continue;
    }
    want_function = true;
    std::size_t colon = l.rfind(':');
    if (colon == std::string::npos) continue;
    source_frame f;
    f.function = readable_function(function);
    f.file = l.substr(0, colon);
    f.line = static_cast<unsigned>(std::strtoul(l.c_str() + colon + 1, nullptr, 10));
    if (f.line > 0 && is_model_source(f.file)) {
      f.file = tidy_path(f.file);
      out.push_back(f);
    }
  }
  return out;
}

}  // namespace

std::vector<source_frame> model_frames(const std::vector<std::uintptr_t>& code_addresses,
                                       const std::vector<std::string>& maps_lines,
                                       const std::map<std::string, std::string>& modules) {
  std::vector<mapping> maps = parse_maps(maps_lines);
  std::vector<source_frame> out;
  for (std::uintptr_t a : code_addresses) {
    for (const mapping& m : maps) {
      if (a < m.start || a >= m.end) continue;
      auto module = modules.find(m.path);
      if (module == modules.end()) break;  // not a model: vvlib inlined into it is, the rest is not
      std::vector<source_frame> found = lookup(module->second, {a - m.start + m.offset});
      out.insert(out.end(), found.begin(), found.end());
      break;
    }
  }
  return out;
}

std::vector<source_frame> model_stack(const child_end& end) {
  const crash_info& c = end.crash;
  // The frames before the faulting instruction are the handler's own.
  std::size_t first = 0;
  for (std::size_t i = 0; i < c.frames.size(); ++i)
    if (c.frames[i] == c.pc) first = i;
  std::vector<std::uintptr_t> calls;
  for (std::size_t i = first; i < c.frames.size(); ++i)
    // A return address points after its call: look up the call itself.
    calls.push_back(c.frames[i] - (i == first && c.frames[i] == c.pc ? 0 : 1));
  return model_frames(calls, c.maps, end.modules);
}

std::string activity_phrase(const child_activity& a) {
  if (a.what == "step") return "in step " + std::to_string(a.step);
  if (a.what == "loading") return "while loading the model (in a global initialiser)";
  if (a.what == "render" || a.what == "render_init" || a.what == "render_screen") return "while drawing (" + a.what + ")";
  if (a.what == "replay") return "while running again to step " + std::to_string(a.step);
  if (!a.what.empty()) return "in " + a.what;
  return "";
}

crash_text describe_crash(const child_end& end, const std::string& model) {
  crash_text t;
  std::vector<source_frame> stack = model_stack(end);
  std::string where = stack.empty() ? model : stack.front().file + ":" + std::to_string(stack.front().line);
  std::string sig = end.crash.signal;
  if (sig.empty()) {  // it died without a report: killed from outside (the kernel's OOM killer, ...)
    const char* abbrev = sigabbrev_np(end.signal);
    sig = abbrev ? std::string("SIG") + abbrev : "signal " + std::to_string(end.signal);
    if (end.signal == SIGKILL) sig += " (out of memory?)";
  }
  std::string activity = activity_phrase(end.activity);
  std::string tail = activity.empty() ? "" : " " + activity;
  if (!end.crash.exception.empty()) {
    t.line = where + ": crashed with an uncaught exception (" + end.crash.exception + ")" + tail;
    t.panel = t.line;
  } else {
    t.line = where + ": crashed with " + sig + tail;
    t.panel = where + ": crashed (" + sig + ")" + tail;
  }
  // A recursion fills the stack with one frame: say it once.
  for (std::size_t i = 0; i < stack.size();) {
    const source_frame& f = stack[i];
    std::size_t same = 1;
    while (i + same < stack.size() && stack[i + same].file == f.file && stack[i + same].line == f.line &&
           stack[i + same].function == f.function)
      ++same;
    t.stack += "  " + f.file + ":" + std::to_string(f.line) + " in " + f.function + "\n";
    if (same > 1) t.stack += "  ... the same " + std::to_string(same - 1) + " more times\n";
    i += same;
  }
  if (end.crash.frames.size() >= 64 && stack.size() >= 32 && end.crash.signal == "SIGSEGV")
    t.stack += "  (the stack is full: an endless recursion?)\n";
  return t;
}

std::string describe_timeout(const child_end& end, const std::string& model, double limit_seconds) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", limit_seconds);
  std::string what = end.activity.what == "step" ? "step " + std::to_string(end.activity.step)
                     : end.activity.what.empty() ? std::string("the model")
                                                 : end.activity.what;
  return model + ": " + what + " ran longer than " + s + " s";
}

}  // namespace vvi
