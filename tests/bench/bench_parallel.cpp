// bench_parallel: a smoothing step on one thread and on several, in the
// same run. The step is synchronise, then a parallel forall that reads the
// old neighbours and writes its own vertex, on an icosphere of 163,842
// vertices by default: tests/bench/smooth.vvp translated and compiled as
// the interpreter compiles models (each run a fresh process, steps only
// timed), and the same step written against vvlib
// (vv::parallel_for_each). For each it prints the median wall time over
// interleaved runs, the CPU time of all threads and per thread, and the
// speed-up of N threads over 1; the positions must be the same bytes,
// or the benchmark fails. A third implementation is the ceiling the
// machine sets: the same step over plain arrays (positions, and the
// neighbours as index lists in the mesh's order), an OpenMP loop with no
// library around it. Its speed-up is what memory allows this loop here.
#include "bench_input.hpp"
#include "bench_translated.hpp"
#include "stopwatch.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <util/point.hpp>
#include <vv/io/from_faces.hpp>
#include <vv/vv.hpp>

namespace {

using Pt = util::Point<double>;
struct vertex_props {
  Pt pos;
};
using graph = vv::graph<vertex_props>;
using vertex = graph::vertex;

// The step of smooth.vvp, against vvlib.
bench_result run_vvlib(const bench_input& input, int steps, unsigned threads) {
  graph::context ctx;
  ctx.threads = threads;
  graph::mesh S(ctx);
  vv::build_from_faces(S, input.points, input.polygons(), "bench input");
  bench_result r;
  const stopwatch timer;
  for (int i = 0; i < steps; ++i) {
    vv::synchronise(S);
    vv::parallel_for_each(S, [](vertex v) {
      Pt sum;
      for (auto&& n : vv::each(vv::old(v))) sum += vv::old(n)->pos;
      v->pos = 0.5 * vv::old(v)->pos + 0.5 / double(vv::valence(vv::old(v))) * sum;
    });
  }
  timer.stop(r);
  for (vertex v : vv::each(S)) r.positions.push_back({v->pos.x(), v->pos.y(), v->pos.z()});
  r.vertices = S.size();
  return r;
}

// The step over plain arrays, in the order and with the arithmetic of the
// others (so the same bytes): the neighbours are read from a vvlib mesh
// built from the same faces, before the clock starts.
bench_result run_plain(const bench_input& input, int steps, unsigned threads) {
  graph::context ctx;
  graph::mesh S(ctx);
  vv::build_from_faces(S, input.points, input.polygons(), "bench input");
  std::vector<std::uint32_t> index(ctx.slot_count(), 0);
  std::vector<Pt> pos;
  for (vertex v : vv::each(S)) {
    index[v.slot()] = static_cast<std::uint32_t>(pos.size());
    pos.push_back(v->pos);
  }
  std::vector<std::size_t> first{0};
  std::vector<std::uint32_t> neighbours;
  for (vertex v : vv::each(S)) {
    for (vertex n : vv::each(v)) neighbours.push_back(index[n.slot()]);
    first.push_back(neighbours.size());
  }
  const long n = static_cast<long>(pos.size());
  std::vector<Pt> old(pos.size());
  bench_result r;
  const stopwatch timer;
  for (int i = 0; i < steps; ++i) {
    old = pos;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1024)
    for (long v = 0; v < n; ++v) {
      Pt sum;
      for (std::size_t k = first[v]; k < first[v + 1]; ++k) sum += old[neighbours[k]];
      pos[v] = 0.5 * old[v] + 0.5 / double(first[v + 1] - first[v]) * sum;
    }
  }
  timer.stop(r);
  for (const Pt& p : pos) r.positions.push_back({p.x(), p.y(), p.z()});
  r.vertices = pos.size();
  return r;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

int int_option(int argc, char** argv, const std::string& name, int fallback) {
  for (int i = 1; i + 1 < argc; ++i)
    if (argv[i] == name) return std::atoi(argv[i + 1]);
  return fallback;
}

struct series {
  std::vector<double> wall, cpu;
  std::vector<std::array<double, 3>> positions;
  bool same = true;
  void add(const bench_result& r) {
    wall.push_back(r.ms);
    cpu.push_back(r.process_cpu_ms);
    if (positions.empty()) positions = r.positions;
    else same = same && positions == r.positions;
  }
};

}  // namespace

int main(int argc, char** argv) {
  const int subdivisions = int_option(argc, argv, "--subdivisions", 7);  // 163,842 vertices
  const int steps = int_option(argc, argv, "--steps", 10);
  const int runs = int_option(argc, argv, "--runs", 5);
  const unsigned threads = static_cast<unsigned>(int_option(argc, argv, "--threads", 2));
  const bench_input input = make_icosphere(subdivisions);
  std::printf("input: icosphere(%d), %zu vertices; %d smoothing steps per run, %d runs; 1 thread against %u\n",
              subdivisions, input.points.size(), steps, runs, threads);

  const std::string scratch = (std::filesystem::temp_directory_path() / ("bench_parallel_" + std::to_string(getpid()))).string();
  translated_model model{std::string(VV_BENCH_MODELS) + "/smooth.so", "icosphere.vvm"};
  series vv1, vvn, lib1, libn, plain1, plainn;
  try {
    // The translated runs fork; a child forked after this process ran
    // OpenMP threads would wait for threads it does not have (libgomp is
    // not fork-safe): they all come first.
    for (int r = 0; r < runs; ++r) {
      model.threads = 1;
      vv1.add(run_translated(model, input, steps, true, scratch));
      model.threads = threads;
      vvn.add(run_translated(model, input, steps, true, scratch));
    }
    for (int r = 0; r < runs; ++r) {
      lib1.add(run_vvlib(input, steps, 1));
      libn.add(run_vvlib(input, steps, threads));
      plain1.add(run_plain(input, steps, 1));
      plainn.add(run_plain(input, steps, threads));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_parallel: %s\n", e.what());
    std::filesystem::remove_all(scratch);
    return 1;
  }
  std::filesystem::remove_all(scratch);
  const bool same = vv1.same && vvn.same && lib1.same && libn.same && plain1.same && plainn.same &&
                    vv1.positions == vvn.positions && vv1.positions == lib1.positions &&
                    lib1.positions == libn.positions && lib1.positions == plain1.positions &&
                    plain1.positions == plainn.positions;
  std::printf("same positions on 1 and %u threads, translated, vvlib and plain arrays: %s\n", threads,
              same ? "yes" : "NO");
  auto line = [&](const char* name, const series& one, const series& many) {
    const double w1 = median(one.wall), wn = median(many.wall), c1 = median(one.cpu), cn = median(many.cpu);
    std::printf("%-10s 1 thread: %8.1f ms (cpu %8.1f)   %u threads: %8.1f ms (cpu %8.1f, %7.1f per thread)   speed-up %.2f\n",
                name, w1, c1, threads, wn, cn, cn / threads, w1 / wn);
    return w1 / wn;
  };
  const double vv_speedup = line("vv", vv1, vvn);
  const double lib_speedup = line("vvlib", lib1, libn);
  const double plain_speedup = line("plain", plain1, plainn);
  std::printf("smooth vv_1_ms=%.3f vv_n_ms=%.3f vv_speedup=%.3f vvlib_1_ms=%.3f vvlib_n_ms=%.3f vvlib_speedup=%.3f "
              "plain_1_ms=%.3f plain_n_ms=%.3f plain_speedup=%.3f threads=%u\n",
              median(vv1.wall), median(vvn.wall), vv_speedup, median(lib1.wall), median(libn.wall), lib_speedup,
              median(plain1.wall), median(plainn.wall), plain_speedup, threads);
  return same ? 0 : 1;
}
