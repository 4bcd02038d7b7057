#include "nurbs/steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tmu::host::nurbs {
namespace {

int steps_for(double length, double threshold) {
  const double n = std::ceil(length / threshold);
  // A huge count (a tiny threshold) is capped later; keep it representable.
  return static_cast<int>(std::clamp(n, 1.0, 1e6));
}

glm::ivec2 combine(glm::ivec2 a, glm::ivec2 b, Tessellation::Combine g) {
  glm::ivec2 r(0);
  for (int k = 0; k < 2; ++k) {
    const double x = a[k], y = b[k];
    switch (g) {
      case Tessellation::Combine::kMean:
        r[k] = static_cast<int>(std::ceil((x + y) / 2));
        break;
      case Tessellation::Combine::kGeometric:
        r[k] = static_cast<int>(std::ceil(std::sqrt(x * y)));
        break;
      case Tessellation::Combine::kMax:
        r[k] = std::max(a[k], b[k]);
        break;
    }
  }
  return r;
}

// ||tau'|| in texels of level 0 per unit of the patch's s and t.
glm::dvec2 tau_bound_texels(const StepContext& c, const glm::dvec4& pc, const Patch& patch) {
  const TauBound b = derivative_bound(*c.tau, pc.x, pc.y, pc.z, pc.w);
  const glm::dvec2 size(c.texture_size);
  // Normalised s per unit of the patch's own s.
  const double ds = (pc.y - pc.x) / (patch.s_max() - patch.s_min());
  const double dt = (pc.w - pc.z) / (patch.t_max() - patch.t_min());
  return {glm::length(b.s * size) * ds, glm::length(b.t * size) * dt};
}

}  // namespace

double view_scale(const Camera& camera, const glm::dvec3& box_min, const glm::dvec3& box_max) {
  const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
  double z_min = std::numeric_limits<double>::infinity();
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p(corner & 1 ? box_max.x : box_min.x, corner & 2 ? box_max.y : box_min.y,
                       corner & 4 ? box_max.z : box_min.z);
    z_min = std::min(z_min, glm::dot(p - camera.position, forward));
  }
  z_min = std::max(z_min, camera.near);
  const double tan_y = std::tan(glm::radians(camera.fov_deg) / 2);
  const double tan_x = tan_y * camera.width / camera.height;
  const double focal = camera.height / (2 * tan_y);
  return focal / z_min * std::sqrt(1 + tan_x * tan_x + tan_y * tan_y);
}

PatchSteps patch_steps(const Patch& patch, const glm::dvec4& pc, const Tessellation& tess,
                       const StepContext& c) {
  const DerivativeBound bound = derivative_bound(patch);
  const glm::dvec2 span(patch.s_max() - patch.s_min(), patch.t_max() - patch.t_min());
  const glm::dvec2 mc_length = glm::dvec2(bound.s, bound.t) * span;  // MC length of the edges

  PatchSteps r;
  if (tess.mc)
    r.mcdc = glm::ivec2(steps_for(mc_length.x, *tess.mc), steps_for(mc_length.y, *tess.mc));
  if (tess.dc && c.camera) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const glm::dvec3& p : patch.points) {
      const glm::dvec3 w(c.model * glm::dvec4(p, 1.0));
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
    const double d_mc = *tess.dc / (c.model_norm * view_scale(*c.camera, lo, hi));
    const glm::ivec2 dc(steps_for(mc_length.x, d_mc), steps_for(mc_length.y, d_mc));
    r.mcdc = r.mcdc ? glm::max(*r.mcdc, dc) : dc;
  }
  glm::dvec2 texels(0);  // TC length of the patch along s and t
  if (c.tau) {
    texels = tau_bound_texels(c, pc, patch) * span;
    if (tess.tc) r.tc = glm::ivec2(steps_for(texels.x, *tess.tc), steps_for(texels.y, *tess.tc));
  }
  glm::ivec2 n = r.mcdc && r.tc ? combine(*r.mcdc, *r.tc, tess.combine)
                 : r.mcdc       ? *r.mcdc
                 : r.tc         ? *r.tc
                                : glm::ivec2(1);
  r.steps = glm::clamp(n, glm::ivec2(1), glm::ivec2(tess.max_steps));
  const double per_step = std::max(texels.x / r.steps.x, texels.y / r.steps.y);
  r.lambda = c.tau ? std::log2(per_step) : -std::numeric_limits<double>::infinity();
  return r;
}

}  // namespace tmu::host::nurbs
