// Shared model types and helpers for the vertex-vertex algebra tests
// (vertex_test, queries_test, edits_test, edges_paths_test).
//
// The model: vertex properties VP (x, n, pos, in declaration order), half-edge
// records EP (mark, b), no mesh properties. build_double_pyramid() creates the
// octahedron of LANGUAGE.md section 7 in file order, so on a fresh context the
// vertex with file index i has label i + 1.
#pragma once

#include <vv/vv.hpp>
#include <util/point.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <string>
#include <vector>

namespace vvtest {

using Pt = util::Point<double>;

struct VP {
  double x = 0;
  int n = 0;
  Pt pos;
};

struct EP {
  int mark = 0;
  bool b = false;
  friend bool operator==(const EP& l, const EP& r) { return l.mark == r.mark && l.b == r.b; }
  friend bool operator!=(const EP& l, const EP& r) { return !(l == r); }
};

using G = vv::graph<VP, EP>;
using V = G::vertex;

//! The double pyramid (octahedron) of LANGUAGE.md section 7. Creates the six
//! vertices in file order, sets their positions and neighbourhoods, adds them
//! to M (in file order) and returns them indexed by file position.
inline std::vector<V> build_double_pyramid(G::context& ctx, G::mesh& M) {
  const double h = 1.4142;
  const Pt pos[6] = {Pt(-1, 0, -1), Pt(1, 0, -1), Pt(1, 0, 1),
                     Pt(-1, 0, 1),  Pt(0, h, 0),  Pt(0, -h, 0)};
  const int nb[6][4] = {{1, 5, 3, 4}, {2, 5, 0, 4}, {3, 5, 1, 4},
                        {0, 5, 2, 4}, {3, 2, 1, 0}, {0, 1, 2, 3}};
  std::vector<V> v;
  for (int i = 0; i < 6; ++i) {
    v.push_back(ctx.new_vertex());
    v.back()->pos = pos[i];
    M.add(v.back());
  }
  for (int i = 0; i < 6; ++i)
    vv::make_nb(v[i], {v[nb[i][0]], v[nb[i][1]], v[nb[i][2]], v[nb[i][3]]});
  return v;
}

//! Labels of the neighbours of a vertex (current or old state) in rotation
//! order, starting from the first entry.
template <class X>
std::vector<unsigned> nb_labels(const X& v) {
  std::vector<unsigned> out;
  for (V x : vv::each(v)) out.push_back(x.label());
  return out;
}

//! The same cyclic list, rotated so that it starts at the smallest label:
//! compares rotations without depending on where the list "starts".
template <class X>
std::vector<unsigned> cycle(const X& v) {
  std::vector<unsigned> out = nb_labels(v);
  if (!out.empty()) std::rotate(out.begin(), std::min_element(out.begin(), out.end()), out.end());
  return out;
}

//! A list of labels, rotated like cycle().
inline std::vector<unsigned> canon(std::vector<unsigned> l) {
  if (!l.empty()) std::rotate(l.begin(), std::min_element(l.begin(), l.end()), l.end());
  return l;
}

inline std::vector<unsigned> labels(std::initializer_list<V> l) {
  std::vector<unsigned> out;
  for (const V& x : l) out.push_back(x.label());
  return out;
}

//! Label of the flagged neighbour (0 when the flag is unset).
template <class X>
unsigned flag_label(const X& v) {
  return vv::flagged_in(v).label();
}

//! Everything an edit can change in one neighbourhood: the entries in order,
//! the flag and the records (mark, b) of each entry.
struct nb_state {
  std::vector<unsigned> nb;
  unsigned flag = 0;
  std::vector<int> marks;
  std::vector<bool> bs;
  friend bool operator==(const nb_state& l, const nb_state& r) {
    return l.nb == r.nb && l.flag == r.flag && l.marks == r.marks && l.bs == r.bs;
  }
};

inline nb_state state_of(const V& v) {
  nb_state s;
  s.nb = nb_labels(v);
  s.flag = flag_label(v);
  for (V x : vv::each(v)) {
    s.marks.push_back(vv::edge(v, x).mark);
    s.bs.push_back(vv::edge(v, x).b);
  }
  return s;
}

inline void PrintTo(const nb_state& s, std::ostream* os) {
  *os << "{nb:";
  for (unsigned l : s.nb) *os << ' ' << l;
  *os << "; flag: " << s.flag << "; marks:";
  for (int m : s.marks) *os << ' ' << m;
  *os << '}';
}

//! Passes when f throws vv::error whose message contains every one of the
//! given pieces.
template <class F>
::testing::AssertionResult throws_vv_error(F&& f, std::initializer_list<std::string> pieces) {
  try {
    f();
  } catch (const vv::error& e) {
    std::string what = e.what();
    for (const std::string& p : pieces)
      if (what.find(p) == std::string::npos)
        return ::testing::AssertionFailure()
               << "vv::error \"" << what << "\" does not mention \"" << p << "\"";
    return ::testing::AssertionSuccess() << what;
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw another exception: " << e.what();
  } catch (...) {
    return ::testing::AssertionFailure() << "threw a non-standard exception";
  }
  return ::testing::AssertionFailure() << "no exception was thrown";
}

//! check_invariants on a mesh holding exactly the given vertices.
inline ::testing::AssertionResult invariants_hold(std::initializer_list<V> vs) {
  G::mesh M;
  for (const V& v : vs) M.add(v);
  try {
    vv::check_invariants(M);
  } catch (const vv::error& e) {
    return ::testing::AssertionFailure() << e.what();
  }
  return ::testing::AssertionSuccess();
}

}  // namespace vvtest
