// Text placed in an XML attribute by vv's hand-written XML writers (.vtp,
// .pvd): the five characters XML reserves in a quoted attribute escaped.
#pragma once

#include <string>

namespace vv::formats_detail {

inline std::string xml_attribute_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace vv::formats_detail
