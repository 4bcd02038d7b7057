#include "render/flyover.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include "blocks/clipmap/clipmap_block.hpp"
#include "blocks/footprint_clip/footprint_clip_block.hpp"
#include "clipmap/terrain.hpp"
#include "clipmap/tile_centre.hpp"
#include "clipmap/tile_manager.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/image_file.hpp"
#include "formats/formats.hpp"
#include "render/contact_sheet.hpp"
#include "render/unit_check.hpp"
#include "scene/json_node.hpp"

namespace tmu::render {
namespace {

using glm::dvec3;
namespace fs = std::filesystem;

}  // namespace

Flyover load_flyover(const std::string& scene_path, const std::string& out_dir) {
  std::ifstream in(scene_path);
  if (!in) throw InputError(scene_path, "", "cannot read the file");
  std::stringstream text;
  text << in.rdbuf();
  const host::Json doc = host::parse_json(text.str(), scene_path);
  const host::JsonNode root(doc, "", scene_path);
  root.expect_object();
  root.allow_keys({"flyover"});
  const host::JsonNode f = root.at("flyover");
  f.allow_keys({"terrain", "file", "tile_log2", "substitution", "kind", "filter", "max_probes",
                "border", "frame", "fov_degrees", "sky", "path"});
  Flyover fo;
  fo.path = scene_path;
  clipmap::Config& c = fo.config;
  if (f.has("terrain") == f.has("file")) f.fail("give one of terrain and file");
  if (const auto t = f.find("terrain")) {
    t->allow_keys({"log2", "seed"});
    fo.terrain_log2 = static_cast<int>(t->at("log2").integer(2, clipmap::kMaxLog2Virtual));
    if (const auto s = t->find("seed"))
      fo.terrain_seed = static_cast<uint32_t>(s->integer(0, 1 << 30));
    c.log2_virtual = fo.terrain_log2;
    fo.texture =
        (fs::path(out_dir) / fmt::format("terrain-{}-{}.tx", fo.terrain_log2, fo.terrain_seed))
            .string();
  } else {
    fo.texture = f.at("file").string();
    const fs::path p(fo.texture);
    if (p.is_relative()) fo.texture = (fs::path(scene_path).parent_path() / p).string();
    // The virtual texture's size is the file's level 0 (the tile manager checks the rest).
    std::string why;
    const auto file = open_image_file(fo.texture, &why);
    if (!file)
      f.at("file").fail(fo.texture + ": cannot open: " + (why.empty() ? "no reader" : why));
    const int side = file->width();
    if (side != file->height() || side < 4 || side > (1 << clipmap::kMaxLog2Virtual) ||
        (side & (side - 1)) != 0) {
      f.at("file").fail(
          fmt::format("{}: {} x {}, expected a square of 4 .. {} texels, a power of two",
                      fo.texture, side, file->height(), 1 << clipmap::kMaxLog2Virtual));
    }
    c.log2_virtual = std::countr_zero(static_cast<unsigned>(side));
  }
  c.log2_tile =
      static_cast<int>(f.at("tile_log2").integer(clipmap::kMinLog2Tile, clipmap::kMaxLog2Tile));
  if (const auto s = f.find("substitution")) {
    c.substitution = s->one_of({"per-sample", "per-tap"}) == "per-tap"
                         ? clipmap::Substitution::kPerTap
                         : clipmap::Substitution::kPerSample;
  }
  c.sampler.kind = texram::TexelKind::kTrueColour;
  if (const auto k = f.find("kind")) {
    c.sampler.kind = k->one_of({"rgba", "luminance"}) == "rgba" ? texram::TexelKind::kTrueColour
                                                                : texram::TexelKind::kLuminance;
  }
  if (const auto k = f.find("filter")) {
    const std::string filter = k->one_of({"nearest", "bilinear", "trilinear", "footprint"});
    fo.footprint = filter == "footprint";
    c.sampler.filter = *texram::parse_filter(fo.footprint ? "trilinear" : filter);
  }
  fo.setup.log2_max_probes = 3;
  if (const auto m = f.find("max_probes")) {
    if (!fo.footprint) m->fail("max_probes is for filter \"footprint\"");
    const int64_t n = m->integer(1, 1 << formats::kMaxProbeLog2);
    if ((n & (n - 1)) != 0) m->fail("expected a power of two, 1..16");
    fo.setup.log2_max_probes = std::countr_zero(static_cast<uint64_t>(n));
  }
  if (const auto b = f.find("border")) {
    c.sampler.border_u = c.sampler.border_v =
        *texram::parse_border(b->one_of({"wrap", "clamp", "mirror"}));
  }
  if (const auto fr = f.find("frame")) {
    const glm::dvec2 wh = fr->vec2();
    if (wh.x < 8 || wh.y < 8 || wh.x > 1920 || wh.y > 1080 || wh.x != std::floor(wh.x) ||
        wh.y != std::floor(wh.y))
      fr->fail("expected whole numbers of pixels, 8..1920 wide and 8..1080 high");
    fo.width = static_cast<int>(wh.x);
    fo.height = static_cast<int>(wh.y);
  }
  if (const auto v = f.find("fov_degrees")) {
    fo.fov_degrees = v->number();
    if (fo.fov_degrees <= 1 || fo.fov_degrees >= 170) v->fail("expected 1 < degrees < 170");
  }
  if (const auto s = f.find("sky")) {
    const glm::dvec3 k = s->colour3(0, 1);
    fo.sky = {static_cast<uint8_t>(std::lround(k.r * 255)),
              static_cast<uint8_t>(std::lround(k.g * 255)),
              static_cast<uint8_t>(std::lround(k.b * 255))};
  }
  const host::JsonNode p = f.at("path");
  p.expect_array();
  if (p.size() == 0) p.fail("expected at least one keyframe");
  for (size_t i = 0; i < p.size(); ++i) {
    const host::JsonNode k = p[i];
    k.allow_keys({"frame", "eye", "look"});
    Keyframe kf{static_cast<int>(k.at("frame").integer(0, 100000)), k.at("eye").vec3(),
                k.at("look").vec3()};
    if (!fo.path_keys.empty() && kf.frame <= fo.path_keys.back().frame)
      k.at("frame").fail("keyframes must be in increasing frame order");
    if (i == 0 && kf.frame != 0) k.at("frame").fail("the first keyframe is frame 0");
    if (kf.eye.z <= 0) k.at("eye").fail("the eye must be above the ground (z > 0)");
    if (glm::length(kf.look - kf.eye) == 0) k.at("look").fail("the eye cannot look at itself");
    fo.path_keys.push_back(kf);
  }
  if (c.log2_tile > c.log2_virtual) f.at("tile_log2").fail("larger than the virtual texture");
  return fo;
}

namespace {

// The eye and the point looked at in frame `n`: linear between keyframes.
Keyframe camera_at(const Flyover& fo, int n) {
  const auto& k = fo.path_keys;
  for (size_t i = 1; i < k.size(); ++i) {
    if (n > k[i].frame) continue;
    const double t = double(n - k[i - 1].frame) / double(k[i].frame - k[i - 1].frame);
    return {n, k[i - 1].eye + (k[i].eye - k[i - 1].eye) * t,
            k[i - 1].look + (k[i].look - k[i - 1].look) * t};
  }
  return k.back();
}

// One pixel's sample: where its ray meets the ground, or the sky.
struct Pixel {
  bool ground = false;
  int32_t u = 0, v = 0, lambda = 0;            // TexCoord, TexCoord, Lod raw
  int32_t r1u = 0, r1v = 0, r2u = 0, r2v = 0;  // d(u, v)/dx and d(u, v)/dy, TexDeriv raw
};

// The frame's pixels by ray casting onto z = 0, with (u, v) in level-0 texels and lambda the
// log2 of the longer of the screen derivatives of (u, v), from the neighbouring pixels' rays.
std::vector<Pixel> cast(const Flyover& fo, const Keyframe& cam) {
  const dvec3 forward = glm::normalize(cam.look - cam.eye);
  const dvec3 right = glm::normalize(glm::cross(forward, dvec3(0, 0, 1)));
  const dvec3 up = glm::cross(right, forward);
  const double half = std::tan(fo.fov_degrees * M_PI / 360);
  const double aspect = double(fo.width) / fo.height;
  const auto hit = [&](double px, double py, glm::dvec2* uv) {
    const dvec3 d = forward + right * ((2 * px / fo.width - 1) * half * aspect) -
                    up * ((2 * py / fo.height - 1) * half);
    if (d.z >= -1e-9) return false;
    const double t = -cam.eye.z / d.z;
    *uv = {cam.eye.x + t * d.x, cam.eye.y + t * d.y};
    return true;
  };
  const auto raw = [](double value, const fx::Format& f) {
    const double r = std::round(value * std::ldexp(1.0, f.frac_bits));
    return static_cast<int32_t>(std::clamp(r, double(f.min_raw()), double(f.max_raw())));
  };
  std::vector<Pixel> out(static_cast<size_t>(fo.width) * fo.height);
  for (int y = 0; y < fo.height; ++y) {
    for (int x = 0; x < fo.width; ++x) {
      glm::dvec2 uv, ux, uy;
      if (!hit(x + 0.5, y + 0.5, &uv) || !hit(x + 1.5, y + 0.5, &ux) || !hit(x + 0.5, y + 1.5, &uy))
        continue;
      const double len = std::max({glm::length(ux - uv), glm::length(uy - uv), 1e-6});
      const auto deriv = [&](double d) { return raw(d, formats::kTexDeriv); };
      out[static_cast<size_t>(y) * fo.width + x] = {true,
                                                    raw(uv.x, formats::kTexCoord),
                                                    raw(uv.y, formats::kTexCoord),
                                                    raw(std::log2(len), formats::kLod),
                                                    deriv(ux.x - uv.x),
                                                    deriv(ux.y - uv.y),
                                                    deriv(uy.x - uv.x),
                                                    deriv(uy.y - uv.y)};
    }
  }
  return out;
}

// The virtual texture seen whole (a level of at most 512 texels a side) with each clipped
// level's tile drawn on it, the finest in red to the coarsest in yellow: where the clip-map is.
ImageRgb8 tiles_picture(clipmap::TileManager& manager, const clipmap::Config& c,
                        const clipmap::Regions& regions) {
  const int level = std::max(0, c.log2_virtual - 9);
  const int side = 1 << (c.log2_virtual - level);
  ImageRgb8 img(side, side);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const uint32_t t = manager.texel(level, static_cast<uint32_t>(x), static_cast<uint32_t>(y));
      img.at(x, y) = c.sampler.kind == texram::TexelKind::kTrueColour
                         ? Rgb8{static_cast<uint8_t>(t >> 24), static_cast<uint8_t>(t >> 16),
                                static_cast<uint8_t>(t >> 8)}
                         : Rgb8{static_cast<uint8_t>(t >> 24), static_cast<uint8_t>(t >> 24),
                                static_cast<uint8_t>(t >> 24)};
    }
  }
  const int clipped = c.clipped_levels();
  for (int l = 0; l < clipped; ++l) {
    const clipmap::Region& r = regions[static_cast<size_t>(l)];
    const double scale = std::ldexp(1.0, l - level);  // level-l texels to picture pixels
    const auto px = [&](uint32_t v) {
      return std::clamp(static_cast<int>(std::lround(v * scale)), 0, side - 1);
    };
    const int x0 = px(r.x0), x1 = px(r.x1), y0 = px(r.y0), y1 = px(r.y1);
    const Rgb8 ink{255, static_cast<uint8_t>(clipped > 1 ? 255 * l / (clipped - 1) : 0), 0};
    for (int x = x0; x <= x1; ++x) img.at(x, y0) = img.at(x, y1) = ink;
    for (int y = y0; y <= y1; ++y) img.at(x0, y) = img.at(x1, y) = ink;
  }
  return img;
}

}  // namespace

bool is_flyover(const std::string& scene_path) {
  std::ifstream in(scene_path);
  std::stringstream text;
  text << in.rdbuf();
  try {
    const auto doc = nlohmann::json::parse(text.str());
    return doc.is_object() && doc.contains("flyover");
  } catch (const std::exception&) {
    return false;  // the scene parser reports what is wrong
  }
}

void make_virtual_texture(const Flyover& fo, std::ostream& log) {
  if (fo.terrain_log2 == 0 || fs::exists(fo.texture)) return;
  log << fmt::format("making the virtual texture {} (texsim terrain --log2 {} --seed {})\n",
                     fo.texture, fo.terrain_log2, fo.terrain_seed);
  fs::create_directories(fs::path(fo.texture).parent_path());
  clipmap::write_terrain_mipmap(fo.texture, fo.terrain_log2, fo.terrain_seed, 64);
}

FlyoverRun run_flyover(const Flyover& fo, Level level, int first, int last, int step) {
  clipmap::TileManager manager(fo.config, fo.texture);
  FlyoverRun out;
  // The unit's items: the configuration, then per frame the updates and the samples (pixels,
  // or fragments of the footprint unit, whose probes the clip-map counts as samples).
  std::shared_ptr<tb::DescribedBlock> block;
  if (fo.footprint) {
    block = std::make_shared<tb::FootprintClipBlock>(fo.config, fo.setup);
  } else {
    block = std::make_shared<tb::ClipmapBlock>(fo.config);
  }
  const auto region_item = fo.footprint ? tb::clip_region_item<tb::desc::footprint_clip>
                                        : tb::clip_region_item<tb::desc::clipmap>;
  const auto load_item = fo.footprint ? tb::clip_load_item<tb::desc::footprint_clip>
                                      : tb::clip_load_item<tb::desc::clipmap>;
  UnitRun& run = out.unit;
  run.kind = fo.footprint ? "footprint_clip" : "clipmap";
  run.material = "terrain";
  attach(run, block);
  run.items = block->setup_items();
  std::vector<std::vector<Pixel>> pixels;
  const clipmap::ClipGeometry g = fo.config.geometry();
  for (int n = first; n <= last; n += step) {
    const Keyframe cam = camera_at(fo, n);
    FrameReport r;
    r.frame = n;
    r.centre = {cam.look.x, cam.look.y};
    const clipmap::FrameUpdate u = manager.update(r.centre.x, r.centre.y);
    for (const auto& [lv, region] : u.regions) run.items.push_back(region_item(lv, region));
    for (const clipmap::Load& l : u.loads) run.items.push_back(load_item(l));
    r.loads = u.loads.size();
    r.rows = u.rows;
    r.file_tiles = u.file_tiles_read;
    pixels.push_back(cast(fo, cam));
    const clipmap::Regions regions = clipmap::centred_regions(fo.config, r.centre.x, r.centre.y);
    // The report's count of wayward samples per frame, from the plans (the unit counts them over
    // the run: its counter is checked against the sum).
    const auto wayward = [&](const texram::Request& q) {
      return clipmap::plan_clip_sample(g, fo.config, regions, q).wayward;
    };
    for (const Pixel& p : pixels.back()) {
      if (!p.ground) continue;
      ++r.samples;
      if (!fo.footprint) {
        run.items.push_back(tb::clipmap_sample_item(p.u, p.v, p.lambda));
        r.wayward += wayward({p.u, p.v, p.lambda, 0});
        continue;
      }
      const footprint::Request q{p.u, p.v, p.r1u, p.r1v, p.r2u, p.r2v, 0xFFFF'FFFFu};
      run.items.push_back(tb::footprint_clip_item(q));
      const footprint::Plan plan = footprint::plan(q, fo.setup);
      for (int i = 0; i < (1 << plan.log2_n); ++i)
        r.wayward += wayward(footprint::probe(q, plan, i, fo.config.sampler));
    }
    out.frames.push_back(r);
  }
  const auto t = std::chrono::steady_clock::now();
  run_unit(run, level, {});
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  if (!run.result.error.empty()) throw std::runtime_error("clipmap unit: " + run.result.error);

  size_t next = 0;
  uint64_t cycle_before = 0;  // the cycle of the previous frame's last sample
  for (size_t f = 0; f < pixels.size(); ++f) {
    ImageRgb8 img(fo.width, fo.height);
    for (size_t i = 0; i < pixels[f].size(); ++i) {
      Rgb8& px = img.pixels[i];
      if (!pixels[f][i].ground) {
        px = fo.sky;
        continue;
      }
      const auto c = static_cast<uint32_t>(run.result.outputs[next++].f[0]);
      px = {static_cast<uint8_t>(c >> 24), static_cast<uint8_t>(c >> 16),
            static_cast<uint8_t>(c >> 8)};
    }
    // Cycles: from the previous frame's last sample out to this frame's (its loads included).
    if (next > 0 && next <= run.result.output_cycles.size()) {
      const uint64_t cycle = run.result.output_cycles[next - 1];
      out.frames[f].cycles = cycle - cycle_before;
      cycle_before = cycle;
    }
    out.images.push_back(std::move(img));
  }
  const Keyframe cam = camera_at(fo, out.frames.back().frame);
  out.tiles = tiles_picture(manager, fo.config,
                            clipmap::centred_regions(fo.config, cam.look.x, cam.look.y));
  return out;
}

FrameRange parse_frame_range(const std::string& text) {
  const auto whole = [&](const std::string& part) {
    size_t end = 0;
    int n = -1;
    try {
      n = std::stoi(part, &end);
    } catch (const std::exception&) {
    }
    if (part.empty() || end != part.size() || n < 0)
      throw InputError("--frames", "",
                       "expected A, A-B or A:B (whole numbers), got '" + text + "'");
    return n;
  };
  const size_t dash = text.find_first_of("-:");
  FrameRange r;
  r.first = whole(text.substr(0, dash));
  r.last = dash == std::string::npos ? r.first : whole(text.substr(dash + 1));
  return r;
}

FrameRange frames_of_path(FrameRange range, int frames) {
  if (range.last < 0) range.last = frames - 1;
  if (range.first < 0 || range.first > range.last || range.last >= frames) {
    throw InputError(
        "--frames", "",
        fmt::format("frames {}..{} of a path of {} frames", range.first, range.last, frames));
  }
  return range;
}

int render_flyover(const std::string& scene_path, const RenderOptions& o, FrameRange range,
                   std::ostream& log) {
  if (o.level == Level::kIdeal || (o.check && *o.check == Level::kIdeal)) {
    throw InputError(scene_path, "flyover", "a fly-over renders at golden, hls or rtl");
  }
  const Flyover fo = load_flyover(scene_path, o.out_dir);
  range = frames_of_path(range, fo.frames());
  fs::create_directories(o.out_dir);  // only once the scene and the range are good
  make_virtual_texture(fo, log);
  FlyoverRun run = run_flyover(fo, o.level, range.first, range.last);
  for (size_t f = 0; f < run.images.size(); ++f) {
    write_image((fs::path(o.out_dir) / fmt::format("flyover.frame-{:04}.png", run.frames[f].frame))
                    .string(),
                run.images[f]);
  }
  write_image((fs::path(o.out_dir) / "flyover.contact.png").string(), contact_sheet(run.images));
  write_image((fs::path(o.out_dir) / "flyover.tiles.png").string(), run.tiles);

  // The check: the same unit at another engine, compared like every unit, and the pixels.
  int status = 0;
  std::string verdict;
  if (o.check) {
    UnitRun ref = run.unit;
    ref.result = {};
    run_unit(ref, *o.check, {});
    const UnitCheck uc = check_units({run.unit}, {ref});
    size_t differing = 0;
    const auto& got = run.unit.result.outputs;
    const auto& want = ref.result.outputs;
    for (size_t i = 0; i < got.size() && i < want.size(); ++i)
      differing += got[i].f[0] != want[i].f[0];
    if (uc.match() && differing == 0 && got.size() == want.size()) {
      verdict = fmt::format("MATCH: {} = {}, every sample of {} frames, every load and counter",
                            name(o.level), name(*o.check), run.frames.size());
    } else {
      status = 1;
      verdict = fmt::format("MISMATCH: {} of {} samples differ", differing, got.size());
      for (const std::string& d : uc.differences) verdict += "\n  " + d;
    }
  }

  // The report.
  const int clipped = fo.config.clipped_levels();
  std::string text = fmt::format(
      "flyover {}: {} frames ({}..{}), {}x{}, engine {}\n  virtual texture {} ({} x {}), tiles of "
      "{} x {} for levels 0..{}, {} substitution, {}\n",
      scene_path, run.frames.size(), range.first, range.last, fo.width, fo.height, name(o.level),
      fo.texture, 1 << fo.config.log2_virtual, 1 << fo.config.log2_virtual,
      1 << fo.config.log2_tile, 1 << fo.config.log2_tile, clipped - 1,
      fo.config.substitution == clipmap::Substitution::kPerTap ? "per-tap" : "per-sample",
      fo.footprint ? fmt::format("footprint unit (at most {} probes; samples are pixels, wayward "
                                 "counts probes)",
                                 1 << fo.setup.log2_max_probes)
                   : std::string(texram::name(fo.config.sampler.filter)));
  text +=
      "  frame  centre (u, v)       samples  wayward  texels loaded  rows per level          "
      "cycles\n";
  uint64_t wayward = 0;
  for (const FrameReport& r : run.frames) {
    std::string rows;
    for (int l = 0; l < clipped; ++l)
      rows += fmt::format("{}{}", l ? " " : "", r.rows[static_cast<size_t>(l)]);
    text += fmt::format("  {:5}  ({:8.1f}, {:8.1f})  {:7}  {:7}  {:13}  {:22}  {:6}\n", r.frame,
                        r.centre.x, r.centre.y, r.samples, r.wayward, r.loads, rows, r.cycles);
    wayward += r.wayward;
  }
  const tb::RunResult& result = run.unit.result;
  text += fmt::format("  unit: {} cycles, {:.2f} s; counters:", result.cycles, run.seconds);
  for (const auto& [k, v] : result.counters) text += fmt::format(" {} {}", k, v);
  text += "\n";
  const auto unit_wayward = tb::counter_value(result.counters, "wayward_samples");
  if (unit_wayward && *unit_wayward != wayward) {
    text += fmt::format("  the unit counted {} wayward samples, the plans {}\n", *unit_wayward,
                        wayward);
    status = 1;
  }
  text += "  host work: the front end (ray casting onto the ground), the tile manager's reads\n";
  text += fmt::format(
      "  wrote {}/flyover.frame-NNNN.png, flyover.contact.png and flyover.tiles.png (the tiles of "
      "the last frame over the texture)\n",
      o.out_dir);
  if (!verdict.empty()) text += "  check: " + verdict + "\n";
  write_file_atomically((fs::path(o.out_dir) / "flyover.report.txt").string(), text);
  log << text;
  return status;
}

}  // namespace tmu::render
