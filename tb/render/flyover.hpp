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
//      "kind": "rgba" | "luminance",
//      "filter": "trilinear" | "bilinear" | "nearest" | "footprint", "max_probes": 8,
//      "border": "wrap" | "clamp" | "mirror",
//      "frame": [width, height], "fov_degrees": 60, "sky": [r, g, b],
//      "path": [{"frame": 0, "eye": [x, y, height], "look": [x, y, z]}, ...]}}
// Frames between keyframes move the eye and the point looked at linearly. "footprint" renders
// through the footprint unit on the clip-map (tmu_footprint_clip: trilinear probes along each
// pixel's longer derivative, up to max_probes, 1..16, a power of two; default 8), where the
// grazing view of the ground is most anisotropic.
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

#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <iosfwd>
#include <string>
#include <vector>

#include "clipmap/clipmap.hpp"
#include "common/image.hpp"
#include "footprint/footprint.hpp"
#include "render/render.hpp"
#include "render/units.hpp"

namespace tmu::render {

struct Keyframe {
  int frame = 0;
  glm::dvec3 eye, look;
};

// A fly-over scene, read.
struct Flyover {
  std::string path;      // the scene file
  std::string texture;   // the tiled mipmap (made from "terrain" when the scene asks)
  int terrain_log2 = 0;  // 0: a given file
  uint32_t terrain_seed = 1;
  clipmap::Config config;
  // The footprint unit in front of the clip-map (filter "footprint"), its setup's configuration.
  bool footprint = false;
  footprint::Config setup;
  int width = 160, height = 120;
  double fov_degrees = 60;
  Rgb8 sky{150, 190, 235};
  std::vector<Keyframe> path_keys;
  int frames() const { return path_keys.back().frame + 1; }
};
// Throws InputError naming the file, the field and the reason. A generated terrain goes to
// `out_dir`.
Flyover load_flyover(const std::string& scene_path, const std::string& out_dir);
// Makes the generated virtual texture when it is not there yet (texsim terrain's).
void make_virtual_texture(const Flyover& flyover, std::ostream& log);

struct FrameReport {
  int frame = 0;
  size_t samples = 0, loads = 0, wayward = 0;
  uint64_t cycles = 0, file_tiles = 0;
  std::array<uint32_t, clipmap::kMaxLevels> rows{};
  glm::dvec2 centre;  // the tiles' centre: the ground point looked at
};

// Frames first, first + step, .. <= last through one clip-map unit at `level`.
struct FlyoverRun {
  std::vector<ImageRgb8> images;
  std::vector<FrameReport> frames;
  ImageRgb8 tiles;  // the last frame's tiles over the texture
  UnitRun unit;
  double seconds = 0;  // the unit's run
};
FlyoverRun run_flyover(const Flyover& flyover, Level level, int first, int last, int step = 1);

// Whether the scene file is a fly-over (has a "flyover" section).
bool is_flyover(const std::string& scene_path);

// Frames first..last (last -1: every frame of the path).
struct FrameRange {
  int first = 0, last = -1;
};
// "A", "A-B" or "A:B", whole numbers; throws InputError("--frames", ...) otherwise.
FrameRange parse_frame_range(const std::string& text);
// `range` with last -1 made the path's last frame; throws InputError("--frames", ...) when it is
// empty or leaves a path of `frames` frames.
FrameRange frames_of_path(FrameRange range, int frames);

// Renders the frames into out_dir: flyover.frame-NNNN.png, flyover.contact.png (every frame),
// flyover.report.txt (per frame: texels loaded, rows per level, wayward samples, cycles). `check`
// compares the unit with another engine's (outputs, every read and write, counters) and every
// pixel. Returns 0, or 1 on a mismatch; throws InputError on bad input.
int render_flyover(const std::string& scene_path, const RenderOptions& options, FrameRange frames,
                   std::ostream& log);

}  // namespace tmu::render
