// The C++ compiler's messages as the host shows them: plain quotes, a
// misspelt property named in the program's words, and output the host
// cannot read into .vvp terms (a #line beyond INT_MAX) shown as it is, in
// --compile-only, batch and the viewer alike, never a crash of the host.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cache_harness.hpp"
#include "model_compiler.hpp"
#include "run_interpreter.hpp"
#include "test_files.hpp"

using test_files::scratch_dir;

namespace fs = std::filesystem;

namespace {

// A #line beyond INT_MAX is legal C++; g++ counts it wrapped and prints a
// negative line. The host shows that message as g++ wrote it (there is no
// .vvp line to quote) and the model builds and runs: the warning is no
// reason to stop, in any mode.
const std::string beyond_int_max = "#line 3000000000 \"w.vvp\"\nstart { int unused_x = 1; }\n";
// (clang prints the line as written.)
const std::string beyond_int_max_warning =
    model_compiler::in_function("w.vvp") + (model_compiler::clang ? "w.vvp:3000000000:36" : "w.vvp:-1294967296:36") +
    ": warning: unused variable 'unused_x' [-Wunused-variable]\n";

TEST(CompilerOutput, LineBeyondIntMaxIsShownAsWrittenInCompileOnlyAndBatch) {
  const std::string model = fresh_dir("line_beyond_int") + "w.vvp";
  write(model, beyond_int_max);
  test_run::result compiled = run({"--compile-only", model});
  EXPECT_EQ(compiled.status, 0) << report(compiled);
  EXPECT_EQ(compiled.err, beyond_int_max_warning);
  test_run::result ran = run({"--batch", "--steps", "1", model});
  EXPECT_EQ(ran.status, 0) << report(ran);
  EXPECT_EQ(ran.err, beyond_int_max_warning);
  EXPECT_TRUE(contains(ran.out, "1 steps in")) << report(ran);
}

TEST(CompilerOutput, LineBeyondIntMaxLoadsInTheViewer) {
  const std::string dir = fresh_dir("line_beyond_int_viewer");
  write(dir + "w.vvp", beyond_int_max);
  write(dir + "script.txt", "step 1\nquit\n");
  test_run::result r =
      test_run::run(test_run::in_virtual_display(test_run::interpreter({"--script", dir + "script.txt", dir + "w.vvp"})),
                    240);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(contains(r.out, "loaded " + dir + "w.vvp")) << report(r);
  EXPECT_FALSE(contains(r.err, "crash")) << report(r);
}

// g++'s own text for a misspelt v$position names vvc's generated types;
// the host names the vertex (the edge record, the mesh) and what it has,
// at the .vvp line and column, with plain quotes.
const std::string misspelt =
    "#include <util/point.hpp>\n"
    "typedef util::Point<double> Pt;\n"
    "edge { int crease; };\n"
    "vertex {\n"
    "  Pt pos;\n"
    "  double c;\n"
    "};\n"
    "mesh { int generation; };\n"
    "mesh S;\n"
    "start {\n"
    "  vertex v, u;\n"
    "  add v to S;\n"
    "  v$position = Pt(0, 0, 0);\n"
    "  double a = `v$cc;\n"
    "  (v^u).creasy = 1;\n"
    "  S.generations = 2;\n"
    "  (void)a;\n"
    "}\n";

TEST(CompilerOutput, MisspeltPropertiesAreNamedInTheProgramsWords) {
  const std::string model = fresh_dir("misspelt") + "p.vvp";
  write(model, misspelt);
  test_run::result compiled = run({"--compile-only", model});
  EXPECT_EQ(compiled.status, 1) << report(compiled);
  // clang suggests no name for `cc`, and shows where the names it
  // suggests are declared: in the program's property blocks.
  const std::string cc_suggestion = model_compiler::clang ? "" : " (did you mean 'c'?)";
  const std::string crease_note =
      model_compiler::clang ? model + ":3:12: note: 'crease' declared here\n  edge { int crease; };\n             ^\n" : "";
  const std::string generation_note =
      model_compiler::clang
          ? model + ":8:12: note: 'generation' declared here\n  mesh { int generation; };\n             ^\n"
          : "";
  EXPECT_EQ(compiled.out,
            model_compiler::in_function(model) +
            model + ":13:5: error: the vertex has no property 'position'; its properties are: pos, c\n"
            "    v$position = Pt(0, 0, 0);\n"
            "      ^\n" +
            model + ":14:17: error: the vertex has no property 'cc'" + cc_suggestion + "; its properties are: pos, c\n"
            "    double a = `v$cc;\n"
            "                  ^\n" +
            model + ":15:9: error: the half-edge record has no property 'creasy' (did you mean 'crease'?); its "
                    "properties are: crease\n"
            "    (v^u).creasy = 1;\n"
            "          ^\n" + crease_note +
            model + ":16:5: error: the mesh has no property or member function 'generations' (did you mean "
                    "'generation'?); its properties are: generation\n"
            "    S.generations = 2;\n"
            "      ^\n" + generation_note);
  const std::string first = "vvinterpreter: " + model +
                            ":13:5: error: the vertex has no property 'position'; its properties are: pos, c\n";
  EXPECT_EQ(compiled.err, first);
  test_run::result ran = run({"--batch", model});
  EXPECT_EQ(ran.status, 1) << report(ran);
  EXPECT_EQ(ran.err, first);
}

}  // namespace
