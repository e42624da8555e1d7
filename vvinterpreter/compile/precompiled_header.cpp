#include "compile/precompiled_header.hpp"

#include <filesystem>

#include "compile/build_config.hpp"
#include "compile/model_cache.hpp"
#include "compile/process.hpp"

namespace vvi {

namespace fs = std::filesystem;

namespace {

const char* header_file(bool clang) { return clang ? "model/model.hpp.pch" : "model/model.hpp.gch"; }


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
  std::vector<std::string> argv = {r.compiler.empty() ? std::string(config::cxx_compiler) : r.compiler};
  argv.insert(argv.end(), r.flags.begin(), r.flags.end());
  // clang: the templates the header instantiates, once here, not in every model.
  if (r.clang) argv.push_back("-fpch-instantiate-templates");
  argv.insert(argv.end(), {"-x", "c++-header", r.include + "/model/model.hpp", "-o", work + "/" + header_file(r.clang)});
  process_result made = run_process(argv);
  if (made.status != 0 || !cache::write_manifest(work, {{header_file(r.clang), cache::check::size}})) {
    fs::remove_all(work, ec);
    error = "cannot precompile model/model.hpp:\n" + made.output;
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
