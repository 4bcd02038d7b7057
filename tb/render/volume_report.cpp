#include "render/volume_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "texram/page_model.hpp"

namespace tmu::render {
namespace {

double ratio(uint64_t a, uint64_t b) {
  return b ? static_cast<double>(a) / static_cast<double>(b) : 0.0;
}

std::string plane_range(uint32_t begin, uint32_t end) {
  return fmt::format("{}-{}", begin, end - 1);
}

}  // namespace

std::string VolumeReport::text() const {
  const VolumeFrame& f = frame;
  std::string s = fmt::format("render {}: {}x{}, engine {}\n", scene, f.width, f.height, engine);
  const int accesses =
      volume::accesses_per_resample(format == "raw" ? volume::Mode::kRaw : volume::Mode::kValue);
  s += fmt::format(
      "  volume: {}, {} ({}), W = {}, step {} voxel\n", volume, format,
      format == "raw"
          ? fmt::format("the unit's raw mode: value and gradient, {} accesses a resample", accesses)
          : fmt::format("pre-classified: each of R, G, B, A in value mode, {} accesses "
                        "a resample of a component",
                        accesses),
      weight_bits, step);
  const host::SlabPlan& p = f.plan;
  if (p.slabs.size() > 1) {
    s += fmt::format("  chips: {} slabs along {}, ghost planes {} before and {} after each ({})\n",
                     p.slabs.size(), "xyz"[p.axis], p.ghost_before, p.ghost_after,
                     p.ghost_before ? "the gradient's i0 - 1 and i0 + 2, the value's i1 = i0 + 1"
                                    : "the value's i1 = i0 + 1");
  } else {
    s += fmt::format("  chips: 1 (the whole volume){}\n",
                     engine == "ideal" ? "; the ideal reads the whole volume, slabs are the "
                                         "hardware's"
                                       : "");
  }
  s += fmt::format("  rays: {}, {} hit the volume ({:.1f} %)", f.rays, f.rays_hit,
                   100 * ratio(f.rays_hit, f.rays));
  if (termination)
    s += fmt::format(", {} reached opacity {:.5g} (early termination)", f.rays_terminated,
                     termination->alpha);
  s += "\n";
  s += fmt::format(
      "  locations: {} set up, {} resampled ({:.1f} % saved by early termination), {} composited, "
      "in {} round{}\n",
      f.locations, f.issued, 100 * (1 - ratio(f.issued, f.locations)), f.composited, f.rounds,
      f.rounds == 1 ? "" : "s");
  const VolumeCounters& t = f.total;
  if (f.has_memory) {
    s += fmt::format(
        "  unit: {} resamples, {} accesses, {} bank reads, {} page faults, {} accesses took two "
        "periods\n",
        t.resamples, t.accesses, t.bank_reads, t.page_faults, t.slow_accesses);
    s += fmt::format(
        "    {:.3f} accesses a resample, {:.4f} page faults a resample; time at {:.0f} ns an "
        "access (two on a fault): {:.3f} ms{}\n",
        ratio(t.accesses, t.resamples), ratio(t.page_faults, t.resamples), texram::kAccessNs,
        f.unit_seconds() * 1e3, f.chips.size() > 1 ? " (the slowest chip: they work at once)" : "");
    const bool clocked = f.pieces > 0;
    if (clocked) {
      const uint64_t slowest = *std::max_element(f.chip_cycles.begin(), f.chip_cycles.end());
      uint64_t cycles = 0;
      for (uint64_t c : f.chip_cycles) cycles += c;
      s += fmt::format(
          "    clocked ({}): {} cycles in {} runs of the block, {:.4f} cycles a resample, {:.3f} "
          "ms at {:.0f} ns a cycle{}\n",
          engine, cycles, f.pieces, ratio(cycles, t.resamples), f.clocked_seconds() * 1e3,
          texram::kAccessNs,
          f.chips.size() > 1 ? fmt::format(" (the slowest chip's {} cycles)", slowest) : "");
    }
    if (f.chips.size() > 1) {
      s += fmt::format("    {:>4}  {:>9}  {:>9}  {:>10}  {:>10}  {:>11}  {:>8}  {:>9}{}\n", "chip",
                       "holds", "owns", "resamples", "accesses", "page faults", "slow", "time ms",
                       clocked ? fmt::format("  {:>10}  {:>9}", "cycles", "clocked ms") : "");
      for (size_t c = 0; c < f.chips.size(); ++c) {
        const host::Slab& sl = p.slabs[c];
        const VolumeCounters& k = f.chips[c];
        s += fmt::format(
            "    {:>4}  {:>9}  {:>9}  {:>10}  {:>10}  {:>11}  {:>8}  {:>9.3f}{}\n", c,
            plane_range(sl.begin, sl.end), plane_range(sl.own_begin, sl.own_end), k.resamples,
            k.accesses, k.page_faults, k.slow_accesses, k.seconds() * 1e3,
            clocked ? fmt::format("  {:>10}  {:>9.3f}", f.chip_cycles[c],
                                  static_cast<double>(f.chip_cycles[c]) * texram::kAccessNs * 1e-6)
                    : "");
      }
    }
  } else {
    s += fmt::format("  unit: {} resamples (the ideal: no memory model, no accesses)\n",
                     t.resamples);
  }
  if (!host_work.empty()) {
    s += "  host work (000 §13 leaves these to the host; no unit computes them):\n";
    for (const HostWork& w : host_work) s += fmt::format("    {}: {}\n", w.stage, w.reason);
  }
  s += fmt::format(
      "  wall time: ray set-up {:.3f} s, unit {:.3f} s, compositing {:.3f} s, total {:.3f} s\n",
      f.setup_s, f.unit_s, f.composite_s, total_s);
  if (check) {
    const std::optional<VolumePieceCheck>& u = check->units;
    const std::string units =
        u ? fmt::format(
                "; unit by unit: {} runs of the block, {} outputs, {} memory requests and "
                "the counters against {}",
                u->pieces, u->outputs, u->requests, u->against)
          : "";
    if (check->match()) {
      s += fmt::format(
          "  check: MATCH: {} = {}, all {} resamples bit-exact, and every chip's counters{}\n",
          engine, check->against, check->compared, units);
    } else {
      s += fmt::format("  check: MISMATCH: {} of {} resamples differ between {} and {}{}{}\n",
                       check->differing, check->compared, engine, check->against,
                       check->counters_match ? "" : "; the counters differ",
                       u && !u->match() ? fmt::format("; {} of {} runs of the block differ",
                                                      u->differing_pieces, u->pieces)
                                        : "");
      for (const std::string& d : check->first) s += "    " + d + "\n";
      if (u) {
        for (const std::string& d : u->first) s += "    " + d + "\n";
      }
    }
  }
  if (compare) {
    s += fmt::format(
        "  against ideal: PSNR {:.2f} dB, max error {:.3f}, mean {:.4f} (8-bit levels)\n",
        compare->psnr, compare->max_error, compare->mean_error);
  }
  for (const std::string& file : files) s += "  wrote " + file + "\n";
  return s;
}

std::string VolumeReport::json() const {
  const VolumeFrame& f = frame;
  nlohmann::json j;
  j["scene"] = scene;
  j["engine"] = engine;
  j["frame"] = {{"width", f.width}, {"height", f.height}};
  j["volume"] = {{"data", volume},
                 {"format", format},
                 {"components", components},
                 {"weight_bits", weight_bits},
                 {"step", step}};
  j["early_termination"] =
      termination ? nlohmann::json{{"alpha", termination->alpha}, {"segment", termination->segment}}
                  : nlohmann::json(false);
  nlohmann::json chips = nlohmann::json::array();
  for (size_t c = 0; c < f.chips.size(); ++c) {
    const host::Slab& sl = f.plan.slabs[c];
    const VolumeCounters& k = f.chips[c];
    chips.push_back({{"holds", {sl.begin, sl.end}},
                     {"rays", k.rays},
                     {"cycles", c < f.chip_cycles.size() ? f.chip_cycles[c] : 0},
                     {"owns", {sl.own_begin, sl.own_end}},
                     {"resamples", k.resamples},
                     {"accesses", k.accesses},
                     {"bank_reads", k.bank_reads},
                     {"page_faults", k.page_faults},
                     {"slow_accesses", k.slow_accesses},
                     {"seconds", k.seconds()}});
  }
  j["slabs"] = {{"axis", std::string(1, "xyz"[f.plan.axis])},
                {"ghost_before", f.plan.ghost_before},
                {"ghost_after", f.plan.ghost_after},
                {"chips", chips}};
  j["rays"] = {{"cast", f.rays}, {"hit", f.rays_hit}, {"terminated", f.rays_terminated}};
  j["locations"] = {{"set_up", f.locations},
                    {"resampled", f.issued},
                    {"composited", f.composited},
                    {"rounds", f.rounds}};
  const VolumeCounters& t = f.total;
  j["unit"] = {{"memory_model", f.has_memory},
               {"resamples", t.resamples},
               {"accesses", t.accesses},
               {"bank_reads", t.bank_reads},
               {"page_faults", t.page_faults},
               {"slow_accesses", t.slow_accesses},
               {"accesses_per_resample", ratio(t.accesses, t.resamples)},
               {"page_faults_per_resample", ratio(t.page_faults, t.resamples)},
               {"seconds", f.unit_seconds()},
               {"clocked", f.pieces > 0},
               {"runs", f.pieces},
               {"clocked_seconds", f.clocked_seconds()}};
  j["host_work"] = nlohmann::json::array();
  for (const HostWork& w : host_work)
    j["host_work"].push_back({{"stage", w.stage}, {"reason", w.reason}});
  j["wall_time"] = {
      {"setup", f.setup_s}, {"unit", f.unit_s}, {"compositing", f.composite_s}, {"total", total_s}};
  if (check) {
    j["check"] = {{"against", check->against},     {"compared", check->compared},
                  {"differing", check->differing}, {"counters_match", check->counters_match},
                  {"first", check->first},         {"match", check->match()}};
    if (check->units) {
      const VolumePieceCheck& u = *check->units;
      j["check"]["units"] = {{"against", u.against},
                             {"runs", u.pieces},
                             {"outputs", u.outputs},
                             {"requests", u.requests},
                             {"differing_runs", u.differing_pieces},
                             {"first", u.first}};
    }
  }
  if (compare) {
    j["compare_ideal"] = {
        {"psnr", std::isinf(compare->psnr) ? nlohmann::json("inf") : nlohmann::json(compare->psnr)},
        {"max_error", compare->max_error},
        {"mean_error", compare->mean_error}};
  }
  j["files"] = files;
  return j.dump(2) + "\n";
}

}  // namespace tmu::render
