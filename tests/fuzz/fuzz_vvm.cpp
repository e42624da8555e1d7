// libFuzzer target for the .vvm reader: any bytes as a .vvm file must be
// read or refused with a vv::error, without crashing, hanging or a
// sanitizer report; a refused file leaves the mesh as it was, and a read
// one satisfies the invariants.
#include <vv/invariants.hpp>
#include <vv/io/vvm.hpp>
#include <vv/vv.hpp>

#include <util/point.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

// A named namespace: the edge record's comparison (which vvlib needs) is
// then not an unused function of this file.
namespace fuzz_vvm {

struct VP {
  util::Point<double> pos;
  double c = 0;
  int n = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos), f("c", c), f("n", n);
  }
};
struct EP {
  int mark = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("mark", mark);
  }
  friend bool operator==(const EP& a, const EP& b) { return a.mark == b.mark; }
  friend bool operator!=(const EP& a, const EP& b) { return !(a == b); }
};
struct MP {
  int generation = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("generation", generation);
  }
};
using G = vv::graph<VP, EP, MP>;

}  // namespace fuzz_vvm

using fuzz_vvm::G;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  G::context ctx;
  G::mesh m(ctx);
  G::vertex keep = ctx.new_vertex();  // what a failed read must leave alone
  m.add(keep);
  m.generation = 7;
  vv::io::text_file file("fuzz.vvm", std::string(reinterpret_cast<const char*>(data), size));
  try {
    vv::parse_vvm(m, file);
  } catch (const vv::error&) {
    if (m.size() != 1 || !vv::is_in(keep, m) || m.generation != 7) std::abort();
    return 0;
  }
  vv::check_invariants(m);  // throws (and so fails the run) on a broken result
  return 0;
}
