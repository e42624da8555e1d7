// The view: a point looked at, a distance, an orientation. Rotation is an
// arcball (a drag turns the scene as if rolling a ball under the cursor),
// panning moves the point in the view plane, zoom changes the distance.
#pragma once

#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace vvi {

struct box {
  glm::dvec3 min{0}, max{0};
  bool empty = true;
  void add(const glm::dvec3& p) {
    if (empty) min = max = p, empty = false;
    else min = glm::min(min, p), max = glm::max(max, p);
  }
};

class camera {
 public:
  //! Shows all of b (its bounding sphere), looking along -z, in a view of
  //! any shape (a view taller than wide sees more above and below).
  void fit(const box& b);
  //! Back to the view of the last fit.
  void reset();
  //! An arcball drag from (x0, y0) to (x1, y1), in pixels of a w x h view.
  void drag_rotate(double x0, double y0, double x1, double y1, int w, int h);
  //! Looks at the same point from a direction: turned by azimuth about the
  //! world's y axis and raised by elevation above the xz-plane (degrees).
  void look_from(double azimuth, double elevation);
  //! Turns by degrees about the view's vertical and horizontal axes.
  void rotate_degrees(double yaw, double pitch);
  //! Moves the scene by a drag of (dx, dy) pixels in a w x h view.
  void pan(double dx, double dy, int w, int h);
  //! factor > 1 comes closer.
  void zoom(double factor);

  //! The whole view as text, and back (a restarted viewer keeps its view).
  std::string save() const;
  bool restore(const std::string& text);

  glm::dmat4 view() const;
  glm::dmat4 projection(double aspect) const;
  glm::dvec3 eye() const;
  //! Pixels per unit of length at the point looked at, in a w x h view.
  double pixels_per_unit(int w, int h) const;

 private:
  //! The field of view across the view's narrower side.
  static constexpr double fov_degrees = 35;
  //! The vertical field of view, in radians, of a view of this aspect.
  static double fov_y(double aspect);
  glm::dvec3 center_{0};
  double distance_ = 5;
  double radius_ = 1;
  glm::dquat orientation_{1, 0, 0, 0};
  glm::dvec3 fit_center_{0};
  double fit_distance_ = 5;
};

}  // namespace vvi
