// The host front end (the rasterizer side of 000 Fig. 3 and 002 ch. 3): transform, clipping
// against the view volume, perspective-correct interpolation, derivatives, LOD, normals, view
// vector, lighting, depth test.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/mesh.hpp"
#include "raster/fragment.hpp"
#include "scene/scene.hpp"

namespace tmu::host {

// lambda = log2 max(|r1|, |r2|) needs a positive argument: a surface whose texture does not
// change across the pixel (uv_repeat tiny, or a texture of one texel) has a footprint of 0.
// 2^-40 texels gives lambda = -40, below anything the Lod format (SQ6.8, >= -32) holds, so the
// clamp never changes a quantized lambda.
inline constexpr double kMinFootprint = 0x1p-40;

struct RasterStats {
  uint64_t triangles = 0;  // after culling and clipping
  uint64_t fragments = 0;  // rasterized, before the depth test (overdraw included)
  uint64_t visible = 0;    // after the depth test: one per covered pixel
};

// The visible fragments of rows [row_begin, row_end) (all rows by default), ordered by
// (y, x). meshes[i] belongs to scene.objects[i]; texture_sizes[m] scales material m's u, v and
// their derivatives to what its first unit takes: the level-0 size of its texture (texels), or
// for a tau unit's (s, t) 256 times the tau grid's cells (nurbs/nurbs_mesh.hpp).
std::vector<Fragment> rasterize(const Scene& scene, const std::vector<Mesh>& meshes,
                                const std::vector<glm::ivec2>& texture_sizes, int row_begin = 0,
                                int row_end = -1, RasterStats* stats = nullptr);

}  // namespace tmu::host
