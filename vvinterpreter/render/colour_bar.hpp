// The colour bar of a drawing coloured by a property. It has a strip at the
// right of the picture to itself (the scene is drawn left of it, so the
// bar never covers the model): the ramp from the lowest value (bottom) to
// the highest (top), a tick with its value at both ends and in the middle,
// and the property's name above. The window and the batch screenshots draw
// the same bar.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "render/label_font.hpp"

namespace vvi {

class colour_bar {
 public:
  //! What the bar shows: the values from lo to hi of the property `name`.
  void set(double lo, double hi, const std::string& name);
  //! The width of its strip in a picture `width` pixels wide.
  int strip_width(int width) const;
  //! Draws it at the right of a width x height picture, in pixel
  //! coordinates (origin at the bottom left, already loaded).
  void draw(int width, int height) const;
  //! Frees its GL objects (before the context goes away).
  void release() { font_.release(); }

 private:
  label_font font_;
  std::string name_;
  //! The ticks' labels from the bottom up, and where they sit on the bar
  //! (0: bottom, 1: top).
  std::vector<std::pair<std::string, double>> ticks_;
};

}  // namespace vvi
