#include "raster/triangle_setup.hpp"

#include <cmath>

namespace tmu::host {

std::optional<TriangleSetup> TriangleSetup::make(const std::array<SetupVertex, 3>& v, int width,
                                                 int height) {
  // M[j] = (X_j, Y_j, W_j), the homogeneous pixel coordinates of vertex j.
  double m[3][3];
  for (size_t j = 0; j < 3; ++j) {
    const glm::dvec4& c = v[j].clip;
    m[j][0] = (c.x + c.w) * 0.5 * width;
    m[j][1] = (c.w - c.y) * 0.5 * height;
    m[j][2] = c.w;
  }
  // Inverse through the adjugate: inv[k][j] = cofactor(j, k) / det.
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  if (det == 0 || !std::isfinite(det)) return std::nullopt;
  const double inv[3][3] = {
      {c00 / det, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det,
       (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det},
      {c01 / det, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det,
       (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det},
      {c02 / det, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det,
       (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det},
  };
  // e_j(x, y) = x inv[0][j] + y inv[1][j] + inv[2][j]; a plane of sum_j e_j a_j.
  const auto plane = [&](const std::array<double, 3>& a) {
    Plane p;
    for (size_t j = 0; j < 3; ++j) {
      p.a += inv[0][j] * a[j];
      p.b += inv[1][j] * a[j];
      p.c += inv[2][j] * a[j];
    }
    return p;
  };
  TriangleSetup s;
  s.planes_[kD] = plane({1, 1, 1});
  s.planes_[kW] = plane({v[0].clip.w, v[1].clip.w, v[2].clip.w});
  s.planes_[kZ] = plane({v[0].clip.z, v[1].clip.z, v[2].clip.z});
  s.planes_[kU] = plane({v[0].uv.x, v[1].uv.x, v[2].uv.x});
  s.planes_[kV] = plane({v[0].uv.y, v[1].uv.y, v[2].uv.y});
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<size_t>(i);
    s.planes_[kSolid + k] = plane({v[0].solid[i], v[1].solid[i], v[2].solid[i]});
    s.planes_[kWorld + k] = plane({v[0].world[i], v[1].world[i], v[2].world[i]});
    s.planes_[kNormal + k] = plane({v[0].normal[i], v[1].normal[i], v[2].normal[i]});
  }
  for (int i = 0; i < 4; ++i) {
    s.planes_[kColour + static_cast<size_t>(i)] =
        plane({v[0].colour[i], v[1].colour[i], v[2].colour[i]});
  }
  return s;
}

double TriangleSetup::depth(double x, double y) const {
  return planes_[kZ].at(x, y) / planes_[kW].at(x, y);
}

Interpolated TriangleSetup::at(double x, double y) const {
  Interpolated r;
  const Plane& d = planes_[kD];
  const double inv_d = 1.0 / d.at(x, y);
  r.depth = depth(x, y);
  const auto value = [&](size_t k) { return planes_[k].at(x, y) * inv_d; };
  r.uv = {value(kU), value(kV)};
  // Quotient rule on N / D at (x, y): dN/dx = a, dD/dx = d.a (and b for y).
  const Plane& nu = planes_[kU];
  const Plane& nv = planes_[kV];
  r.r1 = {(nu.a - r.uv.x * d.a) * inv_d, (nv.a - r.uv.y * d.a) * inv_d};
  r.r2 = {(nu.b - r.uv.x * d.b) * inv_d, (nv.b - r.uv.y * d.b) * inv_d};
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<size_t>(i);
    r.solid[i] = value(kSolid + k);
    r.world[i] = value(kWorld + k);
    r.normal[i] = value(kNormal + k);
  }
  for (int i = 0; i < 4; ++i) r.colour[i] = value(kColour + static_cast<size_t>(i));
  return r;
}

}  // namespace tmu::host
