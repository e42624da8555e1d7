#include "bench_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <sstream>
#include <unordered_map>

namespace {

using point = std::array<double, 3>;

bool close(const point& p, const point& q, double tolerance)
{
  return std::abs(p[0] - q[0]) <= tolerance && std::abs(p[1] - q[1]) <= tolerance &&
         std::abs(p[2] - q[2]) <= tolerance;
}

// Lexicographic order can pair points wrongly when rounding differs in a
// coordinate that ties exactly in theory (common on symmetric meshes), so a
// failed sorted comparison is re-checked by matching through a grid of
// tolerance-sized cells. Returns how many points of `a` found no partner.
std::size_t unmatched_points(const std::vector<point>& a, const std::vector<point>& b,
                             double tolerance, point& example)
{
  const auto cell = [&](double x) { return static_cast<std::int64_t>(std::floor(x / tolerance)); };
  struct key_hash {
    std::size_t operator()(const std::array<std::int64_t, 3>& k) const
    {
      // Unsigned arithmetic: wrapping is defined.
      const auto u = [](std::int64_t x) { return static_cast<std::uint64_t>(x); };
      return std::hash<std::uint64_t>()(u(k[0]) * 73856093u ^ u(k[1]) * 19349663u ^ u(k[2]) * 83492791u);
    }
  };
  std::unordered_map<std::array<std::int64_t, 3>, std::vector<std::size_t>, key_hash> grid;
  for (std::size_t i = 0; i < b.size(); ++i) grid[{cell(b[i][0]), cell(b[i][1]), cell(b[i][2])}].push_back(i);

  std::vector<bool> used(b.size(), false);
  std::size_t missing = 0;
  for (const point& p : a) {
    bool found = false;
    const std::array<std::int64_t, 3> c{cell(p[0]), cell(p[1]), cell(p[2])};
    for (int dx = -1; dx <= 1 && !found; ++dx)
      for (int dy = -1; dy <= 1 && !found; ++dy)
        for (int dz = -1; dz <= 1 && !found; ++dz) {
          const auto bucket = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (bucket == grid.end()) continue;
          for (std::size_t j : bucket->second)
            if (!used[j] && close(p, b[j], tolerance)) {
              used[j] = found = true;
              break;
            }
        }
    if (!found && missing++ == 0) example = p;
  }
  return missing;
}

}  // namespace

std::string compare_results(const bench_result& a, const bench_result& b, double tolerance)
{
  std::ostringstream why;
  if (a.vertices != b.vertices) why << "V " << a.vertices << " vs " << b.vertices;
  else if (a.faces != b.faces) why << "F " << a.faces << " vs " << b.faces;
  else if (a.positions.size() != a.vertices || b.positions.size() != b.vertices)
    why << "positions missing";
  if (!why.str().empty()) return why.str();

  std::vector<point> pa = a.positions, pb = b.positions;
  std::sort(pa.begin(), pa.end());
  std::sort(pb.begin(), pb.end());
  bool same = true;
  for (std::size_t i = 0; i < pa.size() && same; ++i) same = close(pa[i], pb[i], tolerance);
  if (same) return {};

  point example{};
  const std::size_t missing = unmatched_points(pa, pb, tolerance, example);
  if (missing == 0) return {};
  why << missing << " of " << pa.size() << " points have no counterpart within " << tolerance
      << ", e.g. (" << example[0] << ", " << example[1] << ", " << example[2] << ")";
  return why.str();
}
