#include "deflect/cube_map.hpp"

#include <array>
#include <cmath>
#include <cstdlib>

#include "deflect/normal_encoder.hpp"

namespace tmu::deflect {
namespace {

// The face and its (sc, tc) for a vector, on any number type.
template <class T>
uint32_t major_face(T x, T y, T z, T& sc, T& tc, T& ma) {
  const T ax = x < 0 ? -x : x, ay = y < 0 ? -y : y, az = z < 0 ? -z : z;
  if (ax >= ay && ax >= az) {
    ma = ax;
    sc = x < 0 ? z : -z;
    tc = -y;
    return x < 0 ? 1 : 0;
  }
  if (ay >= az) {
    ma = ay;
    sc = x;
    tc = y < 0 ? -z : z;
    return y < 0 ? 3 : 2;
  }
  ma = az;
  sc = z < 0 ? -x : x;
  tc = -y;
  return z < 0 ? 5 : 4;
}

}  // namespace

CubeAddress cube_address(int32_t x, int32_t y, int32_t z, int face_log2, int seed_bits) {
  int32_t sc = 0, tc = 0, ma = 0;
  CubeAddress out;
  out.face = major_face(x, y, z, sc, tc, ma);
  const auto coord = [&](int32_t c) {
    const uint32_t r =
        divide_ratio(static_cast<uint32_t>(std::abs(c)), static_cast<uint32_t>(ma), seed_bits);
    const int64_t s = (1 << 15) + (c < 0 ? -int64_t{r >> 1} : int64_t{r >> 1});  // UQ0.16
    return static_cast<int32_t>(((s << face_log2) + (1 << 7)) >> 8);
  };
  out.u = coord(sc);
  out.v = coord(tc);
  return out;
}

CubeIdeal cube_address_ideal(double x, double y, double z, int face_log2) {
  double sc = 0, tc = 0, ma = 0;
  CubeIdeal out;
  out.face = major_face(x, y, z, sc, tc, ma);
  const double size = std::ldexp(1.0, face_log2);
  out.u = ma == 0 ? size / 2 : (sc / ma + 1) / 2 * size;
  out.v = ma == 0 ? size / 2 : (tc / ma + 1) / 2 * size;
  return out;
}

}  // namespace tmu::deflect
