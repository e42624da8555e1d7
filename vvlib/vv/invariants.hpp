// check_invariants(mesh): the structural rules every edit must keep, used
// by the tests after each edit and available to programs for debugging.
//
// Always checked, for every member v (current and old state):
//   * v and every neighbour are live vertices of the mesh's context;
//   * v is not its own neighbour and no neighbour appears twice;
//   * the flag is unset or names an entry (the old state may also be
//     "never synchronised", and is then empty);
//   * half-edge records match neighbours one to one (they are stored with
//     the entries, so this is a check of the storage itself);
//   * the set's index finds every member at its place in insertion order.
// Optionally: symmetry (u in v* iff v in u*) and manifold orbits (with
// symmetry, every face orbit visits a vertex at most once).
#pragma once

#include <string>
#include <unordered_set>
#include <vector>

#include "mesh.hpp"
#include "faces.hpp"

namespace vv {

struct invariant_options {
  bool symmetric = false;
  bool manifold = false;
};

namespace detail {

template <class Tr, class NB>
void check_nb(context<Tr>& ctx, std::uint32_t v, const NB& nb, const char* which, bool old,
              std::vector<std::string>& out) {
  std::string who = "vertex " + std::to_string(ctx.label(v)) + " (" + which + ")";
  std::int32_t f = nb.flag();
  std::int32_t lowest = old ? NB::never_synchronised : NB::no_flag;
  if (f < lowest || f >= static_cast<std::int32_t>(nb.size()))
    out.push_back(who + ": flag " + std::to_string(f) + " is outside the neighbourhood of " +
                  std::to_string(nb.size()));
  if (f == NB::never_synchronised && nb.size() != 0)
    out.push_back(who + ": never synchronised but has neighbours");
  std::unordered_set<std::uint32_t> seen;
  for (std::uint32_t i = 0; i < nb.size(); ++i) {
    std::uint32_t u = entry_id(nb[i]);
    if (!ctx.is_live(u)) {
      out.push_back(who + ": entry " + std::to_string(i) + " is not a live vertex");
      continue;
    }
    if (u == v) out.push_back(who + ": is its own neighbour");
    if (!seen.insert(u).second)
      out.push_back(who + ": vertex " + std::to_string(ctx.label(u)) + " appears twice");
  }
}

}  // namespace detail

//! Every violated rule, one line each (empty when all hold).
template <class Tr>
std::vector<std::string> invariant_violations(const mesh<Tr>& m, invariant_options opt = {}) {
  std::vector<std::string> out;
  context<Tr>* ctx = m.ctx();
  std::size_t members = 0;
  for (std::size_t pos = 0; pos < m.slots().size(); ++pos) {
    std::uint32_t v = m.slots()[pos];
    if (!v) continue;
    ++members;
    if (!ctx->is_live(v)) {
      out.push_back("member at position " + std::to_string(pos) + " is not a live vertex");
      continue;
    }
    vertex<Tr> h = vertex<Tr>::from_slot(ctx, v);
    if (!m.contains(h))
      out.push_back("vertex " + std::to_string(ctx->label(v)) + " is listed but not indexed");
    detail::check_nb(*ctx, v, ctx->nb(v), "current", false, out);
    detail::check_nb(*ctx, v, ctx->old_nb(v), "old", true, out);
    if (opt.symmetric || opt.manifold)
      for (const auto& e : ctx->nb(v)) {
        std::uint32_t u = detail::entry_id(e);
        if (ctx->is_live(u) && detail::find(ctx->nb(u), v) < 0)
          out.push_back("vertex " + std::to_string(ctx->label(u)) + " is a neighbour of vertex " +
                        std::to_string(ctx->label(v)) + " but not the other way round");
      }
  }
  if (members != m.size())
    out.push_back("the mesh counts " + std::to_string(m.size()) + " members but lists " +
                  std::to_string(members));
  if (opt.manifold && out.empty()) {
    for (const auto& face : face_orbits(m)) {
      std::unordered_set<std::size_t> seen(face.begin(), face.end());
      if (seen.size() != face.size()) {
        std::string s;
        for (std::size_t i : face) s += " " + std::to_string(i);
        out.push_back("face orbit visits a vertex twice: positions" + s);
      }
    }
    if (face_orbit_failures(m) != 0)
      out.push_back(std::to_string(face_orbit_failures(m)) + " oriented edges lie on no closed orbit");
  }
  return out;
}

//! Throws vv::error listing every violated rule.
template <class Tr>
void check_invariants(const mesh<Tr>& m, invariant_options opt = {}, where w = where::here()) {
  auto problems = invariant_violations(m, opt);
  if (problems.empty()) return;
  std::string msg;
  for (const auto& p : problems) msg += (msg.empty() ? "" : "; ") + p;
  throw error(w, "check_invariants", msg);
}

}  // namespace vv
