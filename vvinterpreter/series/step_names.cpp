#include "series/step_names.hpp"

#include <cstring>

#include <vv/io/files.hpp>
#include <vv/io/polygon_files.hpp>

namespace vvi {

bool has_step_mark(const std::string& name) { return name.find(step_mark) != std::string::npos; }

std::string name_at_step(const std::string& pattern, unsigned long step, unsigned digits) {
  std::string number = std::to_string(step);
  if (number.size() < digits) number.insert(0, digits - number.size(), '0');
  std::string out = pattern;
  const std::size_t mark = std::strlen(step_mark);
  for (std::size_t at = 0; (at = out.find(step_mark, at)) != std::string::npos; at += number.size())
    out.replace(at, mark, number);
  return out;
}

unsigned digits_of(unsigned long step) { return static_cast<unsigned>(std::to_string(step).size()); }

std::string with_step_mark(const std::string& name) {
  std::size_t slash = name.rfind('/');
  std::size_t dot = name.rfind('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) || dot == slash + 1)
    return name + "-" + step_mark;
  return name.substr(0, dot) + "-" + step_mark + name.substr(dot);
}

series_file series_file_of(const std::string& name) {
  std::string ext = vv::io::extension_of(name);
  if (ext == ".png") return series_file::picture;
  if (ext == ".mp4") return series_file::movie;
  if (ext == ".vvm" || ext == ".vtp" || vv::detail::is_polygon_format(ext)) return series_file::mesh;
  return series_file::unknown;
}

}  // namespace vvi
