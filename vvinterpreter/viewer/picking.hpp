// Which vertex the user clicked: the one drawn nearest the cursor, within
// a few pixels (the nearer to the eye when two are as near).
#pragma once

#include <vector>

#include "render/camera.hpp"

namespace vvi {

//! positions: 3 per vertex. x, y: the cursor in pixels of a w x h view
//! (y down). The index of the vertex, or -1 when none is within radius.
long pick_vertex(const std::vector<double>& positions, const camera& cam, int w, int h, double x, double y,
                 double radius = 10);

}  // namespace vvi
