// What a context knows of the parallel loop running on it: where it was
// written (for the errors of its body) and, in strict mode, the properties
// each iteration used.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "../error.hpp"

namespace vv::detail {

//! Strict mode: the vertices (other than the loop's own) whose properties
//! or records one iteration used, with the bytes they had when first used.
class strict_watch {
 public:
  struct use {
    std::uint32_t id;
    where at;  //!< the first use
    std::vector<unsigned char> before;
  };
  //! A new iteration, over vertex `own`.
  void begin(std::uint32_t own) noexcept {
    own_ = own;
    used_ = 0;
  }
  std::uint32_t own() const noexcept { return own_; }
  template <class Snapshot>
  void note_use(std::uint32_t id, const where& w, Snapshot&& snapshot) {
    if (id == own_) return;
    for (std::size_t i = 0; i < used_; ++i)
      if (uses_[i].id == id) return;
    if (used_ == uses_.size()) uses_.emplace_back();
    use& u = uses_[used_++];
    u.id = id;
    u.at = w;
    snapshot(u.before);  // reuses the buffer of an earlier iteration
  }
  const use* begin_uses() const noexcept { return uses_.data(); }
  const use* end_uses() const noexcept { return uses_.data() + used_; }

 private:
  std::uint32_t own_ = 0;
  std::size_t used_ = 0;
  std::vector<use> uses_;
};

//! A parallel loop running on a context.
struct parallel_loop {
  where at;                        //!< the `parallel forall` (or parallel_for_each call)
  strict_watch* strict = nullptr;  //!< strict mode only
};

//! "the body of a parallel forall (line 12) must not <what>", naming the
//! loop's file too when it is not that of the error.
inline std::string loop_name(const parallel_loop& loop) {
  if (!loop.at.file) return "a parallel loop";
  return "the parallel forall of line " + std::to_string(loop.at.line);
}
inline std::string parallel_refusal(const parallel_loop& loop, const char* what) {
  return "inside " + loop_name(loop) + ", which must not " + what + " (its iterations run at once)";
}

}  // namespace vv::detail
