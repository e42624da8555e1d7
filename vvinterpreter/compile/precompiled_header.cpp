#include "compile/precompiled_header.hpp"

#include <algorithm>
#include <filesystem>

#include "compile/build_config.hpp"
#include "compile/hashing.hpp"
#include "compile/model_cache.hpp"
#include "compile/process.hpp"

namespace vvi {

namespace fs = std::filesystem;

namespace {

const char* header_file(bool clang) { return clang ? "model/model.hpp.pch" : "model/model.hpp.gch"; }
const char* const code_file = "model/model.hpp.o";

// Compiles the header (and, with codegen, its code) in `work`: `ok` says
// whether it was made; returns what the compiler said.
std::string compile_header(const header_request& r, const std::string& work, bool& ok) {
  std::vector<std::string> argv = {r.compiler.empty() ? std::string(config::cxx_compiler) : r.compiler};
  argv.insert(argv.end(), r.flags.begin(), r.flags.end());
  // clang: the templates the header instantiates, once here, not in every model.
  if (r.clang) argv.push_back("-fpch-instantiate-templates");
  if (r.codegen) argv.push_back("-fpch-codegen");
  std::string pch = work + "/" + header_file(r.clang);
  argv.insert(argv.end(), {"-x", "c++-header", r.include + "/model/model.hpp", "-o", pch});
  process_result made = run_process(argv);
  ok = made.status == 0;
  if (!ok || !r.codegen) return made.output;
  // A section per function, so that a model's link drops what it does not use.
  std::vector<std::string> object = {argv.front()};
  object.insert(object.end(), r.flags.begin(), r.flags.end());
  object.insert(object.end(), {"-Wno-unused-command-line-argument", "-ffunction-sections", "-fdata-sections", "-c", pch,
                               "-o", work + "/" + code_file});
  process_result compiled = run_process(object);
  ok = compiled.status == 0;
  return made.output + compiled.output;
}


// The header the key names now, if it is whole (its damage said and
// discarded otherwise). Resolved once: another process may publish a new
// one meanwhile.
std::string finished_header(const std::string& folder, const std::string& key, std::string& damage) {
  std::error_code ec;
  fs::path current = fs::canonical(folder + "/" + key, ec);
  if (ec) return "";
  std::string why;
  cache::verdict v = cache::verify(current.string(), why);
  if (v == cache::verdict::good) return current.string();
  // Its size is checked, not its content: reading 100 MB would add tens
  // of milliseconds to every compile, and a header the compiler cannot
  // read is rebuilt after the compile fails (unreadable_precompiled_header).
  if (v == cache::verdict::damaged) {
    damage = why;
    discard_precompiled_header(current.string());
  }
  return "";
}

}  // namespace

header_request make_header_request(const std::string& cache_dir, const std::string& include,
                                   const std::vector<std::string>& flags, const std::string& compiler, bool clang,
                                   const std::string& stamp) {
  bool codegen = clang && std::find(flags.begin(), flags.end(), "-O0") != flags.end();
  std::string key =
      content_hash().add(compiler).add(command_line(flags)).add(stamp).add(codegen ? "codegen" : "").hex();
  return header_request{cache_dir, include, flags, key, compiler, clang, codegen};
}

std::vector<std::string> precompiled_header_link(const std::string& dir, const header_request& r) {
  if (dir.empty() || !r.codegen) return {};
  return {dir + "/" + code_file, "-Wl,--gc-sections"};
}

std::string precompiled_header_dir(const header_request& r, std::string& damage, std::string& error) {
  std::string folder = r.cache_dir + "/pch";
  std::error_code ec;
  fs::create_directories(folder, ec);
  cache::remove_leftovers(folder);
  std::string found = finished_header(folder, r.key, damage);
  if (!found.empty()) return found;
  // Another build may be making this header now: wait for it and use it.
  cache::build_lock lock(folder, r.key);
  found = finished_header(folder, r.key, damage);
  if (!found.empty()) return found;

  std::string work = folder + "/tmp-" + r.key + "-" + cache::unique_id();
  fs::create_directories(work + "/model", ec);
  bool compiled = false;
  std::string said = compile_header(r, work, compiled);
  std::vector<cache::listed_file> files = {{header_file(r.clang), cache::check::size}};
  if (r.codegen) files.push_back({code_file, cache::check::content});
  if (!compiled || !cache::write_manifest(work, files)) {
    fs::remove_all(work, ec);
    error = "cannot precompile model/model.hpp:\n" + said;
    return "";
  }
  std::string build = r.key + "." + cache::unique_id();
  fs::rename(work, folder + "/" + build, ec);
  if (ec) {
    fs::remove_all(work, ec);
    error = folder + ": cannot store the precompiled header in the cache";
    return "";
  }
  cache::publish(folder, r.key, build);
  return folder + "/" + build;
}

std::string precompiled_header_file(const std::string& dir, bool clang) { return dir + "/" + header_file(clang); }

void discard_precompiled_header(const std::string& dir) {
  std::error_code ec;
  fs::remove_all(dir, ec);
}

bool unreadable_precompiled_header(const std::string& compiler_output) {
  for (const char* words : {"PCH file", "AST file"})
    if (compiler_output.find(words) != std::string::npos) return true;
  return false;
}

}  // namespace vvi
