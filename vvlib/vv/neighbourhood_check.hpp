// The first broken neighbourhood of a mesh, told with the lines that last
// edited it: what `vvinterpreter --check` reports after each step. The
// lines are known while the context tracks edits (context::track_edits).
#pragma once

#include <string>
#include <vector>

#include "invariants.hpp"

namespace vv {

struct broken_neighbourhood {
  std::string problem;  //!< empty: nothing is broken
  //! The latest edit of the neighbourhoods involved: where it went wrong
  //! (file null when not known).
  where at;
};

namespace detail {

template <class Tr>
std::string last_edit_of(const context<Tr>& ctx, std::uint32_t id) {
  where w = ctx.last_edit(id).at;
  std::string who = "vertex " + std::to_string(ctx.label(id));
  if (!w.file) return who + " not while tracked";
  return who + " at " + w.file + ":" + std::to_string(w.line);
}

template <class Tr>
where latest_edit(const context<Tr>& ctx, std::uint32_t a, std::uint32_t b) {
  auto x = ctx.last_edit(a), y = ctx.last_edit(b);
  return (x.seq >= y.seq ? x : y).at;
}

}  // namespace detail

//! True when u is in v* exactly when v is in u*, for every member v.
template <class Tr>
bool is_symmetric(const mesh<Tr>& m) {
  context<Tr>* ctx = m.ctx();
  for (std::uint32_t v : m.slots()) {
    if (!v || !ctx->is_live(v)) continue;
    for (const auto& e : ctx->nb(v)) {
      std::uint32_t u = detail::entry_id(e);
      if (!ctx->is_live(u) || detail::find(ctx->nb(u), v) < 0) return false;
    }
  }
  return true;
}

//! Nothing when every rule of check_invariants holds (and symmetry, when
//! asked), else the first violation, with where the neighbourhoods
//! involved were last edited.
template <class Tr>
broken_neighbourhood first_broken_neighbourhood(const mesh<Tr>& m, bool symmetric) {
  context<Tr>* ctx = m.ctx();
  if (!ctx) return {};
  for (std::uint32_t v : m.slots()) {
    if (!v || !ctx->is_live(v)) continue;
    std::string who = "vertex " + std::to_string(ctx->label(v));
    for (const auto& e : ctx->nb(v)) {
      std::uint32_t u = detail::entry_id(e);
      if (!ctx->is_live(u))
        return {who + " has a neighbour that no longer exists (no mesh or handle held it; last edit: " +
                    detail::last_edit_of(*ctx, v) + ")",
                ctx->last_edit(v).at};
      if (symmetric && detail::find(ctx->nb(u), v) < 0)
        return {"vertex " + std::to_string(ctx->label(u)) + " is a neighbour of " + who +
                    " but not the other way round (last edits: " + detail::last_edit_of(*ctx, v) + ", " +
                    detail::last_edit_of(*ctx, u) + ")",
                detail::latest_edit(*ctx, u, v)};
    }
  }
  std::vector<std::string> rest = invariant_violations(m);
  if (rest.empty()) return {};
  return {rest.front(), where{}};
}

}  // namespace vv
