#include "compile/declarations_header.hpp"

#include <filesystem>

#include "app/files.hpp"
#include "compile/dependencies.hpp"
#include "compile/model_cache.hpp"
#include "compile/process.hpp"

namespace vvi {

namespace fs = std::filesystem;

namespace {

const char* const header_text_name = "header.hpp";
const char* const header_pch_name = "header.hpp.pch";
const char* const header_object_name = "header.hpp.o";
const char* const header_verdict_name = "verdict";  // "usable", or why not
const char* const usable_verdict = "usable";

std::string headers_folder_of(const std::string& cache_dir) { return cache_dir + "/decl-headers"; }

// Precompiles the header in `work`, then compiles its code, a section per
// function (a model's link keeps what it uses). What the compiler said,
// and whether both were made.
process_result compile_header(const declarations_header_request& r, const std::string& work) {
  std::vector<std::string> argv = r.argv;
  // The header's text goes into the .pch: clang would otherwise look for
  // it in the work folder, which is renamed when the entry is stored.
  argv.insert(argv.end(), {"-fpch-instantiate-templates", "-fpch-codegen", "-Xclang",
                           "-fmodules-embed-file=" + work + "/" + header_text_name, "-MD", "-MF", work + "/header.d", "-x", "c++-header", work + "/" + header_text_name, "-o",
                           work + "/" + header_pch_name});
  process_result made = run_process(argv, r.niceness);
  if (made.status != 0) return made;
  std::vector<std::string> object = {r.argv.front()};
  for (std::size_t i = 1; i < r.argv.size(); ++i) {
    if (r.argv[i] == "-include-pch") {  // the code's compile reads the header it extends through it
      ++i;
      continue;
    }
    object.push_back(r.argv[i]);
  }
  object.insert(object.end(), {"-Wno-unused-command-line-argument", "-ffunction-sections", "-fdata-sections", "-c",
                               work + "/" + header_pch_name, "-o", work + "/" + header_object_name});
  process_result compiled = run_process(object, r.niceness);
  compiled.output = made.output + compiled.output;
  return compiled;
}

}  // namespace

declarations_header find_declarations_header(const std::string& cache_dir, const std::string& key) {
  declarations_header found;
  std::error_code ec;
  fs::path entry = fs::canonical(headers_folder_of(cache_dir) + "/" + key, ec);
  if (ec) return found;
  std::string why;
  cache::verdict v = cache::verify(entry.string(), why);
  if (v == cache::verdict::damaged) {
    fs::remove_all(entry, ec);
    found.why = "the cached header of the declarations was damaged (" + why + ")";  // and removed
    return found;
  }
  if (v != cache::verdict::good) return found;
  std::string verdict = read_file((entry / header_verdict_name).string()).value_or("");
  if (verdict != usable_verdict) {
    found.state = declarations_header::unusable;
    found.why = verdict;
    return found;
  }
  if (!dependencies_unchanged(read_file((entry / "deps").string()).value_or(""))) return found;
  found.state = declarations_header::usable;
  found.pch = (entry / header_pch_name).string();
  found.object = (entry / header_object_name).string();
  found.warnings = read_file((entry / "warnings").string()).value_or("");
  return found;
}

declarations_header build_declarations_header(const declarations_header_request& r) {
  std::string folder = headers_folder_of(r.cache_dir);
  // Another build of this model may be making it now: wait and use it.
  cache::build_lock lock(folder, r.key);
  declarations_header found = find_declarations_header(r.cache_dir, r.key);
  if (found.state != declarations_header::missing) return found;
  std::string damage = found.why;
  auto not_stored = [&](const std::string& why) {
    declarations_header missing;
    missing.why = why;
    missing.damage = damage;
    return missing;
  };
  std::string work = cache::new_work_folder(folder, r.key);
  std::error_code ec;
  if (work.empty() || !write_file(work + "/" + header_text_name, r.text)) {
    fs::remove_all(work, ec);
    return not_stored("cannot write to the model cache");
  }
  process_result c = compile_header(r, work);
  std::vector<cache::listed_file> files = {{header_text_name, cache::check::content}, {header_verdict_name, cache::check::content}};
  bool written = write_file(work + "/command", command_line(r.argv) + "\n");
  if (c.status == 0) {
    written = written && write_file(work + "/" + header_verdict_name, usable_verdict) &&
              write_file(work + "/deps", dependency_list(work + "/header.d", r.include, r.cache_dir)) &&
              write_file(work + "/warnings", c.output);
    // Its size only: a checksum of tens of megabytes on every edit would
    // cost more than it saves; a header the compiler cannot read is
    // discarded when it says so (discard_declarations_header).
    files.insert(files.end(), {{header_pch_name, cache::check::size},
                               {header_object_name, cache::check::content},
                               {"deps", cache::check::content},
                               {"warnings", cache::check::content}});
  } else {
    // Kept as unusable: the program compiles whole, and later edits do
    // not try again. What the compiler said stays beside it.
    written = written && write_file(work + "/" + header_verdict_name, "the header of the declarations does not compile") &&
              write_file(work + "/output", c.output);
    for (const char* made : {header_pch_name, header_object_name}) fs::remove(work + "/" + made, ec);
  }
  fs::remove(work + "/header.d", ec);
  if (!written || !cache::store(folder, work, r.key, files)) {
    fs::remove_all(work, ec);
    return not_stored("cannot store the header of the declarations in the model cache");
  }
  declarations_header made = find_declarations_header(r.cache_dir, r.key);
  made.damage = damage;
  return made;
}

void discard_declarations_header(const std::string& pch) {
  std::error_code ec;
  fs::remove_all(fs::path(pch).parent_path(), ec);
}

}  // namespace vvi
