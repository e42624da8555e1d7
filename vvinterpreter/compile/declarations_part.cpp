#include "compile/declarations_part.hpp"

#include <filesystem>

#include "app/files.hpp"
#include "compile/dependencies.hpp"
#include "compile/model_cache.hpp"
#include "compile/object_symbols.hpp"
#include "compile/process.hpp"

namespace vvi {

namespace fs = std::filesystem;

namespace {

const char* const object_name = "declarations.o";
const char* const verdict_name = "verdict";  // "usable", or why not
const char* const usable = "usable";

std::string folder_of(const std::string& cache_dir) { return cache_dir + "/decls"; }

std::string join(const std::vector<std::string>& argv) {
  std::string s;
  for (const std::string& a : argv) s += (s.empty() ? "" : " ") + a;
  return s;
}

}  // namespace

declarations_part find_declarations(const std::string& cache_dir, const std::string& key) {
  declarations_part found;
  std::error_code ec;
  fs::path entry = fs::canonical(folder_of(cache_dir) + "/" + key, ec);
  if (ec) return found;
  std::string why;
  cache::verdict v = cache::verify(entry.string(), why);
  if (v == cache::verdict::damaged) {
    fs::remove_all(entry, ec);
    found.why = "the cached declarations' part was damaged (" + why + ")";
    return found;
  }
  if (v != cache::verdict::good) return found;
  std::string verdict = read_file((entry / verdict_name).string()).value_or("");
  if (verdict != usable) {
    found.state = declarations_part::unusable;
    found.why = verdict;
    return found;
  }
  if (!dependencies_unchanged(read_file((entry / "deps").string()).value_or(""))) return found;
  found.state = declarations_part::usable;
  found.object = (entry / object_name).string();
  return found;
}

declarations_part build_declarations(const declarations_request& r) {
  std::string folder = folder_of(r.cache_dir);
  // Another model with these declarations may be compiling them now: wait
  // for it and use its part.
  cache::build_lock lock(folder, r.key);
  declarations_part part = find_declarations(r.cache_dir, r.key);
  if (part.state != declarations_part::missing) return part;
  part = {};  // missing until stored
  std::string work = cache::new_work_folder(folder, r.key);
  std::error_code ec;
  if (work.empty() || !write_file(work + "/declarations.cpp", r.cpp)) {
    fs::remove_all(work, ec);
    part.why = "cannot write to the model cache";
    return part;
  }
  std::vector<std::string> argv = r.argv;
  argv.insert(argv.end(), {"-MD", "-MF", work + "/declarations.d", "-c", "-o", work + "/" + object_name,
                           work + "/declarations.cpp"});
  process_result c = run_process(argv);
  if (c.status != 0) {
    fs::remove_all(work, ec);
    part.why = "the declarations' part does not compile";
    return part;
  }
  std::string beyond = definitions_beyond(work + "/" + object_name, "vv_decl_");
  std::string deps = dependency_list(work + "/declarations.d", r.include);
  std::vector<cache::listed_file> files = {{"declarations.cpp", cache::check::content},
                                           {verdict_name, cache::check::content},
                                           {"deps", cache::check::content}};
  bool written = write_file(work + "/" + verdict_name, beyond.empty() ? usable : beyond) &&
                 write_file(work + "/deps", deps) && write_file(work + "/command", join(argv) + "\n");
  if (beyond.empty()) files.push_back({object_name, cache::check::content});
  else fs::remove(work + "/" + object_name, ec);
  fs::remove(work + "/declarations.d", ec);
  if (!written || !cache::store(folder, work, r.key, files)) {
    fs::remove_all(work, ec);
    part.why = "cannot store the declarations' part in the model cache";
    return part;
  }
  return find_declarations(r.cache_dir, r.key);
}

void record_unusable(const std::string& cache_dir, const std::string& key, const std::string& why) {
  std::string folder = folder_of(cache_dir);
  std::string work = cache::new_work_folder(folder, key);
  std::error_code ec;
  if (work.empty() || !write_file(work + "/" + verdict_name, why) ||
      !cache::store(folder, work, key, {{verdict_name, cache::check::content}}))
    fs::remove_all(work, ec);
}

}  // namespace vvi
