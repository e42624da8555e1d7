// From a .vvp file to a loadable plugin: translate (vvc, in-process),
// compile (the system C++ compiler, with a precompiled vvlib header), and
// cache the result by a hash of everything that goes into it, so a model
// that did not change starts without compiling.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace vvi {

struct build_settings {
  std::string cache_dir;  // holds plugins/ and pch/
  int optimization = 1;   // -O level for models
  bool debug = false;     // -g -O0, for gdb (the generated C++ stays in the cache entry)
  bool force = false;     // compile even when a cached plugin exists
  //! Link the part of the model that depends only on its declarations from
  //! the cache (compiled once for them) rather than compile it every time
  //! (declarations_part.hpp). The plugin is the same either way.
  bool declarations_apart = true;
  //! Compile the part from the model's first build (the viewer, and
  //! --expect-edits), rather than once the file has changed (batch runs
  //! and --compile-only: build_history.hpp). An existing part is used
  //! either way.
  bool part_from_the_first_build = false;
  //! After an edit: when the cache holds the optimised build's declarations'
  //! part, compile the program unoptimised with clang and link it with the
  //! part (quick_build.hpp), in about half a second; the optimised build
  //! is then asked for with quick off. A cached optimised build is used
  //! first. Also makes clang's precompiled header beside g++'s.
  bool quick = false;
  //! With quick: make the quick builds' header of the model's declarations
  //! (declarations_header.hpp) while the first build compiles, so that the
  //! first edit is as quick as the next (the viewer a person edits in, and
  //! --expect-edits); otherwise at the first edit (a scripted viewer, which
  //! seldom edits).
  bool declarations_header_ahead = false;
  //! The optimised build behind a quick one: its compiler runs at a lower
  //! priority (nice 10), so that the next edit's quick build and the
  //! running model come first.
  bool in_background = false;
  //! Once set (by another thread), the program's compiler is stopped and
  //! the build fails as cancelled, leaving nothing in the cache: an
  //! optimised build that a newer edit made stale, or one the viewer
  //! closes on.
  const std::atomic<bool>* cancel = nullptr;
  //! The most cores a new model's build counts as idle, 0: no limit
  //! (build_cores.hpp). With one, a new model is compiled whole.
  unsigned build_cores = 0;
  //! Called when the sources have been read and the compiler is about to
  //! start (not for a build found in the cache).
  std::function<void()> compiling;
};

struct build_result {
  bool ok = false;
  std::string plugin;                // the .so to load (its path is new for every build)
  std::string cpp;                   // the generated C++ beside it (for --debug and messages)
  std::string error;                 // one line: where and what ("m.vvp:3:7: error: ...")
  std::string details;               // all diagnostics / the compiler's messages about the model
  std::string warnings;              // the compiler's warnings about the model (shown, not fatal)
  //! The files the model was built from: the .vvp files read and the
  //! headers of the model's own that the C++ includes (to watch them).
  std::vector<std::string> sources;
  bool cached = false;
  bool quick = false;  // unoptimised (settings.quick): the optimised build is still to come
  bool cancelled = false;  // stopped by settings.cancel (not ok)
  double translate_ms = 0, compile_ms = 0;
};

//! Builds (or finds in the cache) the plugin of a .vvp file. A .so path is
//! taken as a prebuilt plugin.
build_result build_model(const std::string& path, const build_settings& settings);

//! A shared object (an ELF file) rather than a .vvp.
bool is_plugin_file(const std::string& path);

//! The include directory of vvlib models are compiled against (the build
//! tree's, or the installed one when running from the install prefix).
std::string vvlib_include_dir();
//! The folder of the vv_formats library models link, beside those headers.
std::string vvlib_library_dir();


}  // namespace vvi
