// VLAB contour files (.con), the formats VLAB's contour editor (cuspy) and
// L-studio read:
//
//   original        cver 1 1            cver 1 2 / cver 1 3   version: 1.4
//   4 2 closed      name: leaf          name: leaf            contact: 0 0 0
//   0.4 0.4         points: 4 4         points: 4 5           end: 0 0 0
//   0.4 -0.4        type: closed        type: cr              heading: 0 1 0
//   ...             x y z m             samples: 8 (1 3 only) up: 0 0 -1
//                   ...                 x y z m               size: 1
//                                       ...                   points: 4
//                                                             range: 0.0 1.0
//                                                             dimension: 4
//                                                             type: bspline
//                                                             x y z m ...
//
// The original format's first line is "count dimension closed|open"; each
// point has `dimension` coordinates (2 or more; x y and, from 3, z). In the
// cver formats `points: N TOTAL` gives the number of point lines and the sum
// of their multiplicities m; `type:` is closed|open (1 1) or two letters (1 2,
// 1 3): c|o for closed or open, then e|r for endpoint-interpolating (the
// clamped spline of functions) or regular (the uniform spline). cver 1 2 and
// 1 3 may have `background:` and `backgroundXY:` lines after the type (or
// the samples), which are skipped. version 1.4 curves are open and regular.
//
// Sources: the contour editor's reader and writer in VLAB
// (github.com/AlgorithmicBotany/vlab) and L-studio's; vv 1.1 read the
// original, cver 1 1 and 1.4 formats. Decisions where they are silent: an
// open curve needs at least 4 control points (counting multiplicity), a
// closed one 3; the counts must match the lines exactly.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "bspline.hpp"
#include "vlab_file.hpp"

namespace util::vlab {

struct contour_file {
  enum class format { original, cver_1_1, cver_1_2, cver_1_3, version_1_4 };

  format version = format::cver_1_1;
  std::string name;
  bool closed = false;
  bool endpoint_interpolating = false;  //!< 'e' in a cver 1 2/1 3 type
  unsigned samples = 8;                 //!< cver 1 3's; the editor's default otherwise
  std::vector<bspline::control_point> points;

  //! The fields, for a model's checkpoint (model/state_values.hpp).
  template <class F>
  void vv_fields(F&& f) {
    f("version", version), f("name", name), f("closed", closed);
    f("endpoint_interpolating", endpoint_interpolating), f("samples", samples), f("points", points);
  }
};

namespace detail {

inline bspline::control_point read_contour_point(text_lines& lines, const text_line& line, std::size_t least_words,
                                                 std::size_t most_words, bool with_multiplicity, const char* form) {
  std::vector<std::string_view> w = words(line.text);
  if (w.size() < least_words || w.size() > most_words)
    lines.fail(line.number, std::string("expected a control point ") + form + ", found " + quoted(trim(line.text)));
  bspline::control_point p;
  const std::size_t coordinates = with_multiplicity ? w.size() - 1 : std::min<std::size_t>(w.size(), 3);
  for (std::size_t i = 0; i < coordinates; ++i)
    p.pos[i] = read_number(lines, line.number, w[i], i == 0 ? "x" : i == 1 ? "y" : "z");
  if (with_multiplicity) {
    unsigned long m = 0;
    if (!parse_count(w.back(), m) || m < 1 || m > 1000)
      lines.fail(line.number, "the multiplicity " + quoted(w.back()) + " is not a whole number from 1 to 1000");
    p.multiplicity = static_cast<unsigned>(m);
  }
  return p;
}

//! The `count` point lines announced at line `announced_on`, then the end.
inline void read_contour_points(text_lines& lines, contour_file& c, unsigned count, int announced_on,
                                std::size_t least_words, std::size_t most_words, bool with_multiplicity,
                                const char* form) {
  const std::string announced =
      " of the " + std::to_string(count) + " announced on line " + std::to_string(announced_on);
  for (unsigned i = 0; i < count; ++i) {
    text_line line = lines.next("control point " + std::to_string(i + 1) + announced);
    c.points.push_back(read_contour_point(lines, line, least_words, most_words, with_multiplicity, form));
  }
  if (!lines.done()) {
    text_line extra = lines.next("");
    lines.fail(extra.number, "text after the " + std::to_string(count) + " control points announced on line " +
                                 std::to_string(announced_on) + ": " + quoted(trim(extra.text)));
  }
}

inline void read_original_contour(text_lines& lines, contour_file& c, const text_line& first) {
  c.version = contour_file::format::original;
  c.name = file_stem(lines.path());
  std::vector<std::string_view> w = words(first.text);
  unsigned long count = 0, dimension = 0;
  if (w.size() != 3 || !parse_count(w[0], count) || !parse_count(w[1], dimension) || count > 1000000000ul)
    lines.fail(first.number, "expected 'COUNT DIMENSION closed|open', found " + quoted(trim(first.text)));
  if (dimension < 2 || dimension > 1000)
    lines.fail(first.number, "the dimension must be at least 2 (x y), found " + std::string(w[1]));
  if (w[2] != "closed" && w[2] != "open")
    lines.fail(first.number, "the curve type must be 'closed' or 'open', found " + quoted(w[2]));
  c.closed = w[2] == "closed";
  const std::string form = "with " + std::to_string(dimension) + " coordinates";
  read_contour_points(lines, c, static_cast<unsigned>(count), first.number, dimension, dimension, false,
                      form.c_str());
}

inline void read_cver_contour(text_lines& lines, contour_file& c, const text_line& first) {
  std::vector<std::string_view> w = words(first.text);
  if (w.size() != 3 || w[1] != "1" || (w[2] != "1" && w[2] != "2" && w[2] != "3"))
    lines.fail(first.number, "unsupported contour file version " + quoted(trim(first.text)) +
                                 " (supported: cver 1 1, 1 2 and 1 3, version: 1.4 and the original format)");
  c.version = w[2] == "1" ? contour_file::format::cver_1_1
              : w[2] == "2" ? contour_file::format::cver_1_2
                            : contour_file::format::cver_1_3;
  c.name = std::string(lines.statement("name:", "'name: NAME'").text);
  text_line points = lines.statement("points:", "'points: N TOTAL'");
  std::vector<std::string_view> pw = words(points.text);
  unsigned long count = 0, total = 0;
  if (pw.size() != 2 || !parse_count(pw[0], count) || !parse_count(pw[1], total) || count > 1000000000ul)
    lines.fail(points.number, "expected 'points: N TOTAL' (point lines, sum of multiplicities), found " +
                                  quoted(points.text));
  text_line type = lines.statement("type:", "'type: TYPE'");
  if (c.version == contour_file::format::cver_1_1) {
    if (type.text != "closed" && type.text != "open")
      lines.fail(type.number, "type: must be 'closed' or 'open' in cver 1 1, found " + quoted(type.text));
    c.closed = type.text == "closed";
  } else {
    if (type.text.size() != 2 || (type.text[0] != 'c' && type.text[0] != 'o') ||
        (type.text[1] != 'e' && type.text[1] != 'r'))
      lines.fail(type.number, "type: must be two letters, c or o (closed, open) then e or r (endpoint-"
                              "interpolating, regular), found " + quoted(type.text));
    c.closed = type.text[0] == 'c';
    c.endpoint_interpolating = type.text[1] == 'e';
  }
  if (c.version == contour_file::format::cver_1_3) {
    text_line samples = lines.statement("samples:", "'samples: N'");
    c.samples = read_count(lines, samples, "samples:");
  }
  if (lines.next_starts_with("background:")) {
    lines.statement("background:", "'background: FILE'");
    lines.statement("backgroundXY:", "'backgroundXY: X Y' after 'background:'");
  }
  read_contour_points(lines, c, static_cast<unsigned>(count), points.number, 4, 4, true, "'x y z multiplicity'");
  unsigned long sum = 0;
  for (const bspline::control_point& p : c.points) sum += p.multiplicity;
  if (sum != total)
    lines.fail(points.number, "points: says the multiplicities add up to " + std::to_string(total) +
                                  ", the points' add up to " + std::to_string(sum));
}

inline void read_version_1_4_contour(text_lines& lines, contour_file& c, const text_line& first) {
  if (trim(first.text) != "version: 1.4")
    lines.fail(first.number, "unsupported contour file version " + quoted(trim(first.text)) + " (supported: 1.4)");
  c.version = contour_file::format::version_1_4;
  c.name = file_stem(lines.path());
  for (const char* key : {"contact:", "end:", "heading:", "up:"}) {
    text_line line = lines.statement(key, std::string("'") + key + " X Y Z'");
    std::vector<std::string_view> w = words(line.text);
    if (w.size() != 3) lines.fail(line.number, std::string("expected '") + key + " X Y Z', found " + quoted(line.text));
    for (std::string_view v : w) read_number(lines, line.number, v, key);
  }
  text_line size = lines.statement("size:", "'size: S'");
  read_number(lines, size.number, size.text, "size:");
  text_line points = lines.statement("points:", "'points: N'");
  const unsigned count = read_count(lines, points, "points:");
  lines.statement("range:", "'range: 0.0 1.0'");
  text_line dimension = lines.statement("dimension:", "'dimension: 4'");
  if (dimension.text != "4") lines.fail(dimension.number, "dimension: must be 4, found " + quoted(dimension.text));
  text_line type = lines.statement("type:", "'type: bspline'");
  if (type.text != "bspline") lines.fail(type.number, "type: must be 'bspline', found " + quoted(type.text));
  read_contour_points(lines, c, count, points.number, 4, 4, true, "'x y z multiplicity'");
}

}  // namespace detail

//! Reads a contour file in any of the formats above; throws vv::error
//! naming the file and line of the first problem.
inline contour_file read_contour_file(const std::string& path) {
  text_lines lines(path);
  contour_file c;
  text_line first = lines.next("a contour ('cver 1 1', 'version: 1.4' or 'COUNT DIMENSION closed|open')");
  std::string_view text = trim(first.text);
  if (text.substr(0, 5) == "cver ")
    detail::read_cver_contour(lines, c, first);
  else if (text.substr(0, 8) == "version:")
    detail::read_version_1_4_contour(lines, c, first);
  else if (text.substr(0, 17) == "contourgalleryver")
    lines.fail(first.number, "this is a contour gallery (several contours); a contour file holds one");
  else if (std::isdigit(static_cast<unsigned char>(text[0])))
    detail::read_original_contour(lines, c, first);
  else
    lines.fail(first.number, "not a contour file: expected 'cver 1 1', 'version: 1.4' or "
                             "'COUNT DIMENSION closed|open', found " + quoted(text));

  std::size_t polygon = 0;
  for (const bspline::control_point& p : c.points) polygon += p.multiplicity;
  const std::size_t least = c.closed ? 3 : 4;
  if (polygon < least)
    lines.fail(first.number, std::string(c.closed ? "a closed" : "an open") + " contour needs at least " +
                                 std::to_string(least) + " control points (counting multiplicity), this one has " +
                                 std::to_string(polygon));
  return c;
}

}  // namespace util::vlab
