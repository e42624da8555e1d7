#include "render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

namespace vvi {

void camera::fit(const box& b) {
  if (b.empty) return;
  center_ = (b.min + b.max) * 0.5;
  radius_ = std::max(glm::length(b.max - b.min) * 0.5, 1e-9);
  distance_ = radius_ / std::sin(glm::radians(fov_degrees) / 2) * 1.05;
  orientation_ = glm::dquat(1, 0, 0, 0);
  fit_center_ = center_;
  fit_distance_ = distance_;
}

std::string camera::save() const {
  std::ostringstream out;
  out.precision(17);
  out << center_.x << ' ' << center_.y << ' ' << center_.z << ' ' << distance_ << ' ' << radius_ << ' '
      << orientation_.w << ' ' << orientation_.x << ' ' << orientation_.y << ' ' << orientation_.z << ' '
      << fit_center_.x << ' ' << fit_center_.y << ' ' << fit_center_.z << ' ' << fit_distance_;
  return out.str();
}

bool camera::restore(const std::string& text) {
  std::istringstream in(text);
  camera c;
  if (!(in >> c.center_.x >> c.center_.y >> c.center_.z >> c.distance_ >> c.radius_ >> c.orientation_.w >>
        c.orientation_.x >> c.orientation_.y >> c.orientation_.z >> c.fit_center_.x >> c.fit_center_.y >>
        c.fit_center_.z >> c.fit_distance_))
    return false;
  *this = c;
  return true;
}

void camera::reset() {
  center_ = fit_center_;
  distance_ = fit_distance_;
  orientation_ = glm::dquat(1, 0, 0, 0);
}

namespace {
// A point of the view on the unit arcball (outside the ball: its rim).
glm::dvec3 on_ball(double x, double y, int w, int h) {
  double s = std::min(w, h) / 2.0;
  glm::dvec3 p((x - w / 2.0) / s, (h / 2.0 - y) / s, 0);
  double d = p.x * p.x + p.y * p.y;
  if (d <= 1) p.z = std::sqrt(1 - d);
  else p /= std::sqrt(d);
  return p;
}
}  // namespace

void camera::drag_rotate(double x0, double y0, double x1, double y1, int w, int h) {
  glm::dvec3 a = on_ball(x0, y0, w, h), b = on_ball(x1, y1, w, h);
  glm::dvec3 axis = glm::cross(a, b);
  double len = glm::length(axis);
  if (len < 1e-12) return;
  double angle = std::atan2(len, glm::dot(a, b));
  // The drag turns the scene; the camera turns the other way, in world terms.
  glm::dquat turn = glm::angleAxis(angle, orientation_ * (axis / len));
  orientation_ = glm::normalize(glm::inverse(turn) * orientation_);
}

void camera::look_from(double azimuth, double elevation) {
  orientation_ = glm::normalize(glm::angleAxis(glm::radians(azimuth), glm::dvec3(0, 1, 0)) *
                                glm::angleAxis(glm::radians(-elevation), glm::dvec3(1, 0, 0)));
}

void camera::rotate_degrees(double yaw, double pitch) {
  glm::dvec3 up = orientation_ * glm::dvec3(0, 1, 0), right = orientation_ * glm::dvec3(1, 0, 0);
  glm::dquat turn = glm::angleAxis(glm::radians(yaw), up) * glm::angleAxis(glm::radians(pitch), right);
  orientation_ = glm::normalize(glm::inverse(turn) * orientation_);
}

double camera::fov_y(double aspect) {
  double half = glm::radians(fov_degrees) / 2;
  return aspect >= 1 || aspect <= 0 ? 2 * half : 2 * std::atan(std::tan(half) / aspect);
}

void camera::pan(double dx, double dy, int w, int h) {
  double per_pixel = 1 / pixels_per_unit(w, h);
  center_ -= orientation_ * glm::dvec3(dx * per_pixel, -dy * per_pixel, 0);
}

void camera::zoom(double factor) {
  if (factor > 0) distance_ = std::max(distance_ / factor, radius_ * 1e-4);
}

glm::dvec3 camera::eye() const { return center_ + orientation_ * glm::dvec3(0, 0, distance_); }

glm::dmat4 camera::view() const {
  return glm::lookAt(eye(), center_, orientation_ * glm::dvec3(0, 1, 0));
}

glm::dmat4 camera::projection(double aspect) const {
  double near = std::max(distance_ - radius_ * 4, distance_ * 1e-3);
  double far = distance_ + radius_ * 4;
  return glm::perspective(fov_y(aspect), aspect, near, far);
}

double camera::pixels_per_unit(int w, int h) const {
  h = std::max(h, 1);
  return h / (2 * distance_ * std::tan(fov_y(double(w) / h) / 2));
}

}  // namespace vvi
