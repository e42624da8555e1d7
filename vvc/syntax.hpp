// The syntax tree. C++ the translator does not need to understand stays a
// sequence of source tokens; vv constructs, and the C++ structure they can
// sit in (statements, bodies, groups), get nodes of their own. Every node
// keeps a token of its source, for diagnostics and #line.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "token.hpp"

namespace vvc {

struct stmt;
using stmt_ptr = std::unique_ptr<stmt>;
using stmt_list = std::vector<stmt_ptr>;

struct piece;
using pieces = std::vector<piece>;

enum class piece_kind {
  token,        // a source token, emitted as it is
  group,        // ( ... ) [ ... ] { ... }: tok opens, close closes, parts[0] inside
  body,         // { statements }: a function or lambda body
  class_body,   // { members }: parts[0] holds them as declarations
  old_state,    // ` X                  -> vv::old(X)
  property,     // X $ name             -> X.props().name (tok = name)
  query,        // nextto X in V, valence V, ... (see query_kind)
  edge_access,  // (X ^ Y), (X | Y)     -> (vv::edge_hat(X, Y)) (tok = operator)
  path,         // @(a, b) ops @        -> vv::path(a, b).op()...
};

enum class query_kind {
  next_to,       // nextto X in V
  prev_to,       // prevto X in V
  next_i_to,     // next(I)to X in V
  prev_i_to,     // prev(I)to X in V
  next_to_flag,  // nextto flag in V
  prev_to_flag,  // prevto flag in V
  any_in,        // any in V
  flagged_in,    // flagged in V
  valence,       // valence V
  is_in,         // is X in V
  label_of,      // labelof V
};

struct piece {
  piece_kind kind = piece_kind::token;
  const token* tok = nullptr;    // the token itself, the opener, or the keyword
  const token* close = nullptr;  // a group's closer, a path's final @
  query_kind query = query_kind::next_to;
  std::vector<pieces> parts;     // operands (in source order) or group contents
  stmt_list body;                // a body's statements
  // Paths: on the old state? assigning back (@&)? and the operations.
  bool old = false;
  bool assign = false;
  bool lambda = false;  // a body: of a lambda (not of a function)
  std::vector<const token*> ops;
};

//! A piece that is just this token.
inline piece token_piece(const token* t) {
  piece p;
  p.tok = t;
  return p;
}

enum class stmt_kind {
  compound,     // { children }
  simple,       // head ; (declarations and expression statements)
  preproc,      // a preprocessor line
  empty,        // ;
  if_,          // if head children[0] [else children[1]]
  while_,       // while head children[0]
  do_while,     // do children[0] while head ;
  for_,         // for head children[0]   (head: the parenthesised group)
  switch_,      // switch head children[0]
  label,        // case X: / default: / name:   (head: up to and with the colon)
  try_,         // try children[0] (catch head children[i])*
  edit,         // a vv edit statement (see edit_kind)
  forall,       // forall name in V children[0]
  vertex_decl,  // vertex declarators ;
};

enum class edit_kind {
  make,              // make {a, b} nb_of V;        operands: V, a, b, ...
  erase,             // erase X from V;             X, V
  erase_flag,        // erase flag from V;          V
  replace,           // replace A with X in V;      A, X, V
  replace_flag,      // replace flag with X in V;   X, V
  splice_after,      // splice X after A in V;      X, A, V
  splice_before,     // splice X before A in V;     X, A, V
  splice_after_flag, // splice X after flag in V;   X, V
  splice_before_flag,// splice X before flag in V;  X, V
  flag,              // flag X in V;                X, V
  add,               // add X to M;                 X, M
  remove,            // remove X from M;            X, M
  merge,             // merge M with N;             M, N
  clear,             // clear M;                    M
  synchronise,       // synchronise M;              M
};

//! One declarator of `vertex a, b(x, y), c = d;`.
struct vertex_declarator {
  const token* name = nullptr;
  enum { create, create_with, reference, plain } how = create;
  //! create_with: one per initial value; reference: [0] = initializer;
  //! plain (an array of handles): [0] = what follows the name, as it is.
  std::vector<pieces> args;
};

struct stmt {
  stmt_kind kind = stmt_kind::simple;
  const token* tok = nullptr;  // first token
  pieces head;                 // see stmt_kind
  stmt_list children;
  std::vector<pieces> heads;   // try: the catch headers
  const token* else_tok = nullptr;
  edit_kind edit = edit_kind::make;
  std::vector<pieces> operands;
  const token* name = nullptr;  // forall: the loop variable
  std::vector<vertex_declarator> declarators;
  const token* end = nullptr;   // the closing } of a compound, the ; of others
};

//! A data member of a property block.
struct field {
  const token* name = nullptr;
  bool in_files = true;  // written to .vvm (not vertex-, mesh- or pointer-typed ones)
  bool computed = false;  // `computed`: the program computes it; files need not give it
};

//! A property block: edge { }, vertex { } or mesh { }.
struct property_block {
  const token* keyword = nullptr;
  const token* open = nullptr;
  const token* close = nullptr;
  pieces members;                          // the body, as declarations
  std::vector<field> fields;               // data members, in declaration order
  std::vector<const token*> value_init_after;  // emit {} after these (value-initialisation)
};

//! `param TYPE NAME = VALUE [in [LO, HI]];`: a global the host can change.
struct parameter {
  const token* keyword = nullptr;
  const token* type = nullptr;   // bool, int, unsigned, float or double
  const token* name = nullptr;
  pieces value, lo, hi;          // lo and hi empty: no range
};

//! `action "NAME" [key 'c'] { ... }`: a block the user runs by name.
struct action_block {
  const token* keyword = nullptr;
  const token* name = nullptr;  // the string literal, quotes included
  const token* key = nullptr;   // the character literal, or null
  char key_char = 0;            // the key as the viewer reads it (lowercase), or 0
  stmt_ptr body;
};

//! `pick (vertex v) { ... }`: run with the vertex the user picks.
struct pick_block {
  const token* keyword = nullptr;
  const token* vertex = nullptr;  // the parameter's type word
  const token* name = nullptr;    // the parameter
  stmt_ptr body;
};

//! The top level of a program, in source order.
struct top_item {
  enum kind_t { declaration, property, block, preproc, parameter, action, pick } kind = declaration;
  std::size_t parameter_index = 0;
  std::size_t action_index = 0;
  pieces cxx;              // a declaration, with any bodies inside
  std::size_t property_index = 0;
  const token* block_name = nullptr;  // execution block
  stmt_ptr block_body;
  const token* tok = nullptr;
};

struct program {
  std::vector<top_item> items;
  std::vector<property_block> properties;  // in the order edge, vertex, mesh (as present)
  const property_block* edge = nullptr;
  const property_block* vertex = nullptr;
  const property_block* mesh = nullptr;
  std::size_t last_property_item = 0;      // index into items; items.size() if none
  std::vector<const token*> global_meshes; // names of top-level `mesh` variables
  std::vector<parameter> parameters;       // `param` globals, in source order
  std::vector<action_block> actions;       // in source order
  std::unique_ptr<pick_block> pick;        // null: the program has none
};

}  // namespace vvc
