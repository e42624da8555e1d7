#include "compile/dependencies.hpp"

#include <sstream>

#include "app/files.hpp"
#include "compile/hashing.hpp"
#include "compile/text_ends.hpp"

namespace vvi {

std::string dependency_list(const std::string& depfile, const std::string& include, const std::string& cache_dir) {
  std::string text = read_file(depfile).value_or("");
  std::string out;
  std::istringstream words(text);
  auto under = [](const std::string& w, const std::string& folder) {
    return !folder.empty() && w.rfind(folder + "/", 0) == 0;
  };
  for (std::string w; words >> w;) {
    if (w == "\\" || ends_with(w, ":") || w.rfind(include, 0) == 0 || w.rfind("/usr/", 0) == 0 || under(w, cache_dir))
      continue;
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

std::vector<std::string> dependency_paths(const std::string& list) {
  std::vector<std::string> out;
  std::istringstream lines(list);
  for (std::string hash, path; lines >> hash >> path;) out.push_back(path);
  return out;
}

}  // namespace vvi
