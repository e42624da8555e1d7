// PLY through CGAL's reader, which says nothing about why it fails: its
// header (text in every PLY file) is looked at here first, with lines, so
// the usual faults have a reason; the faces CGAL returns are then checked.
#include <CGAL/IO/PLY.h>
#include <CGAL/Simple_cartesian.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "readers.hpp"
#include "text_scan.hpp"

namespace vv::formats {

namespace {

struct ply_element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<std::string> properties;
  bool has(const char* p) const {
    for (const std::string& q : properties)
      if (q == p) return true;
    return false;
  }
};

// The header, line by line up to end_header; fails with the line of the
// first fault.
std::vector<ply_element> check_header(const std::string& path, const std::string& bytes) {
  std::size_t end = bytes.find("end_header");
  // The header is text; the body may be binary and must not be split into
  // lines (a line scanner would read on into it).
  std::string header = bytes.substr(0, end == std::string::npos ? bytes.size() : end + 10);
  line_scanner lines(path, header);
  if (!lines.next() || lines.words().empty() || lines.words()[0] != "ply")
    throw error(path, 1, "not a PLY file: it does not start with the line 'ply'");
  std::vector<ply_element> elements;
  bool format = false;
  while (lines.next()) {
    const auto& w = lines.words();
    if (w.empty()) continue;
    if (w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "format") {
      if (w.size() < 2 || (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
        lines.fail("unknown PLY format" + (w.size() > 1 ? " " + quoted(w[1]) : std::string()) +
                   " (expected ascii, binary_little_endian or binary_big_endian)");
      format = true;
    } else if (w[0] == "element") {
      std::int64_t n = 0;
      if (w.size() != 3 || read_integer(w[2], n) != integer_result::ok || n < 0)
        lines.fail("expected 'element NAME COUNT'");
      elements.push_back({std::string(w[1]), static_cast<std::uint64_t>(n), {}});
    } else if (w[0] == "property") {
      if (elements.empty()) lines.fail("a property before any element");
      if (w.size() < 3) lines.fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      elements.back().properties.emplace_back(w.back());
    } else if (w[0] == "end_header") {
      if (!format) lines.fail("the header has no 'format' line");
      return elements;
    } else {
      lines.fail(quoted(w[0]) + " is not a PLY header line (format, element, property, comment, end_header)");
    }
  }
  throw error(path, 0, "the header has no 'end_header' line");
}

using cgal_point = CGAL::Simple_cartesian<double>::Point_3;

}  // namespace

polygon_soup read_ply(const std::string& path, const std::string& bytes) {
  std::vector<ply_element> elements = check_header(path, bytes);
  const ply_element* vertices = nullptr;
  const ply_element* faces = nullptr;
  for (const ply_element& e : elements) {
    if (e.name == "vertex" || e.name == "vertices") vertices = &e;
    if (e.name == "face" || e.name == "faces") faces = &e;
  }
  if (!vertices || !vertices->has("x") || !vertices->has("y") || !vertices->has("z"))
    throw error(path, 0, "no vertex element with properties x, y and z in the header");
  if (!faces || faces->count == 0)
    throw error(path, 0, "no faces: the header announces " + count_text(vertices->count, "vertex", "vertices") + " and " +
                             (faces ? "0 faces" : "no face element") +
                             " (points only); vv reads polygon meshes from .ply files");
  if (!faces->has("vertex_indices") && !faces->has("vertex_index"))
    throw error(path, 0, "the face element has no list property vertex_indices (or vertex_index)");

  std::istringstream in(bytes, std::ios::binary);
  std::vector<cgal_point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_PLY(in, points, polygons, CGAL::parameters::verbose(false)) ||
      points.size() != vertices->count || polygons.size() != faces->count)
    throw error(path, 0, "the data after the header does not match it (it announces " +
                             std::to_string(vertices->count) + " vertices and " + std::to_string(faces->count) +
                             " faces): cut short, or a value of the wrong type");
  std::vector<std::array<double, 3>> xyz;
  xyz.reserve(points.size());
  for (const auto& p : points) xyz.push_back({p.x(), p.y(), p.z()});
  return checked_soup(path, std::move(xyz), polygons);
}

}  // namespace vv::formats
