#pragma once
// The triangle mesh every implementation starts from: plain arrays so that
// building each library's own structure stays outside the timed region.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

struct bench_input {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // CCW seen from outside
};

// Icosahedron split `subdivisions` times (each triangle into 4, new points
// pushed to the unit sphere): 20 * 4^subdivisions triangles.
bench_input make_icosphere(int subdivisions);

// Any format OpenMesh reads; throws std::runtime_error unless the file holds a
// closed triangle mesh.
bench_input read_input(const std::string& path);

// Length of the bounding-box diagonal; scales the agreement tolerance.
double mesh_size(const bench_input& input);
