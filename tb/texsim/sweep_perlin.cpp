#include "texsim/sweep_perlin.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <random>
#include <sstream>
#include <tuple>

#include "common/error.hpp"
#include "common/image.hpp"
#include "perlin/materials.hpp"
#include "perlin/materials_ideal.hpp"
#include "perlin/noise.hpp"
#include "perlin/noise_ideal.hpp"
#include "render/material_config.hpp"
#include "scene/scene.hpp"
#include "texsim/sweep_support.hpp"

namespace tmu::texsim {
namespace {

constexpr int64_t kOne = int64_t{1} << perlin::kCoordFracBits;

std::vector<perlin::NoiseConfig> parse_noise_settings(const std::string& text) {
  std::vector<perlin::NoiseConfig> out;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ';')) {
    perlin::NoiseConfig c;
    char c1 = 0, c2 = 0, c3 = 0;
    std::stringstream one(item);
    if (!(one >> c.frac_bits >> c1 >> c.fade_index_bits >> c2 >> c.fade_bits >> c3 >>
          c.lerp_extra_bits) ||
        c1 != ',' || c2 != ',' || c3 != ',' || !(one >> std::ws).eof()) {
      throw InputError("--settings", item, "expected F,S,B,X (four integers)");
    }
    try {
      perlin::check(c);
    } catch (const std::invalid_argument& e) {
      throw InputError("--settings", item, e.what());
    }
    out.push_back(c);
  }
  if (out.empty()) throw InputError("--settings", "", "no setting given");
  return out;
}

struct NamedMaterial {
  std::string name;
  perlin::MaterialRegs regs;
  perlin::ColourTables tables;
};

std::vector<NamedMaterial> scene_materials(const std::string& path) {
  const host::Scene scene = host::load_scene(path);
  std::vector<NamedMaterial> out;
  for (const host::Material& m : scene.materials) {
    if (!m.procedural) continue;
    out.push_back({m.name, render::material_registers(*m.procedural),
                   render::material_tables(*m.procedural)});
  }
  if (out.empty()) throw InputError(path, "materials", "no procedural material");
  return out;
}

Rgb8 rgb(uint32_t c) {
  return {static_cast<uint8_t>(c >> 16), static_cast<uint8_t>(c >> 8), static_cast<uint8_t>(c)};
}

// The slice u in [-2, 2), v in [-0.5, 3.5) (fire's flame rises from v = 0), w = 0.37, on
// SolidCoord's grid so that both models read the same coordinates.
int64_t slice_u(int x, int n) { return (int64_t{4} * x * kOne) / n - 2 * kOne; }
int64_t slice_v(int y, int n) { return (int64_t{4} * (n - 1 - y) * kOne) / n - kOne / 2; }
constexpr int64_t kSliceW = 1515;  // 0.37 units

// A run's throughput: clocks from its first output to its last, per output after the first.
std::string cycles_per_output(const tb::RunResult& run) {
  const auto& at = run.output_cycles;
  if (at.size() < 2) return "-";
  return fmt::format(
      "{:.2f}", static_cast<double>(at.back() - at.front()) / static_cast<double>(at.size() - 1));
}

}  // namespace

void sweep_perlin(const PerlinSweepArgs& args) {
  const std::vector<perlin::NoiseConfig> settings = parse_noise_settings(args.settings);
  const std::string scene =
      args.scene.empty() ? std::string(TMU_SOURCE_DIR) + "/scenes/procedural.json" : args.scene;
  const std::vector<NamedMaterial> materials = scene_materials(scene);
  // The errors and the speed are golden's; the noise unit's RTL is verilated at the default
  // widths only (its block has no width options, hence no Icarus run at the others).
  std::vector<Column> header = {"F,S,B,X",
                                {"fade bits", Mark::kFormula},
                                {"P max", Mark::kModel},
                                {"P mean", Mark::kModel},
                                {"sums max", Mark::kModel}};
  for (const NamedMaterial& m : materials) header.emplace_back(m.name + " dB", Mark::kModel);
  header.emplace_back("golden ns/sample", Mark::kModel);
  header.emplace_back("rtl = golden", Mark::kSim);
  header.emplace_back("noise cells", Mark::kSynth);
  header.emplace_back("depth", Mark::kSynth);
  SweepTable table(header);

  const int n = args.size;
  for (const perlin::NoiseConfig& c : settings) {
    std::mt19937_64 rng(17);
    std::uniform_int_distribution<int64_t> any(-64 * kOne, 64 * kOne - 1);
    double p_max = 0, p_sum = 0, s_max = 0, golden_s = 0;
    for (int i = 0; i < args.points; ++i) {
      const int64_t u = any(rng), v = any(rng), w = any(rng);
      const auto t0 = std::chrono::steady_clock::now();
      const perlin::FractalSums s = perlin::fractal_sums(c, u, v, w);
      golden_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double du = double(u) / kOne, dv = double(v) / kOne, dw = double(w) / kOne;
      const double e = std::abs(double(perlin::noise(c, u, v, w)) / perlin::noise_one(c) -
                                perlin::ideal::noise(du, dv, dw));
      p_max = std::max(p_max, e);
      p_sum += e;
      const perlin::ideal::FractalSums x = perlin::ideal::fractal_sums(du, dv, dw);
      s_max = std::max({s_max, std::abs(double(s.fractal_sum) / perlin::sum_one(c) - x.fractal_sum),
                        std::abs(double(s.turbulence) / perlin::sum_one(c) - x.turbulence)});
    }
    const std::string tag =
        fmt::format("{},{},{},{}", c.frac_bits, c.fade_index_bits, c.fade_bits, c.lerp_extra_bits);
    std::vector<Cell> row = {
        tag, fmt::format("{}", (uint64_t{1} << c.fade_index_bits) * (c.fade_bits + 1)),
        fmt::format("{:.4f}", p_max), fmt::format("{:.5f}", p_sum / args.points),
        fmt::format("{:.4f}", s_max)};
    for (const NamedMaterial& m : materials) {
      ImageRgb8 golden(n, n), ideal(n, n);
      for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
          const int64_t u = slice_u(x, n), v = slice_v(y, n);
          golden.at(x, y) = rgb(perlin::shade_material(c, m.regs, m.tables, u, v, kSliceW));
          ideal.at(x, y) = rgb(perlin::ideal::shade_material(
              m.regs, m.tables, double(u) / kOne, double(v) / kOne, double(kSliceW) / kOne));
        }
      }
      const double db = psnr(golden, ideal);
      row.push_back(std::isinf(db) ? "inf" : fmt::format("{:.2f}", db));
      if (!args.out_dir.empty()) {
        std::filesystem::create_directories(args.out_dir);
        write_image(fmt::format("{}/perlin_{}_f{}s{}b{}x{}.png", args.out_dir, m.name, c.frac_bits,
                                c.fade_index_bits, c.fade_bits, c.lerp_extra_bits),
                    golden);
        write_image(fmt::format("{}/perlin_{}_ideal.png", args.out_dir, m.name), ideal);
      }
    }
    row.push_back(fmt::format("{:.0f}", golden_s / args.points * 1e9));
    const RtlCheck rtl = c == perlin::NoiseConfig{} ? check_rtl("noise", {}, 20000) : RtlCheck{};
    row.push_back(rtl.verdict());
    // Yosys applies the parameters one at a time and the module checks S <= F at each step:
    // lower S before F, raise F before S.
    std::vector<std::pair<std::string, int>> params = {{"FadeBits", c.fade_bits},
                                                       {"LerpExtraBits", c.lerp_extra_bits}};
    const std::pair<std::string, int> f_param{"FracBits", c.frac_bits},
        s_param{"FadeIndexBits", c.fade_index_bits};
    if (c.fade_index_bits <= perlin::NoiseConfig{}.fade_index_bits) {
      params.insert(params.begin(), {s_param, f_param});
    } else {
      params.insert(params.begin(), {f_param, s_param});
    }
    const SynthFigures f = args.synth ? synthesize("tmu_noise", params) : SynthFigures{};
    row.push_back(synth_cell(f.cells, rtl.simulated()));
    row.push_back(synth_cell(f.depth, rtl.simulated()));
    table.add(row);
    fmt::print("{}\n", table.last_row_text());
  }
  table.print(args.markdown);

  // Area against speed at the default widths: one sample per clock or one per four, as the
  // Verilated model of each runs them against golden at full rate.
  SweepTable configs({"fractal unit",
                      "noise units",
                      {"cycles/sample", Mark::kSim},
                      {"rtl = golden", Mark::kSim},
                      {"cells", Mark::kSynth},
                      {"depth", Mark::kSynth}});
  for (const auto& [top, units, shared] :
       {std::tuple{"tmu_fractal_pipelined", 4, false}, std::tuple{"tmu_fractal_shared", 1, true}}) {
    tb::BlockOptions o;
    o.fractal_shared = shared;
    const RtlCheck rtl = check_rtl("fractal", o, 20000);
    const SynthFigures f = args.synth ? synthesize(top, {}) : SynthFigures{};
    configs.add({top, fmt::format("{}", units), rtl.simulated() ? cycles_per_output(rtl.run) : "-",
                 rtl.verdict(), synth_cell(f.cells, rtl.simulated()),
                 synth_cell(f.depth, rtl.simulated())});
  }
  std::string configs_md = args.markdown;
  if (const auto dot = configs_md.rfind(".md"); dot != std::string::npos) {
    configs_md.insert(dot, "_configs");
  }
  configs.print(configs_md);
}

}  // namespace tmu::texsim
