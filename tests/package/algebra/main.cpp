// Uses vv::vvlib alone: builds a tetrahedron, counts its faces and reads
// its .vvm text back.
#include "../tetrahedron.hpp"

int main() {
  tet::context ctx;
  tet::mesh M(ctx), N(ctx);
  build_tetrahedron(M);
  vv::parse_vvm(N, vv::io::text_file("tetrahedron.vvm", vv::vvm_text(M)));
  bool ok = expect("faces", long(vv::face_orbits(M).size()), 4) &
            expect("edges", long(vv::edge_count(M)), 6) &
            expect("euler", vv::euler_characteristic(M), 2) &
            expect("vertices read back", long(N.size()), 4) &
            expect("faces read back", long(vv::face_orbits(N).size()), 4);
  return ok ? 0 : 1;
}
