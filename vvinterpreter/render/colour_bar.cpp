#include "render/colour_bar.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <algorithm>
#include <cstdio>

#include "render/colour_ramp.hpp"

namespace vvi {

namespace {

// The strip, left to right, in pixels: a gap that keeps the bar off the
// scene, the bar, its ticks, the labels, a margin.
constexpr int gap = 16, bar_width = 16, tick_length = 4, label_gap = 4, margin = 10;
// The bar runs over the middle half of the picture's height.
constexpr double bar_bottom = 0.25, bar_top = 0.75;

const rgb ink = {0.12f, 0.12f, 0.16f};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

}  // namespace

void colour_bar::set(double lo, double hi, const std::string& name) {
  name_ = name;
  ticks_.clear();
  if (hi > lo) ticks_ = {{number(lo), 0}, {number(lo + (hi - lo) / 2), 0.5}, {number(hi), 1}};
  else ticks_ = {{number(lo), 0.5}};  // one value: every vertex has the middle colour
}

int colour_bar::strip_width(int width) const {
  int labels = 0;
  for (const auto& t : ticks_) labels = std::max(labels, font_.width(t.first));
  int w = std::max(gap + bar_width + tick_length + label_gap + labels, gap + font_.width(name_)) + margin;
  return std::min(w, width / 3);  // a narrow picture keeps most of its width for the model
}

void colour_bar::draw(int width, int height) const {
  int x0 = width - strip_width(width) + gap, x1 = x0 + bar_width;
  double y0 = height * bar_bottom, y1 = height * bar_top;
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= 32; ++i) {
    rgb c = colour_ramp(i / 32.0);
    glColor3f(c[0], c[1], c[2]);
    double y = y0 + (y1 - y0) * i / 32.0;
    glVertex2d(x0, y);
    glVertex2d(x1, y);
  }
  glEnd();
  int line = font_.line_height();
  glColor3f(ink[0], ink[1], ink[2]);
  glBegin(GL_LINES);
  for (const auto& t : ticks_) {
    double y = std::min(y0 + (y1 - y0) * t.second, y1 - 1) + 0.5;  // the top tick on the bar's last row
    glVertex2d(x1, y);
    glVertex2d(x1 + tick_length, y);
  }
  glEnd();
  // Labels centred on their ticks; rows counted from the top.
  for (const auto& t : ticks_) {
    int centre = height - static_cast<int>(y0 + (y1 - y0) * t.second);
    font_.draw(t.first, x1 + tick_length + label_gap, centre - line / 2, ink, height);
  }
  int top = height - static_cast<int>(y1);
  font_.draw(name_, x0, top - line / 2 - 4 - line, ink, height);
}

}  // namespace vvi
