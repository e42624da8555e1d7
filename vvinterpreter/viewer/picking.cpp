#include "viewer/picking.hpp"

#include <algorithm>
#include <cmath>

namespace vvi {

long pick_vertex(const std::vector<double>& positions, const camera& cam, int w, int h, double x, double y,
                 double radius) {
  if (w <= 0 || h <= 0) return -1;
  glm::dmat4 to_clip = cam.projection(double(w) / h) * cam.view();
  long best = -1;
  double best_distance = radius * radius, best_depth = 2;
  for (std::size_t i = 0; i + 2 < positions.size(); i += 3) {
    glm::dvec4 c = to_clip * glm::dvec4(positions[i], positions[i + 1], positions[i + 2], 1);
    if (c.w <= 0) continue;  // behind the eye
    double sx = (c.x / c.w * 0.5 + 0.5) * w, sy = (0.5 - c.y / c.w * 0.5) * h, depth = c.z / c.w;
    double d = (sx - x) * (sx - x) + (sy - y) * (sy - y);
    // Within a pixel of the best, the vertex in front wins.
    bool as_near = std::abs(std::sqrt(d) - std::sqrt(best_distance)) < 1;
    if (d < best_distance && !(as_near && depth > best_depth)) {
      best = static_cast<long>(i / 3), best_distance = d, best_depth = depth;
    } else if (as_near && depth < best_depth && d <= radius * radius) {
      best = static_cast<long>(i / 3), best_distance = d, best_depth = depth;
    }
  }
  return best;
}

}  // namespace vvi
