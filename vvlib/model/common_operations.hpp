// The algebra's operations nearly every program calls, named once for a
// model's traits. Never run: a quick build's header of the model's
// declarations (vvinterpreter, compile/declarations_header.hpp) calls it
// in an unused function, so that clang instantiates and compiles these
// operations once per set of declarations instead of once per edit (two
// thirds of a quick build's compile). Only operations valid for every
// traits belong here: the header is built for every model.
#pragma once

#include <vector>

#include "model/model.hpp"

namespace vv::model {

template <class Tr>
void common_operations(program<Tr>& p, mesh<Tr>& m, vertex<Tr> v, void (&block)()) {
  using V = vertex<Tr>;
  V x = p.ctx().new_vertex(where::here());
  old_vertex<Tr> o = old(v);
  // Reading: properties, old state, iteration, queries.
  (void)v.props();
  (void)o.props();
  (void)old(x).props();
  for (auto&& a : each(m)) {
    for (auto&& b : each(a)) (void)b;
    for (auto&& b : each(old(a))) (void)b;
    (void)valence(a);
    (void)valence(old(a));
  }
  (void)any_in(v);
  (void)any_in(o);
  (void)next_to(x, v);
  (void)prev_to(x, v);
  (void)next_to(x, o);
  (void)prev_to(x, o);
  (void)uncounted::next_to(x, o);
  (void)uncounted::prev_to(x, o);
  (void)uncounted::next_to(x, v);
  (void)uncounted::prev_to(x, v);
  (void)is_in(x, v);
  (void)is_in(x, m);
  (void)label_of(v);
  // Editing: neighbourhoods and meshes.
  make_nb(x, {v});
  make_nb(x, {v, x});
  replace_in(v, x, x);
  splice_after(v, x, x);
  splice_before(v, x, x);
  erase_from(v, x);
  mesh<Tr> n;
  add_to(x, n);
  remove_from(x, n);
  merge_with(m, n);
  clear(n);
  synchronise(m);
  // Lists of vertices, as programs keep them.
  std::vector<V> list;
  list.push_back(v);
  list.emplace_back(x);
  for (const V& a : list) (void)a;
  (void)list[0];
  std::vector<std::vector<V>> lists;
  lists.push_back(list);
  // The entry points' own: the model object, a block run, the file
  // objects' paths.
  program<Tr> made("");
  (void)p.run(block);
  (void)file_object_paths(p);
}

}  // namespace vv::model
