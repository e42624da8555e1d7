#pragma once
// The triangle mesh every implementation starts from: plain arrays so that
// building each library's own structure stays outside the timed region.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

// Either triangles or quads (a scheme's input is one or the other).
struct bench_input {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // CCW seen from outside
  std::vector<std::array<std::uint32_t, 4>> quads;      // CCW seen from outside
  // Every face as a list of corners, whichever kind it is.
  std::vector<std::vector<std::uint32_t>> polygons() const;
};

// Icosahedron split `subdivisions` times (each triangle into 4, new points
// pushed to the unit sphere): 20 * 4^subdivisions triangles.
bench_input make_icosphere(int subdivisions);

// A torus of n x n quads (the Catmull-Clark and Doo-Sabin input).
bench_input make_quad_torus(int n);

// Any format OpenMesh reads; throws std::runtime_error unless the file holds a
// closed triangle mesh.
bench_input read_input(const std::string& path);

// Length of the bounding-box diagonal; scales the agreement tolerance.
double mesh_size(const bench_input& input);
