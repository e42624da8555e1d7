// util::Palette: a VLAB colour map (.map), re-read on the host's "reread
// files".
//
//   util::Palette palette("plant.map");
//   palette.useColour(12);             // glColor4fv of colour 12
//   palette.blend(12, 40, 0.25);       // 1/4 of colour 12, 3/4 of colour 40
//
// The file is binary, exactly 768 bytes: 256 entries of one red, one green
// and one blue byte (VLAB's palette editor manual: "A colourmap file is
// always exactly 768 bytes in length"; vv 1.1 read it so too). An index
// above 255 means 255, as in vv 1.1.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <utility>

#include <vv/error.hpp>
#include <model/registered_file.hpp>

#include "colour.hpp"
#include "vlab_file.hpp"

namespace util {

namespace palette_detail {
//! vv 1.1's colour type: bytes 0-255 (alpha 255).
typedef Colour<GLubyte> PaletteColour;
//! A palette's contents; without a file every colour is black.
struct colours {
  std::array<PaletteColour, 256> at;
  colours() { at.fill(PaletteColour(0, 0, 0, 255)); }

  template <class F>
  void vv_fields(F&& f) {
    f("at", at);
  }
};
}  // namespace palette_detail

class Palette : public vv::model::registered_file<Palette, vv::file_kind::palettes, palette_detail::colours> {
 public:
  typedef palette_detail::PaletteColour PaletteColour;
  static constexpr unsigned entries = 256;
  static constexpr std::size_t file_size = 3 * entries;

  //! No file: every colour black; reread() does nothing.
  Palette() = default;

  //! Reads `path`; throws vv::error "file: problem" if it cannot. reread()
  //! reads it again; on an error the colours stay as they were.
  explicit Palette(const std::string& path) : registered_file(path) {}

  //! The file's colours (model/registered_file.hpp calls it).
  static palette_detail::colours read(const std::string& path) {
    const std::string bytes = vlab::read_bytes(path);
    if (bytes.size() != file_size)
      throw vv::error(path, 0, "the file has " + std::to_string(bytes.size()) + " bytes (" +
                                   std::to_string(bytes.size() / 3) + " complete entries): a colour map has "
                                   "256 entries of 3 bytes (red, green, blue), 768 bytes");
    palette_detail::colours c;
    for (std::size_t i = 0; i < entries; ++i)
      c.at[i] = PaletteColour(byte(bytes[3 * i]), byte(bytes[3 * i + 1]), byte(bytes[3 * i + 2]), 255);
    return c;
  }

  //! The colour as the file holds it, bytes 0-255 (vv 1.1).
  const PaletteColour& getColour(unsigned index) const { return contents().at[std::min(index, entries - 1)]; }

  //! The colour with channels in [0, 1], as glColor4fv takes it.
  Colour<float> colour(unsigned index, double alpha = 1) const {
    const PaletteColour& c = getColour(index);
    return Colour<float>(c.r() / 255.0f, c.g() / 255.0f, c.b() / 255.0f, static_cast<float>(alpha));
  }

  //! w of colour i and 1 - w of colour j (vv 1.1's weighting; w is
  //! clamped to [0, 1]).
  Colour<float> blended(unsigned i, unsigned j, double w = 0.5, double alpha = 1) const {
    w = std::clamp(w, 0.0, 1.0);
    Colour<float> c = colour(i) * w + colour(j) * (1.0 - w);
    return c.a(static_cast<float>(alpha));
  }

  void useColour(unsigned index, double alpha = 1) const { glColor4fv(colour(index, alpha).c_data()); }
  void blend(unsigned i, unsigned j, double w = 0.5, double alpha = 1) const {
    glColor4fv(blended(i, j, w, alpha).c_data());
  }

 private:
  static GLubyte byte(char c) { return static_cast<GLubyte>(static_cast<unsigned char>(c)); }

};

}  // namespace util
