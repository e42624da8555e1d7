#include "compile/model_build.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <sstream>
#include <unistd.h>

#include "compile/build_config.hpp"
#include "app/files.hpp"
#include "compile/hashing.hpp"
#include "compile/compiler_messages.hpp"
#include "compile/process.hpp"
#include "translate.hpp"

namespace vvi {

namespace fs = std::filesystem;

namespace {

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// A sanitizer build of the interpreter instruments the models it compiles
// too, unless VV_SANITIZE_MODELS=0: the host stays instrumented, and a
// model compiles in half the time (the test suite's host tests use this;
// its example runs keep instrumented models).
bool instrument_models() {
  const char* setting = std::getenv("VV_SANITIZE_MODELS");
  return setting == nullptr || std::string(setting) != "0";
}

// The options every model and the precompiled header share (they must
// match for the header to be used).
std::vector<std::string> common_flags(const build_settings& s, const std::string& include) {
  // Line tables always (crash reports name .vvp lines); --debug: all of it.
  std::vector<std::string> f = {"-std=c++17", s.debug ? "-O0" : "-O" + std::to_string(s.optimization),
                                s.debug ? "-g" : "-g1", "-fPIC",
                                "-fvisibility=hidden", "-fvisibility-inlines-hidden",
                                // so that unloading a model really unloads it (rewind, reload)
                                "-fno-gnu-unique"};
  std::istringstream extra(instrument_models() ? config::sanitize_flags : "");
  for (std::string w; extra >> w;) f.push_back(w);
  f.push_back("-isystem");
  f.push_back(include);
  return f;
}

// A stamp of the vvlib headers: any change to them makes new builds.
std::string headers_stamp(const std::string& include) {
  content_hash h;
  std::vector<std::string> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(include, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    if (it->is_regular_file() && it->path().extension() == ".hpp") files.push_back(it->path().string());
  std::sort(files.begin(), files.end());
  for (const std::string& f : files) h.add(f).add(read_file(f).value_or(""));
  return h.hex();
}

std::string join(const std::vector<std::string>& argv) {
  std::string s;
  for (const std::string& a : argv) s += (s.empty() ? "" : " ") + a;
  return s;
}

// Builds the precompiled vv/plugin/model.hpp for these flags, once per cache.
std::string precompiled_header_dir(const build_settings& s, const std::string& include,
                                   const std::string& stamp, std::string& error) {
  std::vector<std::string> flags = common_flags(s, include);
  std::string key = content_hash().add(config::cxx_compiler).add(join(flags)).add(stamp).hex();
  std::string dir = s.cache_dir + "/pch/" + key;
  std::string gch = dir + "/vv/plugin/model.hpp.gch";
  if (fs::exists(gch)) return dir;
  std::error_code ec;
  fs::create_directories(dir + "/vv/plugin", ec);
  std::string tmp = gch + ".tmp" + std::to_string(getpid());
  std::vector<std::string> argv = {config::cxx_compiler};
  argv.insert(argv.end(), flags.begin(), flags.end());
  argv.insert(argv.end(), {"-x", "c++-header", include + "/vv/plugin/model.hpp", "-o", tmp});
  process_result r = run_process(argv);
  if (r.status != 0) {
    fs::remove(tmp, ec);
    error = "cannot precompile vv/plugin/model.hpp:\n" + r.output;
    return "";
  }
  fs::rename(tmp, gch, ec);  // another process may have won the race: either copy is good
  return dir;
}

// The files a plugin was built from, other than vvlib's and the system's,
// with their content hashes (to tell whether a cached build is still good).
std::string dependency_list(const std::string& depfile, const std::string& include) {
  std::string text = read_file(depfile).value_or("");
  std::string out;
  std::istringstream words(text);
  for (std::string w; words >> w;) {
    if (w == "\\" || ends_with(w, ":") || w.rfind(include, 0) == 0 || w.rfind("/usr/", 0) == 0) continue;
    if (!ends_with(w, ".cpp")) out += content_hash().add(read_file(w).value_or("")).hex() + " " + w + "\n";
  }
  return out;
}

bool dependencies_unchanged(const std::string& list) {
  std::istringstream lines(list);
  for (std::string hash, path; lines >> hash >> path;)
    if (content_hash().add(read_file(path).value_or("")).hex() != hash) return false;
  return true;
}

}  // namespace

std::string vvlib_include_dir() {
  // Installed: PREFIX/bin/vvinterpreter beside PREFIX/include/vv-1, whatever
  // the prefix (cmake --install --prefix may differ from the configured one).
  fs::path bin = executable_dir();
  fs::path installed = bin.parent_path() / "include" / "vv-1";
  std::error_code ec;
  if (bin.filename() == "bin" && fs::exists(installed / "vv" / "plugin" / "model.hpp", ec)) return installed.string();
  return config::build_tree_include;
}

std::string vvlib_library_dir() {
  fs::path bin = executable_dir();
  fs::path installed = bin.parent_path() / "lib";
  if (vvlib_include_dir() != config::build_tree_include) return installed.string();
  return config::build_tree_lib;
}

bool is_plugin_file(const std::string& path) {
  // Only a regular file can be a plugin; peeking into a pipe would eat the
  // beginning of a model given as <(...).
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  return in.read(magic, 4) && magic[0] == 0x7f && magic[1] == 'E' && magic[2] == 'L' && magic[3] == 'F';
}

namespace {

// The user headers a build read, from its dependency list.
std::vector<std::string> dependency_paths(const std::string& list) {
  std::vector<std::string> out;
  std::istringstream lines(list);
  for (std::string hash, path; lines >> hash >> path;) out.push_back(path);
  return out;
}

std::string unique_build_id() {
  auto ns = std::chrono::steady_clock::now().time_since_epoch().count();
  return std::to_string(getpid()) + "-" + std::to_string(ns);
}

bool process_alive(const std::string& pid_text) {
  long pid = std::strtol(pid_text.c_str(), nullptr, 10);
  return pid > 0 && (kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH);
}

// Work folders of compiles that were killed ("tmp-KEY-PID").
void remove_stale_work(const std::string& plugins) {
  std::error_code ec;
  for (auto it = fs::directory_iterator(plugins, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (name.rfind("tmp-", 0) != 0) continue;
    std::string pid = name.substr(name.rfind('-') + 1);
    std::error_code rm;
    if (!process_alive(pid)) fs::remove_all(it->path(), rm);
  }
}

// Makes `link` (the cache key) name the build in `target` (a sibling
// folder), replacing what it named before in one rename: a reader sees the
// old build or the new one, never neither. Older builds of the key go.
void publish(const std::string& plugins, const std::string& key, const std::string& target) {
  std::error_code ec;
  std::string link = plugins + "/" + key;
  std::string tmp_link = plugins + "/link-" + unique_build_id();
  fs::create_directory_symlink(target, tmp_link, ec);
  if (fs::is_directory(fs::symlink_status(link, ec))) fs::remove_all(link, ec);  // an older cache's layout
  fs::rename(tmp_link, link, ec);
  for (auto it = fs::directory_iterator(plugins, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    std::string name = it->path().filename().string();
    std::error_code rm;
    if (name.rfind(key + ".", 0) == 0 && name != target) fs::remove_all(it->path(), rm);
  }
}

}  // namespace

build_result build_model(const std::string& path, const build_settings& s) {
  build_result r;
  if (is_plugin_file(path)) {  // a prebuilt plugin
    r.ok = true;
    r.plugin = fs::absolute(path).string();
    r.cached = true;
    return r;
  }

  auto t0 = std::chrono::steady_clock::now();
  std::string unreadable;
  vvc::translation t = vvc::translate_file(path, &unreadable);
  r.translate_ms = ms_since(t0);
  r.sources = t.sources.paths();
  if (!t.ok) {
    if (!unreadable.empty()) {
      r.error = path + ": error: cannot read the model: " + unreadable;
      r.details = r.error + "\n";
      return r;
    }
    for (const auto& d : t.diag.list()) r.details += vvc::format(d);
    r.error = r.details.substr(0, r.details.find('\n'));
    return r;
  }

  std::string include = vvlib_include_dir();
  std::string stamp = headers_stamp(include);
  std::vector<std::string> flags = common_flags(s, include);
  std::string model_dir = absolute_folder_of(path);
  std::string key = content_hash()
                        .add(vvc::version())
                        .add(config::cxx_compiler)
                        .add(join(flags))
                        .add(stamp)
                        .add(model_dir)
                        .add(t.cpp)
                        .hex();
  std::string plugins = s.cache_dir + "/plugins";
  std::error_code ec;
  // The build the key names now, resolved once: a rebuild may replace it.
  fs::path entry = fs::canonical(plugins + "/" + key, ec);
  if (!s.force && !ec && fs::exists(entry / "model.so")) {
    std::string deps = read_file((entry / "deps").string()).value_or("");
    if (dependencies_unchanged(deps)) {
      r.ok = true;
      r.cached = true;
      r.plugin = (entry / "model.so").string();
      r.cpp = (entry / "model.cpp").string();
      r.warnings = read_file((entry / "warnings").string()).value_or("");
      for (const std::string& h : dependency_paths(deps)) r.sources.push_back(h);
      return r;
    }
  }

  if (s.compiling) s.compiling();
  auto t1 = std::chrono::steady_clock::now();
  std::string pch_error;
  std::string pch = precompiled_header_dir(s, include, stamp, pch_error);
  fs::create_directories(plugins, ec);
  remove_stale_work(plugins);
  std::string work = plugins + "/tmp-" + key + "-" + std::to_string(getpid());
  fs::remove_all(work, ec);
  fs::create_directories(work, ec);
  if (ec || !write_file(work + "/model.cpp", t.cpp)) {
    r.error = plugins + ": error: cannot write to the model cache";
    return r;
  }
  std::vector<std::string> argv = {config::cxx_compiler};
  argv.insert(argv.end(), flags.begin(), flags.end());
  if (!pch.empty()) argv.insert(argv.begin() + 1, {"-I", pch});
  // The polygon formats come compiled, from vv_formats (M.readFile("x.obj")).
  std::string lib = vvlib_library_dir();
  argv.insert(argv.end(), {"-Wall", "-Wextra", "-I", model_dir, "-shared", "-MD", "-MF", work + "/model.d",
                           "-o", work + "/model.so", work + "/model.cpp", "-L", lib, "-Wl,-rpath," + lib,
                           "-lvv_formats", "-lpugixml", "-lGL"});
  process_result c = run_process(argv);
  r.compile_ms = ms_since(t1);
  std::string about_model = compiler_messages(c.output, include, t.cpp);
  if (c.status != 0) {
    r.details = about_model.empty() ? c.output : about_model;
    // The first message that is an error ("f:12:3: error: ..."); failing
    // that, any line that says error (a linker's).
    for (const char* mark : {": error:", "error"}) {
      std::istringstream lines(r.details);
      for (std::string line; r.error.empty() && std::getline(lines, line);)
        if (line.find(mark) != std::string::npos) r.error = line;
    }
    if (r.error.empty()) r.error = path + ": error: the C++ compiler failed (" + config::cxx_compiler + ")";
    fs::remove_all(work, ec);
    return r;
  }
  std::string deps = dependency_list(work + "/model.d", include);
  write_file(work + "/deps", deps);
  write_file(work + "/command", join(argv) + "\n");  // how it was built, for whoever looks
  write_file(work + "/warnings", about_model);
  // Every build gets a folder of its own, so what a process loaded is never
  // overwritten; the key then names the newest.
  std::string target = key + "." + unique_build_id();
  fs::rename(work, plugins + "/" + target, ec);
  if (ec) {
    fs::remove_all(work, ec);
    r.error = plugins + ": error: cannot store the compiled model in the cache";
    return r;
  }
  publish(plugins, key, target);
  r.ok = true;
  r.plugin = plugins + "/" + target + "/model.so";
  r.cpp = plugins + "/" + target + "/model.cpp";
  r.warnings = about_model;
  for (const std::string& h : dependency_paths(deps)) r.sources.push_back(h);
  return r;
}

}  // namespace vvi
