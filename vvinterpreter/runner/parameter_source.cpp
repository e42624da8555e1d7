#include "runner/parameter_source.hpp"

#include <regex>

#include <vv/io/files.hpp>

#include "app/files.hpp"

namespace vvi {

namespace {

// [begin, end) of line n (1-based) in text, or false.
bool line_span(const std::string& text, int n, std::size_t& begin, std::size_t& end) {
  begin = 0;
  for (int i = 1; i < n; ++i) {
    begin = text.find('\n', begin);
    if (begin == std::string::npos) return false;
    ++begin;
  }
  end = text.find('\n', begin);
  if (end == std::string::npos) end = text.size();
  return true;
}

}  // namespace

std::string with_parameter_values(std::string& source, const std::vector<parameter_value_at>& values,
                                  int& bad_line) {
  for (const parameter_value_at& v : values) {
    std::size_t begin = 0, end = 0;
    bad_line = v.line;
    if (v.line < 1 || !line_span(source, v.line, begin, end))
      return "the file has no such line (the parameter " + v.name + " was declared there)";
    std::string line = source.substr(begin, end - begin);
    // param TYPE NAME = VALUE [in [LO, HI]];   VALUE is what changes.
    const std::regex declaration("(\\bparam\\s+\\w+\\s+" + v.name +
                                 "\\s*=\\s*)(.*?)(\\s*(?:\\bin\\s*\\[[^\\]]*\\])?\\s*;)");
    std::smatch m;
    if (!std::regex_search(line, m, declaration))
      return "no `param ... " + v.name + " = ...;` on this line (was the file edited since it was built?)";
    line.replace(static_cast<std::size_t>(m.position(2)), static_cast<std::size_t>(m.length(2)), v.text);
    source.replace(begin, end - begin, line);
  }
  bad_line = 0;
  return "";
}

std::string save_parameter_values(const std::string& path, const std::vector<parameter_value_at>& values) {
  std::optional<std::string> text = read_file(path);
  if (!text) return path + ": cannot read the file to save the parameters";
  int line = 0;
  std::string why = with_parameter_values(*text, values, line);
  if (!why.empty()) return path + ":" + std::to_string(line) + ": " + why;
  try {
    vv::io::write_text_file(path, *text);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace vvi
