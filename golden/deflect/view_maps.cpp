#include "deflect/view_maps.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace tmu::deflect {
namespace {

uint8_t byte(double v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); }
Rgb8 rgb(const glm::dvec3& c) { return {byte(c.r), byte(c.g), byte(c.b)}; }

template <class F>
ImageRgb8 sphere_map(int side, F&& value_at_normal) {
  ImageRgb8 image(side, side);
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) image.at(i, j) = value_at_normal(sphere_map_normal(side, i, j));
  }
  return image;
}

}  // namespace

glm::dvec3 sphere_map_normal(int side, int i, int j) {
  const double x = 2 * (i + 0.5) / side - 1, y = 1 - 2 * (j + 0.5) / side;
  const double r2 = x * x + y * y;
  if (r2 >= 1) return glm::dvec3(x, y, 0) / std::sqrt(r2);
  return {x, y, std::sqrt(1 - r2)};
}

glm::dvec3 view_reflection(const glm::dvec3& n) { return 2 * n.z * n - glm::dvec3(0, 0, 1); }

ImageRgb8 diffuse_map(int side, const std::vector<MapLight>& lights) {
  return sphere_map(side, [&](const glm::dvec3& n) {
    glm::dvec3 sum(0);
    for (const MapLight& l : lights)
      sum += l.ambient ? l.colour : l.colour * std::max(0.0, glm::dot(n, l.towards));
    return rgb(sum);
  });
}

ImageRgb8 specular_map(int side, const std::vector<MapLight>& lights, const glm::dvec3& k_spec,
                       double exponent) {
  return sphere_map(side, [&](const glm::dvec3& n) {
    const glm::dvec3 r = view_reflection(n);
    glm::dvec3 sum(0);
    for (const MapLight& l : lights) {
      if (!l.ambient) sum += l.colour * std::pow(std::max(0.0, glm::dot(r, l.towards)), exponent);
    }
    return rgb(k_spec * sum);
  });
}

ImageRgb8 sphere_environment(int side, const Environment& environment) {
  return sphere_map(side, [&](const glm::dvec3& n) { return environment(view_reflection(n)); });
}

glm::dvec3 cube_face_direction(uint32_t face, double sc, double tc) {
  switch (face) {
    case 0:
      return {1, -tc, -sc};
    case 1:
      return {-1, -tc, sc};
    case 2:
      return {sc, 1, tc};
    case 3:
      return {sc, -1, -tc};
    case 4:
      return {sc, -tc, 1};
    default:
      return {-sc, -tc, -1};
  }
}

std::array<ImageRgb8, 6> cube_environment(int face_log2, const Environment& environment) {
  const int side = 1 << face_log2;
  std::array<ImageRgb8, 6> faces;
  for (uint32_t f = 0; f < 6; ++f) {
    faces[f] = ImageRgb8(side, side);
    for (int j = 0; j < side; ++j) {
      for (int i = 0; i < side; ++i) {
        const double sc = 2 * (i + 0.5) / side - 1, tc = 2 * (j + 0.5) / side - 1;
        faces[f].at(i, j) = environment(glm::normalize(cube_face_direction(f, sc, tc)));
      }
    }
  }
  return faces;
}

Rgb8 sky_room(const glm::dvec3& direction) {
  const glm::dvec3 r = glm::normalize(direction);
  if (glm::dot(r, glm::normalize(glm::dvec3(0.5, 0.6, 0.4))) > 0.995) return {255, 240, 200};
  if (r.y >= 0) {
    const auto b = static_cast<uint8_t>(150 + 100 * r.y);
    return {static_cast<uint8_t>(90 + 60 * r.y), static_cast<uint8_t>(130 + 80 * r.y), b};
  }
  const double az = std::atan2(r.x, r.z) / std::numbers::pi * 8,
               el = std::asin(-r.y) / std::numbers::pi * 16;
  const bool dark = (static_cast<int>(std::floor(az)) + static_cast<int>(std::floor(el))) & 1;
  return dark ? Rgb8{60, 50, 40} : Rgb8{200, 180, 140};
}

}  // namespace tmu::deflect
