// The clip-map fly-over (issue 17): a camera flies along keyframes over a ground plane that a
// virtual texture far larger than texture memory covers, one texel per world unit; the texture
// is read through the clip-map unit (003), whose tiles the host's manager (clipmap::TileManager)
// updates between frames. `texsim render` takes a scene with a "flyover" section here.
//
// The scene (scenes/flyover.json; scenes/README.md gives every key):
//   {"flyover": {
//      "terrain": {"log2": 10, "seed": 1},   a generated virtual texture (texsim terrain), or
//      "file": "x.tx",                       a tiled mipmap maketx made
//      "tile_log2": 6, "substitution": "per-sample" | "per-tap",
//      "kind": "rgba" | "luminance", "filter": "trilinear" | "bilinear" | "nearest",
//      "border": "wrap" | "clamp" | "mirror",
//      "frame": [width, height], "fov_degrees": 60, "sky": [r, g, b],
//      "path": [{"frame": 0, "eye": [x, y, height], "look": [x, y, z]}, ...]}}
// Frames between keyframes move the eye and the point looked at linearly.
//
// Per frame the front end casts a ray per pixel onto the plane z = 0 (exact, analytic: host
// work): (u, v) is the hit point, lambda the log2 of the longer screen derivative of (u, v)
// (ray differentials), as the rasterizer's rule. The clip-map's tiles are centred on the ground
// point the camera looks at (the "look" of the path, on the ground): 003 centres them on the
// eyepoint, where the finest texels are needed; a camera above the ground needs them where it
// looks, and centring them below it would leave half of every tile behind the camera. One clip-map
// unit runs the whole frame range: its configuration, then per frame the manager's region writes
// and loads, then the frame's samples. So a frame after frames 0..k-1 is checked bit for bit like
// any unit, loads included, and a frame rendered alone (the manager from scratch) equals it
// (docs/clipmap.md).
#pragma once

#include <iosfwd>
#include <string>

#include "render/render.hpp"

namespace tmu::render {

// Whether the scene file is a fly-over (has a "flyover" section).
bool is_flyover(const std::string& scene_path);

// Frames first..last (last -1: every frame of the path).
struct FrameRange {
  int first = 0, last = -1;
};

// Renders the frames into out_dir: flyover.frame-NNNN.png, flyover.contact.png (every frame),
// flyover.report.txt (per frame: texels loaded, rows per level, wayward samples, cycles). `check`
// compares the unit with another engine's (outputs, every read and write, counters) and every
// pixel. Returns 0, or 1 on a mismatch; throws InputError on bad input.
int render_flyover(const std::string& scene_path, const RenderOptions& options, FrameRange frames,
                   std::ostream& log);

}  // namespace tmu::render
