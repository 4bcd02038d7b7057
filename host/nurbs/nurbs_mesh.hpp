// A NURBS object tessellated into a mesh (004 claims 7-11): each patch cut into the steps its
// thresholds give (nurbs/steps.hpp), the joins between patches kept watertight.
//
// Watertight joins: two patch edges that trace the same curve (forward or reversed, found by
// comparing five points along each) share their vertices: the edge gets the larger of the two
// patches' step counts, its points are evaluated once, by the first patch, and both patches use
// those positions. A patch whose edges have other counts than its interior is cut into an inner
// grid (at least 2 x 2 steps) and a ring of four strips, each zipped between the edge's points
// and the inner grid's outer row in parameter order, so no T-junction remains. A closed
// surface's seam (a patch's own two edges meeting) is a join like any other. Collapsed edges
// (a pole) join nothing; their triangles have no area and are dropped. Corners shared by
// patches whose edges other patches evaluated may differ in the last bits; the rasterizer's
// 1/256-pixel snap merges them.
#pragma once

#include <vector>

#include "geometry/mesh.hpp"
#include "nurbs/steps.hpp"
#include "scene/scene.hpp"

namespace tmu::host::nurbs {

struct NurbsStats {
  std::vector<PatchSteps> patches;  // per patch: its steps and claim 12's level
  size_t joins = 0;                 // edges shared between patches (or a seam)
};

// The rectangle (s0, s1, t0, t1) holding every patch's knot domain: the object's parameter
// coordinates are normalised over it.
glm::dvec4 pc_rectangle(const std::vector<Patch>& patches);

// The object's mesh, in object space. Vertex uv: with an order-pc material the normalised
// (s, t) (the rasterizer scales them for the tau unit), else tau(s, t) in texture units (s, t
// themselves without a tau); vertex lod: claim 12's level with lod "tc". `texture_size` is the
// material's level-0 size (TC thresholds, claim 12).
Mesh tessellate(const Object& object, const Material& material, const Camera& camera,
                glm::ivec2 texture_size, NurbsStats* stats = nullptr);

}  // namespace tmu::host::nurbs
