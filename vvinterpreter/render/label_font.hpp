// Text drawn into the picture with OpenGL: the colour bar's numbers and the
// property's name, in the window and in batch screenshots alike.
//
// The glyphs are Dear ImGui's built-in font (ProggyClean, 13 pixels), which
// is compiled into the program: no font file to find at run time, the same
// letters as the viewer's panel, and pictures that stay byte-identical from
// machine to machine. Glyphs are drawn at whole pixels without filtering,
// so each one is copied exactly.
#pragma once

#include <memory>
#include <string>

#include "render/colour_ramp.hpp"

struct ImFontAtlas;
struct ImFont;

namespace vvi {

class label_font {
 public:
  label_font();
  ~label_font();
  label_font(const label_font&) = delete;
  label_font& operator=(const label_font&) = delete;

  //! The width of a line of text, in pixels.
  int width(const std::string& text) const;
  //! The height of a line, in pixels.
  int line_height() const;
  //! Draws one line with its top left corner at (x, y), in pixels from the
  //! top left of a picture `height` pixels high. Needs a current GL context
  //! with pixel coordinates (origin at the bottom left) loaded.
  void draw(const std::string& text, int x, int y, const rgb& ink, int height) const;
  //! Frees the glyph texture (before the context goes away).
  void release();

 private:
  std::unique_ptr<ImFontAtlas> atlas_;
  ImFont* font_ = nullptr;
  unsigned char* pixels_ = nullptr;  // the atlas: one alpha byte a texel, owned by atlas_
  int texture_width_ = 0, texture_height_ = 0;
  mutable unsigned texture_ = 0;  // made on the first draw, in that context
};

}  // namespace vvi
