// The tetrahedron every outside project builds: 4 vertices, 6 edges,
// 4 triangles, neighbourhoods counter-clockwise seen from outside.
#pragma once

#include <cstdio>

#include <util/point.hpp>
#include <vv/vv.hpp>

struct tet_props {
  util::Point<double> pos;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
  }
};
using tet = vv::graph<tet_props>;

inline void build_tetrahedron(tet::mesh& M) {
  tet::context& ctx = *M.ctx();
  tet::vertex a = ctx.new_vertex(), b = ctx.new_vertex(), c = ctx.new_vertex(), d = ctx.new_vertex();
  a->pos = {0, 0, 0};
  b->pos = {1, 0, 0};
  c->pos = {0, 1, 0};
  d->pos = {0, 0, 1};
  vv::make_nb(a, {b, d, c});
  vv::make_nb(b, {a, c, d});
  vv::make_nb(c, {a, d, b});
  vv::make_nb(d, {a, b, c});
  for (const tet::vertex& v : {a, b, c, d}) M.add(v);
}

// Prints what was measured against what was expected; false on a mismatch.
inline bool expect(const char* what, long got, long want) {
  std::printf("%s: %ld (expected %ld)\n", what, got, want);
  return got == want;
}
