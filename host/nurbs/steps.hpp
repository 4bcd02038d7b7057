// Tessellation granularity of 004 claims 7-12: the number of steps a patch is cut into along s
// and t, from the maximum derivative bounds and thresholds in MC, DC and TC space, and the mip
// level the TC criterion gives (claim 12).
//
// Choices where the copy's equations are blank or silent (docs/nurbs.md):
// - The patent's n_s = ||S'_s|| / d_s,mc counts steps over a unit parameter interval; a patch's
//   knot domain may be longer, so n_s = ceil(||S'_s|| (s_max - s_min) / d_mc): every step is at
//   most d_mc long in MC.
// - DC (claim 10): d_mc = d_dc / (||M|| k), ||M|| the modelling transform's norm (its largest
//   scale factor) and k the viewing transform's scaling: the most pixels a unit of world length
//   covers anywhere in the visible part of the patch's box, f / z_min sqrt(1 + tan^2(fov_x / 2) +
//   tan^2(fov_y / 2)) with f the focal length in pixels and z_min the box's nearest depth (at
//   least the near plane). A conservative scale: every step is at most d_dc pixels.
// - TC (claim 9, blank): n_s = ceil(||tau'_s|| (s_max - s_min) / d_tc), ||tau'_s|| the bound of
//   tau's derivative over the patch in texels of level 0 per unit of s: every step is at most
//   d_tc texels.
// - Both (claim 11): n = min(max_steps, ceil(g(n_N, n_T))), g the arithmetic mean (the
//   averaging function; geometric mean and max selectable), n_N the larger of the MC and DC
//   counts. At least one step.
// - Claim 12 (blank): the level whose texels are one tessellation step, l = log2 max(
//   ||tau'_s|| (s_max - s_min) / n_s, ||tau'_t|| (t_max - t_min) / n_t). When the TC criterion
//   decides n, the step is d_tc texels and l = log2 d_tc: claim 13's l = log2 f(d_s,tc, d_t,tc)
//   with f the maximum.
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "nurbs/patch.hpp"
#include "nurbs/tau_map.hpp"
#include "scene/scene.hpp"

namespace tmu::host::nurbs {

// What the counts are measured against.
struct StepContext {
  const Camera* camera = nullptr;  // for DC thresholds
  glm::dmat4 model{1.0};           // the modelling transform
  double model_norm = 1;           // ||M||: its largest scale factor
  // For TC thresholds and claim 12: the material's tau, its texture's level-0 size, and the
  // patch's parameter rectangle normalised into the object's (s0, s1, t0, t1).
  const TauMap* tau = nullptr;
  glm::ivec2 texture_size{1, 1};
};

struct PatchSteps {
  glm::ivec2 steps{1, 1};          // n_s, n_t
  std::optional<glm::ivec2> mcdc;  // n_N (MC or DC), before combining
  std::optional<glm::ivec2> tc;    // n_T
  double lambda = 0;               // claim 12's level (texels per step); -inf without a tau
};

// `pc` is the patch's rectangle in the object's normalised parameter coordinates
// (s0, s1, t0, t1).
PatchSteps patch_steps(const Patch& patch, const glm::dvec4& pc, const Tessellation& tess,
                       const StepContext& context);

// The DC scaling k of the viewing transform for a box of world points (pixels per world unit).
double view_scale(const Camera& camera, const glm::dvec3& box_min, const glm::dvec3& box_max);

}  // namespace tmu::host::nurbs
