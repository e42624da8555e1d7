#include "compile/model_build.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <optional>
#include <sstream>

#include "app/files.hpp"
#include "compile/build_config.hpp"
#include "compile/build_cores.hpp"
#include "compile/build_history.hpp"
#include "compile/compiler_messages.hpp"
#include "compile/dependencies.hpp"
#include "compile/hashing.hpp"
#include "compile/model_cache.hpp"
#include "compile/model_compile.hpp"
#include "compile/model_path.hpp"
#include "compile/declarations_header.hpp"
#include "compile/declarations_part.hpp"
#include "compile/precompiled_header.hpp"
#include "compile/process.hpp"
#include "compile/quick_build.hpp"
#include "compile/shared_declarations.hpp"
#include "translate.hpp"

namespace vvi {

namespace fs = std::filesystem;

namespace {

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

// A sanitizer build of the interpreter instruments the models it compiles
// too, unless VV_SANITIZE_MODELS=0: the host stays instrumented, and a
// model compiles in half the time (the test suite's host tests use this;
// its example runs keep instrumented models).
bool instrument_models() {
  const char* setting = std::getenv("VV_SANITIZE_MODELS");
  return setting == nullptr || std::string(setting) != "0";
}

// Instrumented models are compiled whole: the sanitizers give every object
// state of its own (their module constructors and global descriptions).
bool instrumented(const std::vector<std::string>& flags) {
  return std::any_of(flags.begin(), flags.end(), [](const std::string& f) { return f.rfind("-fsanitize", 0) == 0; });
}

// The options every model and the precompiled header share (they must
// match for the header to be used).
std::vector<std::string> common_flags(const build_settings& s, const std::string& include) {
  // Line tables always (crash reports name .vvp lines); --debug: all of it.
  // DWARF 4: binutils 2.40's addr2line names the .cpp for a model's first code in DWARF 5.
  // The version comes first: to clang, -gdwarf-4 after -g1 means full debug information.
  std::vector<std::string> f = {"-std=c++17", s.debug ? "-O0" : "-O" + std::to_string(s.optimization),
                                "-gdwarf-4", s.debug ? "-g" : "-g1", "-fPIC",
                                "-fvisibility=hidden", "-fvisibility-inlines-hidden",
                                // parallel forall (vv/parallel.hpp)
                                "-fopenmp"};
  // So that unloading a model really unloads it (rewind, reload).
  if (!config::cxx_compiler_is_clang) f.push_back("-fno-gnu-unique");
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

}  // namespace

std::string vvlib_include_dir() {
  // Installed: PREFIX/bin/vvinterpreter beside PREFIX/include/vv-1, whatever
  // the prefix (cmake --install --prefix may differ from the configured one).
  fs::path bin = executable_dir();
  fs::path installed = bin.parent_path() / "include" / "vv-1";
  std::error_code ec;
  if (bin.filename() == "bin" && fs::exists(installed / "model" / "model.hpp", ec)) return installed.string();
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

// What a finished build holds, as its manifest lists it. The plugin is
// small enough to hash on every use (a few hundred KB: well under a
// millisecond).
const std::vector<cache::listed_file> build_files = {{"model.so", cache::check::content},
                                                     {"model.cpp", cache::check::content},
                                                     {"deps", cache::check::content},
                                                     {"warnings", cache::check::content}};

build_result failed(const std::string& path, const std::string& why) {
  build_result r;
  r.error = path + ": error: " + why;
  r.details = r.error + "\n";
  return r;
}

// The translator's messages, under the path as typed: the file is
// translated again under that name (only when translation failed).
build_result translation_failed(const std::string& path) {
  std::string unreadable;
  vvc::translation t = vvc::translate_file(path, &unreadable);
  if (!unreadable.empty()) return failed(path, "cannot read the model: " + unreadable);
  build_result r;
  r.sources = t.sources.paths();
  for (const auto& d : t.diag.list()) r.details += vvc::format(d);
  r.error = r.details.substr(0, r.details.find('\n'));
  if (r.error.empty()) r.error = path + ": error: the model cannot be translated";
  return r;
}

// The one line that says what stopped a compile: the first message that is
// an error ("f:12:3: error: ..."); failing that, any line that says error
// (a linker's).
std::string first_error(const std::string& details) {
  for (const char* mark : {": error:", "error"}) {
    std::istringstream lines(details);
    for (std::string line; std::getline(lines, line);)
      if (line.find(mark) != std::string::npos) return line;
  }
  return "";
}

// One build of a .vvp, phase by phase (build_unguarded runs them in
// order). A phase either ends the build, with its result (found in the
// cache, or an error), or leaves in the members what the next one needs.
struct model_builder {
  model_builder(const std::string& typed, const build_settings& settings) : path(typed), s(settings), where(typed) {}

  std::optional<build_result> translate();
  void name_the_build();
  std::optional<build_result> find_in_cache(const std::string& build_key);
  std::optional<build_result> quick_build();
  std::optional<build_result> prepare_work();
  build_result compile_and_store();
  build_result store(const std::string& build_key, const std::string& about_model, const std::string& commands);
  bool make_work(const std::string& build_key);
  void say_compiling() {  // once, also when a quick build gave way to g++
    if (s.compiling && !said_compiling) s.compiling();
    said_compiling = true;
  }
  bool quick_wanted() const { return s.quick && quick_builds_available() && !s.debug && !instrumented(flags); }
  //! The declarations' text without the model's folder, and its part's key.
  std::string shared_declarations() const { return declarations_without_folder(t.declarations, model_dir); }
  std::string part_key(const std::string& declarations) const {
    return content_hash()
        .add(vvc::version())
        .add(config::cxx_compiler)
        .add(command_line(flags))
        .add(stamp)
        .add(declarations_may_read_folder(declarations, model_dir) ? model_dir : "")
        // Compiled with a header whose code is apart, it links with that code.
        .add(header.codegen ? "codegen" : "")
        .add(declarations)
        .hex();
  }
  //! The quick builds' header of the declarations on the vvlib header
  //! `vvlib_pch`, found or built (niceness: that of its compiler).
  declarations_header declarations_header_on(const std::string& vvlib_pch, int niceness) const {
    declarations_header_request request =
        quick_declarations_header(s.cache_dir, include, model_dir, vvlib_pch, t.header);
    request.niceness = niceness;
    return build_declarations_header(request);
  }
  //! The file and how it is compiled, whatever its text (build_history.hpp).
  std::string history_key() const {
    return content_hash().add(model_dir).add(fs::path(where.built()).filename().string()).add(command_line(flags)).hex();
  }

  const std::string& path;
  const build_settings& s;
  build_result r;
  model_path where;
  vvc::translation t;
  std::string include, stamp, model_dir, key, plugins;
  std::vector<std::string> flags;
  std::string notes;  // what was found broken in the cache and rebuilt, a line each
  header_request header;
  std::string pch, damage, header_error;
  std::string work;  // the folder the build is made in, before it is published
  std::chrono::steady_clock::time_point t1;
  bool said_compiling = false;
  //! A quick build's header, made beside the first build's (quick_wanted).
  std::future<std::string> quick_header_made;
};

// The program in C++, with the files it was read from.
std::optional<build_result> model_builder::translate() {
  auto t0 = std::chrono::steady_clock::now();
  std::string unreadable;
  t = vvc::translate_file(where.built(), &unreadable);
  r.translate_ms = ms_since(t0);
  if (!t.ok) return translation_failed(path);
  for (const std::string& source : t.sources.paths()) r.sources.push_back(where.shown(source));
  return std::nullopt;
}

// The cache key: everything that goes into the plugin.
void model_builder::name_the_build() {
  include = vvlib_include_dir();
  stamp = headers_stamp(include);
  flags = common_flags(s, include);
  header = make_header_request(s.cache_dir, include, flags, config::cxx_compiler, config::cxx_compiler_is_clang, stamp);
  model_dir = absolute_folder_of(where.built());
  key = content_hash()
            .add(vvc::version())
            .add(config::cxx_compiler)
            .add(command_line(flags))
            .add(config::model_link_flags)
            .add(stamp)
            .add(model_dir)
            .add(t.cpp)
            .hex();
  plugins = s.cache_dir + "/plugins";
}

// A whole build under the key, none of whose own headers changed.
std::optional<build_result> model_builder::find_in_cache(const std::string& build_key) {
  std::error_code ec;
  if (!s.force) {
    // The build the key names now, resolved once: a rebuild may replace it.
    fs::path entry = fs::canonical(plugins + "/" + build_key, ec);
    std::string why;
    cache::verdict found = ec ? cache::verdict::unlisted : cache::verify(entry.string(), why);
    if (found == cache::verdict::good) {
      std::string deps = read_file((entry / "deps").string()).value_or("");
      if (dependencies_unchanged(deps)) {
        r.ok = true;
        r.cached = true;
        r.plugin = (entry / "model.so").string();
        r.cpp = (entry / "model.cpp").string();
        r.warnings = where.shown_in(read_file((entry / "warnings").string()).value_or(""));
        for (const std::string& h : dependency_paths(deps)) r.sources.push_back(h);
        return r;
      }
    } else if (found == cache::verdict::damaged) {
      notes += path + ": note: the cached build was damaged (" + why + "); compiling it again\n";
      fs::remove_all(entry, ec);
    }
  }
  return std::nullopt;
}

// What a plugin links: the faster linker where there is one, and the
// polygon formats compiled, from vv_formats (M.readFile("x.obj")).
std::vector<std::string> model_libraries() {
  std::vector<std::string> libraries;
  std::istringstream linker(config::model_link_flags);
  for (std::string w; linker >> w;) libraries.push_back(w);
  std::string lib = vvlib_library_dir();
  libraries.insert(libraries.end(), {"-L", lib, "-Wl,-rpath," + lib, "-lvv_formats", "-lpugixml", "-lGL"});
  return libraries;
}

// The header's code (precompiled_header.hpp), then model_libraries().
std::vector<std::string> libraries_with_header(const std::string& header_dir, const header_request& header) {
  std::vector<std::string> libraries = precompiled_header_link(header_dir, header);
  std::vector<std::string> rest = model_libraries();
  libraries.insert(libraries.end(), rest.begin(), rest.end());
  return libraries;
}

// After an edit, when the optimised build's declarations' part is in the
// cache: the program at -O0 with clang, linked with it (quick_build.hpp).
// Anything else, a compile error included, leaves the build to g++, whose
// messages the user is shown.
std::optional<build_result> model_builder::quick_build() {
  // --rebuild and Recompile ask for the optimised build itself.
  if (!quick_wanted() || !s.declarations_apart || s.force) return std::nullopt;
  declarations_part part = find_declarations(s.cache_dir, part_key(shared_declarations()));
  if (part.state == declarations_part::missing && !part.why.empty())  // a damaged one, removed: g++ makes it again
    notes += path + ": note: " + part.why + "; it was compiled again\n";
  if (part.state != declarations_part::usable) return std::nullopt;
  std::vector<std::string> quick = quick_flags(include);
  std::string quick_key = content_hash().add(key).add(config::quick_compiler).add(command_line(quick)).hex();
  if (std::optional<build_result> found = find_in_cache(quick_key)) {
    found->quick = true;
    return found;
  }
  say_compiling();
  t1 = std::chrono::steady_clock::now();
  header_request quick_pch = quick_header(s.cache_dir, include, stamp);
  std::string quick_damage, quick_error;
  std::string header_dir = precompiled_header_dir(quick_pch, quick_damage, quick_error);
  if (!quick_damage.empty())
    notes += path + ": note: the cached precompiled vvlib header of quick builds was damaged (" + quick_damage +
             "); it was built again\n";
  if (header_dir.empty() || !make_work(quick_key)) return std::nullopt;
  quick_job job{precompiled_header_file(header_dir, true), include, model_dir, work, part.object,
                libraries_with_header(header_dir, quick_pch)};
  // The program alone, on the header of its declarations (made by the first
  // build, or now, once); without one, the whole text.
  declarations_header declared = declarations_header_on(job.header_file, 0);
  if (!declared.damage.empty()) notes += path + ": note: " + declared.damage + "; it was built again\n";
  bool apart = declared.state == declarations_header::usable && write_file(work + "/program.cpp", t.program);
  if (apart) {
    job.header_file = declared.pch;
    job.source = "program.cpp";
    job.libraries.insert(job.libraries.begin(), declared.object);
  }
  std::vector<std::string> argv = quick_command(job);
  process_result c = run_process(argv);
  std::error_code ec;
  if (c.status != 0) {
    if (unreadable_precompiled_header(c.output)) {
      // The header of the declarations, or the vvlib header under it: the
      // one the compiler names is built again at the next edit.
      if (apart) discard_declarations_header(declared.pch);
      if (!apart || c.output.find(header_dir) != std::string::npos) discard_precompiled_header(header_dir);
    }
    fs::remove_all(work, ec);
    return std::nullopt;
  }
  r.compile_ms = ms_since(t1);
  message_sources sources{include, t.cpp, {t.fields.edge, t.fields.vertex, t.fields.mesh}};
  // The declarations' warnings were said when their header was compiled.
  std::string said = apart ? declared.warnings + c.output : c.output;
  build_result done = store(quick_key, compiler_messages(said, sources), command_line(argv) + "\n");
  done.quick = done.ok;
  return done;
}

// A work folder holding the C++, under the cache's plugins/.
bool model_builder::make_work(const std::string& build_key) {
  std::error_code ec;
  fs::create_directories(plugins, ec);
  cache::remove_leftovers(plugins);
  work = plugins + "/tmp-" + build_key + "-" + cache::unique_id();
  fs::create_directories(work, ec);
  if (ec || !write_file(work + "/model.cpp", t.cpp)) {
    fs::remove_all(work, ec);
    return false;
  }
  return true;
}

// The precompiled vvlib header, and a work folder holding the C++.
std::optional<build_result> model_builder::prepare_work() {
  say_compiling();
  t1 = std::chrono::steady_clock::now();
  if (quick_wanted()) {
    // The quick builds' header, for the edits to come: on the other core,
    // while g++ makes its own (a few seconds on one core).
    // Then, for the same edits, the header of this model's declarations,
    // at a lower priority than the build the user waits for.
    header_request quick_pch = quick_header(s.cache_dir, include, stamp);
    quick_header_made = std::async(std::launch::async, [this, quick_pch] {
      std::string damaged, error;
      std::string made = precompiled_header_dir(quick_pch, damaged, error);
      if (!made.empty() && s.declarations_apart && s.declarations_header_ahead)
        declarations_header_on(precompiled_header_file(made, true), 10);
      return made;
    });
  }
  pch = precompiled_header_dir(header, damage, header_error);
  if (!damage.empty())
    notes += path + ": note: the cached precompiled vvlib header was damaged (" + damage + "); it was built again\n";
  if (!make_work(key)) return failed(plugins, "cannot write to the model cache");
  return std::nullopt;
}

// The compiler (once more when the precompiled header proves unreadable),
// its messages in the program's terms, and the build published in the
// cache.
build_result model_builder::compile_and_store() {
  std::error_code ec;
  compile_job job;
  job.libraries = libraries_with_header(pch, header);
  job.work = work;
  job.niceness = s.in_background ? 10 : 0;
  job.cancel = s.cancel;
  job.cache_dir = s.cache_dir;
  job.include = include;
  // A part compiled with the header's code apart needs that code: without
  // the header (it could not be built), the program compiles whole.
  bool part_links = !header.codegen || !pch.empty();
  if (s.declarations_apart && !instrumented(flags) && part_links) {
    // Shared by the same declarations in any folder, unless a header they
    // include could be found in the model's (compile/shared_declarations).
    job.declarations = shared_declarations();
    job.declarations_key = part_key(job.declarations);
    // A new model's part only on a core that would otherwise be idle, or
    // for the edits to come (build_history.hpp, build_cores.hpp).
    job.make_part = s.part_from_the_first_build || compiled_before(s.cache_dir, history_key()) ||
                    idle_cores_for_a_build(s.build_cores) >= 2;
    remember_compiled(s.cache_dir, history_key());
  }
  auto compiler = [&](const std::string& header_dir) {
    std::vector<std::string> argv = {config::cxx_compiler};
    if (!header_dir.empty() && config::cxx_compiler_is_clang)
      argv.insert(argv.end(), {"-include-pch", precompiled_header_file(header_dir, true)});
    else if (!header_dir.empty())
      argv.insert(argv.end(), {"-I", header_dir});
    argv.insert(argv.end(), flags.begin(), flags.end());
    argv.insert(argv.end(), {"-Wall", "-Wextra", "-I", model_dir});
    return argv;
  };
  job.compiler = compiler(pch);
  compile_outcome compiled = compile_model(job);
  if (compiled.result.cancelled) {
    fs::remove_all(work, ec);
    r.cancelled = true;
    r.error = path + ": the build was cancelled";
    return r;
  }
  if (compiled.result.status != 0 && !pch.empty() && unreadable_precompiled_header(compiled.result.output)) {
    // Damaged in a way its size does not show: build it again, once.
    notes += path + ": note: the compiler could not read the cached precompiled vvlib header; it was built again\n";
    discard_precompiled_header(pch);
    pch = precompiled_header_dir(header, damage, header_error);
    job.compiler = compiler(pch);
    job.libraries = libraries_with_header(pch, header);
    if (pch.empty() && header.codegen) job.declarations.clear();
    compiled = compile_model(job);
  }
  std::istringstream compile_notes(compiled.notes);
  for (std::string note; std::getline(compile_notes, note);) notes += path + ": " + note + "\n";
  const process_result& c = compiled.result;
  r.compile_ms = ms_since(t1);
  message_sources sources{include, t.cpp, {t.fields.edge, t.fields.vertex, t.fields.mesh}};
  std::string about_model = compiler_messages(c.output, sources);  // in the built spelling: cached so
  if (c.status != 0) {
    r.details = where.shown_in(about_model.empty() ? plain_quotes(c.output) : about_model);
    r.error = first_error(r.details);
    if (r.error.empty()) r.error = path + ": error: the C++ compiler failed (" + config::cxx_compiler + ")";
    r.details = notes + r.details;
    fs::remove_all(work, ec);
    return r;
  }
  return store(key, about_model, compiled.commands);
}

// The compiled work folder published under the key, with what the model
// is built from and what the compiler said.
build_result model_builder::store(const std::string& build_key, const std::string& about_model,
                                  const std::string& commands) {
  std::error_code ec;
  std::string deps = dependency_list(work + "/model.d", include, s.cache_dir);
  bool stored = write_file(work + "/deps", deps) && write_file(work + "/warnings", about_model) &&
                write_file(work + "/command", commands) &&  // how it was built, for whoever looks
                cache::write_manifest(work, build_files);   // last: the build is whole
  // Every build gets a folder of its own, so what a process loaded is never
  // overwritten; the key then names the newest.
  std::string build = build_key + "." + cache::unique_id();
  if (stored) fs::rename(work, plugins + "/" + build, ec);
  if (!stored || ec) {
    fs::remove_all(work, ec);
    return failed(plugins, "cannot store the compiled model in the cache");
  }
  cache::publish(plugins, build_key, build);
  r.ok = true;
  r.plugin = plugins + "/" + build + "/model.so";
  r.cpp = plugins + "/" + build + "/model.cpp";
  r.warnings = notes + where.shown_in(about_model);
  for (const std::string& h : dependency_paths(deps)) r.sources.push_back(h);
  return r;
}

build_result build_unguarded(const std::string& path, const build_settings& s) {
  if (is_plugin_file(path)) {  // a prebuilt plugin
    build_result r;
    r.ok = true;
    r.plugin = fs::absolute(path).string();
    r.cached = true;
    return r;
  }
  model_builder b(path, s);
  if (std::optional<build_result> done = b.translate()) return *done;
  b.name_the_build();
  // Another process may be compiling this very model: wait, then find its build.
  cache::build_lock lock(b.plugins, b.key);
  if (std::optional<build_result> done = b.find_in_cache(b.key)) return *done;
  if (std::optional<build_result> done = b.quick_build()) return *done;
  if (std::optional<build_result> done = b.prepare_work()) return *done;
  return b.compile_and_store();
}

}  // namespace

build_result build_model(const std::string& path, const build_settings& s) {
  // Whatever goes wrong in building comes back as a message: the viewer and
  // batch report it and stay up.
  try {
    return build_unguarded(path, s);
  } catch (const std::exception& e) {
    return failed(path, std::string("the model could not be built: ") + e.what());
  } catch (...) {
    return failed(path, "the model could not be built (an unknown exception)");
  }
}

}  // namespace vvi
