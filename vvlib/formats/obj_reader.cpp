// Wavefront OBJ, read by vv itself: CGAL's reader stops at the first fault
// without a line or a reason, reads `f 1 2 3 x 4` as a triangle and `2.9`
// as vertex 2. Here each fault is named with its line.
#include <cstdint>
#include <limits>
#include <optional>
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

// The statements of the format that vv passes over: texture and normal
// data, groups, materials, free-form geometry and display settings.
bool is_passed_over(std::string_view keyword) {
  static const char* const words[] = {
      "vt", "vn", "vp", "o", "g", "s", "mg", "usemtl", "mtllib", "usemap", "maplib", "bevel", "lod",
      "ctech", "stech", "c_interp", "d_interp", "shadow_obj", "trace_obj", "cstype", "deg", "step",
      "bmat", "con", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "call",
      "csh", "res", "bsp", "bzp", "cdc", "cdp"};
  for (const char* w : words)
    if (keyword == w) return true;
  return false;
}

// A corner reference past the vertices read so far is allowed (OBJ lets a
// face name a later vertex); it is checked against the whole file at the
// end, with the line of its face.
struct pending_face_check {
  int line;
  std::size_t face;
};

class obj_reader {
 public:
  obj_reader(const std::string& path, const std::string& text) : lines_(path, text, true), path_(path) {}

  polygon_soup read() {
    while (lines_.next()) {
      const auto& w = lines_.words();
      if (w.empty()) continue;
      std::string_view keyword = w[0];
      if (keyword == "v") vertex(w);
      else if (keyword == "f" || keyword == "fo") face(w);
      else if (keyword == "l") ++polylines_;
      else if (keyword == "p") ++point_lines_;
      else if (!is_passed_over(keyword))
        lines_.fail(quoted(keyword) + " is not an OBJ statement (vv reads v and f lines)");
    }
    check_references();
    if (soup_.faces.empty()) fail_without_faces();
    return std::move(soup_);
  }

 private:
  void vertex(const std::vector<std::string_view>& w) {
    // x y z, then an optional weight or colour: all numbers.
    std::array<double, 3> p{};
    for (std::size_t i = 1; i < w.size(); ++i) {
      double value;
      if (!read_number(w[i], value))
        lines_.fail("vertex " + std::to_string(soup_.points.size() + 1) + ": " + quoted(w[i]) + " is not a number");
      if (i <= 3) p[i - 1] = value;
    }
    if (w.size() < 4)
      lines_.fail("vertex " + std::to_string(soup_.points.size() + 1) + " has " + std::to_string(w.size() - 1) +
                  (w.size() == 2 ? " coordinate" : " coordinates") + "; a vertex needs 3 (x y z)");
    soup_.points.push_back(p);
  }

  // One corner: "v", "v/vt", "v/vt/vn" or "v//vn"; the vertex index only is
  // kept. Indices count from 1; negative ones count back from the latest
  // vertex (-1 is the latest).
  std::uint32_t corner(std::string_view word) {
    std::string_view index = word.substr(0, word.find('/'));
    if (word.find('/') != std::string_view::npos) check_corner_form(word);
    std::int64_t i = 0;
    switch (read_integer(index, i)) {
      case integer_result::ok: break;
      case integer_result::not_whole:
        lines_.fail(quoted(index) + " is not a vertex index: indices are whole numbers, counted from 1");
      case integer_result::too_large:
        note_huge(index);
        return 0;
      case integer_result::not_a_number:
        lines_.fail(quoted(word) + " is not a vertex index (a face lists vertex numbers, counted from 1)");
    }
    const std::size_t so_far = soup_.points.size();
    if (i == 0) lines_.fail("0 is not a vertex index: OBJ counts vertices from 1");
    if (i < 0) {
      std::uint64_t back = static_cast<std::uint64_t>(-(i + 1)) + 1;  // no overflow at INT64_MIN
      if (back > so_far)
        lines_.fail(std::to_string(i) + " counts back past the first vertex (" + std::to_string(so_far) +
                    (so_far == 1 ? " vertex" : " vertices") + " so far)");
      return static_cast<std::uint32_t>(so_far - back);
    }
    if (static_cast<std::uint64_t>(i) > std::numeric_limits<std::uint32_t>::max()) {
      note_huge(index);
      return 0;
    }
    std::uint32_t zero_based = static_cast<std::uint32_t>(i - 1);
    if (zero_based >= so_far) forward_ = true;
    return zero_based;
  }

  // v/vt/vn: the texture and normal parts are whole numbers (vt may be empty).
  void check_corner_form(std::string_view word) {
    std::size_t first = word.find('/');
    std::size_t second = word.find('/', first + 1);
    std::string_view vt = word.substr(first + 1, second == std::string_view::npos ? std::string_view::npos
                                                                                 : second - first - 1);
    std::string_view vn = second == std::string_view::npos ? std::string_view() : word.substr(second + 1);
    std::int64_t ignored;
    bool ok = (vt.empty() ? second != std::string_view::npos : read_integer(vt, ignored) == integer_result::ok) &&
              (second == std::string_view::npos || (vn.find('/') == std::string_view::npos &&
                                                   read_integer(vn, ignored) == integer_result::ok));
    if (!ok) lines_.fail(quoted(word) + " is not a corner (v, v/vt, v/vt/vn or v//vn, in whole numbers)");
  }

  void face(const std::vector<std::string_view>& w) {
    std::vector<std::uint32_t> corners;
    corners.reserve(w.size() - 1);
    huge_in_face_ = false;
    for (std::size_t i = 1; i < w.size(); ++i) corners.push_back(corner(w[i]));
    std::string problem = too_few_corners(corners.size());
    if (problem.empty() && !huge_in_face_) problem = repeated_corner_problem(corners, 1);
    if (!problem.empty()) lines_.fail(problem);
    if (forward_ || huge_in_face_) pending_.push_back({lines_.line(), soup_.faces.size()});
    forward_ = false;
    soup_.faces.push_back(std::move(corners));
  }

  // An index too large for any file vv reads: reported at the end, with
  // the number of vertices the file has.
  void note_huge(std::string_view index) {
    huge_in_face_ = true;
    if (!huge_) huge_ = std::make_pair(lines_.line(), std::string(index));
  }

  void check_references() {
    const std::size_t n = soup_.points.size();
    for (const pending_face_check& p : pending_) {
      if (huge_ && huge_->first <= p.line)
        throw error(path_, huge_->first, missing_vertex_problem(huge_->second, n, 1));
      for (std::uint32_t i : soup_.faces[p.face])
        if (i >= n) throw error(path_, p.line, missing_vertex_problem(std::uint64_t(i) + 1, n, 1));
    }
  }

  [[noreturn]] void fail_without_faces() const {
    const std::size_t n = soup_.points.size();
    auto count = [](std::size_t k, const char* one, const char* many) {
      return std::to_string(k) + " " + (k == 1 ? one : many);
    };
    if (n == 0 && polylines_ == 0 && point_lines_ == 0)
      throw error(path_, 0, "no vertices and no faces (an OBJ mesh has v and f lines)");
    std::string what = polylines_ ? "polylines (" + count(polylines_, "l line", "l lines") + " through " +
                                        count(n, "vertex", "vertices") + ")"
                                  : "points (" + count(n, "v line", "v lines") +
                                        (point_lines_ ? ", " + count(point_lines_, "p line", "p lines") : "") + ")";
    throw error(path_, 0, "no faces: the file holds only " + what +
                              " and no f line; vv reads polygon meshes from .obj files");
  }

  line_scanner lines_;
  std::string path_;
  polygon_soup soup_;
  std::vector<pending_face_check> pending_;
  std::optional<std::pair<int, std::string>> huge_;
  bool forward_ = false, huge_in_face_ = false;
  std::size_t polylines_ = 0, point_lines_ = 0;
};

}  // namespace

polygon_soup read_obj(const std::string& path, const std::string& text) { return obj_reader(path, text).read(); }

}  // namespace vv::formats
