// Names as messages list them: "a, b, c".
#pragma once

#include <string>
#include <vector>

namespace vvi {

inline std::string joined_names(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace vvi
