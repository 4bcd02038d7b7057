// Video maps rendered through the chips (render/video_render.hpp, docs/video.md "Rendering a
// video"): each frame's chip memory holds, at the base of the video's DRF, exactly the pyramid of
// the video frame the double buffering makes visible, computed independently (the box pyramid of
// texram/mipmap.hpp, and the MipgenStream run alone), with the previous frame in the other
// buffer; rtl = golden on the chips for every frame; an injected fault and a broken pyramid are
// caught; bad scenes are refused naming the file, the field and the reason, with nothing written.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "blocks/texram_chip/texram_chip_block.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "render/chip_stage.hpp"
#include "render/video_feed.hpp"
#include "render/video_render.hpp"
#include "render/video_unit_feed.hpp"
#include "scene/scene.hpp"
#include "texram/mipgen_stream.hpp"
#include "texram/mipmap.hpp"

namespace tmu::render {
namespace {

namespace fs = std::filesystem;

// A render of `level` on one chip, checked against golden, into OUT (no progress bar).
RenderOptions checked_on_a_chip(Level level, const fs::path& out) {
  RenderOptions o;
  o.level = level;
  o.check = Level::kGolden;
  o.chips = 1;
  o.progress = false;
  o.out_dir = out.string();
  return o;
}

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / fmt::format("tmu_video_{}_{}", name, ::getpid());
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// A small scene: a video on a turned quad, a checker floor beside it on the same chip.
std::string scene_text(const std::string& video, const std::string& extra = "") {
  return fmt::format(R"({{
  "camera": {{"position": [0, 0.3, 2.2], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 45, "resolution": [32, 24]}},
  "materials": {{
    "screen": {{"video": {}{}}},
    "floor": {{"texture": {{"pattern": "checker", "size": [32, 32], "cell": 4}}}}
  }},
  "objects": [
    {{"type": "plane", "size": [1.2, 1.2], "material": "screen", "transform": {{"rotate": [90, -25, 15]}}}},
    {{"type": "plane", "size": [4, 4], "material": "floor", "transform": {{"translate": [0, -0.7, 0]}}}}
  ]
}})",
                     video, extra);
}

std::string generated(bool interlaced, int planes, int frames = 3, int side = 64) {
  return fmt::format(
      R"({{"source": "generated", "pattern": "rings", "size": [{}, {}], "interlaced": {}, "planes": {}, "frames": {}}})",
      side, side, interlaced ? "true" : "false", planes, frames);
}

fs::path write_scene(const fs::path& dir, const std::string& video, const std::string& extra = "") {
  const fs::path p = dir / "scene.json";
  std::ofstream(p) << scene_text(video, extra);
  return p;
}

// Texels of `memory`'s map at `base` (the video's layout) that differ from `expected`, plane by
// plane, level by level (replica cells too: every cell the layout gives a texel).
size_t differences(const texram::chip::ChipMemory& memory, const texram::Geometry& g, uint32_t base,
                   const std::vector<texram::Pyramid8>& expected) {
  size_t n = 0;
  for (int p = 0; p < g.planes(); ++p) {
    for (int l = 0; l < g.levels(); ++l) {
      const texram::Level8& want = expected[static_cast<size_t>(p)][static_cast<size_t>(l)];
      for (uint32_t y = 0; y < want.height; ++y) {
        for (uint32_t x = 0; x < want.width; ++x) {
          const texram::BankCell c = g.cell(l, x, y, p);
          n += memory.cell(static_cast<int>(c.bank), base + c.address) != want.at(x, y);
        }
      }
    }
  }
  return n;
}

// The box pyramid of every plane of video frame k (texram/mipmap.hpp), independent of the
// generator.
std::vector<texram::Pyramid8> box_pyramids(const host::Video& v, int k) {
  std::vector<texram::Pyramid8> out;
  for (const texram::Level8& plane : video_frame(v, k)) out.push_back(texram::build_pyramid(plane));
  return out;
}

std::vector<texram::Pyramid8> zero_pyramids(const host::Video& v) {
  std::vector<texram::Pyramid8> out;
  for (const texram::Level8& plane : video_frame(v, 0)) {
    texram::Pyramid8 p = texram::build_pyramid(plane);
    for (texram::Level8& l : p) std::fill(l.texels.begin(), l.texels.end(), 0);
    out.push_back(p);
  }
  return out;
}

struct Placement {
  uint32_t base = 0;
  int drf = 0;
};

Placement placement(const host::Scene& scene, size_t m) {
  const Pipeline placed(scene, Level::kGolden, 1);
  for (const ChipMap& c : placed.chips()->programs().chips[0].maps) {
    if (c.label == scene.materials[m].name + ".video[0]") return {c.base, c.drf};
  }
  ADD_FAILURE() << "no video map on chip 0";
  return {};
}

// Feeds frames 0..frames-1 and checks each frame's chip memory: the front buffer (at the DRF's
// base) holds frame k's pyramid, the back buffer frame k - 1's (cells 0 before the first).
// `corrupt` flips a cell of the front buffer of frame 1 (the check must then fail once).
size_t check_frames(const host::Scene& scene, bool corrupt) {
  const host::Video& v = *scene.materials[0].video;
  const Placement at = placement(scene, 0);
  VideoFeed feed(v, at.base, at.drf);
  const texram::Geometry g = feed.map().geometry();
  const uint32_t stride = texram::video::VideoMap::buffer_stride(g);
  size_t failures = 0;
  for (int k = 0; k < v.frames; ++k) {
    const VideoFrameFeed fed = feed.feed(k);
    EXPECT_EQ(fed.lost_writes, 0u);
    auto state = std::make_shared<VideoState>(scene.materials.size());
    auto buffers = std::make_shared<VideoBuffers>(*feed.buffers());
    EXPECT_EQ(buffers->shown, k);
    if (corrupt && k == 1) {
      auto broken = std::make_shared<texram::TexramTexture>(
          *buffers->buffers[static_cast<size_t>(buffers->front)]);
      const texram::BankCell c = g.cell(2, 1, 1, 0);
      broken->banks[c.bank][c.address] ^= 0x10;
      buffers->buffers[static_cast<size_t>(buffers->front)] = broken;
    }
    (*state)[0] = buffers;
    const Pipeline frame(scene, Level::kGolden, 1, state.get());
    const ChipProgram& chip = frame.chips()->programs().chips[0];
    std::vector<tb::ChipMapPlacement> maps;
    for (const ChipMap& c : chip.maps) maps.push_back({{}, c.texture, c.base});
    const tb::ChipScene memory = tb::chip_scene_of(maps, texram::Clut32{});
    const uint32_t front = chip.drfs[static_cast<size_t>(at.drf - 1)].base;
    EXPECT_EQ(front, feed.map().drfs()[static_cast<size_t>(at.drf - 1)].base);
    EXPECT_EQ(front, at.base + static_cast<uint32_t>(fed.buffer) * stride);
    const uint32_t back = front == at.base ? at.base + stride : at.base;
    const size_t front_diff = differences(*memory.memory, g, front, box_pyramids(v, k));
    const size_t back_diff =
        differences(*memory.memory, g, back, k == 0 ? zero_pyramids(v) : box_pyramids(v, k - 1));
    EXPECT_EQ(back_diff, 0u) << "frame " << k << ": the back buffer";
    failures += front_diff != 0;
    if (!corrupt) {
      EXPECT_EQ(front_diff, 0u) << "frame " << k << ": the front buffer";
    }
  }
  return failures;
}

TEST(VideoRenderTest, EachFrameSeesThePyramidTheBufferingMakesVisible) {
  const fs::path dir = temp_dir("front");
  for (const bool interlaced : {false, true}) {
    for (const int planes : {1, 4}) {
      SCOPED_TRACE(fmt::format("interlaced {}, planes {}", interlaced, planes));
      const host::Scene scene = host::load_scene(write_scene(dir, generated(interlaced, planes)));
      EXPECT_EQ(check_frames(scene, false), 0u);
    }
  }
  fs::remove_all(dir);
}

TEST(VideoRenderTest, ABrokenPyramidIsCaught) {
  const fs::path dir = temp_dir("broken");
  const host::Scene scene = host::load_scene(write_scene(dir, generated(false, 4)));
  EXPECT_EQ(check_frames(scene, true), 1u);  // frame 1 only
  fs::remove_all(dir);
}

// The references agree: the MipgenStream run alone over frame k (interlaced too) writes the box
// pyramid, so "the pyramid of frame k" has one meaning.
TEST(VideoRenderTest, TheGeneratorAloneWritesTheBoxPyramid) {
  for (const bool interlaced : {false, true}) {
    host::Video v;
    v.pattern = "bars";
    v.interlaced = interlaced;
    v.planes = 4;
    v.width = 64;
    v.height = 32;
    const texram::video::VideoFormat f = video_format(v);
    const texram::video::VideoFrame frame = video_frame(v, 5);
    for (int p = 0; p < 4; ++p) {
      const texram::MipgenConfig cfg{f.log2_w, f.log2_h, interlaced, 4, p};
      texram::BankMemory memory(texram::Geometry(f.log2_w, f.log2_h, 4));
      for (const texram::CellWrite& w : texram::mipgen_frame(cfg, frame[static_cast<size_t>(p)]))
        memory.write(w);
      EXPECT_EQ(memory.read_pyramid(p), texram::build_pyramid(frame[static_cast<size_t>(p)]));
    }
  }
}

// Every pattern moves: from one frame to the next at least a third of the texels change (the bars
// scroll half a bar), and a frame is the same each time it is made.
TEST(VideoRenderTest, GeneratedFramesMove) {
  host::Video v;
  for (const int planes : {1, 4}) {
    v.planes = planes;
    for (const std::string pattern : {"bars", "rings", "noise"}) {
      v.pattern = pattern;
      const auto a = video_frame(v, 0), b = video_frame(v, 1);
      size_t changed = 0;
      for (size_t i = 0; i < a[0].texels.size(); ++i) {
        bool differs = false;
        for (size_t p = 0; p < a.size(); ++p) differs = differs || a[p].texels[i] != b[p].texels[i];
        changed += differs;
      }
      EXPECT_GT(changed, a[0].texels.size() / 3) << pattern << ", planes " << planes;
      EXPECT_EQ(a, video_frame(v, 0)) << pattern << ": deterministic";
    }
  }
}

// rtl = golden on the chip for every frame, progressive and interlaced, one and four planes.
TEST(VideoRenderTest, RtlEqualsGoldenOnTheChipsEveryFrame) {
  const fs::path dir = temp_dir("rtl");
  for (const bool interlaced : {false, true}) {
    for (const int planes : {1, 4}) {
      SCOPED_TRACE(fmt::format("interlaced {}, planes {}", interlaced, planes));
      const fs::path scene = write_scene(dir, generated(interlaced, planes, 2));
      const RenderOptions o = checked_on_a_chip(Level::kRtl, dir / "out");
      std::ostringstream log;
      VideoRenderReport rep;
      EXPECT_EQ(render_video(scene.string(), o, {0, 1}, log, &rep), 0) << log.str();
      ASSERT_EQ(rep.frames.size(), 2u);
      for (const VideoFrameReport& f : rep.frames) {
        EXPECT_EQ(f.shown[0], f.frame);
        ASSERT_TRUE(f.render.check);
        EXPECT_TRUE(f.render.check->match());
        EXPECT_GT(f.render.check->compared, 100u);
        EXPECT_GT(f.feeds[0].sampler_lost, 0u);
        EXPECT_EQ(f.feeds[0].sampler_lost, f.feeds[0].write_cycles + f.feeds[0].read_cycles);
        // The video unit at rtl left both buffers as the golden path did, and, at the same
        // rows of a page, made its accesses: a write a (bank, row) the frame touches, whatever
        // the rate, and the reads of the lines above.
        EXPECT_EQ(f.unit[0].differing, 0u);
        EXPECT_EQ(f.unit[0].writes, f.feeds[0].write_accesses);
        EXPECT_EQ(f.unit[0].reads, f.feeds[0].read_accesses);
        EXPECT_GT(f.unit[0].writes, 0u);
        if (interlaced) {
          EXPECT_GT(f.unit[0].reads, 0u);
        }
      }
      EXPECT_TRUE(fs::exists(dir / "out" / "video.frame-0001.png"));
      EXPECT_TRUE(fs::exists(dir / "out" / "video.report.json"));
      EXPECT_NE(log.str().find("host work"), std::string::npos);
      ASSERT_EQ(rep.units.size(), 1u);
      EXPECT_EQ(rep.units[0].against, "golden");
      EXPECT_TRUE(rep.units[0].match);  // the unit's rtl run = its golden run, bit for bit
    }
  }
  fs::remove_all(dir);
}

// A video is the texture DRF of a chain like any texture: after a bump map's emit DRF, before an
// environment; the chain is on the chip (its DRFs) and rtl = golden.
TEST(VideoRenderTest, AVideoInAChainWithABumpMapOrAnEnvironment) {
  const fs::path dir = temp_dir("chain");
  for (const std::string extra :
       {R"(, "bump": {"heights": {"pattern": "noise"}, "depth": 2})",
        R"(, "environment": {"map": "sphere", "size": 128}, "reflectance": 0.3)"}) {
    SCOPED_TRACE(extra);
    const fs::path scene = write_scene(dir, generated(true, 4, 1), extra);
    const RenderOptions o = checked_on_a_chip(Level::kRtl, dir / "out");
    std::ostringstream log;
    VideoRenderReport rep;
    EXPECT_EQ(render_video(scene.string(), o, {0, 0}, log, &rep), 0) << log.str();
    ASSERT_EQ(rep.frames.size(), 1u);
    EXPECT_EQ(rep.frames[0].render.chips[0], extra.find("bump") != std::string::npos
                                                 ? "screen: chip 0, DRF 1 | 2 3"
                                                 : "screen: chip 0, DRF 1 2");
    // With a bump map: the emit DRF, then the diffuse shading map, then the texture.
    EXPECT_EQ(rep.drfs[0], extra.find("bump") != std::string::npos ? 3 : 1);
    EXPECT_TRUE(rep.match());
  }
  fs::remove_all(dir);
}

// A video with a detail map (000 §9 on a §11 map): the texture DRF of the video, then its offsets
// and detail DRFs; the detail path reads the video's texels at the DRF's base, which the swap
// moves every frame. A 4 x 4 video magnified on the quad (lambda below 0 on most of it): every
// frame rtl = golden on the chip, and the frames differ from the same video without the detail.
TEST(VideoRenderTest, AVideoWithADetailMap) {
  const fs::path dir = temp_dir("detail");
  const std::string detail =
      R"(, "detail": {"map": {"pattern": "noise", "size": [32, 32], "seed": 3}, "combine": "modulate"})";
  std::vector<std::vector<ImageRgb8>> frames;
  for (const std::string& extra : {std::string(), detail}) {
    SCOPED_TRACE(extra.empty() ? "without" : "with the detail map");
    const fs::path scene = write_scene(dir, generated(false, 1, 2, 4), extra);
    const fs::path out = dir / (extra.empty() ? "plain" : "detail");
    const RenderOptions o = checked_on_a_chip(Level::kRtl, out);
    std::ostringstream log;
    VideoRenderReport rep;
    EXPECT_EQ(render_video(scene.string(), o, {0, 1}, log, &rep), 0) << log.str();
    ASSERT_EQ(rep.frames.size(), 2u);
    EXPECT_EQ(rep.frames[0].render.chips[0],
              extra.empty() ? "screen: chip 0, DRF 1" : "screen: chip 0, DRF 1 2 3");
    EXPECT_TRUE(rep.match());
    EXPECT_NE(rep.frames[0].front, rep.frames[1].front);  // the swap moved the base between
    frames.emplace_back();
    for (int f = 0; f < 2; ++f) {
      frames.back().push_back(
          read_image((out / fmt::format("video.frame-{:04d}.png", f)).string()));
    }
  }
  ASSERT_EQ(frames.size(), 2u);
  for (size_t f = 0; f < 2; ++f) {
    size_t differ = 0;
    for (size_t i = 0; i < frames[0][f].pixels.size(); ++i)
      differ += !(frames[0][f].pixels[i] == frames[1][f].pixels[i]);
    EXPECT_GT(differ, frames[0][f].pixels.size() / 20) << "frame " << f << ": the detail map shows";
  }
  fs::remove_all(dir);
}

// The unit's comparison with the golden path can fail: one cell of a buffer changed is one cell
// that differs, and so is the other buffer in front; other row accesses fail the report.
TEST(VideoRenderTest, TheUnitAgainstTheGoldenPathCatchesABrokenBuffer) {
  host::Video v;
  v.pattern = "rings";
  v.planes = 4;
  v.width = 32;
  v.height = 16;
  VideoFeed feed(v, 0, 1);
  feed.feed(0);
  const VideoUnitFeed unit = feed_video_unit(v, 0, 0, Level::kRtl, std::nullopt);
  ASSERT_EQ(unit.frames.size(), 1u);
  const std::shared_ptr<const VideoBuffers> buffers = feed.buffers();
  const VideoBuffers& golden = *buffers;
  EXPECT_EQ(differing_cells(*unit.frames[0].buffers, golden), 0u);
  auto broken = std::make_shared<VideoBuffers>(golden);
  auto texture =
      std::make_shared<texram::TexramTexture>(*broken->buffers[static_cast<size_t>(broken->front)]);
  const texram::BankCell c = texture->geometry.cell(1, 3, 2, 2);
  texture->banks[c.bank][c.address] ^= 1;
  broken->buffers[static_cast<size_t>(broken->front)] = texture;
  EXPECT_EQ(differing_cells(*unit.frames[0].buffers, *broken), 1u);
  broken->front = 1 - broken->front;
  EXPECT_EQ(differing_cells(*unit.frames[0].buffers, *broken), 2u);
  // Equal buffers from other row accesses than the golden path's fail the render too.
  VideoRenderReport rep;
  rep.frames.emplace_back().unit.push_back({unit.frames[0].cycles, unit.frames[0].writes, 0, 0,
                                            /*same_accesses=*/true});
  EXPECT_TRUE(rep.match());
  rep.frames[0].unit[0].same_accesses = false;
  EXPECT_FALSE(rep.match());
}

TEST(VideoRenderTest, AnInjectedFaultIsCaughtOnEveryFrame) {
  const fs::path dir = temp_dir("fault");
  RenderOptions o = checked_on_a_chip(Level::kGolden, dir / "out");
  o.inject_fault = 7;
  std::ostringstream log;
  VideoRenderReport rep;
  EXPECT_EQ(render_video(write_scene(dir, generated(false, 4, 2)).string(), o, {0, 1}, log, &rep),
            1);
  for (const VideoFrameReport& f : rep.frames) EXPECT_EQ(f.render.check->differing, 1u);
  EXPECT_NE(log.str().find("MISMATCH"), std::string::npos);
  fs::remove_all(dir);
}

// The refusal: what was thrown, and that the output directory was not made.
std::string refusal(const fs::path& scene, int chips, const fs::path& out) {
  RenderOptions o;
  o.chips = chips;
  o.progress = false;
  o.out_dir = out.string();
  std::ostringstream log;
  try {
    render_video(scene.string(), o, {}, log);
  } catch (const InputError& e) {
    EXPECT_FALSE(fs::exists(out)) << "written on error";
    return e.what();
  }
  return "(nothing thrown)";
}

TEST(VideoSceneTest, BadVideosAreRefusedNamingTheFileFieldAndReason) {
  const fs::path dir = temp_dir("errors");
  ImageRgb8 img(32, 32);
  for (int k = 0; k < 3; ++k) write_image((dir / fmt::format("clip-{:04d}.png", k)).string(), img);
  write_image((dir / "small-0000.png").string(), ImageRgb8(16, 16));
  write_image((dir / "small-0001.png").string(), ImageRgb8(32, 32));
  const fs::path out = dir / "out";
  // The files render (three found).
  {
    const fs::path scene = write_scene(dir, R"({"files": "clip-%04d.png", "planes": 1})");
    const host::Scene s = host::load_scene(scene.string());
    EXPECT_EQ(s.materials[0].video->frames, 3);
    EXPECT_EQ(s.materials[0].video->width, 32);
  }
  const std::string missing =
      refusal(write_scene(dir, R"({"files": "clip-%04d.png", "frames": 4})"), 1, out);
  EXPECT_NE(missing.find("materials.screen.video.files"), std::string::npos) << missing;
  EXPECT_NE(missing.find("frame 3: file not found"), std::string::npos) << missing;
  EXPECT_NE(missing.find("clip-0003.png"), std::string::npos) << missing;
  const std::string size = refusal(write_scene(dir, R"({"files": "small-%04d.png"})"), 1, out);
  EXPECT_NE(size.find("frame 1"), std::string::npos) << size;
  EXPECT_NE(size.find("is 32x32, the video 16x16"), std::string::npos) << size;
  const std::string no_chips = refusal(write_scene(dir, generated(false, 1)), 0, out);
  EXPECT_NE(no_chips.find("materials.screen.video"), std::string::npos) << no_chips;
  EXPECT_NE(no_chips.find("--chips"), std::string::npos) << no_chips;
  const std::string side = refusal(write_scene(dir, generated(false, 1, 3, 1024)), 1, out);
  EXPECT_NE(side.find("materials.screen.video.size"), std::string::npos) << side;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tmu::render
