// The independent implementations the examples are checked against:
// OpenMesh's uniform subdividers and CGAL's Subdivision_method_3, both on
// double-precision points. They are compiled once, in peers_openmesh.cpp
// and peers_cgal.cpp (the oracle_peers library), so that the oracle tests
// do not each instantiate OpenMesh's and CGAL's templates again.
//
//   oracle::polygons theirs = peers::openmesh_loop(oracle::read_polygons(model), 2);
//   oracle::polygons also = peers::cgal_loop(oracle::read_polygons(model), 2);
#pragma once

#include "oracle.hpp"

namespace peers {

// `steps` steps of OpenMesh's Subdivider::Uniform schemes on a copy of `in`
// (triangles for Loop, sqrt(3) and the modified butterfly).
oracle::polygons openmesh_loop(const oracle::polygons& in, unsigned steps);
oracle::polygons openmesh_sqrt3(const oracle::polygons& in, unsigned steps);
oracle::polygons openmesh_modified_butterfly(const oracle::polygons& in, unsigned steps);
oracle::polygons openmesh_catmull_clark(const oracle::polygons& in, unsigned steps);

// `steps` steps of CGAL's Subdivision_method_3 on a copy of `in`.
oracle::polygons cgal_loop(const oracle::polygons& in, unsigned steps);
oracle::polygons cgal_sqrt3(const oracle::polygons& in, unsigned steps);
oracle::polygons cgal_catmull_clark(const oracle::polygons& in, unsigned steps);
oracle::polygons cgal_doo_sabin(const oracle::polygons& in, unsigned steps);
//! Primal triangle quadrisection (PTQ) with a linear mask: edge points at
//! the midpoints, vertices unchanged.
oracle::polygons cgal_midpoint(const oracle::polygons& in, unsigned steps);

}  // namespace peers
