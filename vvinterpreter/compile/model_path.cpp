#include "compile/model_path.hpp"

#include <filesystem>
#include <sstream>

#include <vv/io/files.hpp>

namespace vvi {

namespace fs = std::filesystem;

namespace {

std::string built_spelling(const std::string& typed) {
  std::error_code ec;
  fs::path given(typed);
  fs::path name = given.filename();
  if (name.empty() || name == "." || name == "..") return typed;
  fs::path folder = fs::canonical(fs::absolute(given, ec).parent_path(), ec);
  if (ec) return typed;
  fs::path file = folder / name;
  // Not a regular file: the translator says what it is, under the typed name.
  if (!fs::is_regular_file(file, ec)) return typed;
  fs::path target = fs::canonical(file, ec);
  if (!ec && target.parent_path() == folder) return target.string();
  return file.string();
}

}  // namespace

model_path::model_path(const std::string& typed)
    : typed_(typed),
      built_(built_spelling(typed)),
      typed_folder_(vv::io::folder_of(typed)),
      built_folder_(vv::io::folder_of(built_)) {}

std::string model_path::shown(const std::string& path) const {
  if (path == built_) return typed_;
  if (built_ == typed_ || built_folder_.empty()) return path;
  // Included files: the translator joins the including file's folder and
  // the name written in the program (vv::io::resolve).
  std::string prefix = built_folder_.back() == '/' ? built_folder_ : built_folder_ + "/";
  if (path.size() > prefix.size() && path.compare(0, prefix.size(), prefix) == 0)
    return vv::io::resolve(typed_folder_, path.substr(prefix.size()));
  return path;
}

std::string model_path::shown_in(const std::string& text) const {
  if (built_ == typed_) return text;
  std::istringstream in(text);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    std::size_t colon = line.find(':');
    if (!line.empty() && line[0] != ' ' && colon != std::string::npos)
      line = shown(line.substr(0, colon)) + line.substr(colon);
    out += line + "\n";
  }
  if (!text.empty() && text.back() != '\n' && !out.empty()) out.pop_back();
  return out;
}

}  // namespace vvi
