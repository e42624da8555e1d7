// Uses vv::openmesh: converts the tetrahedron to OpenMesh and back.
#include <vv/io/openmesh.hpp>

#include "../tetrahedron.hpp"

int main() {
  tet::context ctx;
  tet::mesh M(ctx), N(ctx);
  build_tetrahedron(M);
  vv::openmesh_mesh om = vv::to_openmesh(M);
  vv::from_openmesh(N, om);
  bool ok = expect("OpenMesh vertices", long(om.n_vertices()), 4) &
            expect("OpenMesh faces", long(om.n_faces()), 4) &
            expect("OpenMesh edges", long(om.n_edges()), 6) &
            expect("faces back in vv", long(vv::face_orbits(N).size()), 4);
  return ok ? 0 : 1;
}
