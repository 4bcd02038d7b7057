#include "render/report.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

namespace tmu::render {
namespace {

uint64_t sum_counter(const std::vector<UnitReport>& units, const std::string& kind,
                     const std::string& name) {
  uint64_t n = 0;
  for (const UnitReport& u : units) {
    if (u.kind == kind) n += tb::counter_value(u.counters, name).value_or(0);
  }
  return n;
}

// The TEXRAM's banks: read by the trilinear units, the footprint units' own and the chips.
uint64_t memory_counter(const std::vector<UnitReport>& units, const std::string& name) {
  return sum_counter(units, "trilinear", name) + sum_counter(units, "footprint", name) +
         sum_counter(units, "texram_chip", name);
}

uint64_t footprint_transactions(const std::vector<UnitReport>& units) {
  uint64_t n = 0;
  for (const UnitReport& u : units) n += u.kind == "footprint" ? u.transactions : 0;
  return n;
}

double per(uint64_t a, uint64_t b) {
  return b ? static_cast<double>(a) / static_cast<double>(b) : 0.0;
}

}  // namespace

uint64_t RenderReport::unit_cycles() const {
  uint64_t n = 0;
  for (const UnitReport& u : units) n += u.cycles;
  return n;
}

std::string RenderReport::text() const {
  std::string s = fmt::format("render {}: {}x{}", scene, band.frame_width, band.frame_height);
  if (band.count > 1)
    s += fmt::format(", band {}/{} (rows {}-{})", band.index, band.count, band.row_begin,
                     band.row_end);
  s += fmt::format(", engine {}\n", engine);
  s += fmt::format("  front end: {} triangles, {} fragments, {} visible of {} pixels ({:.1f} %)\n",
                   raster.triangles, raster.fragments, raster.visible, pixels,
                   100 * per(raster.visible, pixels));
  s += "  units built:\n";
  s += fmt::format("    {:<32} {:>12} {:>12}  {:>10} {:>9}\n", "unit", "transactions", "cycles",
                   "cycles/txn", "seconds");
  for (const UnitReport& u : units) {
    s += fmt::format("    {:<32} {:>12} {:>12}{} {:>10.2f} {:>9.3f}\n", u.name, u.transactions,
                     u.cycles, u.predicted ? "*" : " ", per(u.cycles, u.transactions), u.seconds);
  }
  if (units.empty()) s += "    (none: the ideal engine runs no hardware units)\n";
  for (const UnitReport& u : units) {
    if (u.predicted) {
      s += "    * predicted by the page model (golden is untimed): one period per access, two on a "
           "fault\n";
      break;
    }
  }
  if (!chips.empty()) {
    s += "  TEXRAM chips (--chips): the materials' maps\n";
    for (const std::string& c : chips) s += "    " + c + "\n";
  }
  if (!host_work.empty()) {
    s += "  host work (stages of the documents' pipelines computed on the host, not in a unit):\n";
    for (const HostWork& w : host_work) s += fmt::format("    {}: {}\n", w.stage, w.reason);
  }
  s += fmt::format("  cycles per pixel: {:.2f} ({} unit cycles, {} pixels)\n",
                   per(unit_cycles(), pixels), unit_cycles(), pixels);
  const uint64_t accesses = memory_counter(units, "accesses");
  if (accesses) {
    s += fmt::format(
        "  memory: {} accesses, {} bank reads, {} page faults, {} accesses took two periods\n",
        accesses, memory_counter(units, "bank_reads"), memory_counter(units, "page_faults"),
        memory_counter(units, "slow_accesses"));
  }
  if (const uint64_t fragments = footprint_transactions(units)) {
    const uint64_t probes = sum_counter(units, "footprint", "probes");
    s += fmt::format(
        "  footprint assembly: {} probes for {} fragments, {:.2f} probes per fragment\n", probes,
        fragments, per(probes, fragments));
  }
  const uint64_t hits = sum_counter(units, "ccc_cache_bilinear", "hits"),
                 misses = sum_counter(units, "ccc_cache_bilinear", "misses");
  if (hits + misses) {
    s +=
        fmt::format("  low-cost unit cache: {} hits, {} misses, {} prefetches, hit rate {:.1f} %\n",
                    hits, misses, sum_counter(units, "ccc_cache_bilinear", "prefetches"),
                    100 * per(hits, hits + misses));
  }
  const uint64_t map_hits = sum_counter(units, "deflect", "hits"),
                 map_misses = sum_counter(units, "deflect", "misses");
  if (map_hits + map_misses) {
    s += fmt::format(
        "  deflection cache (MBR): {} hits, {} misses, {} bypasses (z = 0), hit rate {:.1f} %, "
        "{} stall cycles\n",
        map_hits, map_misses, sum_counter(units, "deflect", "bypasses"),
        100 * per(map_hits, map_hits + map_misses), sum_counter(units, "deflect", "stall_cycles"));
  }
  s += fmt::format(
      "  wall time: front end {:.3f} s, textures {:.3f} s, units {:.3f} s, total {:.3f} s\n",
      front_end_s, textures_s, units_s, total_s);
  if (check) {
    if (check->match()) {
      s += fmt::format(
          "  check: MATCH: {} = {}, all {} fragments bit-exact, and all {} units' outputs, memory "
          "requests and counters\n",
          engine, check->against, check->compared, check->units_compared);
    } else {
      s += fmt::format(
          "  check: MISMATCH: {} of {} fragments differ between {} and {}; {} of {} units "
          "differ\n",
          check->differing, check->compared, engine, check->against, check->unit_differences.size(),
          check->units_compared);
      for (const std::string& d : check->unit_differences) s += "    unit " + d + "\n";
      for (const Mismatch& m : check->first) {
        s += fmt::format("    pixel ({}, {}): expected 0x{:08X}, got 0x{:08X}; fragment {}\n", m.x,
                         m.y, m.expected, m.got, m.fragment);
      }
      if (!check->waveform.empty()) s += "    waveform: " + check->waveform + "\n";
    }
  }
  if (compare) {
    s += fmt::format(
        "  against ideal: PSNR {:.2f} dB, max error {:.3f}, mean {:.4f} (8-bit levels)\n",
        compare->psnr, compare->max_error, compare->mean_error);
  }
  for (const std::string& f : files) s += "  wrote " + f + "\n";
  return s;
}

std::string RenderReport::json() const {
  nlohmann::json j;
  j["scene"] = scene;
  j["engine"] = engine;
  j["frame"] = {{"width", band.frame_width}, {"height", band.frame_height}};
  j["band"] = {
      {"index", band.index}, {"count", band.count}, {"rows", {band.row_begin, band.row_end}}};
  j["pixels"] = pixels;
  j["front_end"] = {{"triangles", raster.triangles},
                    {"fragments", raster.fragments},
                    {"visible", raster.visible}};
  for (const UnitReport& u : units) {
    nlohmann::json c;
    for (const auto& [k, v] : u.counters) c[k] = v;
    j["units"].push_back({{"name", u.name},
                          {"kind", u.kind},
                          {"transactions", u.transactions},
                          {"cycles", u.cycles},
                          {"cycles_predicted", u.predicted},
                          {"seconds", u.seconds},
                          {"counters", c}});
  }
  if (units.empty()) j["units"] = nlohmann::json::array();
  j["chips"] = chips;
  j["host_work"] = nlohmann::json::array();
  for (const HostWork& w : host_work)
    j["host_work"].push_back({{"stage", w.stage}, {"reason", w.reason}});
  j["cycles"] = unit_cycles();
  j["cycles_per_pixel"] = per(unit_cycles(), pixels);
  j["memory"] = {{"accesses", memory_counter(units, "accesses")},
                 {"bank_reads", memory_counter(units, "bank_reads")},
                 {"page_faults", memory_counter(units, "page_faults")},
                 {"slow_accesses", memory_counter(units, "slow_accesses")}};
  const uint64_t fp_fragments = footprint_transactions(units),
                 fp_probes = sum_counter(units, "footprint", "probes");
  j["footprint"] = {{"fragments", fp_fragments},
                    {"probes", fp_probes},
                    {"probes_per_fragment", per(fp_probes, fp_fragments)}};
  const uint64_t hits = sum_counter(units, "ccc_cache_bilinear", "hits"),
                 misses = sum_counter(units, "ccc_cache_bilinear", "misses");
  j["cache"] = {{"hits", hits},
                {"misses", misses},
                {"prefetches", sum_counter(units, "ccc_cache_bilinear", "prefetches")},
                {"hit_rate", per(hits, hits + misses)}};
  j["wall_time"] = {
      {"front_end", front_end_s}, {"textures", textures_s}, {"units", units_s}, {"total", total_s}};
  if (check) {
    j["check"] = {{"against", check->against},
                  {"compared", check->compared},
                  {"differing", check->differing},
                  {"units_compared", check->units_compared},
                  {"unit_differences", check->unit_differences},
                  {"match", check->match()}};
    for (const Mismatch& m : check->first) {
      j["check"]["first"].push_back({{"x", m.x},
                                     {"y", m.y},
                                     {"expected", m.expected},
                                     {"got", m.got},
                                     {"fragment", m.fragment}});
    }
    if (!check->waveform.empty()) j["check"]["waveform"] = check->waveform;
  }
  if (compare) {
    j["compare_ideal"] = {{"psnr", compare->psnr},
                          {"max_error", compare->max_error},
                          {"mean_error", compare->mean_error}};
  }
  j["files"] = files;
  return j.dump(2) + "\n";
}

}  // namespace tmu::render
