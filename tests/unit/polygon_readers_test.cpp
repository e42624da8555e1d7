// The polygon-file readers (vv_formats): what each reads from small files
// written here, and, for each fault, the message, with the line where the
// format has lines. Faces a reader let through unchecked used to surface
// in build_from_faces as "face 0 repeats a vertex", whatever the fault.
#include <vv/vv.hpp>
#include <vv/io/mesh_io.hpp>
#include <vv/io/polygon_files.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "positions_graph.hpp"
#include "special_files.hpp"
#include "test_files.hpp"

namespace {

using test_files::write_scratch;
using Points = std::vector<std::array<double, 3>>;
using Faces = std::vector<std::vector<std::uint32_t>>;

using G = positions_graph::graph;

// The message of reading `bytes` as file `name` into a mesh, without the
// scratch folder; the mesh must be unchanged.
std::string read_error(const std::string& name, const std::string& bytes) {
  const std::string path = write_scratch(name, bytes);
  G::context ctx;
  G::mesh M(ctx);
  std::string message = special_files::error_of([&] { vv::read_mesh(M, path); });
  EXPECT_EQ(M.size(), 0u) << name;
  const std::string folder = test_files::scratch_dir();
  if (message.rfind(folder, 0) == 0) message.erase(0, folder.size());
  return message;
}

vv::polygon_soup read(const std::string& name, const std::string& bytes) {
  return vv::read_polygon_file(write_scratch(name, bytes));
}

const std::string triangle_vs = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

// ---- OBJ ----

TEST(ObjReader, ReadsCornerFormsNegativeIndicesCommentsAndContinuations) {
  vv::polygon_soup soup = read("forms.obj",
                               "# a comment\n"
                               "o square\nv 0 0 0\nv 1 0 0 1\nv 1 1 0 # the third\nv 0 1 0 0.5 0.5 0.5\n"
                               "vt 0 0\nvn 0 0 1\ng side\nusemtl red\ns off\n"
                               "f 1/1/1 2/1/1 3//1\n"
                               "f -4 \\\n -2 -1\n");
  EXPECT_EQ(soup.points, (Points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  EXPECT_EQ(soup.faces, (Faces{{0, 1, 2}, {0, 2, 3}}));
}

// A face may name a vertex that a later line gives.
TEST(ObjReader, TakesAVertexGivenAfterTheFace) {
  vv::polygon_soup soup = read("forward.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n");
  EXPECT_EQ(soup.faces, (Faces{{0, 1, 2}}));
  EXPECT_EQ(soup.points.size(), 3u);
}

TEST(ObjReader, ReadsNumbersExactly) {
  vv::polygon_soup soup = read("exact.obj", "v 0.1 -2.5e-300 1e300\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(soup.points[0][0], 0.1);
  EXPECT_EQ(soup.points[0][1], -2.5e-300);
  EXPECT_EQ(soup.points[0][2], 1e300);
}

TEST(ObjReader, EachFaultHasItsLineAndReason) {
  struct Case {
    const char* text;
    const char* message;
  } cases[] = {
      // A word in a face was skipped: this read as the triangle 1 2 3.
      {"f 1 2 3 x 4\n", "bad.obj:4: 'x' is not a vertex index (a face lists vertex numbers, counted from 1)"},
      // 2.9 read as vertex 2.
      {"f 1 2.9 3\n", "bad.obj:4: '2.9' is not a vertex index: indices are whole numbers, counted from 1"},
      {"f 1 2\n", "bad.obj:4: a face needs at least 3 vertices; this one has 2"},
      {"f 1 2 3000000000\n", "bad.obj:4: vertex 3000000000 does not exist: the file has 3 vertices, numbered from 1"},
      {"f 1 2 99999999999999\n",
       "bad.obj:4: vertex 99999999999999 does not exist: the file has 3 vertices, numbered from 1"},
      {"f 1 2 99999999999999999999999\n",
       "bad.obj:4: vertex 99999999999999999999999 does not exist: the file has 3 vertices, numbered from 1"},
      {"f 1 2 0\n", "bad.obj:4: 0 is not a vertex index: OBJ counts vertices from 1"},
      {"f 1 2 -4\n", "bad.obj:4: -4 counts back past the first vertex (3 vertices so far)"},
      {"f 1 2 1\n", "bad.obj:4: the face lists vertex 1 twice"},
      {"f 1 2 -3\n", "bad.obj:4: the face lists vertex 1 twice"},
      {"f 1/x 2 3\n", "bad.obj:4: '1/x' is not a corner (v, v/vt, v/vt/vn or v//vn, in whole numbers)"},
      {"f 1 2 3\nf 1 3 7\n", "bad.obj:5: vertex 7 does not exist: the file has 3 vertices, numbered from 1"},
      {"v 1 2\n", "bad.obj:4: vertex 4 has 2 coordinates; a vertex needs 3 (x y z)"},
      {"v 1 x 2\n", "bad.obj:4: vertex 4: 'x' is not a number"},
      {"v 1 2 1e999\n", "bad.obj:4: vertex 4: '1e999' is not a number"},
      {"q 1 2 3\n", "bad.obj:4: 'q' is not an OBJ statement (vv reads v and f lines)"},
  };
  for (const Case& c : cases) EXPECT_EQ(read_error("bad.obj", triangle_vs + c.text), c.message) << c.text;
}

TEST(ObjReader, AFileWithoutFacesSaysWhatItHolds) {
  EXPECT_EQ(read_error("points.obj", triangle_vs),
            "points.obj: no faces: the file holds only points (3 v lines) and no f line; vv reads polygon meshes "
            "from .obj files");
  EXPECT_EQ(read_error("cloud.obj", triangle_vs + "p 1 2 3\n"),
            "cloud.obj: no faces: the file holds only points (3 v lines, 1 p line) and no f line; vv reads polygon "
            "meshes from .obj files");
  EXPECT_EQ(read_error("curve.obj", triangle_vs + "l 1 2 3\n"),
            "curve.obj: no faces: the file holds only polylines (1 l line through 3 vertices) and no f line; vv "
            "reads polygon meshes from .obj files");
  EXPECT_EQ(read_error("empty.obj", ""), "empty.obj: no vertices and no faces (an OBJ mesh has v and f lines)");
}

// ---- STL ----

std::string binary_stl(const std::vector<std::array<float, 9>>& triangles) {
  std::string bytes(80, ' ');
  auto put32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes += static_cast<char>((v >> (8 * i)) & 0xff);
  };
  auto put_float = [&](float f) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    put32(bits);
  };
  put32(static_cast<std::uint32_t>(triangles.size()));
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i) put_float(0);  // the normal
    for (float c : t) put_float(c);
    bytes += std::string(2, '\0');
  }
  return bytes;
}

TEST(StlReader, JoinsCornersAtOnePointInTheOrderTheyAppear) {
  vv::polygon_soup soup = read("two.stl", binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0}}));
  EXPECT_EQ(soup.points, (Points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}));
  EXPECT_EQ(soup.faces, (Faces{{0, 1, 2}, {1, 3, 2}}));
  vv::polygon_soup ascii = read("two_ascii.stl",
                                "solid two\n"
                                "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
                                "      vertex 0 1 0\n    endloop\n  endfacet\n"
                                "  facet normal 0 0 1\n    outer loop\n      vertex 1 0 0\n      vertex 1 1 0\n"
                                "      vertex 0 1 0\n    endloop\n  endfacet\n"
                                "endsolid two\n");
  EXPECT_EQ(ascii.points, soup.points);
  EXPECT_EQ(ascii.faces, soup.faces);
}

TEST(StlReader, EachFaultHasItsReason) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // An empty file was an empty mesh, read "successfully".
  EXPECT_EQ(read_error("empty.stl", ""),
            "empty.stl: empty file (an STL file starts with 'solid' or with an 84-byte binary header)");
  // A NaN broke the joining of corners: "face 0 repeats a vertex".
  EXPECT_EQ(read_error("nan.stl", binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, nan, 0, 0, 1, 0}})),
            "nan.stl: triangle 1: corner 2 has y = nan; STL corners are joined into vertices by position, which "
            "takes finite numbers");
  EXPECT_EQ(read_error("flat.stl", binary_stl({{0, 0, 0, 1, 0, 0, 1, 0, 0}})),
            "flat.stl: triangle 0: corners 2 and 3 are the same point (1, 0, 0), so the triangle has fewer than 3 "
            "vertices");
  EXPECT_EQ(read_error("none.stl", binary_stl({})), "none.stl: no triangles (the binary STL header's triangle count is 0)");
  std::string cut = binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}});
  cut.resize(cut.size() - 10);
  EXPECT_EQ(read_error("cut.stl", cut),
            "cut.stl: not an STL file, or a cut-short one: it does not start with 'solid' (ASCII STL), and as binary "
            "STL its header announces 1 triangles, which take 134 bytes, but the file has 124");
  EXPECT_EQ(read_error("short.stl", "hello"),
            "short.stl: not an STL file: it does not start with 'solid' (ASCII STL), and at 5 bytes it is shorter "
            "than a binary STL header (84 bytes)");
  const std::string facet_head = "solid s\nfacet normal 0 0 1\nouter loop\n";
  EXPECT_EQ(read_error("quad.stl", facet_head + "vertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\n"),
            "quad.stl:7: a facet with more than 3 vertices: STL holds triangles only");
  EXPECT_EQ(read_error("word.stl", facet_head + "vertex 0 0 0\nvertex 1 zero 0\n"),
            "word.stl:5: 'zero' is not a number (in a vertex)");
  EXPECT_EQ(read_error("nan_ascii.stl", facet_head + "vertex 0 0 0\nvertex 1 0 0\nvertex nan 1 0\nendloop\nendfacet\n"),
            "nan_ascii.stl:8: triangle 0: corner 3 has x = nan; STL corners are joined into vertices by position, "
            "which takes finite numbers");
  EXPECT_EQ(read_error("open.stl", facet_head + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"),
            "open.stl:8: the file ends inside a solid (no 'endsolid')");
  EXPECT_EQ(read_error("empty_solid.stl", "solid nothing\nendsolid nothing\n"),
            "empty_solid.stl: no triangles (the solid has no facet)");
}

// ---- OFF ----

TEST(OffReader, ReadsColoursAndCountsOnTheHeaderLine) {
  vv::polygon_soup soup = read("coloured.off",
                               "COFF 4 1 0\n# vertices\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1#red\n1 1 0 1 0 0 1 # red\n"
                               "0 1 0 1 0 0 1\n4 0 1 2 3 255 0 0\n");
  EXPECT_EQ(soup.points, (Points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  EXPECT_EQ(soup.faces, (Faces{{0, 1, 2, 3}}));
}

TEST(OffReader, EachFaultHasItsLineAndReason) {
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  struct Case {
    std::string text;
    const char* message;
  } cases[] = {
      {"hello world\n", "bad.off:1: the file starts with 'hello', not an OFF header (OFF, COFF, NOFF, STOFF, ...)"},
      {"", "bad.off: empty file (expected an OFF header)"},
      {"OFF\n3\n", "bad.off:2: expected the counts 'vertices faces edges' after the header, found 1 word"},
      {"OFF\n3 x 0\n", "bad.off:2: the count of faces is 'x', not a whole number of 0 or more"},
      {"OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n",
       "bad.off:2: no faces: the header announces 3 vertices and 0 faces (points only); vv reads polygon meshes from "
       ".off files"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n", "bad.off:4: the file ends after 2 vertices; the header announces 3 vertices and 1 faces"},
      {"OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "bad.off:4: vertex 1 has 2 coordinates; a vertex needs 3 (x y z)"},
      {head + "3 0 1 9\n", "bad.off:6: face 0: vertex 9 does not exist: the file has 3 vertices, numbered from 0"},
      {head + "3 0 1 -1\n", "bad.off:6: face 0: '-1' is not a vertex index (indices count from 0)"},
      {head + "3 0 1.5 2\n", "bad.off:6: face 0: '1.5' is not a vertex index (indices are whole numbers, counted from 0)"},
      {head + "2 0 1\n", "bad.off:6: face 0: a face needs at least 3 vertices; this one has 2"},
      {head + "3 0 1 0\n", "bad.off:6: face 0: the face lists vertex 0 twice"},
      {head + "4 0 1 2\n", "bad.off:6: face 0: says it has 4 vertices but lists 3"},
      {head + "3 0 1 2 red\n",
       "bad.off:6: face 0: 'red' after its 3 vertices is no colour component (a face line is: count, indices, "
       "optional colour)"},
      {head + "3 0 1 2\n3 0 2 1\n", "bad.off:7: more lines than the header announces (3 vertices, 1 faces)"},
  };
  for (const Case& c : cases) EXPECT_EQ(read_error("bad.off", c.text), c.message) << c.text;
}

// ---- PLY ----

std::string ascii_ply(const std::string& faces, int face_count) {
  return "ply\nformat ascii 1.0\ncomment made here\nelement vertex 3\nproperty double x\nproperty double y\n"
         "property double z\nelement face " +
         std::to_string(face_count) + "\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n" +
         faces;
}

TEST(PlyReader, ReadsAnAsciiFile) {
  vv::polygon_soup soup = read("one.ply", ascii_ply("3 0 1 2\n", 1));
  EXPECT_EQ(soup.points, (Points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(soup.faces, (Faces{{0, 1, 2}}));
}

TEST(PlyReader, EachFaultHasItsReason) {
  EXPECT_EQ(read_error("bad.ply", "hello\n"), "bad.ply:1: not a PLY file: it does not start with the line 'ply'");
  EXPECT_EQ(read_error("bad.ply", "ply\nformat ascii 1.0\nelement vertex 2\n"),
            "bad.ply: the header has no 'end_header' line");
  EXPECT_EQ(read_error("bad.ply", "ply\nformat text 1.0\nend_header\n"),
            "bad.ply:2: unknown PLY format 'text' (expected ascii, binary_little_endian or binary_big_endian)");
  EXPECT_EQ(read_error("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nend_header\n0\n"),
            "bad.ply: no vertex element with properties x, y and z in the header");
  EXPECT_EQ(read_error("bad.ply", ascii_ply("", 0)),
            "bad.ply: no faces: the header announces 3 vertices and 0 faces (points only); vv reads polygon meshes "
            "from .ply files");
  EXPECT_EQ(read_error("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
                                  "property double z\nend_header\n0 0 0\n"),
            "bad.ply: no faces: the header announces 1 vertex and no face element (points only); vv reads polygon "
            "meshes from .ply files");
  EXPECT_EQ(read_error("bad.ply", ascii_ply("3 0 1 9\n", 1)),
            "bad.ply: face 0: vertex 9 does not exist: the file has 3 vertices, numbered from 0");
  EXPECT_EQ(read_error("bad.ply", ascii_ply("3 0 1 -1\n", 1)), "bad.ply: face 0: -1 is not a vertex index");
  EXPECT_EQ(read_error("bad.ply", ascii_ply("2 0 1\n", 1)),
            "bad.ply: face 0: a face needs at least 3 vertices; this one has 2");
  EXPECT_EQ(read_error("bad.ply", ascii_ply("3 0 1 1\n", 1)), "bad.ply: face 0: the face lists vertex 1 twice");
  EXPECT_EQ(read_error("bad.ply", ascii_ply("3 0 1\n", 1)),
            "bad.ply: the data after the header does not match it (it announces 3 vertices and 1 faces): cut short, "
            "or a value of the wrong type");
}

// ---- build_from_faces: faces given by a program ----

TEST(BuildFromFaces, SaysWhatIsWrongWithAFace) {
  const Points points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  auto build_error = [&](const Faces& faces) {
    G::context ctx;
    G::mesh M(ctx);
    return special_files::error_of([&] { vv::build_from_faces(M, points, faces, "soup"); });
  };
  EXPECT_EQ(build_error({{0, 1, 2}, {0, 1}}), "soup: face 1: a face needs at least 3 vertices; this one has 2");
  EXPECT_EQ(build_error({{0, 1, 3}}), "soup: face 0: vertex 3 does not exist: the file has 3 vertices, numbered from 0");
  EXPECT_EQ(build_error({{0, 1, 2, 1}}), "soup: face 0: the face lists vertex 1 twice");
}

}  // namespace
