// util::Materials: a VLAB material file (.mat), re-read on the host's
// "reread files".
//
//   util::Materials materials("plant.mat");
//   materials.useMaterial(3);          // glMaterial* on GL_FRONT_AND_BACK
//
// The file is binary: a record of 15 bytes per material that differs from
// OpenGL's default, in any order:
//
//   byte 0       the material's index, 0-255
//   byte 1       transparency, 0 (opaque) to 255 (transparent)
//   bytes 2-4    ambient red, green, blue     (each 0-255 for 0 to 1)
//   bytes 5-7    diffuse
//   bytes 8-10   emission
//   bytes 11-13  specular
//   byte 14      shininess, 0-128
//
// Every colour's alpha is 1 - transparency. Materials the file leaves out
// are OpenGL's default (ambient 0.2, diffuse 0.8, emission and specular 0,
// shininess 0). Source: VLAB's material editor medit, which reads and writes
// these records (github.com/AlgorithmicBotany/vlab, medit/mwviewer.cpp) and
// whose manual gives the ranges. vv 1.1 read the records in order and
// ignored byte 0; this reads them as medit does, by index.
// Decided here: a file whose size is not a multiple of 15, or that gives
// one index twice, is an error naming the record and its byte offset. An
// index above 255 means 255, as in vv 1.1.
#pragma once

#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <utility>

#include <vv/error.hpp>
#include <model/registered_file.hpp>

#include "vlab_file.hpp"

namespace util {

namespace materials_detail {
//! vv 1.1's layout: RGBA arrays in [0, 1] that go straight to
//! glMaterialfv (`m.diffuse`, `m.diffuse[0]`).
struct Material {
  GLfloat ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
  GLfloat diffuse[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  GLfloat emission[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  GLfloat specular[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  GLfloat shiny = 0.0f;         //!< shininess, 0-128
  GLfloat transparency = 0.0f;  //!< 0 opaque, 1 transparent

  //! The fields, for a model's checkpoint (model/state_values.hpp).
  template <class F>
  void vv_fields(F&& f) {
    f("ambient", ambient), f("diffuse", diffuse), f("emission", emission), f("specular", specular);
    f("shiny", shiny), f("transparency", transparency);
  }
};
//! The 256 materials; without a file every one is OpenGL's default.
struct table {
  std::array<Material, 256> at{};

  template <class F>
  void vv_fields(F&& f) {
    f("at", at);
  }
};
}  // namespace materials_detail

class Materials : public vv::model::registered_file<Materials, vv::file_kind::materials, materials_detail::table> {
 public:
  using Material = materials_detail::Material;
  static constexpr unsigned entries = 256;
  static constexpr std::size_t record_size = 15;

  //! No file: every material OpenGL's default; reread() does nothing.
  Materials() = default;

  //! Reads `path`; throws vv::error "file: problem" if it cannot. reread()
  //! reads it again; on an error the materials stay as they were.
  explicit Materials(const std::string& path) : registered_file(path) {}

  //! The file's materials (model/registered_file.hpp calls it).
  static materials_detail::table read(const std::string& path) {
    const std::string bytes = vlab::read_bytes(path);
    if (bytes.size() % record_size != 0) {
      const std::size_t record = bytes.size() / record_size;
      throw vv::error(path, 0, "the file ends inside record " + std::to_string(record) + " (byte offset " +
                                     std::to_string(record * record_size) + "): it has " +
                                     std::to_string(bytes.size() % record_size) + " of its 15 bytes");
    }
    materials_detail::table materials;
    std::array<int, entries> given_by;  // the record that set each index, or -1
    given_by.fill(-1);
    for (std::size_t record = 0; record * record_size < bytes.size(); ++record) {
      const char* r = bytes.data() + record * record_size;
      const unsigned index = byte(r[0]);
      if (given_by[index] >= 0)
        throw vv::error(path, 0, "record " + std::to_string(record) + " (byte offset " +
                                       std::to_string(record * record_size) + ") gives material " +
                                       std::to_string(index) + " again, after record " +
                                       std::to_string(given_by[index]));
      given_by[index] = static_cast<int>(record);
      materials.at[index] = decode(r);
    }
    return materials;
  }

  const Material& getMaterial(unsigned index) const { return contents().at[std::min(index, entries - 1)]; }

  //! t of material i and 1 - t of material j, every value (vv 1.1's
  //! weighting; t is clamped to [0, 1]).
  Material blended(unsigned i, unsigned j, double t) const {
    t = std::clamp(t, 0.0, 1.0);
    const Material& a = getMaterial(i);
    const Material& b = getMaterial(j);
    auto mix = [t](GLfloat x, GLfloat y) { return static_cast<GLfloat>(x * t + y * (1.0 - t)); };
    Material m;
    for (std::size_t c = 0; c < 4; ++c) {
      m.ambient[c] = mix(a.ambient[c], b.ambient[c]);
      m.diffuse[c] = mix(a.diffuse[c], b.diffuse[c]);
      m.emission[c] = mix(a.emission[c], b.emission[c]);
      m.specular[c] = mix(a.specular[c], b.specular[c]);
    }
    m.shiny = mix(a.shiny, b.shiny);
    m.transparency = mix(a.transparency, b.transparency);
    return m;
  }

  void useMaterial(unsigned index) const { apply(getMaterial(index)); }
  void blend(unsigned i, unsigned j, double t) const { apply(blended(i, j, t)); }

  //! Sets the OpenGL material of both faces.
  static void apply(const Material& m) {
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, m.ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, m.diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, m.emission);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, m.specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, m.shiny);
  }

 private:
  static unsigned byte(char c) { return static_cast<unsigned char>(c); }

  static Material decode(const char* r) {
    auto unit = [r](std::size_t i) { return static_cast<GLfloat>(byte(r[i])) / 255.0f; };
    Material m;
    m.transparency = unit(1);
    for (std::size_t c = 0; c < 3; ++c) {
      m.ambient[c] = unit(2 + c);
      m.diffuse[c] = unit(5 + c);
      m.emission[c] = unit(8 + c);
      m.specular[c] = unit(11 + c);
    }
    m.ambient[3] = m.diffuse[3] = m.emission[3] = m.specular[3] = 1.0f - m.transparency;
    m.shiny = static_cast<GLfloat>(byte(r[14]));
    return m;
  }

};

}  // namespace util
