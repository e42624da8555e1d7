#include "runner/crash_report.hpp"

#include <signal.h>
#include <string.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "compile/process.hpp"
#include "compile/shared_declarations.hpp"
#include "compile/text_ends.hpp"
#include "runner/report_words.hpp"

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
    if (ends_with(m.path, deleted)) m.path.erase(m.path.size() - deleted.size());
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

// vvc names block bodies vv_block_NAME, actions vv_action_N (the report's
// first line names the action) and the pick block vv_pick_block; the
// compiler names the code that initialises globals after the file.
std::string readable_function(const std::string& f) {
  const std::string block = "vv_block_";
  if (f.rfind(block, 0) == 0) return "the " + f.substr(block.size(), f.find('(') - block.size()) + " block";
  if (f.rfind("vv_action_", 0) == 0) return "an action's block";
  if (f.rfind("vv_pick_block", 0) == 0) return "the pick block";
  // g++'s names for that code, then clang's.
  if (f.rfind("_GLOBAL__sub_I", 0) == 0 || f.rfind("__static_initialization_and_destruction", 0) == 0 ||
      f.rfind("__cxx_global_var_init", 0) == 0)
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

// What addr2line says of one address: the model's .vvp frames there
// (innermost first) and the function the address is in.
struct looked_up {
  std::vector<source_frame> frames;
  std::string function;  //!< "??" where no function is
};

// addr2line -a prints each address, then function / file:line pairs (more
// than one when calls were inlined, innermost first).
std::vector<looked_up> lookup(const std::string& file, const std::vector<std::uintptr_t>& addresses) {
  std::vector<std::string> argv = {"addr2line", "-a", "-f", "-C", "-i", "-e", file};
  for (std::uintptr_t a : addresses) {
    char hex[32];
    std::snprintf(hex, sizeof hex, "0x%llx", static_cast<unsigned long long>(a));
    argv.push_back(hex);
  }
  process_result r = run_process(argv);
  std::vector<looked_up> out;
  if (r.status != 0) return out;
  std::istringstream lines(r.output);
  std::string l, function;
  bool want_function = true;
  while (std::getline(lines, l)) {
    if (l.rfind("0x", 0) == 0 && want_function) {  // the address line: the next address's answer
      out.emplace_back();
      continue;
    }
    if (out.empty()) continue;
    if (want_function) {
      function = l;
      out.back().function = l;
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
      if (f.file.rfind(model_folder_marker, 0) == 0) f.file = in_model_folder(f.file, model_folder_of_build(file));
      f.file = tidy_path(f.file);
      out.back().frames.push_back(f);
    }
  }
  return out;
}

// The plugin file an address is in, and the address in that file; an
// empty file when the address is not in a model.
std::pair<std::string, std::uintptr_t> in_module(std::uintptr_t a, const std::vector<mapping>& maps,
                                                 const std::map<std::string, std::string>& modules) {
  for (const mapping& m : maps) {
    if (a < m.start || a >= m.end) continue;
    auto module = modules.find(m.path);
    if (module == modules.end()) break;  // not a model: vvlib inlined into it is, the rest is not
    return {module->second, a - m.start + m.offset};
  }
  return {"", 0};
}

// How far back an interrupted instruction's line is looked for.
constexpr std::uintptr_t line_search_bytes = 256;

// The frames of an interrupted instruction. The compiler gives some
// instructions no line (line 0: a vv::where stored for error messages, a
// spill): a sample that lands on one takes the line of the code just
// before it. The search ends where no function is (the padding before a
// function; a function's first instruction always has its line).
std::vector<source_frame> interrupted_frames(std::uintptr_t pc, const std::vector<mapping>& maps,
                                             const std::map<std::string, std::string>& modules) {
  auto [file, at] = in_module(pc, maps, modules);
  if (file.empty()) return {};
  std::vector<std::uintptr_t> addresses;
  for (std::uintptr_t back = 0; back <= line_search_bytes && back <= at; ++back) addresses.push_back(at - back);
  for (const looked_up& l : lookup(file, addresses)) {
    if (!l.frames.empty()) return l.frames;
    if (l.function.empty() || l.function == "??") break;
  }
  return {};
}

}  // namespace

std::vector<source_frame> model_frames(const std::vector<std::uintptr_t>& code_addresses,
                                       const std::vector<std::string>& maps_lines,
                                       const std::map<std::string, std::string>& modules) {
  std::vector<mapping> maps = parse_maps(maps_lines);
  std::vector<source_frame> out;
  for (std::uintptr_t a : code_addresses) {
    auto [file, at] = in_module(a, maps, modules);
    if (file.empty()) continue;
    for (const looked_up& l : lookup(file, {at})) out.insert(out.end(), l.frames.begin(), l.frames.end());
  }
  return out;
}

std::vector<source_frame> model_stack(const stack_sample& sample, const std::map<std::string, std::string>& modules) {
  // The frames before the interrupted instruction are the handler's own.
  std::size_t first = 0;
  for (std::size_t i = 0; i < sample.frames.size(); ++i)
    if (sample.frames[i] == sample.pc) first = i;
  std::vector<source_frame> out;
  if (first < sample.frames.size() && sample.frames[first] == sample.pc) {
    out = interrupted_frames(sample.pc, parse_maps(sample.maps), modules);
    ++first;
  }
  std::vector<std::uintptr_t> calls;
  // A return address points after its call: look up the call itself.
  for (std::size_t i = first; i < sample.frames.size(); ++i) calls.push_back(sample.frames[i] - 1);
  std::vector<source_frame> callers = model_frames(calls, sample.maps, modules);
  out.insert(out.end(), callers.begin(), callers.end());
  return out;
}

std::vector<source_frame> model_stack(const child_end& end) { return model_stack(end.crash, end.modules); }

std::string activity_phrase(const child_activity& a) {
  if (a.what == "step") return "in step " + std::to_string(a.step);
  if (a.what == "loading") return "while loading the model (in a global initialiser)";
  if (a.what == "render" || a.what == "render_init" || a.what == "render_screen") return "while drawing (" + a.what + ")";
  if (a.what == "replay") return "while running again to step " + std::to_string(a.step);
  if (!a.what.empty()) return "in " + a.what;
  return "";
}

std::string activity_name(const child_activity& a) {
  if (a.what == "step") return "step " + std::to_string(a.step);
  if (a.what == "loading") return "loading the model (its global initialisers)";
  if (a.what == "replay") return "running again to step " + std::to_string(a.step);
  if (a.what.rfind("render", 0) == 0) return "drawing (" + a.what + ")";
  // `action "Grow"`, `pick of vertex 12` (session::run_action, run_pick)
  if (a.what.rfind("action ", 0) == 0 || a.what.rfind("pick ", 0) == 0) return a.what;
  if (a.what.empty()) return "the model";
  return "the " + a.what + " block";
}

namespace {

// "model.vvp:20" from the innermost .vvp frame, or the model's name.
std::string place(const std::vector<source_frame>& stack, const std::string& model) {
  return stack.empty() ? model : stack.front().file + ":" + std::to_string(stack.front().line);
}

// The model's call stack as lines; a recursion that fills the stack with
// one frame is said once.
std::string stack_lines(const std::vector<source_frame>& stack) {
  std::string out;
  for (std::size_t i = 0; i < stack.size();) {
    const source_frame& f = stack[i];
    std::size_t same = 1;
    while (i + same < stack.size() && stack[i + same].file == f.file && stack[i + same].line == f.line &&
           stack[i + same].function == f.function)
      ++same;
    out += "  " + f.file + ":" + std::to_string(f.line) + " in " + f.function + "\n";
    if (same > 1) out += "  ... the same " + std::to_string(same - 1) + " more times\n";
    i += same;
  }
  return out;
}

std::string seconds_text(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

std::string signal_text(int sig) {
  const char* abbrev = sigabbrev_np(sig);
  return abbrev ? std::string("SIG") + abbrev : "signal " + std::to_string(sig);
}

// A signal nobody reported (SIGKILL cannot be caught): who sent it, as far
// as the system says.
std::string killer(const child_end& end) {
  if (end.signal != SIGKILL) return "";
  if (end.oom_kills > 0) return " (the kernel's out-of-memory killer killed a process meanwhile: out of memory?)";
  if (end.oom_kills == 0) return " (not by the kernel's out-of-memory killer)";
  return " (by another process, or by the kernel's out-of-memory killer: the system does not say)";
}

// "in step 2", or for a death between blocks, the file being written.
std::string where_it_was(const child_end& end) {
  std::string activity = activity_phrase(end.activity);
  if (activity.empty() && !end.writing.empty()) activity = "while writing " + end.writing.front().first;
  return activity.empty() ? "" : " " + activity;
}

std::string stop_reason(int sig) {
  switch (sig) {
    case SIGSTOP: return "the model stopped itself, or another process stopped it";
    case SIGTSTP: return "a terminal's stop (Ctrl+Z) that reached the model alone";
    case SIGTTIN: return "it read from the terminal while running in the background";
    case SIGTTOU: return "it wrote to the terminal while running in the background";
    default: return "";
  }
}

crash_text from_sample(const child_end& end, const std::string& model, const std::string& what) {
  std::vector<source_frame> stack = model_stack(end.sample, end.modules);
  crash_text t;
  t.line = place(stack, model) + ": " + what;
  t.panel = t.line;
  t.stack = stack_lines(stack);
  return t;
}

}  // namespace

crash_text describe_crash(const child_end& end, const std::string& model) {
  if (end.kind == child_end::timed_out) return describe_timeout(end, model);
  if (end.kind == child_end::stopped) return describe_stop(end, model);
  if (end.kind == child_end::exited) return describe_exit(end, model);
  crash_text t;
  std::vector<source_frame> stack = model_stack(end);
  std::string where = place(stack, model);
  std::string tail = where_it_was(end);
  if (!end.crash.exception.empty()) {
    // Raised in a shared declarations' part: its file named in the model's folder.
    std::string exception = end.crash.exception;
    if (!end.modules.empty()) exception = message_of_build(exception, end.modules.begin()->second);
    t.line = where + ": crashed with an uncaught exception (" + exception + ")" + tail;
    t.panel = t.line;
  } else if (end.crash.signal.empty()) {  // it died without a report: killed from outside
    t.line = where + ": killed by " + signal_text(end.signal) + tail + killer(end);
    t.panel = t.line;
  } else {
    t.line = where + ": crashed with " + end.crash.signal + tail;
    t.panel = where + ": crashed (" + end.crash.signal + ")" + tail;
  }
  t.stack = stack_lines(stack);
  if (end.crash.frames.size() >= 64 && stack.size() >= 32 && end.crash.signal == "SIGSEGV")
    t.stack += "  (the stack is full: an endless recursion?)\n";
  return t;
}

crash_text describe_timeout(const child_end& end, const std::string& model) {
  return from_sample(end, model,
                     activity_name(end.activity) + " ran longer than " + seconds_text(end.time_limit) + " s and was ended");
}

crash_text describe_stop(const child_end& end, const std::string& model) {
  std::string activity = activity_phrase(end.activity);
  std::string reason = stop_reason(end.signal);
  return from_sample(end, model,
                     "stopped by " + signal_text(end.signal) + (activity.empty() ? "" : " " + activity) +
                         (reason.empty() ? "" : " (" + reason + ")") + ", and ended");
}

crash_text describe_exit(const child_end& end, const std::string& model) {
  std::string status = std::to_string(end.exit_code), activity = activity_phrase(end.activity);
  if (end.sample.why == report_words::exit_call)
    return from_sample(end, model, "the model called exit(" + status + ") " + activity + ", before the run was done");
  crash_text t;  // _exit: no handler ran, so no line
  t.line = t.panel =
      model + ": the model ended its process (exit status " + status + ") " + activity + ", before the run was done";
  return t;
}

std::string describe_long_activity(const long_activity& a, const std::string& model, double limit) {
  std::vector<source_frame> stack;
  if (a.sample && a.modules) stack = model_stack(*a.sample, *a.modules);
  std::string hint = limit > 0 ? "it is stopped at " + seconds_text(limit) + " s (--step-timeout)"
                               : "--step-timeout SECONDS stops a step that runs longer";
  return place(stack, model) + ": " + activity_name(a.activity) + " has been running for " + seconds_text(a.seconds) +
         " s" + (a.waiting ? ", waiting in a system call (a sleep, or input)" : "") + "; " + hint;
}

std::string stopped_place(const child_end& end, const std::string& model) {
  if (end.sample.why != report_words::running) return model;
  return place(model_stack(end.sample, end.modules), model);
}

}  // namespace vvi
