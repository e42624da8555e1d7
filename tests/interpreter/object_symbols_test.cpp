// definitions_beyond (vvinterpreter/compile/object_symbols.hpp): which
// compiled objects may be linked into every build of a model, read from
// objects the C++ compiler makes of small sources here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "compile/object_symbols.hpp"
#include "compile/process.hpp"
#include "model_compiler.hpp"
#include "test_files.hpp"

namespace fs = std::filesystem;

namespace {

// The object of `source`, compiled as models are (position-independent,
// hidden symbols, no unique symbols).
std::string object_of(const std::string& name, const std::string& source) {
  std::string dir = test_files::scratch_dir() + "object_symbols/";
  fs::create_directories(dir);
  std::ofstream(dir + name + ".cpp") << source;
  std::vector<std::string> argv = {VV_CXX, "-std=c++17", "-O1", "-fPIC", "-fvisibility=hidden",
                                   "-fvisibility-inlines-hidden", "-c", "-o", dir + name + ".o", dir + name + ".cpp"};
  if (!model_compiler::clang) argv.push_back("-fno-gnu-unique");  // clang makes no unique symbols
  vvi::process_result r = vvi::run_process(argv);
  EXPECT_EQ(r.status, 0) << r.output;
  return dir + name + ".o";
}

const char* const prefix = "vv_decl_";

}  // namespace

TEST(ObjectSymbols, InlineFunctionsTemplatesTheirStaticsConstantsAndTheAllowedFunctionsMayBeShared) {
  std::string o = object_of("shared",
                            "#include <iostream>\n"  // its stream initialiser does the same in every file
                            "#include <string>\n"
                            "#include <vector>\n"
                            "template <class T> T twice(T x) { static int calls = 0; ++calls; return 2 * x; }\n"
                            "inline int& counter() { static int n = 0; return n; }\n"
                            "static const char* const names[] = {\"a\", \"b\"};\n"
                            "static int helper(int x) { return x + 1; }\n"
                            "const char* vv_decl_name(int i) noexcept { return names[helper(i) % 2]; }\n"
                            "int vv_decl_use(std::vector<std::string>& v) { v.push_back(\"x\");\n"
                            "  return twice(++counter()); }\n");
  EXPECT_EQ(vvi::definitions_beyond(o, prefix), "");
}

TEST(ObjectSymbols, AGlobalVariableOrFunctionOfTheProgramIsDefinedTwice) {
  EXPECT_EQ(vvi::definitions_beyond(object_of("variable", "int steps_done = 3;\n"), prefix),
            "defines the global symbol steps_done");
  EXPECT_EQ(vvi::definitions_beyond(object_of("function", "double half(double x) { return x / 2; }\n"), prefix),
            "defines the global symbol _Z4halfd");
  // The allowed prefix is of the declared name, not of any part of it.
  EXPECT_EQ(vvi::definitions_beyond(object_of("near_miss", "int my_vv_decl_f() { return 1; }\n"), prefix),
            "defines the global symbol _Z12my_vv_decl_fv");
}

TEST(ObjectSymbols, StateOfItsOwnWouldDivergeFromTheProgramsCopy) {
  EXPECT_EQ(vvi::definitions_beyond(object_of("static", "static int made = 0;\n"
                                                        "int vv_decl_make() { return ++made; }\n"),
                                    prefix),
            "writable data of its own (_ZL4made)");
  // A static variable of a function of its own.
  EXPECT_EQ(vvi::definitions_beyond(object_of("local_static", "static int next() { static int n = 0; return ++n; }\n"
                                                              "int vv_decl_next() { return next(); }\n"),
                                    prefix),
            "writable data of its own (_ZZL4nextvE1n)");
}

TEST(ObjectSymbols, AFileThatIsNoObjectIsSaidSo) {
  std::string dir = test_files::scratch_dir() + "object_symbols/";
  fs::create_directories(dir);
  std::ofstream(dir + "text.o") << "not an object file\n";
  EXPECT_EQ(vvi::definitions_beyond(dir + "text.o", prefix), dir + "text.o is not an object file of this machine");
  EXPECT_EQ(vvi::definitions_beyond(dir + "missing.o", prefix), "cannot read " + dir + "missing.o");
}
