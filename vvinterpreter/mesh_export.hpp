// Writing a model's global mesh: .vvm through the model itself (it knows
// the properties), polygon formats here from the mesh's face orbits.
#pragma once

#include <cstddef>
#include <string>

#include <vv/plugin.hpp>

namespace vvi {

//! Writes the mesh to path (format by extension); "" or the error.
std::string export_mesh(const vv_mesh_entry& mesh, const std::string& path, std::size_t max_face);

}  // namespace vvi
