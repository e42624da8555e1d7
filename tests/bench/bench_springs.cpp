// bench_springs: the mass-spring step of a closed surface (springs with
// rest lengths in the half-edge records, drag, pressure along the normals,
// explicit Euler) in vvlib — algorithms::MassSpring, i.e. forall over the
// mesh and the old neighbourhoods after a synchronise — against the same
// step in plain C++ over arrays (compressed adjacency), in the same run.
// Both must compute the same positions, bit for bit; the benchmark fails
// otherwise. The vvlib step runs on the context's threads (vv/parallel.hpp):
// it is timed on one thread and on --threads N (default 2), which must
// give the same positions too, and the speed-up of N threads is printed.
#include "bench_input.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <algorithms/physics.hpp>
#include <util/point.hpp>
#include <vv/io/from_faces.hpp>
#include <vv/vv.hpp>

namespace {

using Pt = util::Point<double>;

struct vertex_props {
  Pt pos, vel;
};
struct edge_props {
  double rest;
};
using graph = vv::graph<vertex_props, edge_props>;
using vertex = graph::vertex;

struct parameters {
  double stiffness = 20, drag = 0.5, mass = 1, dt = 0.01, pressure = 0.3;
};

// The rest length of the spring a-b: shorter or longer than it starts, by
// an amount that depends on its ends' positions (the same in both versions).
double initial_rest(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz) * (0.9 + 0.2 * std::fabs(std::sin(7 * (a[0] + b[1]))));
}

// ---- vvlib ----
struct vv_run {
  graph::context ctx;
  graph::mesh S{ctx};
  std::vector<vertex> order;

  vv_run(const bench_input& input, unsigned threads) {
    ctx.threads = threads;
    std::vector<std::vector<std::uint32_t>> faces;
    for (const auto& t : input.triangles) faces.push_back({t[0], t[1], t[2]});
    vv::build_from_faces(S, input.points, faces, "bench input");
    for (vertex v : vv::each(S)) order.push_back(v);
    for (std::size_t i = 0; i < order.size(); ++i)
      for (vertex n : vv::each(order[i])) vv::edge(order[i], n).rest = initial_rest(input.points[i], input.points[index_of(n)]);
  }
  std::size_t index_of(const vertex& v) const { return v.label() - order.front().label(); }

  double steps(const parameters& p, int count) {
    algorithms::MassSpring<vertex> springs;
    springs.stiffness = p.stiffness;
    springs.drag = p.drag;
    springs.mass = p.mass;
    springs.dt = p.dt;
    const double pressure = p.pressure;
    auto inflate = [pressure](const vertex& v) { return algorithms::surface_pressure(vv::old(v), pressure); };
    double fastest = 0;
    for (int i = 0; i < count; ++i) fastest = springs.step(S, algorithms::RestFromRecords(), inflate);
    return fastest;
  }
};

// ---- plain arrays ----
struct array_run {
  std::vector<std::uint32_t> first;  // neighbours of i: nbr[first[i] .. first[i+1]), counter-clockwise
  std::vector<std::uint32_t> nbr;
  std::vector<double> rest;          // per entry of nbr
  std::vector<Pt> pos, vel, old_pos, old_vel;

  // The same neighbourhoods, in the same order, as the vv mesh.
  explicit array_run(const vv_run& model, const bench_input& input) {
    first.push_back(0);
    for (const vertex& v : model.order) {
      for (vertex n : vv::each(v)) {
        nbr.push_back(static_cast<std::uint32_t>(model.index_of(n)));
        rest.push_back(vv::edge(v, n).rest);
      }
      first.push_back(static_cast<std::uint32_t>(nbr.size()));
    }
    for (const auto& p : input.points) pos.push_back(Pt(p[0], p[1], p[2]));
    vel.assign(pos.size(), Pt());
  }

  double steps(const parameters& p, int count) {
    double fastest = 0;
    const std::size_t n = pos.size();
    for (int s = 0; s < count; ++s) {
      old_pos = pos;
      old_vel = vel;
      fastest = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const Pt centre = old_pos[i];
        Pt spring, fan, first_arm, previous_arm;
        for (std::uint32_t e = first[i]; e < first[i + 1]; ++e) {
          const Pt d = old_pos[nbr[e]] - centre;
          const double length = d.length();
          if (length > 0) spring += (p.stiffness * (length - rest[e]) / length) * d;
        }
        for (std::uint32_t e = first[i]; e < first[i + 1]; ++e) {
          const Pt arm = old_pos[nbr[e]] - centre;
          if (e == first[i]) first_arm = arm;
          else fan += previous_arm.cross(arm);
          previous_arm = arm;
        }
        if (first[i + 1] > first[i]) fan += previous_arm.cross(first_arm);
        const Pt a = (spring + (p.pressure / 6.0) * fan - p.drag * old_vel[i]) / p.mass;
        pos[i] = old_pos[i] + p.dt * old_vel[i];
        vel[i] = old_vel[i] + p.dt * a;
        fastest = std::max(fastest, vel[i].length());
      }
    }
    return fastest;
  }
};

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

template <class F>
double time_ms(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

int int_option(int argc, char** argv, const std::string& name, int fallback) {
  for (int i = 1; i + 1 < argc; ++i)
    if (argv[i] == name) return std::atoi(argv[i + 1]);
  return fallback;
}

}  // namespace

int main(int argc, char** argv) {
  const int subdivisions = int_option(argc, argv, "--subdivisions", 5);  // 10,242 vertices
  const int steps = int_option(argc, argv, "--steps", 20);
  const int runs = int_option(argc, argv, "--runs", 5);
  const unsigned threads = static_cast<unsigned>(std::max(1, int_option(argc, argv, "--threads", 2)));
  const bench_input input = make_icosphere(subdivisions);
  const parameters p;
  std::printf("input: icosphere(%d), %zu vertices; %d mass-spring steps per run, %d runs; vvlib on 1 thread and on %u\n",
              subdivisions, input.points.size(), steps, runs, threads);

  std::vector<double> vv_ms, vv_n_ms, array_ms;
  double max_difference = 0;
  bool same_on_threads = true;
  for (int r = 0; r < runs; ++r) {
    vv_run model(input, 1), model_n(input, threads);
    array_run arrays(model, input);
    double vv_fastest = 0, vv_n_fastest = 0, array_fastest = 0;
    vv_ms.push_back(time_ms([&] { vv_fastest = model.steps(p, steps); }));
    vv_n_ms.push_back(time_ms([&] { vv_n_fastest = model_n.steps(p, steps); }));
    array_ms.push_back(time_ms([&] { array_fastest = arrays.steps(p, steps); }));
    for (std::size_t i = 0; i < model.order.size(); ++i) {
      const Pt d = model.order[i]->pos - arrays.pos[i];
      max_difference = std::max({max_difference, std::fabs(d.x()), std::fabs(d.y()), std::fabs(d.z())});
      same_on_threads = same_on_threads && std::memcmp(&model.order[i]->pos, &model_n.order[i]->pos, sizeof(Pt)) == 0 &&
                        std::memcmp(&model.order[i]->vel, &model_n.order[i]->vel, sizeof(Pt)) == 0;
    }
    max_difference = std::max(max_difference, std::fabs(vv_fastest - array_fastest));
    same_on_threads = same_on_threads && vv_fastest == vv_n_fastest;
  }
  const double vv = median_of(vv_ms), vv_n = median_of(vv_n_ms), arrays = median_of(array_ms);
  std::printf("same positions: %s (largest difference %g)\n", max_difference == 0 ? "yes" : "NO", max_difference);
  std::printf("same bytes on 1 and %u threads: %s\n", threads, same_on_threads ? "yes" : "NO");
  std::printf("springs vv_ms=%.3f array_ms=%.3f ratio=%.3f vv_threads_ms=%.3f threads=%u speedup=%.3f\n", vv, arrays,
              vv / arrays, vv_n, threads, vv / vv_n);
  return max_difference == 0 && same_on_threads ? 0 : 1;
}
