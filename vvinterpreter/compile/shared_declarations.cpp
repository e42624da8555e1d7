#include "compile/shared_declarations.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compile/text_ends.hpp"

namespace vvi {

const char* const model_folder_marker = "/vv-model-folder";

namespace {

// The name a preprocessor line gives after `directive` ("include"): the
// text between its quotes or angle brackets, or "".
std::string quoted_name(const std::string& line, const std::string& directive) {
  std::size_t at = line.find_first_not_of(" \t");
  if (at == std::string::npos || line[at] != '#') return "";
  at = line.find_first_not_of(" \t", at + 1);
  if (at == std::string::npos || line.compare(at, directive.size(), directive) != 0) return "";
  std::size_t open = line.find_first_of("\"<", at + directive.size());
  if (open == std::string::npos) return "";
  std::size_t close = line.find(line[open] == '"' ? '"' : '>', open + 1);
  if (close == std::string::npos) return "";
  return line.substr(open + 1, close - open - 1);
}

}  // namespace

std::string declarations_without_folder(const std::string& text, const std::string& model_dir) {
  const std::string inside = "\"" + model_dir + "/";
  const std::string marked = "\"" + std::string(model_folder_marker) + "/";
  std::string out;
  out.reserve(text.size());
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::size_t quote = line.find(inside);
    // Only the #line directives: the program's own text stays as written.
    if (line.rfind("#line ", 0) == 0 && quote != std::string::npos)
      line.replace(quote, inside.size(), marked);
    out += line;
    out += '\n';
  }
  return out;
}

bool declarations_may_read_folder(const std::string& text, const std::string& model_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (const char* vvlib_folder : {"vv", "util", "algorithms", "model"})
    if (fs::exists(fs::path(model_dir) / vvlib_folder, ec)) return true;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::string name = quoted_name(line, "include");
    if (!name.empty() && fs::exists(fs::path(model_dir) / name, ec)) return true;
  }
  return false;
}

std::string in_model_folder(const std::string& file, const std::string& model_dir) {
  const std::string marked = std::string(model_folder_marker) + "/";
  if (model_dir.empty() || file.rfind(marked, 0) != 0) return file;
  return model_dir + "/" + file.substr(marked.size());
}

std::string with_model_folder(std::string text, const std::string& model_dir) {
  const std::string marked = std::string(model_folder_marker) + "/";
  if (model_dir.empty()) return text;
  for (std::size_t at = text.find(marked); at != std::string::npos; at = text.find(marked, at + model_dir.size() + 1))
    text.replace(at, marked.size(), model_dir + "/");
  return text;
}

std::string model_folder_of_build(const std::string& plugin) {
  std::ifstream cpp(std::filesystem::path(plugin).parent_path() / "model.cpp");
  for (std::string line; std::getline(cpp, line);) {
    if (line.rfind("#line ", 0) != 0) continue;
    std::size_t open = line.find("\"/");
    std::size_t close = line.rfind('"');
    if (open == std::string::npos || close <= open) continue;
    std::string file = line.substr(open + 1, close - open - 1);
    if (ends_with(file, ".vvp")) return file.substr(0, file.rfind('/'));
  }
  return "";
}

std::string message_of_build(const std::string& message, const std::string& plugin) {
  if (message.find(model_folder_marker) == std::string::npos) return message;
  return with_model_folder(message, model_folder_of_build(plugin));
}

}  // namespace vvi
