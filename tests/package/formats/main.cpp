// Uses vv::formats: writes the tetrahedron as OFF and reads it back.
#include <vv/io/mesh_io.hpp>

#include "../tetrahedron.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  tet::context ctx;
  tet::mesh M(ctx), N(ctx);
  build_tetrahedron(M);
  vv::write_mesh(M, argv[1]);
  vv::read_mesh(N, argv[1]);
  bool ok = expect("vertices read back", long(N.size()), 4) &
            expect("faces read back", long(vv::face_orbits(N).size()), 4) &
            expect("euler read back", vv::euler_characteristic(N), 2);
  return ok ? 0 : 1;
}
