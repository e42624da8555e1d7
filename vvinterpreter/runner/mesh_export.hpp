// Writing a model's global meshes: .vvm and .vtp through the model itself
// (it knows the properties), polygon formats here from the meshes' face
// orbits.
#pragma once

#include <string>

#include <model/abi.hpp>

namespace vvi {

//! Writes polygons to a polygon file (.obj .off .ply .stl); "" or the
//! error. `what` names the meshes in messages ("mesh S", "meshes J, C").
std::string export_polygons(const vv_geometry& g, const std::string& path, const std::string& what);

//! True for the formats the model writes itself (vv_mesh_entry::write_file:
//! .vvm, .vtp); export_polygons writes the others.
bool is_written_by_model(const std::string& path);

}  // namespace vvi
