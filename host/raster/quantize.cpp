// Fragment -> FragmentRecord: every value rounded to nearest (ties to even) and saturated into
// its port format by fx::Fixed::from_double, so out-of-range values (a lambda of -40, a
// derivative of 10^6 texels per pixel near a silhouette) clamp rather than wrap.
#include <algorithm>

#include "formats/formats.hpp"
#include "raster/fragment.hpp"

namespace tmu::host {
namespace {

template <class F>
auto raw(double v) {
  return F::from_double(v, fx::Round::kHalfEven).raw();
}

}  // namespace

FragmentRecord quantize(const Fragment& f) {
  using namespace formats;
  FragmentRecord r;
  r.x = static_cast<uint16_t>(raw<PixelCoord>(f.x));
  r.y = static_cast<uint16_t>(raw<PixelCoord>(f.y));
  r.material = static_cast<uint8_t>(raw<MaterialId>(f.material));
  r.u = static_cast<int32_t>(raw<TexCoord>(f.uv.x));
  r.v = static_cast<int32_t>(raw<TexCoord>(f.uv.y));
  r.lambda = static_cast<int32_t>(raw<Lod>(f.lambda));
  uint32_t shade = 0;
  for (int c = 0; c < 3; ++c) {
    shade = (shade << 8) | static_cast<uint32_t>(raw<Channel>(255.0 * f.shade[c]));
  }
  r.shade = (shade << 8) | 0xFFu;
  for (int i = 0; i < 2; ++i) {
    r.r1[i] = static_cast<int32_t>(raw<TexDeriv>(f.r1[i]));
    r.r2[i] = static_cast<int32_t>(raw<TexDeriv>(f.r2[i]));
  }
  for (int i = 0; i < 3; ++i) {
    r.solid[i] = static_cast<int32_t>(raw<SolidCoord>(f.solid[i]));
    r.normal[i] = static_cast<int16_t>(raw<UnitComp>(f.normal[i]));
    r.view[i] = static_cast<int16_t>(raw<UnitComp>(f.view[i]));
  }
  return r;
}

}  // namespace tmu::host
