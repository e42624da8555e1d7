// Loop subdivision of a closed triangle mesh, written against vvlib exactly
// as the translator turns the vv program below into C++ (each statement is
// preceded by its vv source). Used by the default demo, the tests that
// compare it with OpenMesh, and the benchmark.
#pragma once

#include <cmath>

#include <util/point.hpp>
#include <vv/vv.hpp>

namespace loop_example {

using Pt = util::Point<double>;

//! vertex { Pt pos; }
struct vertex_props {
  Pt pos;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
  }
};

using graph = vv::graph<vertex_props>;

//! The weight of an old vertex of valence n: w v + (1 - w) avg(neighbours).
inline double old_vertex_weight(std::size_t n) {
  double c = 3.0 / 8.0 + std::cos(2.0 * M_PI / static_cast<double>(n)) / 4.0;
  return c * c + 3.0 / 8.0;
}

//! One Loop step on S (closed, triangulated, counter-clockwise).
template <class Tr>
void subdivide(vv::mesh<Tr>& S) {
  using vertex = vv::vertex<Tr>;
  using mesh = vv::mesh<Tr>;
  // synchronise S;
  vv::synchronise(S);
  // mesh N;
  mesh N(vv::context_of(S));
  // forall p in S {
  for (vertex p : vv::each(S)) {
    // forall q in `p {
    for (vertex q : vv::each(vv::old(p))) {
      // if (p < q) {
      if (p < q) {
        // vertex x;
        vertex x = vv::context_of(S).new_vertex();
        // x$pos = 3.0/8 * (`p$pos + `q$pos)
        //       + 1.0/8 * (`(nextto q in `p)$pos + `(prevto q in `p)$pos);
        x.props().pos = 3.0 / 8 * (vv::old(p).props().pos + vv::old(q).props().pos) +
                        1.0 / 8 * (vv::old(vv::next_to(q, vv::old(p))).props().pos +
                                   vv::old(vv::prev_to(q, vv::old(p))).props().pos);
        // replace q with x in p;  replace p with x in q;
        vv::replace_in(q, x, p);
        vv::replace_in(p, x, q);
        // make {p, q} nb_of x;   (completed below, once all edges are split)
        vv::make_nb(x, {p, q});
        // add x to N;
        N.add(x);
      }
    }
    // double w = old_vertex_weight(valence `p);  Pt sum;
    double w = old_vertex_weight(vv::valence(vv::old(p)));
    Pt sum;
    // forall q in `p { sum += `q$pos; }
    for (vertex q : vv::each(vv::old(p))) sum += vv::old(q).props().pos;
    // p$pos = w * `p$pos + (1 - w) / valence `p * sum;
    p.props().pos = w * vv::old(p).props().pos +
                    (1 - w) / static_cast<double>(vv::valence(vv::old(p))) * sum;
  }
  // forall x in N {
  for (vertex x : vv::each(N)) {
    // vertex p = any in x;  vertex q = nextto p in x;
    vertex p = vv::any_in(x);
    vertex q = vv::next_to(p, x);
    // Around x: p, the midpoints of p-r and r-q, q, of q-l and l-p.
    // make {p, prevto x in p, nextto x in q, q, prevto x in q, nextto x in p} nb_of x;
    vv::make_nb(x, {p, vv::prev_to(x, p), vv::next_to(x, q), q, vv::prev_to(x, q),
                    vv::next_to(x, p)});
  }
  // merge S with N;
  S.merge(N);
}

}  // namespace loop_example
