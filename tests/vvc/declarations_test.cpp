// The declarations' part of a translation (vvc::emit_declarations): what
// it holds of the program, and that it stays the same while only the code
// below the last property block changes (the interpreter caches it by its
// text). That the two parts linked behave as the program compiled whole
// is checked by the interpreter's tests and the examples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <string>

#include "squeezed.hpp"
#include "translate.hpp"

namespace {

vvc::translation translated(const std::string& program) {
  vvc::translation t = vvc::translate_text("m.vvp", program);
  std::string errors;
  for (const auto& d : t.diag.list()) errors += vvc::format(d);
  EXPECT_TRUE(t.ok) << errors;
  return t;
}

bool has(const std::string& text, const std::string& part) {
  return squeeze(text).find(squeeze(part)) != std::string::npos;
}

const std::string declarations =
    "#include <cmath>\n"
    "typedef double real;\n"
    "param double rate = 0.5 in [0, 1];\n"
    "vertex {\n"
    "  real h;\n"
    "};\n";

}  // namespace

TEST(DeclarationsPart, HoldsTheDeclarationsAndTheTraitsButNoCodeAfterThem) {
  vvc::translation t = translated(declarations +
                                  "mesh S;\n"
                                  "void grow() { forall v in S { v$h += rate; } }\n"
                                  "step { grow(); }\n");
  const std::string& d = t.declarations;
  EXPECT_TRUE(has(d, "#include <model/model.hpp>")) << d;
  EXPECT_TRUE(has(d, "typedef double real;")) << d;
  EXPECT_TRUE(has(d, "struct vv_vertex_props { real h{};")) << d;
  EXPECT_TRUE(has(d, "struct vv_traits : vv::traits<vv_vertex_props, vv_edge_props, vv_mesh_props>")) << d;
  // The parameter is the program's global: declared here, not defined.
  EXPECT_TRUE(has(d, "extern double rate;")) << d;
  EXPECT_FALSE(has(d, "rate = 0.5")) << d;
  EXPECT_FALSE(has(d, "mesh S")) << d;
  EXPECT_FALSE(has(d, "grow")) << d;
  EXPECT_FALSE(has(d, "vv_block_step")) << d;
  EXPECT_FALSE(has(d, "vv_model")) << d;
  // What it compiles for the model's traits.
  EXPECT_TRUE(has(d, "\ntemplate class vv::context<vv_traits>;\ntemplate class vv::mesh<vv_traits>;\n")) << d;
  EXPECT_TRUE(has(d, "const char* vv_decl_check(vv::model::program<vv_traits>& vv_p, "
                     "const vv::model::named_mesh<vv_traits> (&vv_all)[1]) noexcept {"))
      << d;
}

TEST(DeclarationsPart, IsTheSameWhileOnlyTheCodeAfterTheDeclarationsChanges) {
  vvc::translation before = translated(declarations + "mesh S;\nstep { S.clear(); }\n");
  vvc::translation after = translated(declarations + "mesh S;\nvoid f() {}\nstep { f(); S.clear(); }\n");
  EXPECT_EQ(before.declarations, after.declarations);
  EXPECT_NE(before.cpp, after.cpp);
  // A parameter's value is the program's: changing it keeps the part.
  std::string other_value = declarations;
  other_value.replace(other_value.find("0.5"), 3, "0.7");
  EXPECT_EQ(before.declarations, translated(other_value + "mesh S;\nstep { S.clear(); }\n").declarations);
  // A new property does not.
  std::string more = declarations;
  more.replace(more.find("real h;"), 7, "real h, k;");
  EXPECT_NE(before.declarations, translated(more + "mesh S;\nstep { S.clear(); }\n").declarations);
}

TEST(DeclarationsPart, DeclaresTheFunctionsTheProgramDefinesOnce) {
  vvc::translation t = translated(
      "double half(double x) { return x / 2; }\n"
      "static double twice(double x) { return 2 * x; }\n"
      "inline double third(double x) { return x / 3; }\n"
      "template <class T> T quarter(T x) { return x / 4; }\n"
      "struct counter { int n = 0; int next(); };\n"
      "int counter::next() { return ++n; }\n"
      "struct pair2 { double a, b; };\n"
      "pair2 operator+(pair2 p, pair2 q) { return {p.a + q.a, p.b + q.b}; }\n"
      "vertex { double h = half(1.0); };\n"
      "step {}\n");
  const std::string& d = t.declarations;
  EXPECT_TRUE(has(d, "double half(double x);")) << d;
  EXPECT_FALSE(has(d, "return x / 2")) << d;
  EXPECT_TRUE(has(d, "pair2 operator+(pair2 p, pair2 q);")) << d;
  EXPECT_FALSE(has(d, "p.a + q.a")) << d;
  // Functions every file may define keep their bodies.
  EXPECT_TRUE(has(d, "static double twice(double x) { return 2 * x; }")) << d;
  EXPECT_TRUE(has(d, "inline double third(double x) { return x / 3; }")) << d;
  EXPECT_TRUE(has(d, "template <class T> T quarter(T x) { return x / 4; }")) << d;
  // A member defined outside its class is declared by the class.
  EXPECT_TRUE(has(d, "struct counter { int n = 0; int next(); };")) << d;
  EXPECT_FALSE(has(d, "counter::next")) << d;
}

TEST(DeclarationsPart, TheProgramUsesItOnlyWhenToldItIsApart) {
  vvc::translation t = translated(declarations + "mesh S;\nstep { S.clear(); }\n");
  // Compiled whole, the program defines what the part would.
  EXPECT_TRUE(has(t.cpp, "#ifndef VV_DECLARATIONS_APART\nconst char* vv_decl_write_file(")) << t.cpp;
  // Compiled apart, it leaves the instantiations of vvlib's context and
  // mesh for its traits (files' reading and writing among them) to the part.
  EXPECT_TRUE(has(t.cpp, "#ifdef VV_DECLARATIONS_APART\n"
                         "extern template class vv::context<vv_traits>;\n"
                         "extern template class vv::mesh<vv_traits>;\n"))
      << t.cpp;
  EXPECT_TRUE(has(t.cpp, "return vv_decl_write_file(vv_model, S, vv_path, vv_max_face);")) << t.cpp;
}

TEST(DeclarationsPart, AProgramWithoutPropertyBlocksHasTheTraitsAlone) {
  vvc::translation t = translated("int steps_done = 0;\nstep { ++steps_done; }\n");
  EXPECT_TRUE(has(t.declarations, "struct vv_vertex_props : vv::no_props {};")) << t.declarations;
  EXPECT_FALSE(has(t.declarations, "steps_done")) << t.declarations;
  // No global mesh: no functions over the meshes.
  EXPECT_FALSE(has(t.declarations, "vv_decl_check")) << t.declarations;
}
