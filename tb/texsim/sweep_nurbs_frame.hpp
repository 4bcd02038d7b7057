// The frames `texsim sweep nurbs` compares: a scene changed in memory (its NURBS objects'
// thresholds, its materials' composition order) rendered at one level the way `texsim render`
// renders it (the front end, then the pipeline), kept pixel by pixel with the pixels it covers;
// and one frame's error against another over the pixels both cover, since a coarser
// tessellation moves the silhouettes and a pixel only one frame covers holds no texture error.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "render/units.hpp"
#include "scene/scene.hpp"

namespace tmu::texsim {

struct NurbsFrame {
  int width = 0, height = 0;
  std::vector<uint8_t> covered;      // per pixel, row-major: 1 where a fragment landed
  std::vector<glm::dvec3> colour;    // RGB 0..255: ideal's unrounded colours, others' 8-bit ones
  uint64_t triangles = 0;            // the meshes' (what the tessellation made)
  double front_end_s = 0;            // tessellation and rasterization, not the vertex colours
  uint64_t unit_cycles = 0;          // every unit's; golden's untimed units: predicted
  std::optional<bool> equals_check;  // with a check level: frame and every unit bit for bit
};

// Renders `scene` at `level`; with `check`, also shades the same fragments at that level (with
// its own vertex colours) and compares the colours and every unit (render/unit_check.hpp), as
// `texsim render --check` does.
NurbsFrame render_frame(const host::Scene& scene, render::Level level,
                        std::optional<render::Level> check = std::nullopt);

struct NurbsFrameError {
  double psnr = 0, max = 0, mean = 0;  // RGB, 8-bit levels, over the pixels both cover
  uint64_t compared = 0;               // pixels both cover
  uint64_t coverage_diff = 0;          // pixels only one of them covers
};
NurbsFrameError frame_error(const NurbsFrame& got, const NurbsFrame& reference);

struct ReferenceStats {
  uint64_t moved = 0;  // fragments put on the surface
  uint64_t kept = 0;   // fragments Newton found no hit for (grazing rays), left as they were
  NurbsFrameError tessellation_error;  // the frame before the move against the one after
};

// The reference: `scene` rendered at ideal with every fragment of a NURBS object whose
// parameter coordinates reach the units as they are (order pc, or no tau) moved onto the true
// surface (nurbs/ray_hit.hpp): its (s, t), their screen derivatives, its normal and lighting
// from the ray through the pixel's centre, not from the triangle under it. The tessellation
// still decides which pixels an object covers and where Newton starts.
NurbsFrame reference_render(const host::Scene& scene, ReferenceStats* stats);

}  // namespace tmu::texsim
