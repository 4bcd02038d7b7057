// Bump maps (001 §4.2): a height field turned into bump texels, the deflected normal of each
// texel as x-polar angles (phi_D, theta_D) on the sphere grid's nodes (s2s_map.hpp gives the
// frame). An offline host tool: `texsim bumpmap`.
//
// Slopes: central differences with wrap-around, du = (h[x+1] - h[x-1]) / 2 * scale and
// dv = (h[y-1] - h[y+1]) / 2 * scale (the bump frame's v points up the image, towards row 0),
// h the luminance in 0..1, `scale` the height of luminance 1 in texels. The texel's normal in
// the frame is (-du, -dv, 1); its angles are rounded to the nearest node, |theta_D| saturated
// to Q - 1.
//
// Stored as an RGB texel (a true-colour TEXRAM texture, sampled nearest: angles wrap and must
// not be blended): R = phi_D bits 7:0, G = |theta_D|, B = sign of theta_D in bit 7 and phi_D's
// bits above 7 in bits 6:0. Grids up to A = 10 fit.
#pragma once

#include <glm/vec2.hpp>

#include "common/image.hpp"
#include "deflect/sphere_grid.hpp"

namespace tmu::deflect {

constexpr int kMaxBumpGridBits = 10;

// The bump texel of a surface with slopes (du, dv) per unit of arc length.
SphereAngle bump_texel(const SphereGrid& grid, double du, double dv);

Rgb8 pack_bump(const SphereGrid& grid, SphereAngle texel);
SphereAngle unpack_bump(const SphereGrid& grid, Rgb8 rgb);

// The slopes (du, dv) at texel (x, y) of the height field (the rule above).
glm::dvec2 bump_slope(const ImageRgb8& heights, int x, int y, double scale);
ImageRgb8 bump_map_from_heights(const ImageRgb8& heights, double scale, const SphereGrid& grid);

}  // namespace tmu::deflect
