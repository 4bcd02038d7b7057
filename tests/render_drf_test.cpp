// The host's DRF compiler (render/drf_compile.hpp): every bundled scene's materials placed on
// TEXRAM chips with their maps apart, page aligned, inside the banks, their chains as the links
// say and their DRFs describing their maps; and the clear errors when a scene does not fit (no
// DRF left, no cells left, a second palette).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "render/drf_compile.hpp"
#include "texram/chip/chip_memory.hpp"
#include "texram/page_model.hpp"

namespace tmu::render {
namespace {

namespace fs = std::filesystem;
using texram::chip::DrfOp;

ScenePrograms compile(const host::Scene& scene, int chips) {
  const Pipeline pipe(scene, Level::kGolden, chips);
  return compile_drfs(scene, pipe.textures(), chips);
}

// A scene with `n` plain materials of `side` x `side` texels in `config`, one plane each.
host::Scene plain_materials(int n, int side, const std::string& config) {
  nlohmann::json j = nlohmann::json::parse(R"({
    "camera": {"position": [0, 2, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 50,
               "resolution": [32, 24]}, "objects": []})");
  for (int m = 0; m < n; ++m) {
    const std::string name = "m" + std::to_string(m);
    j["materials"][name] = {{"texture", {{"pattern", "checker"}, {"size", {side, side}}}},
                            {"config", config}};
    j["objects"].push_back({{"type", "plane"}, {"size", {1, 1}}, {"material", name}});
  }
  return host::parse_scene(j.dump(), "test.json", ".");
}

void expect_error(const host::Scene& scene, int chips, const std::string& field,
                  const std::string& reason) {
  try {
    compile(scene, chips);
    ADD_FAILURE() << "no error; expected " << field << ": " << reason;
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
  }
}

TEST(RenderDrfTest, EveryBundledSceneCompilesWithItsMapsApart) {
  constexpr uint32_t kPage = texram::kPageCells;
  for (const auto& entry : fs::directory_iterator(std::string(TMU_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().filename().string());
    std::ifstream in(entry.path());
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.contains("flyover")) continue;  // a clip-map fly-over (003)
    if (j.contains("volume")) continue;   // a volume scene (000 §13): no maps, no DRFs
    const host::Scene scene = host::load_scene(entry.path().string());
    const Pipeline pipe(scene, Level::kGolden, 4);  // 4: a detail scene needs chips
    const ScenePrograms p = compile_drfs(scene, pipe.textures(), 4);
    ASSERT_EQ(p.materials.size(), scene.materials.size());
    for (const ChipProgram& chip : p.chips) {
      std::vector<ChipMap> maps = chip.maps;
      std::sort(maps.begin(), maps.end(),
                [](const ChipMap& a, const ChipMap& b) { return a.base < b.base; });
      for (size_t i = 0; i < maps.size(); ++i) {
        EXPECT_EQ(maps[i].base % kPage, 0u) << maps[i].label;
        const uint64_t end = uint64_t{maps[i].base} + maps[i].cells;
        EXPECT_LE(end, i + 1 < maps.size() ? maps[i + 1].base : chip.used_cells) << maps[i].label;
        EXPECT_LE(end, texram::chip::kBankCells);
      }
    }
    for (const MaterialProgram& m : p.materials) {
      const host::Material& mat = scene.materials[static_cast<size_t>(m.material)];
      SCOPED_TRACE(mat.name);
      if (m.chip < 0) {
        EXPECT_FALSE(m.why.empty());
        EXPECT_TRUE(mat.procedural || mat.unit == host::Material::Unit::kLowcost) << m.why;
        continue;
      }
      const ChipProgram& chip = p.chips[static_cast<size_t>(m.chip)];
      // The passes' chains, one after the other, are the material's chain; only a bump map's
      // emit DRF ends a pass before the last.
      std::vector<int> chains;
      for (int lead : m.passes) {
        for (int n : texram::chip::chain(chip.drfs, lead)) chains.push_back(n);
        if (lead != m.passes.back()) {
          EXPECT_EQ(chip.drfs[static_cast<size_t>(chains.back() - 1)].op, DrfOp::kEmit);
        }
      }
      EXPECT_EQ(chains, m.drfs);
      // The texture's DRF describes the material's texture; every DRF's map is where it says.
      const auto& tex = *pipe.textures()[static_cast<size_t>(m.material)].texram;
      bool texture_seen = false;
      for (int n : m.drfs) {
        const texram::chip::Drf& d = chip.drfs[static_cast<size_t>(n - 1)];
        const auto at = std::find_if(chip.maps.begin(), chip.maps.end(), [&](const ChipMap& c) {
          return c.drf == n && c.material == m.material;
        });
        ASSERT_NE(at, chip.maps.end()) << "DRF " << n;
        EXPECT_EQ(d.base, at->base);
        if (d.op != DrfOp::kTexture) continue;
        texture_seen = true;
        EXPECT_EQ(d.log2_w, tex.geometry.log2_width());
        EXPECT_EQ(d.log2_h, tex.geometry.log2_height());
        EXPECT_EQ(d.sampler, mat.sampler);
        EXPECT_EQ(at->cells, tex.geometry.bank_cells());
      }
      EXPECT_TRUE(texture_seen);
      EXPECT_EQ(m.parameters.size(),
                1 + static_cast<size_t>(std::count_if(m.drfs.begin() + 1, m.drfs.end(), [&](int n) {
                  return chip.drfs[static_cast<size_t>(n - 1)].takes_coords;
                })));
    }
  }
}

// scenes/detail.json: the texture's and the reflectance map's detail maps are each an offsets
// DRF (both offset maps, v right after u where the chip reads it) and a detail DRF after the
// map's own; the extreme chain takes all seven DRFs, so the two materials take two chips.
TEST(RenderDrfTest, DetailMapsCompileToOffsetsAndDetailDrfs) {
  const host::Scene scene = host::load_scene(std::string(TMU_SOURCE_DIR) + "/scenes/detail.json");
  const ScenePrograms p = compile(scene, 4);
  ASSERT_EQ(p.materials.size(), 2u);
  const std::vector<DrfOp> plain = {DrfOp::kTexture, DrfOp::kOffsets, DrfOp::kDetail};
  const std::vector<DrfOp> extreme = {DrfOp::kTexture,     DrfOp::kOffsets, DrfOp::kDetail,
                                      DrfOp::kReflectance, DrfOp::kOffsets, DrfOp::kDetail,
                                      DrfOp::kEnvironment};
  for (size_t m = 0; m < 2; ++m) {
    const MaterialProgram& prog = p.materials[m];
    SCOPED_TRACE(scene.materials[m].name);
    ASSERT_GE(prog.chip, 0) << prog.why;
    EXPECT_EQ(prog.chip, static_cast<int>(m));  // the extreme chain does not fit beside another
    const ChipProgram& chip = p.chips[static_cast<size_t>(prog.chip)];
    std::vector<DrfOp> ops;
    for (int n : prog.drfs) ops.push_back(chip.drfs[static_cast<size_t>(n - 1)].op);
    EXPECT_EQ(ops, m == 0 ? plain : extreme);
    for (size_t k = 0; k < prog.drfs.size(); ++k) {
      const texram::chip::Drf& d = chip.drfs[static_cast<size_t>(prog.drfs[k] - 1)];
      if (d.op == DrfOp::kTexture || d.op == DrfOp::kReflectance) {
        const host::Detail& want = d.op == DrfOp::kTexture ? *scene.materials[m].detail
                                                           : *scene.materials[m].reflectance.detail;
        EXPECT_TRUE(d.detail);
        EXPECT_EQ(d.detail_combine == texram::DetailCombine::kModulate, want.modulate);
      }
      if (d.op != DrfOp::kOffsets) continue;
      std::vector<uint32_t> bases;  // the offsets DRF's two maps
      for (const ChipMap& c : chip.maps)
        if (c.drf == prog.drfs[k]) bases.push_back(c.base);
      ASSERT_EQ(bases.size(), 2u);
      EXPECT_EQ(bases[0], d.base);
      EXPECT_EQ(bases[1], texram::chip::offsets_v_base(d));
    }
  }
  // On one chip the second material finds no DRF left: a clear error.
  expect_error(scene, 1, "materials.lacquer", "4 DRFs left, 7 needed");
}

TEST(RenderDrfTest, AChipFullOfDrfsPassesTheNextMaterialOn) {
  const host::Scene scene = plain_materials(8, 16, "luminance");
  const ScenePrograms p = compile(scene, 2);
  EXPECT_EQ(p.chips[0].used_drfs, 7);
  EXPECT_EQ(p.materials[7].chip, 1);
  expect_error(scene, 1, "materials.m7", "chip 0: 0 DRFs left, 1 needed");
}

TEST(RenderDrfTest, AChipFullOfCellsPassesTheNextMaterialOn) {
  // 1024 x 1024 true colour: 4 planes of 262 144 + ... cells a bank, more than half a bank.
  const host::Scene scene = plain_materials(2, 1024, "rgba");
  const ScenePrograms p = compile(scene, 2);
  EXPECT_EQ(p.materials[1].chip, 1);
  expect_error(scene, 1, "materials.m1", "cells a bank left");
}

TEST(RenderDrfTest, TwoPalettesNeedTwoChips) {
  // The default scene's CCC sphere and its index-mapped label bring different palettes.
  const host::Scene scene = host::load_scene(std::string(TMU_SOURCE_DIR) + "/scenes/default.json");
  expect_error(scene, 1, "materials.label", "its CLUT holds another palette");
  const ScenePrograms p = compile(scene, 2);
  EXPECT_NE(p.materials[2].chip, p.materials[3].chip);  // compressed, label
}

}  // namespace
}  // namespace tmu::render
