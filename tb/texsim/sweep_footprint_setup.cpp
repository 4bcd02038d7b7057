#include "texsim/sweep_footprint_setup.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <sstream>
#include <vector>

#include "common/error.hpp"
#include "footprint/footprint.hpp"
#include "footprint/footprint_ideal.hpp"
#include "texsim/sweep_support.hpp"

namespace tmu::texsim {
namespace {

std::vector<footprint::Widths> parse_setup_widths(const std::string& text) {
  std::vector<footprint::Widths> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ';');) {
    footprint::Widths w;
    if (std::sscanf(item.c_str(), "%d,%d,%d", &w.deriv_bits, &w.table_bits, &w.log_frac) != 3 ||
        w.deriv_bits < 6 || w.deriv_bits > 24 || w.table_bits < 1 || w.table_bits > 10 ||
        w.log_frac < 1 || w.log_frac > 12) {
      throw InputError("--settings", "",
                       "'" + item + "' is not D,T,F with D 6..24, T 1..10, F 1..12");
    }
    out.push_back(w);
  }
  if (out.empty()) throw InputError("--settings", "", "no settings");
  return out;
}

// Random footprints: lengths 2^-3 .. 2^12 texels, ratios 1 .. 64, any angle, skewed up to
// about 25 degrees from a rectangle; on the port grid (what the unit receives).
std::vector<footprint::Request> random_footprints(int count) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi), ratio_log(0, 6),
      length_log(-3, 12), skew(-0.4, 0.4);
  std::vector<footprint::Request> out;
  const auto raw = [](double x) { return static_cast<int32_t>(std::lround(x * 256)); };
  for (int i = 0; i < count; ++i) {
    const double a = angle(rng), len = std::exp2(length_log(rng)),
                 ratio = std::exp2(ratio_log(rng)), s = skew(rng);
    const double l2 = len / ratio;
    out.push_back({0, 0, raw(len * std::cos(a)), raw(len * std::sin(a)), raw(-l2 * std::sin(a + s)),
                   raw(l2 * std::cos(a + s)), 0});
  }
  return out;
}

// The setup's RTL at `w` against golden: tmu_footprint_setup on its own where the build
// verilated it (the default widths), else inside tmu_footprint (the footprint block's width
// variants); neither has an Icarus level.
std::string check_setup_rtl(const footprint::Widths& w, bool* simulated) {
  constexpr size_t kItems = 20000;
  tb::BlockOptions o;
  o.fp_widths = w;
  RtlCheck check = check_rtl("footprint_setup", o, kItems);
  std::string where;
  if (check.simulator.empty()) {
    check = check_rtl("footprint", o, kItems);
    where = " (in tmu_footprint)";
  }
  *simulated = check.simulated();
  return check.simulator.empty() ? check.verdict() : check.verdict() + where;
}

}  // namespace

void sweep_footprint_setup(const FootprintSetupSweepArgs& args) {
  const std::vector<footprint::Widths> settings = parse_setup_widths(args.settings);
  const std::vector<footprint::Request> footprints = random_footprints(args.count);
  footprint::IdealConfig ideal;
  ideal.log2_max_probes = 4;
  std::vector<footprint::IdealPlan> exact;
  for (const footprint::Request& r : footprints) {
    exact.push_back(footprint::ideal_plan({r.r1u / 256.0, r.r1v / 256.0},
                                          {r.r2u / 256.0, r.r2v / 256.0}, ideal));
  }
  fmt::print(
      "footprint setup: {} random footprints (ratio 1..64, lengths 1/8..4096 texels), "
      "N max 16, q rule heights; lambda error in levels where N agrees\n",
      footprints.size());
  SweepTable table({"D,T,F",
                    {"lambda max err", Mark::kModel},
                    {"lambda mean err", Mark::kModel},
                    {"N differs %", Mark::kModel},
                    {"golden M setups/s", Mark::kModel},
                    {"rtl = golden", Mark::kSim},
                    {"cells", Mark::kSynth},
                    {"logic", Mark::kSynth},
                    {"depth", Mark::kSynth}});
  for (const footprint::Widths& w : settings) {
    footprint::Config c;
    c.log2_max_probes = 4;
    c.widths = w;
    double worst = 0, sum = 0;
    size_t agree = 0, differ = 0;
    const auto start = std::chrono::steady_clock::now();
    std::vector<footprint::Plan> plans;
    plans.reserve(footprints.size());
    for (const footprint::Request& r : footprints) plans.push_back(footprint::plan(r, c));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (size_t i = 0; i < footprints.size(); ++i) {
      if (!std::isfinite(exact[i].lambda)) continue;
      if (plans[i].log2_n != exact[i].log2_n) {
        ++differ;
        continue;
      }
      const double e = std::abs(plans[i].lambda / 256.0 - std::max(exact[i].lambda, -32.0));
      worst = std::max(worst, e);
      sum += e;
      ++agree;
    }
    const SynthFigures synth =
        args.synth ? synthesize("tmu_footprint_setup", {{"DerivBits", w.deriv_bits},
                                                        {"TableBits", w.table_bits},
                                                        {"LogFracBits", w.log_frac}})
                   : SynthFigures{};
    bool simulated = false;
    const std::string verdict = check_setup_rtl(w, &simulated);
    table.add({fmt::format("{},{},{}", w.deriv_bits, w.table_bits, w.log_frac),
               fmt::format("{:.4f}", worst),
               fmt::format("{:.5f}", sum / static_cast<double>(std::max<size_t>(agree, 1))),
               fmt::format("{:.3f}", 100.0 * static_cast<double>(differ) /
                                         static_cast<double>(agree + differ)),
               fmt::format("{:.1f}", static_cast<double>(footprints.size()) / seconds / 1e6),
               verdict, synth_cell(synth.cells, simulated), synth_cell(synth.logic, simulated),
               synth_cell(synth.depth, simulated)});
    fmt::print("{}\n", table.last_row_text());
  }
  table.print(args.markdown);
}

}  // namespace tmu::texsim
