// `texsim drf SCENE`: the DRF programs and memory map a scene compiles to on the TEXRAM chip
// (000 §14, docs/texram_chip.md): per chip its programmed DRFs, the maps at their bases and what
// is left; per material its chain and the parameters a pixel brings; the materials the TEXRAM
// does not sample, with the reason. --writes lists the write-port words that load the DRFs.
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <string_view>

#include "render/drf_compile.hpp"
#include "render/pipeline.hpp"
#include "scene/scene.hpp"
#include "texram/chip/chip_memory.hpp"
#include "texsim/commands.hpp"

namespace tmu::texsim {
namespace {

using texram::chip::Drf;
using texram::chip::kDrfs;

struct DrfArgs {
  std::string scene;
  int chips = 4;
  bool writes = false;
};

std::string borders(const texram::SamplerConfig& s) {
  return fmt::format("{}/{}", texram::name(s.border_u), texram::name(s.border_v));
}

// What else the DRF's samples do: footprint assembly (its most probes), a detail map (its rule).
std::string also(const Drf& d) {
  std::string out;
  if (d.footprint) out = fmt::format("footprint <={}", 1 << std::min(d.log2_max_probes, 4));
  if (d.detail) {
    out += fmt::format("{}detail {}", out.empty() ? "" : ", ",
                       d.detail_combine == texram::DetailCombine::kModulate ? "mod" : "repl");
  }
  return out.empty() ? "-" : out;
}

std::string mib(uint64_t cells) {  // eight banks of one byte a cell
  return fmt::format("{:.2f} MiB", static_cast<double>(cells) * 8 / (1 << 20));
}

void print_chip(const host::Scene& scene, const render::ChipProgram& chip, int c, bool writes) {
  fmt::print("chip {}: {} DRF{}{}, {} maps, {} of {} ({:.1f} %), CLUT {}\n", c, chip.used_drfs,
             chip.used_drfs == 1 ? "" : "s", chip.cube_used ? " and DRF 7 (cube)" : "",
             chip.maps.size(), mib(chip.used_cells), mib(texram::chip::kBankCells),
             100.0 * chip.used_cells / texram::chip::kBankCells, chip.clut ? "in use" : "unused");
  // One format for the header and the rows, so the columns line up.
  constexpr std::string_view kRow =
      "  {:>3}  {:<11} {:<28} {:>8}  {:>9}  {:<11} {:<9} {:<13} {:<7} {:<16} {:>4}  {}\n";
  fmt::print(fmt::runtime(kRow), "DRF", "op", "map", "base", "size", "kind", "filter", "borders",
             "address", "also", "link", "coords");
  for (int n = 1; n <= kDrfs; ++n) {
    const bool used = n <= chip.used_drfs || (n == texram::chip::kCubeDrf && chip.cube_used);
    if (!used) continue;
    const Drf& d = chip.drfs[static_cast<size_t>(n - 1)];
    std::string map;
    for (const render::ChipMap& m : chip.maps) {
      if (m.drf == n) {
        map = d.cube ? m.label.substr(0, m.label.size() - 2) + " (6 faces)" : m.label;
        break;
      }
    }
    fmt::print(fmt::runtime(kRow), n, texram::chip::name(d.op), map, fmt::format("{:#x}", d.base),
               fmt::format("{}x{}", 1 << d.log2_w, 1 << d.log2_h), texram::name(d.sampler.kind),
               texram::name(d.sampler.filter), borders(d.sampler),
               texram::name(d.sampler.addressing), also(d),
               d.link == 0 ? "end" : std::to_string(d.link), d.takes_coords ? "new" : "-");
  }
  fmt::print("  memory map (cells of every bank):\n");
  for (const render::ChipMap& m : chip.maps) {
    fmt::print("    {:#08x} .. {:#08x}  {:>8} cells  DRF {}  {}\n", m.base, m.base + m.cells - 1,
               m.cells, m.drf, m.label);
  }
  fmt::print("    {:#08x} .. {:#08x}  free\n", chip.used_cells, texram::chip::kBankCells - 1);
  if (writes) {
    fmt::print("  write port (drf, field, value):\n");
    for (int n = 1; n <= kDrfs; ++n) {
      const bool used = n <= chip.used_drfs || (n == texram::chip::kCubeDrf && chip.cube_used);
      if (!used) continue;
      for (const texram::chip::DrfWrite& w :
           texram::chip::drf_writes(n, chip.drfs[static_cast<size_t>(n - 1)]))
        fmt::print("    {} {:>2} {:#010x}\n", w.drf, w.field, w.value);
    }
  }
  (void)scene;
}

void run_drf(const DrfArgs& a) {
  const host::Scene scene = host::load_scene(a.scene);
  // Golden loads the maps as the chip holds them (a mipgen material's levels have the sizes of
  // the host pyramid).
  const render::Pipeline pipe(scene, render::Level::kGolden, a.chips);
  const render::ScenePrograms programs = render::compile_drfs(scene, pipe.textures(), a.chips);
  int used = 0;
  for (const render::ChipProgram& c : programs.chips) used += c.used_drfs > 0 || c.cube_used;
  fmt::print("{}: {} materials on {} of {} chip{} (000 §14; docs/texram_chip.md)\n", a.scene,
             scene.materials.size(), used, a.chips, a.chips == 1 ? "" : "s");
  for (size_t c = 0; c < programs.chips.size(); ++c) {
    const render::ChipProgram& chip = programs.chips[c];
    if (chip.used_drfs > 0 || chip.cube_used)
      print_chip(scene, chip, static_cast<int>(c), a.writes);
  }
  fmt::print("materials:\n");
  for (const render::MaterialProgram& p : programs.materials) {
    const std::string& name = scene.materials[static_cast<size_t>(p.material)].name;
    if (p.chip < 0) {
      fmt::print("  {:<14} not on a chip: {}\n", name, p.why);
      continue;
    }
    std::vector<std::string> passes;  // "1" or "1 | 2 -> 3": a pass ends at an emit DRF
    for (int lead : p.passes) {
      passes.push_back(fmt::format(
          "{}",
          fmt::join(texram::chip::chain(programs.chips[static_cast<size_t>(p.chip)].drfs, lead),
                    " -> ")));
    }
    fmt::print("  {:<14} chip {}, DRF {}; a pixel brings {}\n", name, p.chip,
               fmt::join(passes, " | "), fmt::join(p.parameters, ", then "));
  }
}

}  // namespace

void add_drf_command(CLI::App& app, ExitCode& exit_code) {
  auto* cmd = app.add_subcommand(
      "drf",
      "The DRF programs and memory map a scene compiles to on the TEXRAM chip (000 §14): per "
      "chip the description register files (op, map, base, size, kind, filter, borders, "
      "addressing, link, whether a new parameter comes first) and every map's cells; per "
      "material its chain and the parameters each pixel brings; the materials the TEXRAM does "
      "not sample, and why (docs/texram_chip.md)");
  auto a = std::make_shared<DrfArgs>();
  cmd->add_option("scene", a->scene, "The scene file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--chips", a->chips, "TEXRAM chips to place the materials on (first fit)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  cmd->add_flag("--writes", a->writes, "Also list the write-port words that load each DRF");
  cmd->callback([a, &exit_code] {
    run_drf(*a);
    exit_code.value = 0;
  });
}

}  // namespace tmu::texsim
