// Reading text in screenshots: the expected text is rasterised here with
// the font the viewer's panel and the colour bar use (Dear ImGui's built-in
// one, at its own size, on whole pixels), and looked for in the picture
// glyph pixel by glyph pixel. A label that shows other numbers, is cut
// off, or is covered by something is not found.
#pragma once

#include <imgui.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "viewer_harness.hpp"

namespace viewer_harness {

//! The panel's area of a window screenshot (Dear ImGui's window, at most
//! 520 pixels wide and 10 from the window's left edge).
constexpr int panel_right_limit = 530;

//! A line of text as the font draws it: which pixels are ink.
struct text_mask {
  int width = 0, height = 0;
  std::vector<char> ink;  // row by row
  bool at(int x, int y) const { return ink[static_cast<std::size_t>(y * width + x)] != 0; }
};

inline text_mask rasterise(const std::string& text) {
  static ImFontAtlas atlas;
  static ImFont* font = atlas.AddFontDefault();
  static unsigned char* pixels = nullptr;
  static int atlas_width = 0, atlas_height = 0;
  if (!pixels) atlas.GetTexDataAsAlpha8(&pixels, &atlas_width, &atlas_height);
  text_mask m;
  m.height = static_cast<int>(font->FontSize);
  float pen = 0;
  for (unsigned char c : text) pen += font->FindGlyph(c)->AdvanceX;
  m.width = static_cast<int>(pen);
  m.ink.assign(static_cast<std::size_t>(m.width * m.height), 0);
  pen = 0;
  for (unsigned char c : text) {
    const ImFontGlyph* g = font->FindGlyph(c);
    // The font's glyph boxes and places are whole texels and pixels.
    int u0 = static_cast<int>(std::lround(g->U0 * atlas_width)), v0 = static_cast<int>(std::lround(g->V0 * atlas_height));
    int w = static_cast<int>(std::lround(g->X1 - g->X0)), h = static_cast<int>(std::lround(g->Y1 - g->Y0));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        int mx = static_cast<int>(std::lround(pen + g->X0)) + x, my = static_cast<int>(std::lround(g->Y0)) + y;
        if (mx < 0 || my < 0 || mx >= m.width || my >= m.height) continue;
        if (pixels[(v0 + y) * atlas_width + u0 + x] >= 128) m.ink[static_cast<std::size_t>(my * m.width + mx)] = 1;
      }
    pen += g->AdvanceX;
  }
  return m;
}

//! Where a line of text is in a picture: its box, top left inclusive.
struct text_place {
  int x = -1, y = -1, width = 0, height = 0;
  bool found() const { return x >= 0; }
  int centre_y() const { return y + height / 2; }
};

//! Which pixels of a picture are ink (e.g. "dark", for dark text on a
//! light background).
using ink_test = std::function<bool(const unsigned char*)>;

//! The first place (rows from the top, then columns) in the region
//! [x0, x1) x [y0, y1) of `im` where `text` is written: every pixel of the
//! line's box is ink exactly where the font's glyphs are.
inline text_place find_text(const image& im, const std::string& text, const ink_test& is_ink, int x0 = 0, int y0 = 0,
                            int x1 = -1, int y1 = -1) {
  text_mask m = rasterise(text);
  if (x1 < 0) x1 = im.width;
  if (y1 < 0) y1 = im.height;
  std::vector<char> ink(static_cast<std::size_t>(im.width) * static_cast<std::size_t>(im.height));
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) ink[static_cast<std::size_t>(y) * static_cast<std::size_t>(im.width) + static_cast<std::size_t>(x)] = is_ink(im.at(x, y));
  // The glyphs' pixels first: most places fail on the first of them.
  std::vector<std::pair<int, int>> on, off;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) (m.at(x, y) ? on : off).emplace_back(x, y);
  auto ink_at = [&](int x, int y) { return ink[static_cast<std::size_t>(y) * static_cast<std::size_t>(im.width) + static_cast<std::size_t>(x)] != 0; };
  for (int y = std::max(y0, 0); y + m.height <= std::min(y1, im.height); ++y)
    for (int x = std::max(x0, 0); x + m.width <= std::min(x1, im.width); ++x) {
      bool match = true;
      for (const auto& [dx, dy] : on)
        if (!ink_at(x + dx, y + dy)) {
          match = false;
          break;
        }
      for (std::size_t i = 0; match && i < off.size(); ++i)
        if (ink_at(x + off[i].first, y + off[i].second)) match = false;
      if (match) return {x, y, m.width, m.height};
    }
  return {};
}

inline bool is_dark(const unsigned char* p) { return p[0] < 100 && p[1] < 100 && p[2] < 100; }
inline bool is_white(const unsigned char* p) { return p[0] > 160 && p[1] > 160 && p[2] > 160; }
//! The panel's grey help text (and anything lighter) on its dark background.
inline bool is_light(const unsigned char* p) { return p[0] > 90 && p[1] > 90 && p[2] > 90; }

//! How many pixels of the region [x0, x1) x [y0, y1) are near the colour.
inline long count_colour(const image& im, const unsigned char (&rgb)[3], int tolerance, int x0 = 0, int y0 = 0,
                         int x1 = -1, int y1 = -1) {
  if (x1 < 0) x1 = im.width;
  if (y1 < 0) y1 = im.height;
  long n = 0;
  for (int y = std::max(y0, 0); y < std::min(y1, im.height); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, im.width); ++x) {
      const unsigned char* p = im.at(x, y);
      bool near = true;
      for (int c = 0; c < 3; ++c) near = near && std::abs(int(p[c]) - int(rgb[c])) <= tolerance;
      n += near;
    }
  return n;
}

}  // namespace viewer_harness
