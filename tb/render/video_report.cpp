// The report of a video render (render/video_render.hpp): per frame the video frame each render
// sees, the swap that showed it, what the video's writes cost the sampler, the chip's cycles and
// the check's verdict.
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "render/video_render.hpp"

namespace tmu::render {
namespace {

double percent(uint64_t a, uint64_t b) {
  return b ? 100.0 * static_cast<double>(a) / static_cast<double>(b) : 0.0;
}

uint64_t chip_cycles(const RenderReport& r) {
  uint64_t n = 0;
  for (const UnitReport& u : r.units) n += u.kind == "texram_chip" ? u.cycles : 0;
  return n;
}

std::string verdict(const RenderReport& r) {
  if (!r.check) return "-";
  return r.check->match() ? "MATCH" : fmt::format("MISMATCH ({})", r.check->differing);
}

// "2731 writes =", or "2731 writes, 3 !=" (the unit's buffers against the golden path's cells),
// or "2730 writes, accesses !=" (its row accesses not the golden path's).
std::string unit_cell(const VideoFrameReport::Unit& u) {
  if (u.differing) return fmt::format("{} writes, {} !=", u.writes, u.differing);
  if (!u.same_accesses) return fmt::format("{} writes, accesses !=", u.writes);
  return fmt::format("{} writes =", u.writes);
}

}  // namespace

bool VideoRenderReport::match() const {
  for (const VideoFrameReport& f : frames) {
    if (f.render.check && !f.render.check->match()) return false;
    for (const VideoFrameReport::Unit& u : f.unit) {
      if (u.differing != 0 || !u.same_accesses) return false;
    }
  }
  for (const UnitRunReport& u : units) {
    if (!u.match) return false;
  }
  return true;
}

std::string VideoRenderReport::text() const {
  std::string s = fmt::format("render video {}: engine {}, {} chip{}, frames {}..{}\n", scene,
                              engine, chips, chips == 1 ? "" : "s", first, last);
  for (size_t i = 0; i < videos.size(); ++i) {
    s += fmt::format("  video {}; buffers at cell {} of every bank, DRF {}\n", videos[i], bases[i],
                     drfs[i]);
  }
  if (!frames.empty() && !frames.front().render.chips.empty()) {
    s += "  chips:\n";
    for (const std::string& line : frames.front().render.chips) s += "    " + line + "\n";
  }
  s += "  the time: frame f's pixel pass starts once video frame f has been fed (at the video's "
       "rate, the sampler\n  wanting every cycle) and swapped in; the other buffer holds frame "
       "f - 1 (cycles of 30 ns)\n";
  // One row a frame and video: frame, video, shown, buffer, cycles (first item, last item,
  // swap, fed), sampler lost (cycles, %), writes, reads, mipgen, chip cycles, check.
  constexpr auto kRow =
      "  {:>5} {:<8} {:>5} {:>6} {:>10} {:>10} {:>10} {:>9} {:>6} {:>7} {:>6} {:>5} {:>17} {:>11}  "
      "{}\n";
  s += fmt::format(kRow, "frame", "video", "shown", "buffer", "first item", "last item", "swap",
                   "fed", "lost", "lost %", "writes", "reads", "unit = golden", "chip cycles",
                   "check");
  for (const VideoFrameReport& f : frames) {
    for (size_t i = 0; i < f.feeds.size(); ++i) {
      const VideoFrameFeed& v = f.feeds[i];
      s += fmt::format(kRow, f.frame, videos[i].substr(0, videos[i].find(':')), f.shown[i],
                       f.front[i], v.begin_cycle, v.end_cycle, v.swap_cycle, v.cycles,
                       v.sampler_lost,
                       fmt::format("{:.3f}", percent(v.sampler_lost, v.sampler_wanted)),
                       v.write_accesses, v.read_accesses, unit_cell(f.unit[i]),
                       i == 0 ? chip_cycles(f.render) : 0, i == 0 ? verdict(f.render) : "");
    }
  }
  s += fmt::format(
      "  (first item .. reads: the golden VideoMap at the chip's 512-cell rows, the frame's items "
      "at the video's rate;\n  fed: the cycles the frame took until its swap; lost: the "
      "sampler's cycles the writes and reads took,\n  faults included; writes, reads: row-buffer "
      "accesses; unit = golden: the video unit at {} (rows of a page,\n  its rate below), its "
      "row writes; its writes and reads, and its two buffers at the swap cell for cell, equal\n"
      "  to the golden path's)\n",
      engine);
  for (size_t i = 0; i < units.size(); ++i) {
    const UnitRunReport& u = units[i];
    s += fmt::format("  video unit of {} at {}: {} items, {} memory cycles (a texel in {}){}\n",
                     videos[i].substr(0, videos[i].find(':')), engine, u.items, u.cycles,
                     u.cycles_per_item,
                     u.against.empty() ? ""
                     : u.match ? fmt::format("; check: MATCH against {} (every output, request "
                                             "and counter)",
                                             u.against)
                               : fmt::format("; check: MISMATCH against {}", u.against));
  }
  if (!frames.empty() && !frames.front().render.host_work.empty()) {
    s += "  host work:\n";
    for (const HostWork& w : frames.front().render.host_work)
      s += fmt::format("    {}: {}\n", w.stage, w.reason);
  }
  uint64_t compared = 0;
  bool checked = false;
  for (const VideoFrameReport& f : frames) {
    if (!f.render.check) continue;
    checked = true;
    compared += f.render.check->compared;
  }
  s += fmt::format(
      "  wrote {}/video.frame-NNNN.png (frames {}..{}), video.contact.png, each frame's "
      "video.frame-NNNN.report.{{txt,json}}\n  and video.report.{{txt,json}}\n",
      out_dir, first, last);
  uint64_t unit_writes = 0, unit_differing = 0, other_accesses = 0;
  for (const VideoFrameReport& f : frames) {
    for (const VideoFrameReport::Unit& u : f.unit) {
      unit_writes += u.writes;
      unit_differing += u.differing;
      other_accesses += !u.same_accesses;
    }
  }
  if (unit_writes > 0 || unit_differing > 0 || other_accesses > 0) {
    s +=
        fmt::format("  video unit = golden path on every frame: {} row writes, {}\n", unit_writes,
                    unit_differing ? fmt::format("MISMATCH: {} cells differ", unit_differing)
                    : other_accesses
                        ? fmt::format("MISMATCH: other row accesses in {} frames", other_accesses)
                        : "MATCH: both buffers and the front cell for cell, the same row accesses");
  }
  if (checked || !match()) {
    s += match()
             ? fmt::format(
                   "  check: MATCH: {} = {} on every frame ({} frames, {} fragments "
                   "bit-exact, and every unit's outputs, requests and counters)\n",
                   engine, frames.front().render.check->against, frames.size(), compared)
             : "  check: MISMATCH: see the frames above and their video.frame-NNNN.report.txt\n";
  }
  return s;
}

std::string VideoRenderReport::json() const {
  nlohmann::json j;
  j["scene"] = scene;
  j["engine"] = engine;
  j["chips"] = chips;
  j["frames_rendered"] = {first, last};
  j["videos"] = nlohmann::json::array();
  for (size_t i = 0; i < videos.size(); ++i) {
    j["videos"].push_back({{"video", videos[i]}, {"base", bases[i]}, {"drf", drfs[i]}});
    if (i < units.size()) {
      j["videos"][i]["unit"] = {{"items", units[i].items},
                                {"cycles", units[i].cycles},
                                {"cycles_per_item", units[i].cycles_per_item},
                                {"check_against", units[i].against},
                                {"match", units[i].match}};
    }
  }
  j["frames"] = nlohmann::json::array();
  for (const VideoFrameReport& f : frames) {
    nlohmann::json fj;
    fj["frame"] = f.frame;
    fj["videos"] = nlohmann::json::array();
    for (size_t i = 0; i < f.feeds.size(); ++i) {
      const VideoFrameFeed& v = f.feeds[i];
      fj["videos"].push_back({{"shown", f.shown[i]},
                              {"front_buffer", f.front[i]},
                              {"written_to", v.buffer},
                              {"tag", v.tag},
                              {"first_item_cycle", v.begin_cycle},
                              {"last_item_cycle", v.end_cycle},
                              {"swap_cycle", v.swap_cycle},
                              {"cycles_fed", v.cycles},
                              {"sampler_wanted", v.sampler_wanted},
                              {"sampler_lost", v.sampler_lost},
                              {"write_accesses", v.write_accesses},
                              {"write_cycles", v.write_cycles},
                              {"page_faults", v.page_faults},
                              {"read_accesses", v.read_accesses},
                              {"read_cycles", v.read_cycles},
                              {"lost_writes", v.lost_writes},
                              {"max_write_latency", v.max_latency}});
    }
    for (size_t i = 0; i < f.unit.size(); ++i) {
      const VideoFrameReport::Unit& u = f.unit[i];
      fj["videos"][i]["unit"] = {{"engine", engine},
                                 {"cycles", u.cycles},
                                 {"writes", u.writes},
                                 {"reads", u.reads},
                                 {"differing", u.differing},
                                 {"same_accesses", u.same_accesses},
                                 {"match", u.differing == 0 && u.same_accesses}};
    }
    fj["chip_cycles"] = chip_cycles(f.render);
    fj["files"] = f.render.files;
    if (f.render.check) {
      fj["check"] = {{"against", f.render.check->against},
                     {"compared", f.render.check->compared},
                     {"differing", f.render.check->differing},
                     {"unit_differences", f.render.check->unit_differences},
                     {"match", f.render.check->match()}};
    }
    j["frames"].push_back(fj);
  }
  j["host_work"] = nlohmann::json::array();
  if (!frames.empty()) {
    for (const HostWork& w : frames.front().render.host_work)
      j["host_work"].push_back({{"stage", w.stage}, {"reason", w.reason}});
  }
  j["match"] = match();
  return j.dump(2) + "\n";
}

}  // namespace tmu::render
