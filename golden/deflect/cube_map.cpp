#include "deflect/cube_map.hpp"

#include <array>
#include <cmath>
#include <cstdlib>

#include "deflect/normal_encoder.hpp"

namespace tmu::deflect {
namespace {

// The face and its (sc, tc) for a vector.
uint32_t major_face(int32_t x, int32_t y, int32_t z, int32_t& sc, int32_t& tc, int32_t& ma) {
  const int32_t ax = x < 0 ? -x : x, ay = y < 0 ? -y : y, az = z < 0 ? -z : z;
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

}  // namespace tmu::deflect
