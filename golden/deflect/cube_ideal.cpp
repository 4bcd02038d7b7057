#include "deflect/cube_ideal.hpp"

#include <array>
#include <cmath>

namespace tmu::deflect {

CubeIdeal cube_address_ideal(double x, double y, double z, int face_log2) {
  const std::array<double, 3> r{x, y, z};
  // The major axis: the largest |component|, the first of equals.
  size_t axis = 0;
  for (size_t i = 1; i < 3; ++i) {
    if (std::abs(r[i]) > std::abs(r[axis])) axis = i;
  }
  const bool negative = r[axis] < 0;
  const double ma = std::abs(r[axis]);
  // OpenGL's face coordinates (sc, tc) per face:
  //   +X: -z, -y   -X: +z, -y   +Y: +x, +z   -Y: +x, -z   +Z: +x, -y   -Z: -x, -y
  double sc = 0, tc = 0;
  switch (axis) {
    case 0:
      sc = negative ? z : -z;
      tc = -y;
      break;
    case 1:
      sc = x;
      tc = negative ? -z : z;
      break;
    default:
      sc = negative ? -x : x;
      tc = -y;
      break;
  }
  CubeIdeal out;
  out.face = static_cast<uint32_t>(2 * axis + (negative ? 1 : 0));
  const double size = std::ldexp(1.0, face_log2);
  out.u = ma == 0 ? size / 2 : (sc / ma + 1) / 2 * size;
  out.v = ma == 0 ? size / 2 : (tc / ma + 1) / 2 * size;
  return out;
}

}  // namespace tmu::deflect
