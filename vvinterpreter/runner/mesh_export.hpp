// Writing a model's global meshes: .vvm through the model itself (it knows
// the properties), polygon formats here from the meshes' face orbits.
#pragma once

#include <string>

#include <model/abi.hpp>

namespace vvi {

//! Writes polygons to a polygon file (.obj .off .ply .stl); "" or the
//! error. `what` names the meshes in messages ("mesh S", "meshes J, C").
std::string export_polygons(const vv_geometry& g, const std::string& path, const std::string& what);

//! True for the extensions export_polygons writes; .vvm is written by the
//! model.
bool is_vvm_path(const std::string& path);

}  // namespace vvi
