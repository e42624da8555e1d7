// OFF in ASCII, read by vv itself so that every fault has its line and its
// reason: the header (OFF with the prefixes ST, C, N), the counts, one
// vertex per line (x y z, then normals, colours, texture coordinates: all
// numbers) and one face per line (the number of corners, the indices from
// 0, then an optional colour). Binary OFF and the higher-dimensional
// variants (4OFF, nOFF) go to CGAL's reader.
#include <CGAL/IO/OFF.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <vv/io/face_check.hpp>

#include "readers.hpp"
#include "text_scan.hpp"

namespace vv::formats {

using io::missing_vertex_problem;
using io::repeated_corner_problem;
using io::too_few_corners;

namespace {

// "OFF", "COFF", "NOFF", "STOFF", "STCNOFF", ...: what the prefixes say
// each vertex line carries after x y z. CGAL-only forms: "4OFF", "nOFF",
// and a header followed by BINARY.
struct off_header {
  bool known = false;   // one of ours
  bool cgal = false;    // a form CGAL reads and we do not
};

off_header parse_header(std::string_view word, std::string_view next) {
  off_header h;
  if (word.size() < 3 || word.substr(word.size() - 3) != "OFF") return h;
  std::string_view prefix = word.substr(0, word.size() - 3);
  if (prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
  if (!prefix.empty() && prefix.front() == 'C') prefix.remove_prefix(1);
  if (!prefix.empty() && prefix.front() == 'N') prefix.remove_prefix(1);
  if (prefix == "4" || prefix == "n" || prefix == "4n") {
    h.cgal = true;
    return h;
  }
  if (!prefix.empty()) return h;
  if (next == "BINARY") h.cgal = true;
  else h.known = true;
  return h;
}

using cgal_point = CGAL::Simple_cartesian<double>::Point_3;

polygon_soup read_with_cgal(const std::string& path, const std::string& bytes) {
  std::istringstream in(bytes, std::ios::binary);
  std::vector<cgal_point> points;
  std::vector<std::vector<std::size_t>> faces;
  if (!CGAL::IO::read_OFF(in, points, faces))
    throw error(path, 0, "not a readable OFF file (CGAL's reader of binary and higher-dimensional OFF gives no reason)");
  std::vector<std::array<double, 3>> xyz;
  xyz.reserve(points.size());
  for (const auto& p : points) xyz.push_back({p.x(), p.y(), p.z()});
  return checked_soup(path, std::move(xyz), faces);
}

class off_reader {
 public:
  off_reader(const std::string& path, const std::string& bytes) : lines_(path, bytes), path_(path) {}

  // nullopt: a form for CGAL's reader.
  std::optional<polygon_soup> read() {
    if (!next_content_line()) throw error(path_, 0, "empty file (expected an OFF header)");
    const auto& head = lines_.words();
    off_header h = parse_header(head[0], head.size() > 1 ? head[1] : std::string_view());
    if (h.cgal) return std::nullopt;
    if (!h.known)
      lines_.fail("the file starts with " + quoted(head[0]) + ", not an OFF header (OFF, COFF, NOFF, STOFF, ...)");
    std::vector<std::string_view> counts(head.begin() + 1, head.end());
    if (counts.empty()) {
      if (!next_content_line()) lines_.fail("the file ends after its header; expected the counts (vertices faces edges)");
      counts = lines_.words();
    }
    if (counts.size() < 2 || counts.size() > 3)
      lines_.fail("expected the counts 'vertices faces edges' after the header, found " +
                  std::to_string(counts.size()) + (counts.size() == 1 ? " word" : " words"));
    const std::uint64_t vertices = count(counts[0], "vertices"), faces = count(counts[1], "faces");
    if (counts.size() == 3) count(counts[2], "edges");
    if (faces == 0)
      lines_.fail("no faces: the header announces " + count_text(vertices, "vertex", "vertices") +
                  " and 0 faces (points only); vv reads polygon meshes from .off files");

    polygon_soup soup;
    soup.points.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(vertices, 1u << 20)));
    for (std::uint64_t v = 0; v < vertices; ++v) {
      if (!next_content_line()) ends_early(vertices, faces, v, "vertices");
      soup.points.push_back(vertex(v));
    }
    soup.faces.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(faces, 1u << 20)));
    for (std::uint64_t f = 0; f < faces; ++f) {
      if (!next_content_line()) ends_early(vertices, faces, f, "faces");
      soup.faces.push_back(face(f, vertices));
    }
    if (next_content_line())
      lines_.fail("more lines than the header announces (" + std::to_string(vertices) + " vertices, " +
                  std::to_string(faces) + " faces)");
    return soup;
  }

 private:
  bool next_content_line() {
    while (lines_.next())
      if (!lines_.words().empty()) return true;
    return false;
  }

  std::uint64_t count(std::string_view word, const char* what) {
    std::int64_t n = 0;
    if (read_integer(word, n) != integer_result::ok || n < 0)
      lines_.fail("the count of " + std::string(what) + " is " + quoted(word) + ", not a whole number of 0 or more");
    return static_cast<std::uint64_t>(n);
  }

  [[noreturn]] void ends_early(std::uint64_t vertices, std::uint64_t faces, std::uint64_t read, const char* what) {
    throw error(path_, lines_.line(),
                "the file ends after " + std::to_string(read) + " " + what + "; the header announces " +
                    std::to_string(vertices) + " vertices and " + std::to_string(faces) + " faces");
  }

  std::array<double, 3> vertex(std::uint64_t index) {
    const auto& w = lines_.words();
    std::array<double, 3> p{};
    for (std::size_t i = 0; i < w.size(); ++i) {
      double value;
      if (!read_number(w[i], value))
        lines_.fail("vertex " + std::to_string(index) + ": " + quoted(w[i]) + " is not a number");
      if (i < 3) p[i] = value;
    }
    if (w.size() < 3)
      lines_.fail("vertex " + std::to_string(index) + " has " + std::to_string(w.size()) +
                  (w.size() == 1 ? " coordinate" : " coordinates") + "; a vertex needs 3 (x y z)");
    return p;
  }

  std::vector<std::uint32_t> face(std::uint64_t index, std::uint64_t vertices) {
    const auto& w = lines_.words();
    const std::string who = "face " + std::to_string(index) + ": ";
    std::int64_t k = 0;
    if (read_integer(w[0], k) != integer_result::ok || k < 0)
      lines_.fail(who + "the line starts with " + quoted(w[0]) + ", not the number of its vertices");
    std::string few = too_few_corners(static_cast<std::size_t>(k));
    if (!few.empty()) lines_.fail(who + few);
    if (w.size() - 1 < static_cast<std::uint64_t>(k))
      lines_.fail(who + "says it has " + std::to_string(k) + " vertices but lists " + std::to_string(w.size() - 1));
    std::vector<std::uint32_t> corners;
    corners.reserve(static_cast<std::size_t>(k));
    for (std::size_t i = 1; i <= static_cast<std::size_t>(k); ++i) {
      std::int64_t v = 0;
      integer_result r = read_integer(w[i], v);
      if (r == integer_result::not_whole || r == integer_result::not_a_number)
        lines_.fail(who + quoted(w[i]) + " is not a vertex index (indices are whole numbers, counted from 0)");
      if (r == integer_result::too_large || v < 0 || static_cast<std::uint64_t>(v) >= vertices)
        lines_.fail(who + (v < 0 ? quoted(w[i]) + " is not a vertex index (indices count from 0)"
                                 : missing_vertex_problem(std::string(w[i]), static_cast<std::size_t>(vertices), 0)));
      corners.push_back(static_cast<std::uint32_t>(v));
    }
    for (std::size_t i = static_cast<std::size_t>(k) + 1; i < w.size(); ++i) {
      double colour;
      if (!read_number(w[i], colour))
        lines_.fail(who + quoted(w[i]) + " after its " + std::to_string(k) +
                    " vertices is no colour component (a face line is: count, indices, optional colour)");
    }
    std::string twice = repeated_corner_problem(corners, 0);
    if (!twice.empty()) lines_.fail(who + twice);
    return corners;
  }

  line_scanner lines_;
  std::string path_;
};

}  // namespace

polygon_soup read_off(const std::string& path, const std::string& bytes) {
  if (std::optional<polygon_soup> soup = off_reader(path, bytes).read()) return std::move(*soup);
  return read_with_cgal(path, bytes);
}

}  // namespace vv::formats
