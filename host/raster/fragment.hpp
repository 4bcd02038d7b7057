// What the front end hands the texture unit: one fragment per covered pixel after the depth
// test, in double precision (the ideal engine uses it as it is) and as the fixed-point record
// the hardware ports carry (formats from golden/formats/formats.def).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

namespace tmu::host {

struct Fragment {
  int x = 0, y = 0;            // pixel
  int object = 0;              // Scene::objects index
  int material = 0;            // Scene::materials index
  double depth = 0;            // NDC z (0 near .. 1 far), the depth test's key
  glm::dvec2 uv{0};            // texels of level 0 of the material's texture, centres at i + 0.5
  glm::dvec2 r1{0}, r2{0};     // d(u, v)/dx and d(u, v)/dy, texels per pixel
  double lambda = 0;           // log2 max(|r1|, |r2|)
  glm::dvec3 solid{0};         // object-space position: the solid texture coordinates (u, v, w)
  glm::dvec3 normal{0, 0, 1};  // unit, world space, interpolated
  glm::dvec3 view{0, 0, 1};    // unit, world space, from the surface to the eye
  glm::dvec3 shade{1};         // lighting, each channel 0..1: I_d of eq. 5
  glm::dvec4 colour{0};        // the vertex colours interpolated (004 claims 17, 18), 0..255
};

// The fixed-point record: raw values of the declared formats.
struct FragmentRecord {
  uint16_t x = 0, y = 0;                   // PixelCoord
  uint8_t material = 0;                    // MaterialId
  int32_t u = 0, v = 0;                    // TexCoord SQ16.8
  int32_t lambda = 0;                      // Lod SQ6.8
  uint32_t shade = 0;                      // Rgba8888 (alpha 255)
  int32_t r1[2] = {0, 0}, r2[2] = {0, 0};  // TexDeriv SQ16.8
  int32_t solid[3] = {0, 0, 0};            // SolidCoord SQ12.12
  int16_t normal[3] = {0, 0, 0};           // UnitComp SQ2.14
  int16_t view[3] = {0, 0, 0};             // UnitComp SQ2.14
  friend bool operator==(const FragmentRecord&, const FragmentRecord&) = default;
};

// Rounds to nearest (ties to even) and saturates into each format; shade channels are
// round(255 * value).
FragmentRecord quantize(const Fragment& f);

}  // namespace tmu::host
