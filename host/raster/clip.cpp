#include "raster/clip.hpp"

namespace tmu::host {
namespace {

// Signed distance to plane `p` (inside >= 0); the near plane first (see clip.hpp).
double distance(const glm::dvec4& v, int p) {
  switch (p) {
    case 0:
      return v.z;  // near
    case 1:
      return v.w - v.z;  // far
    case 2:
      return v.w + v.x;  // left
    case 3:
      return v.w - v.x;  // right
    case 4:
      return v.w + v.y;  // bottom
    default:
      return v.w - v.y;  // top
  }
}

glm::dvec4 intersect(const glm::dvec4& inside, double d_in, const glm::dvec4& outside,
                     double d_out) {
  const double t = d_in / (d_in - d_out);  // d_in >= 0 > d_out: t in [0, 1)
  return inside + t * (outside - inside);
}

}  // namespace

ClipPolygon clip_triangle(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c) {
  ClipPolygon poly;
  poly.v[0] = a;
  poly.v[1] = b;
  poly.v[2] = c;
  poly.count = 3;
  for (int plane = 0; plane < 6 && poly.count >= 3; ++plane) {
    std::array<double, ClipPolygon::kCapacity> d{};
    bool all_inside = true;
    for (int i = 0; i < poly.count; ++i) {
      d[static_cast<size_t>(i)] = distance(poly.v[static_cast<size_t>(i)], plane);
      all_inside = all_inside && d[static_cast<size_t>(i)] >= 0;
    }
    if (all_inside) continue;
    ClipPolygon out;
    // Each vertex adds at most two; a polygon that could outgrow the buffer is a sliver far
    // below a pixel: drop it.
    if (2 * poly.count > ClipPolygon::kCapacity) return {};
    for (int i = 0; i < poly.count; ++i) {
      const auto cur = static_cast<size_t>(i);
      const auto next = static_cast<size_t>((i + 1) % poly.count);
      const bool cur_in = d[cur] >= 0, next_in = d[next] >= 0;
      if (cur_in) out.v[static_cast<size_t>(out.count++)] = poly.v[cur];
      if (cur_in && !next_in) {
        out.v[static_cast<size_t>(out.count++)] =
            intersect(poly.v[cur], d[cur], poly.v[next], d[next]);
      } else if (!cur_in && next_in) {
        out.v[static_cast<size_t>(out.count++)] =
            intersect(poly.v[next], d[next], poly.v[cur], d[cur]);
      }
    }
    poly = out;
  }
  if (poly.count < 3) poly.count = 0;
  return poly;
}

}  // namespace tmu::host
