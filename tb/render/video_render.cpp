#include "render/video_render.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <ostream>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "render/chip_stage.hpp"
#include "render/contact_sheet.hpp"
#include "render/pipeline.hpp"
#include "render/video_unit_feed.hpp"

namespace tmu::render {
namespace {

std::string describe(const host::Material& m) {
  const host::Video& v = *m.video;
  const std::string source =
      v.source == host::Video::Source::kGenerated ? "generated " + v.pattern : "files " + v.files;
  return fmt::format("{}: {}x{} {}, {}, {} plane{}, {} fps, {} frames", m.name, v.width, v.height,
                     source, v.interlaced ? "interlaced" : "progressive", v.planes,
                     v.planes == 1 ? "" : "s", v.fps, v.frames);
}

// Where the chips put video material m's buffer 0, and its DRF.
std::pair<uint32_t, int> video_placement(const host::Scene& scene, const ChipStage& chips,
                                         size_t m) {
  const MaterialProgram& p = chips.programs().materials[m];
  const std::string label = scene.materials[m].name + ".video[0]";
  for (const ChipMap& c : chips.programs().chips.at(static_cast<size_t>(p.chip)).maps) {
    if (c.label == label) return {c.base, c.drf};
  }
  throw std::logic_error("render_video: no chip map " + label);
}

}  // namespace

bool is_video_scene(const std::string& scene_path) {
  const host::Scene scene = host::load_scene(scene_path);
  for (const host::Material& m : scene.materials) {
    if (m.video) return true;
  }
  return false;
}

int render_video(const std::string& scene_path, const RenderOptions& o, FrameRange range,
                 std::ostream& log, VideoRenderReport* report_out) {
  const host::Scene scene = host::load_scene(scene_path);
  std::vector<size_t> videos;
  int frames = 0;
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    if (!scene.materials[m].video) continue;
    const int n = scene.materials[m].video->frames;
    frames = videos.empty() ? n : std::min(frames, n);  // the scene's: its shortest video's
    videos.push_back(m);
  }
  if (videos.empty()) throw InputError(scene_path, "", "no material has a video");
  const std::string first_video = "materials." + scene.materials[videos[0]].name + ".video";
  // Everything refused before anything is written.
  if (o.chips <= 0) {
    throw InputError(scene_path, first_video,
                     "the video port writes a TEXRAM chip's memory, and only the chip samples a "
                     "video map: render with --chips N");
  }
  if (o.level == Level::kIdeal || (o.check && *o.check == Level::kIdeal) || o.compare_ideal)
    throw InputError(scene_path, first_video, "a video map renders at golden, hls or rtl");
  if (o.tiles > 1 || !o.save_trace.empty() || !o.replay_trace.empty())
    throw InputError(scene_path, first_video,
                     "--tile, --save-trace and --replay are for one frame");
  if (range.last < 0) range.last = frames - 1;
  if (range.first > range.last || range.last >= frames) {
    throw InputError("--frames", "",
                     fmt::format("frames {}..{} of a video of {} frames (0..{})", range.first,
                                 range.last, frames, frames - 1));
  }

  VideoRenderReport rep;
  rep.scene = scene_path;
  rep.engine = std::string(name(o.level));
  rep.chips = o.chips;
  rep.first = range.first;
  rep.last = range.last;
  rep.out_dir = o.out_dir;
  // The chips' placement (the same every frame: it depends on sizes only) gives each video's base
  // and DRF, which the VideoMap's swaps then write.
  int code = 0;
  std::vector<VideoFeed> feeds;
  // Per video: the video unit at the engine over every frame.
  std::vector<VideoUnitFeed> units;
  {
    const Pipeline placed(scene, Level::kGolden, o.chips);
    for (size_t m : videos) {
      const auto [base, drf] = video_placement(scene, *placed.chips(), m);
      feeds.emplace_back(*scene.materials[m].video, base, drf);
      rep.videos.push_back(describe(scene.materials[m]));
      rep.bases.push_back(base);
      rep.drfs.push_back(drf);
      try {
        units.push_back(
            feed_video_unit(*scene.materials[m].video, base, range.last, o.level, o.check));
      } catch (const std::runtime_error& e) {  // a format the unit cannot take (none of a scene's)
        throw InputError(scene_path, "materials." + scene.materials[m].name + ".video", e.what());
      }
      const VideoUnitFeed& u = units.back();
      rep.units.push_back(
          {u.items, u.cycles, u.cycles_per_item, u.check_level, u.check ? u.check->match() : true});
      if (!rep.units.back().match) code = 1;
    }
  }
  std::filesystem::create_directories(o.out_dir);

  for (int f = 0; f <= range.last; ++f) {
    VideoFrameReport fr;
    fr.frame = f;
    auto state = std::make_shared<VideoState>(scene.materials.size());
    for (size_t i = 0; i < videos.size(); ++i) {
      try {
        fr.feeds.push_back(feeds[i].feed(f));
      } catch (const std::logic_error& e) {  // a rate the memory cannot keep up with
        throw InputError(scene_path, "materials." + scene.materials[videos[i]].name + ".video.fps",
                         e.what());
      }
      // The chip samples what the video unit wrote; the golden path must have written the same.
      const VideoUnitFrame& u = units[i].frames[static_cast<size_t>(f)];
      (*state)[videos[i]] = u.buffers;
      const VideoFrameFeed& golden = fr.feeds.back();
      fr.unit.push_back({u.cycles, u.writes, u.reads,
                         differing_cells(*u.buffers, *feeds[i].buffers()),
                         u.writes == golden.write_accesses && u.reads == golden.read_accesses});
      if (fr.unit.back().differing != 0 || !fr.unit.back().same_accesses) code = 1;
      fr.shown.push_back((*state)[videos[i]]->shown);
      fr.front.push_back((*state)[videos[i]]->front);
    }
    if (f < range.first) continue;
    // The chip's DRF reads the front buffer at the base the VideoMap's swap wrote.
    {
      const Pipeline frame(scene, Level::kGolden, o.chips, state.get());
      for (size_t i = 0; i < videos.size(); ++i) {
        const MaterialProgram& p = frame.chips()->programs().materials[videos[i]];
        const auto& drfs = frame.chips()->programs().chips[static_cast<size_t>(p.chip)].drfs;
        const auto d = static_cast<size_t>(rep.drfs[i] - 1);
        if (drfs[d].base != feeds[i].map().drfs()[d].base)
          throw std::logic_error("render_video: the chip's DRF base is not the swap's");
      }
    }
    RenderOptions one = o;
    one.video = state;
    one.stem = fmt::format("video.frame-{:04d}", f);
    std::ostringstream frame_log;
    if (render_scene(scene_path, one, frame_log, &fr.render) != 0) code = 1;
    rep.frames.push_back(std::move(fr));
  }

  const std::filesystem::path dir(o.out_dir);
  // The contact sheet from the frames as written (PNG is lossless; render_scene keeps no image).
  std::vector<ImageRgb8> pictures;
  for (int f = range.first; f <= range.last; ++f)
    pictures.push_back(read_image((dir / fmt::format("video.frame-{:04d}.png", f)).string()));
  write_image((dir / "video.contact.png").string(), contact_sheet(pictures));
  write_file_atomically((dir / "video.report.json").string(), rep.json());
  const std::string text = rep.text();
  write_file_atomically((dir / "video.report.txt").string(), text);
  log << text;
  if (report_out) *report_out = std::move(rep);
  return code;
}

}  // namespace tmu::render
