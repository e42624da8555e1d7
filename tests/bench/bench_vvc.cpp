// Translator speed: translates a generated vv program of N lines (default
// 20,000) in-process and prints the median time over R runs.
//
//   bench_vvc [--lines N] [--runs R]
//
// Ends with one machine-readable line: vvc lines=... median_ms=... lines_per_s=...
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "translate.hpp"

namespace {

// A Loop-style function: queries, old state, edits, loops, a path and an
// edge record, as real models mix them. 24 lines.
std::string chunk(int i) {
  std::string n = std::to_string(i);
  return "void subdivide_" + n + "(mesh& S) {\n"
         "  synchronise S;\n"
         "  mesh N;\n"
         "  forall p in S {\n"
         "    forall q in `p {\n"
         "      if (p < q) {\n"
         "        vertex x;\n"
         "        x$pos = 3.0/8 * (`p$pos + `q$pos) + 1.0/8 * (`(nextto q in `p)$pos + `(prevto q in `p)$pos);\n"
         "        replace q with x in p;\n"
         "        replace p with x in q;\n"
         "        make {p, q} nb_of x;\n"
         "        (p|x).mark = " + n + ";\n"
         "        add x to N;\n"
         "      }\n"
         "    }\n"
         "  }\n"
         "  forall x in N {\n"
         "    vertex p = any in x;\n"
         "    vertex q = nextto p in x;\n"
         "    vertex r = @(p, x) swap next @;\n"
         "    make {p, prevto x in p, nextto x in q, q, prevto x in q, r} nb_of x;\n"
         "  }\n"
         "  merge S with N;\n"
         "}\n";
}

std::string program(int lines) {
  std::string s =
      "#include <util/point.hpp>\n"
      "typedef util::Point<double> Pt;\n"
      "edge { int mark; };\n"
      "vertex { Pt pos; };\n"
      "mesh S;\n";
  int n = 5;
  for (int i = 0; n < lines; ++i, n += 24) s += chunk(i);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  int lines = 20000, runs = 5;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--lines") && i + 1 < argc) lines = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) runs = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr, "usage: bench_vvc [--lines N] [--runs R]\n");
      return 2;
    }
  }
  if (lines < 1 || runs < 1) {
    std::fprintf(stderr, "bench_vvc: --lines and --runs must be positive\n");
    return 2;
  }
  std::string text = program(lines);
  int actual_lines = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  std::vector<double> ms;
  std::size_t out_bytes = 0;
  for (int r = 0; r < runs; ++r) {
    auto start = std::chrono::steady_clock::now();
    vvc::translation t = vvc::translate_text("bench.vvp", text);
    auto stop = std::chrono::steady_clock::now();
    if (!t.ok) {
      std::fprintf(stderr, "bench_vvc: the generated program did not translate\n");
      return 1;
    }
    out_bytes = t.cpp.size();
    ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
  }
  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  double median = sorted[sorted.size() / 2];
  std::printf("translated %d lines (%zu bytes in, %zu bytes of C++ out), %d runs:", actual_lines,
              text.size(), out_bytes, runs);
  for (double m : ms) std::printf(" %.2f", m);
  std::printf(" ms\nmedian %.2f ms (target: under 100 ms)\n", median);
  std::printf("vvc lines=%d median_ms=%.3f lines_per_s=%.0f\n", actual_lines, median,
              actual_lines / (median / 1000.0));
  return 0;
}
