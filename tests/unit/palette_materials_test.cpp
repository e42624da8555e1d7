// util::Palette and util::Materials: reading binary files with known bytes,
// the colours and materials they give, the OpenGL calls they make (recorded
// by stand-ins: this executable does not link libGL), file errors and
// rereading.
#include <util/materials.hpp>
#include <util/palette.hpp>

#include <gtest/gtest.h>

#include <GL/gl.h>

#include <string>
#include <vector>

#include "test_files.hpp"

namespace {

struct gl_call {
  std::string name;
  GLenum face = 0, pname = 0;
  std::vector<float> values;
};
std::vector<gl_call> recorded;

}  // namespace

extern "C" void glColor4fv(const GLfloat* v) { recorded.push_back({"glColor4fv", 0, 0, {v[0], v[1], v[2], v[3]}}); }
extern "C" void glMaterialfv(GLenum face, GLenum pname, const GLfloat* v) {
  recorded.push_back({"glMaterialfv", face, pname, {v[0], v[1], v[2], v[3]}});
}
extern "C" void glMaterialf(GLenum face, GLenum pname, GLfloat v) {
  recorded.push_back({"glMaterialf", face, pname, {v}});
}

namespace {

using test_files::write_scratch;
using util::Materials;
using util::Palette;

// Entry i is (i, 255 - i, 7i mod 256).
std::string palette_bytes() {
  std::string bytes;
  for (int i = 0; i < 256; ++i) {
    bytes += static_cast<char>(i);
    bytes += static_cast<char>(255 - i);
    bytes += static_cast<char>((7 * i) % 256);
  }
  return bytes;
}

std::string palette_error(const std::string& path) {
  try {
    Palette p(path);
  } catch (const vv::error& e) {
    return e.what();
  }
  return "";
}

std::string materials_error(const std::string& path) {
  try {
    Materials m(path);
  } catch (const vv::error& e) {
    return e.what();
  }
  return "";
}

void expect_colour(const util::Colour<float>& c, float r, float g, float b, float a) {
  EXPECT_FLOAT_EQ(c.r(), r);
  EXPECT_FLOAT_EQ(c.g(), g);
  EXPECT_FLOAT_EQ(c.b(), b);
  EXPECT_FLOAT_EQ(c.a(), a);
}

void expect_colour(const GLfloat (&c)[4], float r, float g, float b, float a) {
  expect_colour(util::Colour<float>(c[0], c[1], c[2], c[3]), r, g, b, a);
}

TEST(UtilPalette, ReadsTheBytes) {
  Palette p(write_scratch("plant.map", palette_bytes()));
  const Palette::PaletteColour& c = p.getColour(10);  // 10, 245, 70
  EXPECT_EQ(c.r(), 10);
  EXPECT_EQ(c.g(), 245);
  EXPECT_EQ(c.b(), 70);
  EXPECT_EQ(c.a(), 255);
  expect_colour(p.colour(10), 10 / 255.0f, 245 / 255.0f, 70 / 255.0f, 1);
  expect_colour(p.colour(255), 1, 0, (7 * 255 % 256) / 255.0f, 1);  // 7·255 mod 256 = 249
  EXPECT_EQ(p.getColour(300), p.getColour(255));                     // clamped as in vv 1.1
}

TEST(UtilPalette, UseColourAndBlendSetTheGlColour) {
  Palette p(write_scratch("gl.map", palette_bytes()));
  recorded.clear();
  p.useColour(51, 0.5);  // 51, 204, 101
  ASSERT_EQ(recorded.size(), 1u);
  EXPECT_EQ(recorded[0].name, "glColor4fv");
  EXPECT_EQ(recorded[0].values, (std::vector<float>{51 / 255.0f, 204 / 255.0f, 101 / 255.0f, 0.5f}));

  // 1/4 of entry 0 (0, 255, 0) and 3/4 of entry 100 (100, 155, 188):
  // (75, 255/4 + 465/4 = 180, 141) / 255.
  recorded.clear();
  p.blend(0, 100, 0.25);
  ASSERT_EQ(recorded.size(), 1u);
  ASSERT_EQ(recorded[0].values.size(), 4u);
  EXPECT_FLOAT_EQ(recorded[0].values[0], 75 / 255.0f);
  EXPECT_FLOAT_EQ(recorded[0].values[1], 180 / 255.0f);
  EXPECT_FLOAT_EQ(recorded[0].values[2], 141 / 255.0f);
  EXPECT_FLOAT_EQ(recorded[0].values[3], 1.0f);
  expect_colour(p.blended(0, 100, 2.0), 0, 1, 0, 1);  // w clamped to 1: all of entry 0
}

TEST(UtilPalette, WrongSizeIsAnError) {
  const std::string bytes = palette_bytes();
  const std::string short_path = write_scratch("short.map", bytes.substr(0, 700));
  EXPECT_EQ(palette_error(short_path), short_path + ": the file has 700 bytes (233 complete entries): a colour map "
                                                    "has 256 entries of 3 bytes (red, green, blue), 768 bytes");
  const std::string long_path = write_scratch("long.map", bytes + "x");
  EXPECT_EQ(palette_error(long_path), long_path + ": the file has 769 bytes (256 complete entries): a colour map "
                                                  "has 256 entries of 3 bytes (red, green, blue), 768 bytes");
  const std::string missing = test_files::scratch_dir() + "missing.map";
  EXPECT_EQ(palette_error(missing), missing + ": cannot open: No such file or directory");
}

TEST(UtilPalette, RereadKeepsLastGoodColours) {
  std::string bytes = palette_bytes();
  const std::string path = write_scratch("live.map", bytes);
  Palette p(path);
  write_scratch("live.map", bytes.substr(0, 300));
  EXPECT_THROW(p.reread(), vv::error);
  EXPECT_EQ(p.getColour(200).r(), 200);
  bytes[3 * 200] = static_cast<char>(7);
  write_scratch("live.map", bytes);
  p.reread();
  EXPECT_EQ(p.getColour(200).r(), 7);
}

// A 15-byte record: index, transparency, ambient rgb, diffuse rgb,
// emission rgb, specular rgb, shininess.
std::string record(int index, int transparency, int base, int shininess) {
  std::string r;
  r += static_cast<char>(index);
  r += static_cast<char>(transparency);
  for (int i = 0; i < 12; ++i) r += static_cast<char>(base + i);
  r += static_cast<char>(shininess);
  return r;
}

TEST(UtilMaterials, ReadsRecordsByIndex) {
  // Material 3 first, then material 0; the rest stay OpenGL's default.
  Materials m(write_scratch("plant.mat", record(3, 51, 100, 64) + record(0, 0, 200, 128)));
  const Materials::Material& three = m.getMaterial(3);
  const float alpha = 1 - 51 / 255.0f;  // transparency 51/255 = 0.2
  EXPECT_FLOAT_EQ(three.transparency, 0.2f);
  expect_colour(three.ambient, 100 / 255.0f, 101 / 255.0f, 102 / 255.0f, alpha);
  expect_colour(three.diffuse, 103 / 255.0f, 104 / 255.0f, 105 / 255.0f, alpha);
  expect_colour(three.emission, 106 / 255.0f, 107 / 255.0f, 108 / 255.0f, alpha);
  expect_colour(three.specular, 109 / 255.0f, 110 / 255.0f, 111 / 255.0f, alpha);
  EXPECT_EQ(three.shiny, 64.0f);
  const GLfloat* to_gl = three.diffuse;  // vv 1.1's arrays go straight to glMaterialfv
  EXPECT_EQ(to_gl[1], three.diffuse[1]);

  const Materials::Material& zero = m.getMaterial(0);
  expect_colour(zero.ambient, 200 / 255.0f, 201 / 255.0f, 202 / 255.0f, 1);
  EXPECT_EQ(zero.shiny, 128.0f);

  const Materials::Material& seven = m.getMaterial(7);  // not in the file
  expect_colour(seven.ambient, 0.2f, 0.2f, 0.2f, 1);
  expect_colour(seven.diffuse, 0.8f, 0.8f, 0.8f, 1);
  expect_colour(seven.emission, 0, 0, 0, 1);
  expect_colour(seven.specular, 0, 0, 0, 1);
  EXPECT_EQ(seven.shiny, 0.0f);
  EXPECT_EQ(seven.transparency, 0.0f);
  EXPECT_EQ(&m.getMaterial(1000), &m.getMaterial(255));  // clamped as in vv 1.1
}

TEST(UtilMaterials, EmptyFileIsAllDefaults) {
  Materials m(write_scratch("none.mat", ""));
  expect_colour(m.getMaterial(0).diffuse, 0.8f, 0.8f, 0.8f, 1);
}

TEST(UtilMaterials, UseMaterialSetsBothFaces) {
  Materials m(write_scratch("gl.mat", record(5, 0, 10, 32)));
  recorded.clear();
  m.useMaterial(5);
  ASSERT_EQ(recorded.size(), 5u);
  const GLenum pnames[] = {GL_AMBIENT, GL_DIFFUSE, GL_EMISSION, GL_SPECULAR};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(recorded[i].name, "glMaterialfv");
    EXPECT_EQ(recorded[i].face, static_cast<GLenum>(GL_FRONT_AND_BACK));
    EXPECT_EQ(recorded[i].pname, pnames[i]);
    const float base = static_cast<float>(10 + 3 * i);
    EXPECT_EQ(recorded[i].values,
              (std::vector<float>{base / 255.0f, (base + 1) / 255.0f, (base + 2) / 255.0f, 1.0f}));
  }
  EXPECT_EQ(recorded[4].name, "glMaterialf");
  EXPECT_EQ(recorded[4].face, static_cast<GLenum>(GL_FRONT_AND_BACK));
  EXPECT_EQ(recorded[4].pname, static_cast<GLenum>(GL_SHININESS));
  EXPECT_EQ(recorded[4].values, std::vector<float>{32.0f});
}

TEST(UtilMaterials, BlendWeighsTheFirst) {
  Materials m(write_scratch("blend.mat", record(1, 0, 0, 100)));
  // 3/4 of material 1 (shininess 100) and 1/4 of the default 2 (0).
  EXPECT_FLOAT_EQ(m.blended(1, 2, 0.75).shiny, 75.0f);
  EXPECT_FLOAT_EQ(m.blended(1, 2, 0.75).diffuse[0], 0.75f * 3 / 255.0f + 0.25f * 0.8f);
  recorded.clear();
  m.blend(1, 2, 0.75);
  ASSERT_EQ(recorded.size(), 5u);
  EXPECT_FLOAT_EQ(recorded[4].values[0], 75.0f);
}

TEST(UtilMaterials, FileErrors) {
  const std::string torn = write_scratch("torn.mat", record(0, 0, 0, 0) + record(1, 0, 0, 0).substr(0, 14));
  EXPECT_EQ(materials_error(torn), torn + ": the file ends inside record 1 (byte offset 15): it has 14 of its 15 bytes");
  const std::string twice = write_scratch("twice.mat", record(4, 0, 0, 0) + record(9, 0, 0, 0) + record(4, 0, 0, 0));
  EXPECT_EQ(materials_error(twice), twice + ": record 2 (byte offset 30) gives material 4 again, after record 0");
}

TEST(UtilMaterials, RereadKeepsLastGoodMaterials) {
  const std::string path = write_scratch("live.mat", record(2, 0, 50, 10));
  Materials m(path);
  write_scratch("live.mat", record(2, 0, 60, 10).substr(0, 7));
  EXPECT_THROW(m.reread(), vv::error);
  EXPECT_FLOAT_EQ(m.getMaterial(2).ambient[0], 50 / 255.0f);
  write_scratch("live.mat", record(2, 0, 60, 10));
  m.reread();
  EXPECT_FLOAT_EQ(m.getMaterial(2).ambient[0], 60 / 255.0f);
}

TEST(UtilPaletteMaterials, DefaultObjects) {
  Palette p;
  EXPECT_EQ(p.getColour(3), Palette::PaletteColour(0, 0, 0, 255));
  Materials m;
  EXPECT_EQ(m.getMaterial(3).shiny, 0.0f);
  p.reread();
  m.reread();
  EXPECT_EQ(p.path(), "");
}

}  // namespace
