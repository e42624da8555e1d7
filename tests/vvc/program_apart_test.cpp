// The translation in two (vvc::emit_apart): the header of the declarations
// a quick build precompiles, and the program compiled with it. Together
// they must be the whole translation, its lines in one order or the other,
// and the header must define nothing of vvc's that holds state (the model
// object): a precompiled header's code is compiled apart, and a variable
// there would be a second one. That the two compiled together run as the
// whole does is checked by the interpreter's quick-build tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "translate.hpp"

namespace {

vvc::translation translation_in_two(const std::string& program) {
  vvc::translation t = vvc::translate_text("m.vvp", program);
  std::string errors;
  for (const auto& d : t.diag.list()) errors += vvc::format(d);
  EXPECT_TRUE(t.ok) << errors;
  return t;
}

// The code's lines, sorted, without #line directives and blank lines (each
// part names its lines afresh) and without the header's extern declarations
// of the parameters (the program defines them).
std::vector<std::string> sorted_lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line.rfind("#line ", 0) != 0 && line.rfind("extern double rate;", 0) != 0)
      lines.push_back(line);
  std::sort(lines.begin(), lines.end());
  return lines;
}

// The header's lines before the call of the common operations it ends with.
std::string header_without_the_call(const std::string& header) {
  std::size_t call = header.rfind("#line 1 \"<vvc generated>\"\n#include <model/common_operations.hpp>");
  EXPECT_NE(call, std::string::npos) << header;
  return header.substr(0, call);
}

const std::string with_properties =
    "#include <cmath>\n"
    "typedef double real;\n"
    "inline real twice(real x) { return 2 * x; }\n"
    "param double rate = 0.5 in [0, 1];\n"
    "start { proxy.steps = 3; }\n"
    "vertex {\n"
    "  real h;\n"
    "};\n"
    "mesh S;\n"
    "void grow() { forall v in S { v$h = twice(v$h); } }\n"
    "step { grow(); }\n";

}  // namespace

TEST(ProgramApart, HeaderAndProgramAreTheWholeTranslationInTwo) {
  for (const std::string& source : {with_properties, std::string("mesh S;\nstep { }\n")}) {
    vvc::translation t = translation_in_two(source);
    std::vector<std::string> whole = sorted_lines_of(t.cpp);
    std::vector<std::string> parts = sorted_lines_of(header_without_the_call(t.header) + t.program);
    std::vector<std::string> only_whole, only_parts;
    std::set_difference(whole.begin(), whole.end(), parts.begin(), parts.end(), std::back_inserter(only_whole));
    std::set_difference(parts.begin(), parts.end(), whole.begin(), whole.end(), std::back_inserter(only_parts));
    EXPECT_TRUE(only_whole.empty() && only_parts.empty())
        << "only in the whole: " << ::testing::PrintToString(only_whole)
        << "\nonly in the parts: " << ::testing::PrintToString(only_parts) << "\nheader:\n"
        << t.header << "\nprogram:\n"
        << t.program;
  }
}

TEST(ProgramApart, TheHeaderHoldsTheDeclarationsAndTheProgramTheModelObject) {
  vvc::translation t = translation_in_two(with_properties);
  const std::string& h = t.header;
  const std::string& p = t.program;
  EXPECT_NE(h.find("inline real twice(real x)"), std::string::npos) << h;
  EXPECT_NE(h.find("struct vv_traits : vv::traits<vv_vertex_props, vv_edge_props, vv_mesh_props>"), std::string::npos)
      << h;
  EXPECT_NE(h.find("extern template class vv::context<vv_traits>;"), std::string::npos) << h;
  EXPECT_NE(h.find("vv::model::common_operations(vv_p, vv_m, vv_v, vv_block);"), std::string::npos) << h;
  // No variable, which the header's code would copy: the model object,
  // the parameter (declared only), and no block that names them.
  EXPECT_EQ(h.find("vv_model"), std::string::npos) << h;
  EXPECT_EQ(h.find("proxy"), std::string::npos) << h;
  EXPECT_EQ(h.find("mesh S"), std::string::npos) << h;
  EXPECT_NE(h.find("extern double rate;"), std::string::npos) << h;
  EXPECT_EQ(h.find("rate = 0.5"), std::string::npos) << h;
  EXPECT_EQ(h.find("vv_block_start"), std::string::npos) << h;
  EXPECT_NE(p.find("double rate = 0.5;"), std::string::npos) << p;
  EXPECT_NE(p.find("static void vv_block_start() { proxy.steps = 3; }"), std::string::npos) << p;
  // The program begins with the model object, still the first global.
  EXPECT_EQ(p.find("#line 1 \"<vvc generated>\"\n// The model object"), 0u) << p;
  EXPECT_LT(p.find("static vv::model::program<vv_traits> vv_model("), p.find("double rate = 0.5;")) << p;
  EXPECT_LT(p.find("double rate = 0.5;"), p.find("mesh S")) << p;
  EXPECT_NE(p.find("vv::context<vv_traits>& vv_traits::context() { return vv_model.ctx(); }"), std::string::npos)
      << p;
  EXPECT_EQ(p.find("struct vv_vertex_props"), std::string::npos) << p;
}

TEST(ProgramApart, EachPartBeginsItsLinesAfresh) {
  // The program's code after the helpers, and the parameter moved from the
  // declarations, are named by their .vvp lines again.
  vvc::translation t = translation_in_two(with_properties);
  std::size_t code = t.program.find("mesh S;");
  ASSERT_NE(code, std::string::npos) << t.program;
  std::size_t line = t.program.rfind("#line ", code);
  ASSERT_NE(line, std::string::npos);
  EXPECT_EQ(t.program.substr(line, t.program.find('\n', line) - line), "#line 9 \"m.vvp\"") << t.program;
  std::size_t rate = t.program.find("double rate = 0.5;");
  ASSERT_NE(rate, std::string::npos) << t.program;
  line = t.program.rfind("#line ", rate);
  EXPECT_EQ(t.program.substr(line, t.program.find('\n', line) - line), "#line 4 \"m.vvp\"") << t.program;
}
