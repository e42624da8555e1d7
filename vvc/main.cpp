// vvc: translate a vv program (.vvp) to C++.
//
//   vvc INPUT.vvp -o OUTPUT.cpp     (-o - writes to standard output)
//   vvc --help | --version
//
// Diagnostics go to standard error as file:line:col: error: message, with
// the source line and a caret. On any error the exit status is 1 and no
// output file is left (a stale one from an earlier run is removed). An
// output that would overwrite the program or a file it includes is
// refused (exit status 2). How the output is written: vv/io/output_file.hpp.
#include <iostream>
#include <optional>
#include <string>

#include <vv/io/output_file.hpp>

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
    "  -o FILE     where to write the C++ ('-' for standard output; never\n"
    "              over the program or a file it includes)\n"
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
  const bool to_stdout = output == "-";
  // Checked before translating, so that no path below (not even removing a
  // stale output after an error) can touch the program.
  if (!to_stdout && vv::io::same_file(output, input)) {
    std::cerr << "vvc: refusing to write over the program: -o '" << output << "' is the input file '" << input
              << "'\n";
    return 2;
  }
  std::optional<vv::io::output_file> out;
  if (!to_stdout) {
    out.emplace(output);
    if (!out->problem().empty()) {
      std::cerr << output << ": error: cannot write file: " << out->problem() << "\n";
      return 1;
    }
  }
  std::string unreadable;
  vvc::translation t = vvc::translate_file(input, &unreadable);
  if (std::string source = to_stdout ? "" : vv::io::file_among(output, t.sources.paths()); !source.empty()) {
    std::cerr << "vvc: refusing to write over the program: -o '" << output << "' is '" << source
              << "', which the program includes\n";
    return 2;
  }
  if (!t.ok) {
    if (!unreadable.empty()) std::cerr << input << ": error: cannot read file: " << unreadable << "\n";
    t.diag.print(std::cerr);
    if (out) out->remove_previous();
    return 1;
  }
  if (to_stdout) {
    std::cout << t.cpp;
    return std::cout.flush() ? 0 : 1;
  }
  if (std::string why = out->write(t.cpp); !why.empty()) {
    std::cerr << output << ": error: cannot write file: " << why << "\n";
    return 1;
  }
  return 0;
}
