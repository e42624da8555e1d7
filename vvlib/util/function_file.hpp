// VLAB function files (.func), as VLAB's funcedit and L-studio write them.
//
//   original format          fver 1 1
//   range: 0.0 1.0           fver 1 1
//   points: 4                name: growth
//   0.0 0.0                  samples: 10
//   0.3 0.1                  background: sketch.png     (optional, both
//   0.6 0.9                  backgroundXY: 0.1 0.2       lines or neither)
//   1.0 0.3                  flip: off
//                            points: 4
//                            0.0 0.0 [multiplicity]
//                            ...
//
// Sources: the VLAB funcedit manual ("Function File Format": range, points,
// at least 4 control points, non-decreasing x) and the readers and writers
// of VLAB's and L-studio's function editors (github.com/AlgorithmicBotany/vlab):
// the statement order above, flip on|off, the optional background lines and
// the optional third column, the point's multiplicity (funcedit).
//
// Decisions where the sources are silent:
// * `range:` (original format) is read and kept, not used: the function's
//   domain is its first and last control point x.
// * The original format has no name or samples: the name is the file name
//   without folder and extension (as funcedit does), samples 10 (funcedit's
//   default).
// * `flip` only tells the editor to show x vertically; the file always
//   holds x y, and evaluation ignores flip.
// * Stricter than the editors: the count after `points:` must match the
//   point lines exactly, and nothing may follow the last point.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "bspline.hpp"
#include "vlab_file.hpp"

namespace util::vlab {

struct function_file {
  enum class format { original, fver_1_1 };

  format version = format::fver_1_1;
  std::string name = "noname";
  unsigned samples = 10;  //!< values lpfg and cpfg precompute; kept for the editor
  bool flip = false;      //!< the editor shows x vertically
  bool has_background = false;  //!< funcedit's tracing image
  std::string background;
  double background_x = 0, background_y = 0;
  double range_min = 0, range_max = 1;  //!< original format only
  std::vector<bspline::control_point> points;

  //! The fields, for a model's checkpoint (model/state_values.hpp).
  template <class F>
  void vv_fields(F&& f) {
    f("version", version), f("name", name), f("samples", samples), f("flip", flip);
    f("has_background", has_background), f("background", background);
    f("background_x", background_x), f("background_y", background_y);
    f("range_min", range_min), f("range_max", range_max), f("points", points);
  }
};

//! What is wrong with these control points as a function ("" if nothing),
//! and which point is at fault.
struct function_points_problem {
  std::string problem;
  std::size_t point = 0;
};

inline function_points_problem check_function_points(const std::vector<bspline::control_point>& points) {
  if (points.size() < 4)
    return {"a function needs at least 4 control points, this one has " + std::to_string(points.size()), 0};
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].multiplicity < 1) return {"a control point's multiplicity must be at least 1", i};
    if (i > 0 && points[i].pos.x() < points[i - 1].pos.x())
      return {"x decreases from " + format_number(points[i - 1].pos.x()) + " to " +
                  format_number(points[i].pos.x()) +
                  ": a function's control points must have non-decreasing x",
              i};
  }
  return {};
}

namespace detail {

//! `fver 1 1` or `range:` and what follows up to `points:`.
inline void read_function_header(text_lines& lines, function_file& f) {
  text_line first = lines.next("'fver 1 1' or 'range:'");
  std::string_view text = trim(first.text);
  std::vector<std::string_view> w = words(text);
  if (w[0] == "range:") {
    f.version = function_file::format::original;
    f.name = file_stem(lines.path());
    if (w.size() != 3) lines.fail(first.number, "expected 'range: MIN MAX', found " + quoted(text));
    f.range_min = read_number(lines, first.number, w[1], "range");
    f.range_max = read_number(lines, first.number, w[2], "range");
    return;
  }
  if (w[0] == "funcgalleryver")
    lines.fail(first.number, "this is a function gallery (several functions); a function file holds one");
  if (w[0] != "fver")
    lines.fail(first.number, "not a function file: expected 'fver 1 1' or 'range:', found " + quoted(text));
  if (w.size() != 3 || w[1] != "1" || w[2] != "1")
    lines.fail(first.number, "unsupported function file version " + quoted(text) +
                                 " (supported: 'fver 1 1' and the original format starting with 'range:')");
  f.version = function_file::format::fver_1_1;
  f.name = std::string(lines.statement("name:", "'name: NAME'").text);
  text_line samples = lines.statement("samples:", "'samples: N'");
  f.samples = read_count(lines, samples, "samples:");
  if (f.samples < 1) lines.fail(samples.number, "samples: must be at least 1");
  if (lines.next_starts_with("background:")) {
    f.has_background = true;
    f.background = std::string(lines.statement("background:", "'background: FILE'").text);
    text_line xy = lines.statement("backgroundXY:", "'backgroundXY: X Y' after 'background:'");
    std::vector<std::string_view> xyw = words(xy.text);
    if (xyw.size() != 2) lines.fail(xy.number, "expected 'backgroundXY: X Y', found " + quoted(xy.text));
    f.background_x = read_number(lines, xy.number, xyw[0], "backgroundXY:");
    f.background_y = read_number(lines, xy.number, xyw[1], "backgroundXY:");
  }
  text_line flip = lines.statement("flip:", "'flip: on' or 'flip: off'");
  if (flip.text != "on" && flip.text != "off")
    lines.fail(flip.number, "flip: must be 'on' or 'off', found " + quoted(flip.text));
  f.flip = flip.text == "on";
}

//! `points: N` and the N control points.
inline void read_function_points(text_lines& lines, function_file& f) {
  text_line statement = lines.statement("points:", "'points: N'");
  const unsigned count = read_count(lines, statement, "points:");
  if (count < 4)
    lines.fail(statement.number, "a function needs at least 4 control points, 'points:' says " + std::to_string(count));
  const std::string announced = " of the " + std::to_string(count) + " that 'points:' on line " +
                                std::to_string(statement.number) + " announces";
  int previous_line = 0;
  for (unsigned i = 0; i < count; ++i) {
    text_line line = lines.next("control point " + std::to_string(i + 1) + announced);
    std::vector<std::string_view> w = words(line.text);
    if (w.size() != 2 && w.size() != 3)
      lines.fail(line.number, "expected a control point 'x y' or 'x y multiplicity', found " + quoted(trim(line.text)));
    bspline::control_point p;
    p.pos = Point<double>(read_number(lines, line.number, w[0], "x"), read_number(lines, line.number, w[1], "y"));
    if (w.size() == 3) {
      unsigned long m = 0;
      if (!parse_count(w[2], m) || m < 1 || m > 1000)
        lines.fail(line.number, "the multiplicity " + quoted(w[2]) + " is not a whole number from 1 to 1000");
      p.multiplicity = static_cast<unsigned>(m);
    }
    if (!f.points.empty() && p.pos.x() < f.points.back().pos.x())
      lines.fail(line.number, "x decreases from " + format_number(f.points.back().pos.x()) + " (line " +
                                  std::to_string(previous_line) + ") to " + format_number(p.pos.x()) +
                                  ": a function's control points must have non-decreasing x");
    f.points.push_back(p);
    previous_line = line.number;
  }
  if (!lines.done()) {
    text_line extra = lines.next("");
    lines.fail(extra.number, "text after the " + std::to_string(count) + " control points that 'points:' on line " +
                                 std::to_string(statement.number) + " announces: " + quoted(trim(extra.text)));
  }
}

}  // namespace detail

//! Reads a function file in either format; throws vv::error naming the
//! file and line of the first problem.
inline function_file read_function_file(const std::string& path) {
  text_lines lines(path);
  function_file f;
  detail::read_function_header(lines, f);
  detail::read_function_points(lines, f);
  return f;
}

//! The file in the `fver 1 1` format. Numbers are written in their
//! shortest exact form, so reading the text back gives the same function;
//! the multiplicity column appears only where it is not 1 (L-studio reads
//! two columns).
inline std::string function_file_text(const function_file& f) {
  std::string out = "fver 1 1\nname: " + f.name + "\nsamples: " + std::to_string(f.samples) + "\n";
  if (f.has_background)
    out += "background: " + f.background + "\nbackgroundXY: " + format_number(f.background_x) + " " +
           format_number(f.background_y) + "\n";
  out += std::string("flip: ") + (f.flip ? "on" : "off") + "\n";
  out += "points: " + std::to_string(f.points.size()) + "\n";
  for (const bspline::control_point& p : f.points) {
    out += format_number(p.pos.x()) + " " + format_number(p.pos.y());
    if (p.multiplicity != 1) out += " " + std::to_string(p.multiplicity);
    out += "\n";
  }
  return out;
}

}  // namespace util::vlab
