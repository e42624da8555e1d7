// STL, ASCII and binary, read by vv itself: an empty file is an error, not
// an empty mesh, and a corner that is not a finite number is named as such
// (CGAL's reader joins corners by position in a map that a NaN breaks,
// which surfaced as "face 0 repeats a vertex"). Corners at the same point
// become one vertex, numbered in the order they first appear.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "readers.hpp"
#include "text_scan.hpp"

namespace vv::formats {

namespace {

constexpr std::size_t binary_header = 80 + 4;  // 80 bytes of text, the triangle count
constexpr std::size_t binary_triangle = 50;    // normal, 3 corners (12 floats), 2 bytes of attributes

// Joins corners at the same point into vertices. Ordered by <, as CGAL's
// reader does, so -0 and 0 are one point.
class vertex_joiner {
 public:
  explicit vertex_joiner(polygon_soup& soup) : soup_(soup) {}
  std::uint32_t at(const std::array<double, 3>& p) {
    auto [it, added] = index_.emplace(p, static_cast<std::uint32_t>(soup_.points.size()));
    if (added) soup_.points.push_back(p);
    return it->second;
  }

 private:
  polygon_soup& soup_;
  std::map<std::array<double, 3>, std::uint32_t> index_;
};

std::string point_text(const std::array<double, 3>& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", p[0], p[1], p[2]);
  return text;
}

// What is wrong with a triangle's corners ("" when nothing): a coordinate
// that is no finite number, or two corners at one point.
std::string triangle_problem(const std::array<std::array<double, 3>, 3>& corners) {
  static const char* const axis = "xyz";
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t k = 0; k < 3; ++k)
      if (!std::isfinite(corners[c][k]))
        return "corner " + std::to_string(c + 1) + " has " + axis[k] + " = " +
               (std::isnan(corners[c][k]) ? "nan" : corners[c][k] > 0 ? "inf" : "-inf") +
               "; STL corners are joined into vertices by position, which takes finite numbers";
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t d = 0; d < c; ++d)
      if (!(corners[c] < corners[d]) && !(corners[d] < corners[c]))
        return "corners " + std::to_string(d + 1) + " and " + std::to_string(c + 1) + " are the same point " +
               point_text(corners[c]) + ", so the triangle has fewer than 3 vertices";
  return "";
}

std::uint32_t little_endian_u32(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

float little_endian_float(const char* p) {
  std::uint32_t bits = little_endian_u32(p);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

polygon_soup read_binary(const std::string& path, const std::string& bytes) {
  const std::uint64_t count = little_endian_u32(bytes.data() + 80);
  if (count == 0) throw error(path, 0, "no triangles (the binary STL header's triangle count is 0)");
  polygon_soup soup;
  vertex_joiner join(soup);
  soup.faces.reserve(static_cast<std::size_t>(count));
  for (std::uint64_t t = 0; t < count; ++t) {
    const char* record = bytes.data() + binary_header + t * binary_triangle + 12;  // past the normal
    std::array<std::array<double, 3>, 3> corners;
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t k = 0; k < 3; ++k) corners[c][k] = little_endian_float(record + 12 * c + 4 * k);
    std::string problem = triangle_problem(corners);
    if (!problem.empty()) throw error(path, 0, "triangle " + std::to_string(t) + ": " + problem);
    soup.faces.push_back({join.at(corners[0]), join.at(corners[1]), join.at(corners[2])});
  }
  return soup;
}

// The words of an ASCII STL one by one, each with its line.
class word_cursor {
 public:
  word_cursor(const std::string& path, const std::string& text) : lines_(path, text) {}
  //! The next word, or an empty view at the end of the file.
  std::string_view next() {
    while (at_ >= lines_.words().size()) {
      if (!lines_.next()) return {};
      at_ = 0;
    }
    return lines_.words()[at_++];
  }
  //! Leaves the rest of the current line (a solid's name).
  void skip_line() { at_ = lines_.words().size(); }
  [[noreturn]] void fail(const std::string& problem) const { lines_.fail(problem); }
  void expect(std::string_view word, const char* where) {
    std::string_view got = next();
    if (got != word)
      fail("expected '" + std::string(word) + "' " + where + ", found " +
           (got.empty() ? std::string("the end of the file") : quoted(got)));
  }
  double number(const char* what) {
    std::string_view w = next();
    double value;
    if (w.empty()) fail(std::string("the file ends inside ") + what);
    if (!read_number(w, value)) fail(quoted(w) + " is not a number (in " + what + ")");
    return value;
  }

 private:
  line_scanner lines_;
  std::size_t at_ = 0;
};

polygon_soup read_ascii(const std::string& path, const std::string& text) {
  polygon_soup soup;
  vertex_joiner join(soup);
  word_cursor words(path, text);
  words.expect("solid", "at the start of an ASCII STL file");
  words.skip_line();
  while (true) {
    std::string_view w = words.next();
    if (w.empty()) words.fail("the file ends inside a solid (no 'endsolid')");
    if (w == "endsolid") {
      words.skip_line();
      std::string_view after = words.next();
      if (after.empty()) break;
      if (after != "solid") words.fail("expected 'solid' or the end of the file after 'endsolid', found " + quoted(after));
      words.skip_line();
      continue;
    }
    if (w != "facet") words.fail("expected 'facet' or 'endsolid', found " + quoted(w));
    words.expect("normal", "after 'facet'");
    for (int k = 0; k < 3; ++k) words.number("the facet's normal");
    words.expect("outer", "after the facet's normal");
    words.expect("loop", "after 'outer'");
    std::array<std::array<double, 3>, 3> corners;
    int count = 0;
    for (std::string_view v = words.next(); v != "endloop"; v = words.next()) {
      if (v.empty()) words.fail("the file ends inside a facet (no 'endloop')");
      if (v != "vertex") words.fail("expected 'vertex' or 'endloop' in a facet, found " + quoted(v));
      if (count == 3) words.fail("a facet with more than 3 vertices: STL holds triangles only");
      for (int k = 0; k < 3; ++k) corners[count][k] = words.number("a vertex");
      ++count;
    }
    if (count < 3)
      words.fail("a facet with " + std::to_string(count) + (count == 1 ? " vertex" : " vertices") +
                 ": a triangle needs 3");
    words.expect("endfacet", "after 'endloop'");
    std::string problem = triangle_problem(corners);
    if (!problem.empty()) words.fail("triangle " + std::to_string(soup.faces.size()) + ": " + problem);
    soup.faces.push_back({join.at(corners[0]), join.at(corners[1]), join.at(corners[2])});
  }
  if (soup.faces.empty()) throw error(path, 0, "no triangles (the solid has no facet)");
  return soup;
}

bool starts_with_solid(const std::string& bytes) {
  return bytes.compare(0, 5, "solid") == 0 &&
         (bytes.size() == 5 || std::strchr(" \t\r\n", bytes[5]) != nullptr);
}

}  // namespace

polygon_soup read_stl(const std::string& path, const std::string& bytes) {
  if (bytes.empty())
    throw error(path, 0, "empty file (an STL file starts with 'solid' or with an 84-byte binary header)");
  // As large as its triangle count says: binary, even when its header text
  // starts with "solid" as some writers' does.
  const bool binary_size = bytes.size() >= binary_header &&
      bytes.size() >= binary_header + std::uint64_t(little_endian_u32(bytes.data() + 80)) * binary_triangle;
  if (starts_with_solid(bytes)) {
    try {
      return read_ascii(path, bytes);
    } catch (const error&) {
      if (!binary_size) throw;
    }
    return read_binary(path, bytes);
  }
  if (bytes.size() < binary_header)
    throw error(path, 0, "not an STL file: it does not start with 'solid' (ASCII STL), and at " +
                             std::to_string(bytes.size()) + " bytes it is shorter than a binary STL header (84 bytes)");
  if (!binary_size) {
    const std::uint64_t count = little_endian_u32(bytes.data() + 80);
    throw error(path, 0, "not an STL file, or a cut-short one: it does not start with 'solid' (ASCII STL), and as "
                         "binary STL its header announces " + std::to_string(count) + " triangles, which take " +
                             std::to_string(binary_header + count * binary_triangle) + " bytes, but the file has " +
                             std::to_string(bytes.size()));
  }
  return read_binary(path, bytes);
}

}  // namespace vv::formats
