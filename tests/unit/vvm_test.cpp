// The .vvm file format (LANGUAGE.md section 7): the double pyramid, mesh,
// vertex and edge properties, the writer's records and stability, and
// malformed files (tests/data/malformed), each of which must be reported as
// "file:line: problem" and leave the target mesh exactly as it was.
#include <vv/vv.hpp>
#include <vv/io/mesh_io.hpp>
#include <vv/io/vvm.hpp>
#include <vv/neighbourhood_check.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
#include <tuple>
#include <vector>

#include <unistd.h>

#include "test_files.hpp"

#ifndef VV_SOURCE_DIR
#error "compile with -DVV_SOURCE_DIR='\"/path/to/source\"'"
#endif
#ifndef VV_TEST_DATA
#define VV_TEST_DATA VV_SOURCE_DIR "/tests/data"
#endif

using test_files::scratch_dir;
using test_files::slurp;

namespace {

using Pt = util::Point<double>;

const std::string pyramid_path = VV_SOURCE_DIR "/models/pyramid.vvm";
const std::string malformed_dir = VV_TEST_DATA "/malformed/";

// Positions only: the pyramid file is written back byte for byte.
struct PosOnly {
  Pt pos;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
  }
};
using PG = vv::graph<PosOnly>;

// A model with properties of every kind.
struct VP {
  Pt pos;
  double c = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
    f("c", c);
  }
};
struct EP {
  int mark = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("mark", mark);
  }
  friend bool operator==(const EP& a, const EP& b) { return a.mark == b.mark; }
  friend bool operator!=(const EP& a, const EP& b) { return !(a == b); }
};
struct MP {
  int generation = 0;
  std::string name;
  template <class F>
  void vv_fields(F&& f) {
    f("generation", generation);
    f("name", name);
  }
};
using G = vv::graph<VP, EP, MP>;
using V = G::vertex;
using Labels = std::vector<unsigned>;

// ---- helpers ----



template <class M>
auto members(const M& m) {
  std::vector<std::decay_t<decltype(*m.begin())>> out;
  for (auto v : m) out.push_back(v);
  return out;
}

// The neighbourhood of each member as member positions (-1: not a member).
template <class M>
std::vector<std::vector<int>> nb_positions(const M& m) {
  auto vs = members(m);
  std::vector<std::vector<int>> out;
  for (const auto& v : vs) {
    std::vector<int> row;
    for (auto x : vv::each(v)) {
      auto it = std::find(vs.begin(), vs.end(), x);
      row.push_back(it == vs.end() ? -1 : static_cast<int>(it - vs.begin()));
    }
    out.push_back(row);
  }
  return out;
}

// Every record of the mesh, by member positions: (from, to, mark).
std::vector<std::tuple<int, int, int>> records(const G::mesh& m) {
  auto vs = members(m);
  std::vector<std::tuple<int, int, int>> out;
  for (std::size_t i = 0; i < vs.size(); ++i)
    for (V x : vv::each(vs[i])) {
      auto it = std::find(vs.begin(), vs.end(), x);
      if (it == vs.end()) continue;
      out.emplace_back(static_cast<int>(i), static_cast<int>(it - vs.begin()),
                       vv::edge(vs[i], x).mark);
    }
  return out;
}

std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, prefix.size(), prefix) == 0) out.push_back(line);
  return out;
}

void parse(G::mesh& m, const std::string& text, const std::string& name = "inline.vvm") {
  vv::parse_vvm(m, vv::io::text_file(name, text));
}

const char* const pyramid_text =
    "<mesh>\n"
    "  <v pos=\"-1 0 -1\" nb=\"1 5 3 4\" />\n"
    "  <v pos=\"1 0 -1\" nb=\"2 5 0 4\" />\n"
    "  <v pos=\"1 0 1\" nb=\"3 5 1 4\" />\n"
    "  <v pos=\"-1 0 1\" nb=\"0 5 2 4\" />\n"
    "  <v pos=\"0 1.4142 0\" nb=\"3 2 1 0\" />\n"
    "  <v pos=\"0 -1.4142 0\" nb=\"0 1 2 3\" />\n"
    "</mesh>\n";

const std::vector<Pt> pyramid_positions = {Pt(-1, 0, -1), Pt(1, 0, -1),     Pt(1, 0, 1),
                                           Pt(-1, 0, 1),  Pt(0, 1.4142, 0), Pt(0, -1.4142, 0)};
const std::vector<std::vector<int>> pyramid_nbs = {{1, 5, 3, 4}, {2, 5, 0, 4}, {3, 5, 1, 4},
                                                   {0, 5, 2, 4}, {3, 2, 1, 0}, {0, 1, 2, 3}};

// =====================================================================
// The double pyramid
// =====================================================================

TEST(VvmPyramid, FileIsTheOneInTheSpecification) {
  EXPECT_EQ(slurp(pyramid_path), pyramid_text);
}

TEST(VvmPyramid, ReadGivesSixVerticesInFileOrderWithExactPositions) {
  PG::context ctx;
  PG::mesh M(ctx);
  unsigned before = ctx.new_vertex().label();
  vv::read_vvm(M, pyramid_path);
  ASSERT_EQ(M.size(), 6u);
  auto vs = members(M);
  for (std::size_t i = 0; i < 6; ++i) {
    // Labels follow file order, right after the last vertex created.
    EXPECT_EQ(vs[i].label(), before + 1 + i);
    EXPECT_EQ(vs[i]->pos, pyramid_positions[i]) << "vertex " << i;
  }
  EXPECT_EQ(vs[4]->pos.y(), 1.4142);
  EXPECT_EQ(vs[5]->pos.y(), -1.4142);
  EXPECT_EQ(nb_positions(M), pyramid_nbs);
  EXPECT_TRUE(vs[0] < vs[1] && vs[4] < vs[5]);
  EXPECT_NO_THROW(vv::check_invariants(M, {true, true}));
}

TEST(VvmPyramid, EightOutwardTriangles) {
  PG::context ctx;
  PG::mesh M(ctx);
  vv::read_vvm(M, pyramid_path);
  auto vs = members(M);
  auto faces = vv::face_orbits(M);
  ASSERT_EQ(faces.size(), 8u);
  std::vector<std::vector<std::uint32_t>> sorted_faces;
  for (const auto& f : faces) {
    ASSERT_EQ(f.size(), 3u);
    Pt a = vs[f[0]]->pos, b = vs[f[1]]->pos, c = vs[f[2]]->pos;
    Pt normal = (b - a).cross(c - a);
    Pt centroid = (a + b + c) / 3.0;
    EXPECT_GT(normal * centroid, 0.1) << "face " << f[0] << " " << f[1] << " " << f[2]
                                      << " faces inwards";
    // Each face has one apex and two consecutive equator vertices.
    std::vector<std::uint32_t> s = f;
    std::sort(s.begin(), s.end());
    sorted_faces.push_back(s);
  }
  std::sort(sorted_faces.begin(), sorted_faces.end());
  EXPECT_EQ(std::unique(sorted_faces.begin(), sorted_faces.end()), sorted_faces.end());
  EXPECT_EQ(vv::orbits(M).broken_edges, 0u);
  EXPECT_EQ(vv::orbits(M).long_orbits, 0u);
}

TEST(VvmPyramid, EulerCharacteristicIsTwo) {
  PG::context ctx;
  PG::mesh M(ctx);
  vv::read_vvm(M, pyramid_path);
  EXPECT_EQ(vv::edge_count(M), 12u);
  EXPECT_EQ(vv::euler_characteristic(M), 2);
}

TEST(VvmPyramid, WrittenBackByteIdentical) {
  PG::context ctx;
  PG::mesh M(ctx);
  vv::read_vvm(M, pyramid_path);
  EXPECT_EQ(vv::vvm_text(M), slurp(pyramid_path));
  std::string out = scratch_dir() + "pyramid_copy.vvm";
  vv::write_vvm(M, out);
  EXPECT_EQ(slurp(out), slurp(pyramid_path));
}

TEST(VvmPyramid, ReadAndWriteXMLFileResolveAgainstBaseDir) {
  PG::context ctx;
  ctx.base_dir = VV_SOURCE_DIR "/models";
  PG::mesh M(ctx);
  M.readXMLFile("pyramid.vvm");
  EXPECT_EQ(M.vertexCount(), 6u);
  ctx.base_dir = scratch_dir();
  M.writeXMLFile("relative_pyramid.vvm");
  EXPECT_EQ(slurp(scratch_dir() + "relative_pyramid.vvm"), pyramid_text);
  // An absolute path ignores base_dir.
  PG::mesh N(ctx);
  N.readXMLFile(pyramid_path);
  EXPECT_EQ(N.size(), 6u);
}

// =====================================================================
// Warnings: what a read lets through without an error
// =====================================================================

TEST(VvmWarnings, UnknownAttributesAndMissingFieldsAreSaidOncePerName) {
  G::context ctx;
  std::vector<std::string> said;
  ctx.warning_sink = [&](const std::string& m) { said.push_back(m); };
  std::string path = scratch_dir() + "warn.vvm";
  std::ofstream(path) << "<mesh generation=\"2\" name=\"m\">\n"
                         "  <v pos=\"0 0 0\" c=\"1\" colr=\"red\" nb=\"1\"/>\n"
                         "  <v pos=\"1 0 0\" colr=\"blue\" nb=\"0\"/>\n"
                         "  <e first=\"0\" second=\"1\" weight=\"2\"/>\n"
                         "</mesh>\n";
  G::mesh M(ctx);
  M.readXMLFile(path, vv::where{"model.vvp", 7});
  M.readXMLFile(path, vv::where{"model.vvp", 7});  // read again: nothing new to say
  EXPECT_EQ(M.size(), 2u);
  EXPECT_EQ(said, (std::vector<std::string>{
                      path + ":2: warning: the attribute colr of <v> matches no field of the program's vertex "
                             "and is ignored (read at model.vvp:7)",
                      path + ":4: warning: the attribute weight of <e> matches no field of the program's "
                             "edge records and is ignored (read at model.vvp:7)",
                      path + ": warning: the vertex field c is missing from 1 of the 2 vertices, which keep its "
                             "default value (read at model.vvp:7)"}));
}

TEST(VvmWarnings, AMeshFieldTheFileLacksAndACompleteFileIsSilent) {
  G::context ctx;
  std::vector<std::string> said;
  ctx.warning_sink = [&](const std::string& m) { said.push_back(m); };
  G::mesh M(ctx);
  M.readXMLFile(pyramid_path, vv::where{"model.vvp", 3});
  EXPECT_EQ(said, (std::vector<std::string>{
                      pyramid_path + ": warning: the mesh field generation is not in the file and keeps its "
                                     "default value (read at model.vvp:3)",
                      pyramid_path + ": warning: the mesh field name is not in the file and keeps its "
                                     "default value (read at model.vvp:3)",
                      pyramid_path + ": warning: the vertex field c is in no vertex of the file and keeps its "
                                     "default value (read at model.vvp:3)"}));
  PG::context quiet;
  bool any = false;
  quiet.warning_sink = [&](const std::string&) { any = true; };
  PG::mesh P(quiet);
  P.readXMLFile(pyramid_path);
  EXPECT_FALSE(any);
}

// A field the program computes itself (`computed double radius;` in a
// .vvp) is no news when a file lacks it, wholly or in part.
struct WithComputed {
  Pt pos;
  double radius = 0;
  int ring = 0;
  static constexpr const char* vv_computed_fields[] = {"radius", "ring"};
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
    f("radius", radius);
    f("ring", ring);
  }
};
using CG = vv::graph<WithComputed>;

TEST(VvmWarnings, AComputedFieldTheFileLacksIsNoWarning) {
  EXPECT_TRUE(vv::is_computed_field<WithComputed>("radius"));
  EXPECT_FALSE(vv::is_computed_field<WithComputed>("pos"));
  EXPECT_FALSE(vv::is_computed_field<VP>("c"));
  CG::context ctx;
  std::vector<std::string> said;
  ctx.warning_sink = [&](const std::string& m) { said.push_back(m); };
  CG::mesh M(ctx);
  M.readXMLFile(pyramid_path, vv::where{"model.vvp", 3});
  EXPECT_EQ(M.size(), 6u);
  std::string path = scratch_dir() + "some_rings.vvm";
  std::ofstream(path) << "<mesh>\n  <v pos=\"0 0 0\" ring=\"2\" nb=\"\"/>\n  <v pos=\"1 0 0\" nb=\"\"/>\n</mesh>\n";
  M.readXMLFile(path, vv::where{"model.vvp", 4});
  EXPECT_EQ(said, std::vector<std::string>{});
  // What the file gives is read all the same.
  std::vector<int> rings;
  for (CG::vertex v : M) rings.push_back(v->ring);
  EXPECT_EQ(rings, (std::vector<int>{2, 0}));
}

// A warning is said once in a run: the same file read again, into other
// meshes, under another spelling of its path, or by readFile.
TEST(VvmWarnings, AreSaidOnceAcrossReadsMeshesAndSpellings) {
  G::context ctx;
  std::vector<std::string> said;
  ctx.warning_sink = [&](const std::string& m) { said.push_back(m); };
  const std::string folder = VV_SOURCE_DIR "/models";
  G::mesh A(ctx), B(ctx);
  A.readXMLFile(pyramid_path, vv::where{"model.vvp", 3});
  A.readXMLFile(pyramid_path, vv::where{"model.vvp", 4});
  B.readXMLFile(folder + "/./pyramid.vvm", vv::where{"model.vvp", 5});
  B.readXMLFile(folder + "/../models/pyramid.vvm", vv::where{"model.vvp", 6});
  B.readFile(pyramid_path, vv::where{"model.vvp", 7});
  EXPECT_EQ(said.size(), 3u);  // generation, name, c: each once
  for (const std::string& m : said) EXPECT_NE(m.find("(read at model.vvp:3)"), std::string::npos) << m;
}

// =====================================================================
// Edits: a read notes its edits at the line that read the file, which
// `vvinterpreter --check` names when a neighbourhood is found broken
// =====================================================================

TEST(VvmEdits, AreNotedAtTheLineThatReadTheFile) {
  PG::context ctx;
  ctx.track_edits(true);
  PG::mesh M(ctx);
  M.readXMLFile(pyramid_path, vv::where{"model.vvp", 5});
  EXPECT_TRUE(vv::first_broken_neighbourhood(M, true).problem.empty());
  // Vertex 2 lists vertex 0, which does not list it back.
  std::string path = scratch_dir() + "one_way.vvm";
  std::ofstream(path) << "<mesh>\n  <v pos=\"0 0 0\" nb=\"1\"/>\n  <v pos=\"1 0 0\" nb=\"0 2\"/>\n"
                         "  <v pos=\"0 1 0\" nb=\"1 0\"/>\n</mesh>\n";
  M.readXMLFile(path, vv::where{"model.vvp", 9});
  for (std::uint32_t id : M.slots()) {
    if (!id) continue;
    vv::where at = ctx.last_edit(id).at;
    ASSERT_NE(at.file, nullptr);
    EXPECT_EQ(std::string(at.file) + ":" + std::to_string(at.line), "model.vvp:9");
  }
  vv::broken_neighbourhood broken = vv::first_broken_neighbourhood(M, true);
  ASSERT_NE(broken.at.file, nullptr);
  EXPECT_EQ(std::string(broken.at.file) + ":" + std::to_string(broken.at.line), "model.vvp:9");
  EXPECT_NE(broken.problem.find("(last edits: vertex 9 at model.vvp:9, vertex 7 at model.vvp:9)"), std::string::npos)
      << broken.problem;
}

// =====================================================================
// Properties
// =====================================================================

TEST(VvmProperties, MeshPropertiesAreRootAttributes) {
  G::context ctx;
  G::mesh M(ctx);
  parse(M, "<mesh generation=\"2\" name=\"leaf\">\n  <v pos=\"1 2 3\" c=\"0.25\" nb=\"\" />\n</mesh>\n");
  EXPECT_EQ(M.generation, 2);
  EXPECT_EQ(M.name, "leaf");
  ASSERT_EQ(M.size(), 1u);
  EXPECT_EQ(members(M)[0]->pos, Pt(1, 2, 3));
  EXPECT_EQ(members(M)[0]->c, 0.25);
  M.generation = 7;
  M.name = "stem";
  EXPECT_EQ(vv::vvm_text(M),
            "<mesh generation=\"7\" name=\"stem\">\n"
            "  <v pos=\"1 2 3\" c=\"0.25\" nb=\"\" />\n"
            "</mesh>\n");
}

TEST(VvmProperties, UnknownAttributesAreIgnored) {
  G::context ctx;
  G::mesh M(ctx);
  parse(M,
        "<mesh generation=\"4\" colour=\"red\" version=\"1.1\">\n"
        "  <v pos=\"0 0 1\" weight=\"heavy\" c=\"2\" nb=\"1\" />\n"
        "  <v id=\"x\" pos=\"0 1 0\" nb=\"0\" />\n"
        "  <e symmetric=\"1\" first=\"0\" second=\"1\" mark=\"6\" style=\"dashed\" />\n"
        "</mesh>\n");
  EXPECT_EQ(M.generation, 4);
  ASSERT_EQ(M.size(), 2u);
  auto vs = members(M);
  EXPECT_EQ(vs[0]->pos, Pt(0, 0, 1));
  EXPECT_EQ(vs[0]->c, 2);
  EXPECT_EQ(vs[1]->pos, Pt(0, 1, 0));
  EXPECT_EQ(vv::edge(vs[0], vs[1]).mark, 6);
  EXPECT_EQ(vv::edge(vs[1], vs[0]).mark, 6);
  // They are not written back.
  std::string text = vv::vvm_text(M);
  EXPECT_EQ(text.find("colour"), std::string::npos);
  EXPECT_EQ(text.find("weight"), std::string::npos);
  EXPECT_EQ(text.find("style"), std::string::npos);
}

TEST(VvmProperties, MissingAttributesLeaveTheDefault) {
  G::context ctx;
  G::mesh M(ctx);
  M.generation = 9;  // replaced by the file's mesh: its default
  M.name = "before";
  parse(M,
        "<mesh>\n"
        "  <v c=\"1.5\" nb=\"1\" />\n"
        "  <v pos=\"3 4 5\" nb=\"0\" />\n"
        "  <e symmetric=\"1\" first=\"0\" second=\"1\" />\n"
        "</mesh>\n");
  EXPECT_EQ(M.generation, 0);
  EXPECT_EQ(M.name, "");
  auto vs = members(M);
  ASSERT_EQ(vs.size(), 2u);
  EXPECT_EQ(vs[0]->pos, Pt(0, 0, 0));
  EXPECT_EQ(vs[0]->c, 1.5);
  EXPECT_EQ(vs[1]->pos, Pt(3, 4, 5));
  EXPECT_EQ(vs[1]->c, 0);
  EXPECT_EQ(vv::edge(vs[0], vs[1]).mark, 0);
  EXPECT_EQ(vv::edge(vs[1], vs[0]).mark, 0);
}

TEST(VvmProperties, ValuesAreParsedAndRoundTripExactly) {
  G::context ctx;
  G::mesh M(ctx);
  parse(M,
        "<mesh generation=\" 12 \">\n"
        "  <v pos=\"  1e-3   -2.5 7 \" c=\"0.1\" nb=\"\" />\n"
        "  <v pos=\"0.30000000000000004 1e300 -0\" c=\"-1E2\" nb=\"\" />\n"
        "</mesh>\n");
  EXPECT_EQ(M.generation, 12);
  auto vs = members(M);
  EXPECT_EQ(vs[0]->pos, Pt(0.001, -2.5, 7));
  EXPECT_EQ(vs[0]->c, 0.1);
  EXPECT_EQ(vs[1]->pos.x(), 0.30000000000000004);
  EXPECT_EQ(vs[1]->pos.y(), 1e300);
  EXPECT_EQ(vs[1]->c, -100);
  // Values the writer produces read back to the same doubles.
  vs[0]->c = 1.0 / 3.0;
  vs[1]->pos = Pt(0.1 + 0.2, 2.0 / 7.0, -1e-310);
  G::mesh N(ctx);
  parse(N, vv::vvm_text(M));
  auto ws = members(N);
  EXPECT_EQ(ws[0]->c, 1.0 / 3.0);
  EXPECT_EQ(ws[1]->pos, Pt(0.1 + 0.2, 2.0 / 7.0, -1e-310));
  EXPECT_EQ(N.generation, 12);
}

// =====================================================================
// Edge records
// =====================================================================

TEST(VvmEdges, SymmetricZeroSetsOneDirectionAndOneSetsBoth) {
  G::context ctx;
  G::mesh M(ctx);
  parse(M,
        "<mesh>\n"
        "  <v pos=\"0 0 0\" nb=\"1 2\" />\n"
        "  <v pos=\"1 0 0\" nb=\"2 0\" />\n"
        "  <v pos=\"0 1 0\" nb=\"0 1\" />\n"
        "  <e symmetric=\"0\" first=\"0\" second=\"1\" mark=\"3\" />\n"
        "  <e symmetric=\"1\" first=\"1\" second=\"2\" mark=\"5\" />\n"
        "  <e symmetric=\"0\" first=\"0\" second=\"2\" mark=\"8\" />\n"
        "  <e symmetric=\"0\" first=\"2\" second=\"0\" mark=\"9\" />\n"
        "</mesh>\n");
  auto vs = members(M);
  EXPECT_EQ(vv::edge(vs[0], vs[1]).mark, 3);
  EXPECT_EQ(vv::edge(vs[1], vs[0]).mark, 0);
  EXPECT_EQ(vv::edge(vs[1], vs[2]).mark, 5);
  EXPECT_EQ(vv::edge(vs[2], vs[1]).mark, 5);
  EXPECT_EQ(vv::edge(vs[0], vs[2]).mark, 8);
  EXPECT_EQ(vv::edge(vs[2], vs[0]).mark, 9);
}

TEST(VvmEdges, SymmetricOneOnlyNeedsThePairAdjacentBothWays) {
  // symmetric="0" on a one-way pair is fine.
  G::context ctx;
  G::mesh M(ctx);
  parse(M,
        "<mesh>\n"
        "  <v pos=\"0 0 0\" nb=\"1\" />\n"
        "  <v pos=\"1 0 0\" nb=\"\" />\n"
        "  <e symmetric=\"0\" first=\"0\" second=\"1\" mark=\"4\" />\n"
        "</mesh>\n");
  auto vs = members(M);
  EXPECT_EQ(vv::edge(vs[0], vs[1]).mark, 4);
  EXPECT_EQ(vv::valence(vs[1]), 0u);
}

TEST(VvmEdges, WriterEmitsNonDefaultRecordsOnceForEqualPairs) {
  G::context ctx;
  G::mesh M(ctx);
  parse(M, pyramid_text);
  auto vs = members(M);
  vv::edge(vs[0], vs[1]).mark = 3;  // equal both ways: one symmetric element
  vv::edge(vs[1], vs[0]).mark = 3;
  vv::edge(vs[2], vs[3]).mark = 5;  // one way only
  vv::edge(vs[4], vs[0]).mark = 7;  // different both ways: two elements
  vv::edge(vs[0], vs[4]).mark = 8;
  EXPECT_TRUE(vv::edge(vs[4], vs[0]) != vv::edge(vs[0], vs[4]));
  EXPECT_FALSE(vv::edge(vs[0], vs[1]) != vv::edge(vs[1], vs[0]));
  std::string text = vv::vvm_text(M);
  std::vector<std::string> es = lines_starting(text, "  <e ");
  std::sort(es.begin(), es.end());
  std::vector<std::string> expected = {
      "  <e symmetric=\"0\" first=\"0\" second=\"4\" mark=\"8\" />",
      "  <e symmetric=\"0\" first=\"2\" second=\"3\" mark=\"5\" />",
      "  <e symmetric=\"0\" first=\"4\" second=\"0\" mark=\"7\" />",
      "  <e symmetric=\"1\" first=\"0\" second=\"1\" mark=\"3\" />",
  };
  EXPECT_EQ(es, expected);
  // Every record (24 half-edges) reads back the same.
  G::mesh N(ctx);
  parse(N, text);
  EXPECT_EQ(records(N), records(M));
  EXPECT_EQ(records(N).size(), 24u);
  EXPECT_EQ(nb_positions(N), pyramid_nbs);
}

TEST(VvmEdges, DefaultRecordsAreNotWritten) {
  G::context ctx;
  G::mesh M(ctx);
  parse(M, pyramid_text);
  EXPECT_EQ(lines_starting(vv::vvm_text(M), "  <e ").size(), 0u);
  // A record set and reset to the default is not written either.
  auto vs = members(M);
  vv::edge(vs[3], vs[2]).mark = 1;
  vv::edge(vs[3], vs[2]).mark = 0;
  EXPECT_EQ(lines_starting(vv::vvm_text(M), "  <e ").size(), 0u);
}

// =====================================================================
// Writer: stability and induced sub-graph
// =====================================================================

TEST(VvmWriter, ReadWriteReadWriteIsByteStable) {
  G::context ctx;
  G::mesh M(ctx);
  parse(M, pyramid_text);
  M.generation = 3;
  M.name = "octahedron";
  auto vs = members(M);
  for (std::size_t i = 0; i < vs.size(); ++i) vs[i]->c = 0.1 * static_cast<double>(i);
  vv::edge(vs[5], vs[2]).mark = -4;
  vv::edge(vs[3], vs[4]).mark = 11;
  vv::edge(vs[4], vs[3]).mark = 11;

  std::string a = scratch_dir() + "stable_a.vvm", b = scratch_dir() + "stable_b.vvm";
  vv::write_vvm(M, a);
  G::mesh N(ctx);
  vv::read_vvm(N, a);
  vv::write_vvm(N, b);
  EXPECT_EQ(slurp(a), slurp(b));
  G::mesh P(ctx);
  vv::read_vvm(P, b);
  EXPECT_EQ(vv::vvm_text(P), slurp(a));
  EXPECT_EQ(records(P), records(M));
  EXPECT_EQ(P.generation, 3);
  EXPECT_EQ(P.name, "octahedron");
  auto ps = members(P);
  for (std::size_t i = 0; i < ps.size(); ++i) EXPECT_EQ(ps[i]->c, 0.1 * static_cast<double>(i));
}

TEST(VvmWriter, SameMeshWrittenTwiceIsIdentical) {
  G::context ctx;
  G::mesh M(ctx);
  parse(M, pyramid_text);
  std::string a = scratch_dir() + "twice_a.vvm", b = scratch_dir() + "twice_b.vvm";
  vv::write_vvm(M, a);
  vv::write_vvm(M, b);
  EXPECT_EQ(slurp(a), slurp(b));
  EXPECT_EQ(slurp(a), vv::vvm_text(M));
}

TEST(VvmWriter, NeighbourOutsideTheMeshIsLeftOut) {
  G::context ctx;
  V a = ctx.new_vertex(), b = ctx.new_vertex(), c = ctx.new_vertex();
  a->pos = Pt(1, 0, 0);
  c->pos = Pt(0, 0, 1);
  vv::make_nb(a, {b, c});
  vv::make_nb(b, {c, a});
  vv::make_nb(c, {a, b});
  vv::edge(a, b).mark = 9;  // to a non-member: not written
  vv::edge(c, a).mark = 2;
  G::mesh M(ctx);
  M.add(c);
  M.add(a);
  EXPECT_EQ(vv::vvm_text(M),
            "<mesh generation=\"0\" name=\"\">\n"
            "  <v pos=\"0 0 1\" c=\"0\" nb=\"1\" />\n"
            "  <v pos=\"1 0 0\" c=\"0\" nb=\"0\" />\n"
            "  <e symmetric=\"0\" first=\"0\" second=\"1\" mark=\"2\" />\n"
            "</mesh>\n");
  // The vertices themselves are not changed by writing.
  EXPECT_EQ(vv::valence(a), 2u);
}

TEST(VvmWriter, EmptyMeshRoundTrips) {
  G::context ctx;
  G::mesh M(ctx);
  M.generation = 1;
  std::string text = vv::vvm_text(M);
  EXPECT_EQ(text.find("<v"), std::string::npos);
  G::mesh N(ctx);
  N.add(ctx.new_vertex());
  parse(N, text);
  EXPECT_EQ(N.size(), 0u);
  EXPECT_EQ(N.generation, 1);
}

TEST(VvmReader, ReadingReplacesTheMeshContents) {
  G::context ctx;
  G::mesh M(ctx);
  V old_member = ctx.new_vertex();
  M.add(old_member);
  parse(M, pyramid_text);
  EXPECT_EQ(M.size(), 6u);
  EXPECT_FALSE(M.contains(old_member));
  // Reading twice gives new vertices each time.
  auto first = members(M);
  parse(M, pyramid_text);
  auto second = members(M);
  EXPECT_EQ(second[0].label(), first[5].label() + 1);
  EXPECT_FALSE(M.contains(first[0]));
}

// =====================================================================
// Malformed files: error "file:line: problem", mesh unchanged
// =====================================================================

struct Snapshot {
  Labels labels;
  std::vector<std::vector<int>> nbs;
  std::vector<std::tuple<int, int, int>> recs;
  std::vector<Pt> pos;
  std::vector<double> cs;
  int generation;
  std::string name;
  bool operator==(const Snapshot& o) const {
    return std::tie(labels, nbs, recs, pos, cs, generation, name) ==
           std::tie(o.labels, o.nbs, o.recs, o.pos, o.cs, o.generation, o.name);
  }
};

Snapshot snapshot(const G::mesh& m) {
  Snapshot s;
  for (V v : m) {
    s.labels.push_back(v.label());
    s.pos.push_back(v->pos);
    s.cs.push_back(v->c);
  }
  s.nbs = nb_positions(m);
  s.recs = records(m);
  s.generation = m.generation;
  s.name = m.name;
  return s;
}

// Reads a malformed file into a populated mesh and checks the error and
// that nothing changed (members, neighbourhoods, records, properties, and
// no vertex label consumed).
void expect_rejected(const std::string& file, int line, const std::vector<std::string>& phrases) {
  const std::string path = malformed_dir + file;
  G::context ctx;
  G::mesh M(ctx);
  parse(M, pyramid_text);
  M.generation = 5;
  M.name = "keep";
  auto vs = members(M);
  vs[0]->c = 2.5;
  vv::edge(vs[0], vs[1]).mark = 4;
  vs.clear();
  const Snapshot before = snapshot(M);
  const unsigned next_label = ctx.new_vertex().label() + 1;  // the probe takes one

  std::string message;
  try {
    vv::read_vvm(M, path);
    ADD_FAILURE() << path << " was accepted";
  } catch (const vv::error& e) {
    message = e.what();
    EXPECT_EQ(e.line(), line) << message;
    EXPECT_EQ(e.file(), path) << message;
  } catch (const std::exception& e) {
    ADD_FAILURE() << path << " threw something other than vv::error: " << e.what();
  }
  const std::string where = path + ":" + std::to_string(line) + ":";
  EXPECT_NE(message.find(where), std::string::npos)
      << "message \"" << message << "\" does not contain \"" << where << "\"";
  auto lower = [](std::string t) {
    std::transform(t.begin(), t.end(), t.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return t;
  };
  for (const std::string& p : phrases)
    EXPECT_NE(lower(message).find(lower(p)), std::string::npos)
        << "message \"" << message << "\" does not mention \"" << p << "\"";
  EXPECT_TRUE(snapshot(M) == before) << "the mesh was changed by a failed read";
  EXPECT_EQ(M.generation, 5);
  EXPECT_EQ(M.name, "keep");
  EXPECT_EQ(ctx.new_vertex().label(), next_label) << "the failed read consumed vertex labels";
  EXPECT_NO_THROW(vv::check_invariants(M, {true, true}));
}

TEST(VvmMalformed, TruncatedXml) { expect_rejected("truncated.vvm", 3, {"malformed XML"}); }

TEST(VvmMalformed, MismatchedClosingTag) {
  expect_rejected("mismatched_tag.vvm", 4, {"malformed XML", "mismatch"});
}

TEST(VvmMalformed, IndexOutOfRange) {
  expect_rejected("index_out_of_range.vvm", 4, {"vertex 2", "index 3", "out of range"});
}

TEST(VvmMalformed, HugeIndex) {
  expect_rejected("huge_index.vvm", 3, {"99999999999999999999", "out of range"});
}

TEST(VvmMalformed, NegativeIndex) {
  expect_rejected("negative_index.vvm", 2, {"\"-1\"", "not a vertex index"});
}

TEST(VvmMalformed, SelfInNeighbourhood) {
  expect_rejected("self_in_nb.vvm", 3, {"vertex 1", "itself"});
}

TEST(VvmMalformed, DuplicateInNeighbourhood) {
  expect_rejected("duplicate_in_nb.vvm", 2, {"vertex 0", "twice"});
}

TEST(VvmMalformed, EdgeBetweenNonAdjacentVertices) {
  expect_rejected("non_adjacent_e.vvm", 5, {"edge", "not a neighbour"});
}

TEST(VvmMalformed, SymmetricEdgeWhoseReverseIsNotAdjacent) {
  expect_rejected("e_symmetric_not_reverse.vvm", 5, {"symmetric", "not a neighbour"});
}

TEST(VvmMalformed, EdgeIndexOutOfRange) {
  expect_rejected("e_index_out_of_range.vvm", 4, {"edge", "9", "out of range"});
}

TEST(VvmMalformed, EdgeWithoutFirst) {
  expect_rejected("e_missing_first.vvm", 4, {"edge", "no first attribute"});
}

TEST(VvmMalformed, EdgeSymmetricNotABoolean) {
  expect_rejected("bad_symmetric.vvm", 5, {"symmetric", "\"yes\""});
}

TEST(VvmMalformed, UnparsableNumberInVertexProperty) {
  expect_rejected("unparsable_number.vvm", 3, {"vertex 1", "\"1.5x\"", "c"});
}

TEST(VvmMalformed, UnparsablePoint) {
  expect_rejected("unparsable_point.vvm", 4, {"vertex 2", "\"1 2\"", "pos"});
}

TEST(VvmMalformed, UnparsableMeshProperty) {
  expect_rejected("bad_mesh_property.vvm", 1, {"\"two\"", "generation"});
}

TEST(VvmMalformed, UnparsableEdgeProperty) {
  expect_rejected("bad_edge_property.vvm", 5, {"\"many\"", "mark"});
}

TEST(VvmMalformed, MissingNeighbourList) {
  expect_rejected("missing_nb.vvm", 4, {"vertex 2", "no nb attribute"});
}

TEST(VvmMalformed, EmptyFile) { expect_rejected("empty.vvm", 1, {"empty file"}); }

TEST(VvmMalformed, BinaryGarbage) { expect_rejected("binary_garbage.vvm", 1, {"malformed XML"}); }

TEST(VvmMalformed, WrongRootElement) {
  expect_rejected("wrong_root.vvm", 2, {"root element", "<model>"});
}

TEST(VvmMalformed, UnknownElement) {
  expect_rejected("unknown_element.vvm", 4, {"unexpected element", "<face>"});
}

TEST(VvmMalformed, ErrorAfterValidContentKeepsNothing) {
  expect_rejected("late_error.vvm", 10, {"vertex 6", "itself"});
}

// Not well-formed XML that a lenient parser might let through: a repeated
// attribute (which value?), a second document element, text after the root.
TEST(VvmMalformed, DuplicateAttribute) {
  expect_rejected("duplicate_attribute.vvm", 3, {"malformed XML", "duplicate"});
}

TEST(VvmMalformed, SecondRootElement) {
  expect_rejected("two_roots.vvm", 5, {"malformed XML"});
}

TEST(VvmMalformed, TextAfterTheRootElement) {
  expect_rejected("text_after_root.vvm", 5, {"malformed XML"});
}

TEST(VvmMalformed, MissingFileNamesTheFile) {
  G::context ctx;
  G::mesh M(ctx);
  parse(M, pyramid_text);
  M.generation = 5;
  const Snapshot before = snapshot(M);
  const unsigned next_label = ctx.new_vertex().label() + 1;
  const std::string path = scratch_dir() + "no_such_dir/absent.vvm";
  try {
    vv::read_vvm(M, path);
    ADD_FAILURE() << "reading a missing file succeeded";
  } catch (const vv::error& e) {
    std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find("cannot open"), std::string::npos) << message;
  }
  EXPECT_TRUE(snapshot(M) == before);
  EXPECT_EQ(ctx.new_vertex().label(), next_label);
  // readXMLFile names the resolved path.
  ctx.base_dir = scratch_dir();
  try {
    M.readXMLFile("absent.vvm");
    ADD_FAILURE() << "reading a missing file succeeded";
  } catch (const vv::error& e) {
    EXPECT_NE(std::string(e.what()).find(scratch_dir() + "absent.vvm"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(snapshot(M) == before);
}

TEST(VvmMalformed, ThereAreAtLeastTwelveMalformedFiles) {
  // Every file of the folder is covered by one of the tests above.
  const char* files[] = {"truncated.vvm",         "mismatched_tag.vvm",
                         "index_out_of_range.vvm", "huge_index.vvm",
                         "negative_index.vvm",     "self_in_nb.vvm",
                         "duplicate_in_nb.vvm",    "non_adjacent_e.vvm",
                         "e_symmetric_not_reverse.vvm", "e_index_out_of_range.vvm",
                         "e_missing_first.vvm",    "bad_symmetric.vvm",
                         "unparsable_number.vvm",  "unparsable_point.vvm",
                         "bad_mesh_property.vvm",  "bad_edge_property.vvm",
                         "missing_nb.vvm",         "empty.vvm",
                         "binary_garbage.vvm",     "wrong_root.vvm",
                         "unknown_element.vvm",    "late_error.vvm",
                         "duplicate_attribute.vvm", "two_roots.vvm",
                         "text_after_root.vvm"};
  int present = 0;
  for (const char* f : files) {
    std::ifstream in(malformed_dir + f, std::ios::binary);
    EXPECT_TRUE(in.good()) << f;
    present += in.good() ? 1 : 0;
  }
  EXPECT_EQ(present, 25);
  // The empty file is really empty, the garbage really binary.
  EXPECT_EQ(slurp(malformed_dir + "empty.vvm").size(), 0u);
  std::string garbage = slurp(malformed_dir + "binary_garbage.vvm");
  EXPECT_NE(garbage.find('\0'), std::string::npos);
  EXPECT_EQ(garbage.find('\n'), std::string::npos);
}

}  // namespace

// Issue 9, item 16: a NaN or infinite position was written but could not
// be read back ("cannot read \"nan 0 0\""); every double must round-trip,
// bit for bit (NaN as NaN).
TEST(VvmValues, EveryDoubleRoundTrips) {
  const double values[] = {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::denorm_min(),
                           -std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::lowest(),
                           std::numeric_limits<double>::min(),
                           -0.0,
                           0.1,
                           1.0 / 3};
  std::string path = scratch_dir() + "every_double.vvm";
  {
    vv::graph<VP>::context ctx;
    vv::graph<VP>::mesh m(ctx);
    for (double d : values) {
      auto v = ctx.new_vertex();
      v->pos = Pt(d, -d, 1);
      v->c = d;
      m.add(v);
    }
    vv::write_vvm(m, path);
  }
  vv::graph<VP>::context ctx;
  vv::graph<VP>::mesh m(ctx);
  ASSERT_NO_THROW(vv::read_vvm(m, path)) << slurp(path);
  ASSERT_EQ(m.size(), std::size(values));
  std::size_t i = 0;
  auto same = [](double a, double b) {
    return std::isnan(a) ? std::isnan(b) : std::memcmp(&a, &b, sizeof a) == 0;
  };
  for (auto v : vv::each(m)) {
    double d = values[i++];
    EXPECT_TRUE(same(v->c, d)) << d << " came back as " << v->c;
    EXPECT_TRUE(same(v->pos.x(), d) && same(v->pos.y(), -d)) << d << " came back as " << v->pos;
  }
}

// Issue 9, item 16: "1e999" was rejected while "1e5000" was read as inf.
// A literal past the range of double is an infinity, whatever its exponent.
TEST(VvmValues, LiteralsPastTheRangeAreInfinities) {
  std::string path = scratch_dir() + "out_of_range.vvm";
  std::ofstream(path) << "<mesh>\n  <v pos=\"1e999 -1e5000 0\" c=\"1e999\" nb=\"\" />\n"
                         "  <v pos=\"0 0 0\" c=\"-1e5000\" nb=\"\" />\n</mesh>\n";
  vv::graph<VP>::context ctx;
  vv::graph<VP>::mesh m(ctx);
  ASSERT_NO_THROW(vv::read_vvm(m, path));
  std::vector<vv::graph<VP>::vertex> vs;
  for (auto v : vv::each(m)) vs.push_back(v);
  ASSERT_EQ(vs.size(), 2u);
  EXPECT_EQ(vs[0]->c, std::numeric_limits<double>::infinity());
  EXPECT_EQ(vs[0]->pos.x(), std::numeric_limits<double>::infinity());
  EXPECT_EQ(vs[0]->pos.y(), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(vs[1]->c, -std::numeric_limits<double>::infinity());
}
