// vvc: translate a vv program (.vvp) to C++.
//
//   vvc INPUT.vvp -o OUTPUT.cpp     (-o - writes to standard output)
//   vvc --help | --version
//
// Diagnostics go to standard error as file:line:col: error: message, with
// the source line and a caret. On any error the exit status is 1 and no
// output file is left (a stale one from an earlier run is removed).
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

#include <vv/io/files.hpp>

#include "translate.hpp"

namespace {

const char* usage =
    "usage: vvc INPUT.vvp -o OUTPUT.cpp\n"
    "\n"
    "Translates a vv program (C++ with the vertex-vertex algebra) to C++\n"
    "that includes vvlib and exports the plugin entry points of the vv\n"
    "interpreter. #line directives map the output back to INPUT.vvp.\n"
    "\n"
    "options:\n"
    "  -o FILE     where to write the C++ ('-' for standard output)\n"
    "  --help      this text\n"
    "  --version   the translator's version\n";

}  // namespace

int main(int argc, char** argv) {
  std::string input, output;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << usage;
      return 0;
    }
    if (a == "--version") {
      std::cout << "vvc " << vvc::version() << "\n";
      return 0;
    }
    if (a == "-o") {
      if (i + 1 == argc) {
        std::cerr << "vvc: -o needs a file name\n" << usage;
        return 2;
      }
      output = argv[++i];
    } else if (!a.empty() && a[0] == '-' && a != "-") {
      std::cerr << "vvc: unknown option '" << a << "'\n" << usage;
      return 2;
    } else if (input.empty()) {
      input = a;
    } else {
      std::cerr << "vvc: more than one input file ('" << input << "' and '" << a << "')\n";
      return 2;
    }
  }
  if (input.empty() || output.empty()) {
    std::cerr << "vvc: " << (input.empty() ? "no input file" : "no output file (-o)") << "\n" << usage;
    return 2;
  }
  std::string unreadable;
  vvc::translation t = vvc::translate_file(input, &unreadable);
  if (!t.ok) {
    if (!unreadable.empty()) std::cerr << input << ": error: cannot read file: " << unreadable << "\n";
    t.diag.print(std::cerr);
    if (output != "-") std::remove(output.c_str());
    return 1;
  }
  if (output == "-") {
    std::cout << t.cpp;
    return std::cout.flush() ? 0 : 1;
  }
  try {
    vv::io::write_text_file(output, t.cpp);  // atomically: never half a file
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
