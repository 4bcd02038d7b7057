// `texsim sweep nurbs`: what accuracy costs for NURBS texturing (004, EP0637814).
//
// 1. Per tessellation threshold (claims 8-11: MC, DC, TC, combined): a scene (default
//    scenes/nurbs_freeform.json) with every NURBS object tessellated by the row and every
//    material with a tau in order tc (claim 16: (u, v) from tau at the vertices, interpolated
//    over the triangles, so the threshold moves both the geometry and the texture), sampled by
//    the trilinear unit at the pixel's lambda (sweep_nurbs.cpp per_pixel_isotropic: why):
//    triangles, front-end time, the units' cycles, and the frame's error against the reference.
// 2. Per tau grid size and interpolation (claims 4-6): the tau unit's error against the
//    functional map, and its rtl against golden (sweep_nurbs_tau.hpp).
// 3. Per composition order (claims 15-18: pc, tc, texture, composed) on one sphere of
//    scenes/nurbs_orders.json: the error against the reference, the rtl's cycles, rtl = golden.
//
// The reference is the same scene at the ideal engine in order pc, tessellated through
// quarter-pixel steps (DC 0.25, up to 1024 steps a patch and direction), and then every fragment
// moved onto the true surface along its pixel's ray (sweep_nurbs_frame.hpp reference_render,
// nurbs/ray_hit.hpp): tau is applied per pixel in double precision (render/tau_stage.cpp
// ideal_tau) to the exact (s, t) and screen derivatives. Errors are taken over the pixels both
// frames cover; the pixels only one covers are counted.
#pragma once

#include <cstddef>
#include <string>

namespace tmu::texsim {

struct NurbsSweepArgs {
  // Rows of table 1: terms key=value joined by '+', rows separated by ';'. Keys: mc (modelling
  // units), dc (pixels), tc (texels of level 0), g (mean | geometric | max: claim 11's
  // averaging), max (max steps a patch and direction, default 1024).
  std::string settings = "mc=0.4;mc=0.1;mc=0.025;dc=16;dc=4;dc=1;tc=32;tc=8;tc=2;dc=4+tc=8";
  std::string scene;            // table 1's; default scenes/nurbs_freeform.json
  size_t tau_samples = 200000;  // table 2's random (s, t) per row
  bool quick = false;           // half the frames' resolution, fewer tau samples and rtl items
  std::string markdown;         // table 1; _tau and _orders beside it
};

void sweep_nurbs(const NurbsSweepArgs& args);

}  // namespace tmu::texsim
