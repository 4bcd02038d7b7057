// The cube environment map's addressing unit (000 §7): golden vs hls vs rtl, bit for bit, on
// the block's directed hard cases (each axis +-, the zero vector, cube edges and corners, near
// ties, the largest component's sign, the extreme components, every seed-table index, face
// sizes 2^0 .. 2^10) and random vectors of any length under back-pressure; the 4-bit L port
// beyond 10; one vector per clock; and proof that the comparison has teeth (RTL mutants: an
// x-y tie going to y, the -Z face's u mirrored; an injected wrong bit).
#include <Vtmu_cube_address_mutant_sign.h>
#include <Vtmu_cube_address_mutant_tie.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

#include "blocks/cube_map_block.hpp"
#include "deflect/cube_map.hpp"
#include "harness/cosim.hpp"
#include "harness/vector_file.hpp"
#include "tests/cosim_test_support.hpp"

namespace tmu::tb {
namespace {

constexpr auto options = testing::cosim_options;

CubeMapBlock make_block() { return CubeMapBlock(BlockOptions{}); }

void expect_every_case_hit(const Coverage& coverage) {
  for (const auto& [name, n] : coverage) EXPECT_GT(n, 0u) << "coverage case not hit: " << name;
}

// The directed items and a million random vectors through the rtl (twice, for the X check),
// 20000 through the hls model, under back-pressure; every case hit.
TEST(CubeMapCosimTest, GoldenVsHlsVsRtl) {
  const CubeMapBlock block = make_block();
  {
    std::stringstream log;
    const CosimResult r = run_cosim(block, options(20260101, 1'000'000, {"rtl"}), log);
    EXPECT_TRUE(r.pass) << log.str();
    expect_every_case_hit(r.coverage);
    std::cout << log.str().substr(log.str().find("coverage:"));
  }
  std::stringstream log;
  const CosimResult r = run_cosim(block, options(17, 20'000, {"hls", "rtl"}), log);
  EXPECT_TRUE(r.pass) << log.str();
  expect_every_case_hit(r.coverage);
}

TEST(CubeMapCosimTest, HeavyBackPressure) {
  const CubeMapBlock block = make_block();
  CosimOptions o = options(7, 20'000, {"hls", "rtl"});
  o.in_idle = 0.6;
  o.out_stall = 0.6;
  std::stringstream log;
  EXPECT_TRUE(run_cosim(block, o, log).pass) << log.str();
}

// One vector per clock: without bubbles or stalls the rtl takes the items, its latency (7
// cycles) and the harness's 16 drain cycles.
TEST(CubeMapCosimTest, OneVectorPerClock) {
  const CubeMapBlock block = make_block();
  CosimOptions o = options(3, 20'000, {"hls", "rtl"});
  o.in_idle = 0.0;
  o.out_stall = 0.0;
  std::stringstream log;
  const CosimResult r = run_cosim(block, o, log);
  ASSERT_TRUE(r.pass) << log.str();
  EXPECT_LE(r.runs.at("rtl").cycles, r.items + 7 + 16) << log.str();
  EXPECT_LE(r.runs.at("hls").cycles, r.items + 7 + 16) << log.str();
}

// The directed items alone hit every coverage case (each face, each tie kind, the zero
// vector, the extremes, face sizes 0 .. 10, every seed-table index), and address every hard
// vector at L = 0, 1, 9 and 10.
TEST(CubeMapCosimTest, DirectedItemsHitEveryCase) {
  const CubeMapBlock block = make_block();
  const std::vector<Txn> items = block.directed_items();
  Coverage coverage;
  for (const std::string& name : block.coverage_cases()) coverage[name] = 0;
  for (size_t i = 0; i < items.size(); ++i) block.cover(items, i, Txn{}, coverage);
  expect_every_case_hit(coverage);

  // Each of these vectors at each of these sizes.
  const auto has = [&items](int32_t x, int32_t y, int32_t z, int l) {
    const Txn want = cube_item(x, y, z, l);
    return std::find(items.begin(), items.end(), want) != items.end();
  };
  for (int l : {0, 1, 9, 10}) {
    EXPECT_TRUE(has(0, 0, 0, l)) << "zero vector, L " << l;
    for (int32_t m : {1, 16384, 32767, -1, -16384, -32767, -32768}) {
      EXPECT_TRUE(has(m, 0, 0, l) && has(0, m, 0, l) && has(0, 0, m, l)) << m << ", L " << l;
    }
    EXPECT_TRUE(has(11585, 11585, 0, l) && has(11585, 0, -11585, l) && has(0, -11585, -11585, l));
    EXPECT_TRUE(has(-32768, -32768, 0, l) && has(0, -32768, -32768, l));
    EXPECT_TRUE(has(9459, 9459, 9459, l) && has(-9459, -9459, -9459, l));
    EXPECT_TRUE(has(-32768, -32768, -32768, l) && has(32767, 32767, 32767, l));
    EXPECT_TRUE(has(32767, -32768, 0, l) && has(-32768, 32767, 5, l));
  }
}

// The directed hard cases through golden, with the expectations of cube_map.hpp: the edges
// and corners go to the earlier axis, the axes and the zero vector to the face's centre.
TEST(CubeMapCosimTest, HardCasesAsSpecified) {
  for (int l : {0, 1, 9, 10}) {
    const int32_t centre = 128 << l;  // 2^(L-1) texels in SQ16.8
    for (uint32_t face = 0; face < 6; ++face) {
      int32_t r[3] = {0, 0, 0};
      r[face / 2] = face % 2 ? -32768 : 32767;
      const deflect::CubeAddress a = deflect::cube_address(r[0], r[1], r[2], l);
      EXPECT_EQ(a.face, face);
      EXPECT_EQ(a.u, centre);
      EXPECT_EQ(a.v, centre);
    }
    EXPECT_EQ(deflect::cube_address(0, 0, 0, l).face, 0u);
    EXPECT_EQ(deflect::cube_address(-5, 5, 0, l).face, 1u);          // x-y edge: -X
    EXPECT_EQ(deflect::cube_address(0, -7, 7, l).face, 3u);          // y-z edge: -Y
    EXPECT_EQ(deflect::cube_address(-9, 3, 9, l).face, 1u);          // x-z edge: -X
    EXPECT_EQ(deflect::cube_address(-3, -3, -3, l).face, 1u);        // corner: -X
    EXPECT_EQ(deflect::cube_address(32767, -32768, 0, l).face, 3u);  // |-32768| is larger
    EXPECT_EQ(cube_face_coords(-3, -3, -3).face, 1u);
  }
}

// L is a 4-bit port: the unit computes golden's formula for L = 11 .. 15 too (the largest
// coordinate, 2^23 at L = 15, still fits TexCoord's 24 bits as raw bits), replayed from a
// vector file.
TEST(CubeMapCosimTest, FaceLog2BeyondTenAgrees) {
  const CubeMapBlock block = make_block();
  std::vector<Txn> items;
  for (int l = 11; l <= 15; ++l) {
    for (const auto& [x, y, z] : std::vector<std::array<int32_t, 3>>{{0, 0, 0},
                                                                     {16384, 0, 0},
                                                                     {11585, 11585, 0},
                                                                     {-32768, 32767, -32767},
                                                                     {100, -3000, -2999},
                                                                     {-9459, 9459, 9459}}) {
      items.push_back(cube_item(x, y, z, l));
    }
  }
  const auto path = testing::temp_dir("tmu_cube_map_test") / "beyond_ten.csv";
  write_vectors(path.string(), block.inputs(), items);
  CosimOptions o = options(11, 0, {"hls", "rtl"});
  o.vectors_in = path.string();
  std::stringstream log;
  EXPECT_TRUE(run_cosim(block, o, log).pass) << log.str();
}

// --- teeth ---------------------------------------------------------------------------------

template <class Model>
CosimResult run_mutant(uint64_t seed, size_t count, bool directed, std::stringstream& log) {
  CosimOptions o = options(seed, count, {"rtl"});
  o.x_check = false;
  o.directed = directed;
  return run_cosim(make_block(), o, log, [](const std::string& level) -> std::unique_ptr<Engine> {
    if (level != "rtl") return nullptr;
    return make_cube_map_rtl_engine<Model>("rtl");
  });
}

// A tie of |x| and |y| goes to y: only the cube's x-y edges and corners change face, which
// the directed edges catch.
TEST(CubeMapCosimTest, TieMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_cube_address_mutant_tie>(9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim cube-map --seed 9");
}

// The -Z face's sc = -x loses its sign: the directed vectors on -Z catch it.
TEST(CubeMapCosimTest, SignMutantIsCaughtWithAWaveform) {
  std::stringstream log;
  const CosimResult r = run_mutant<Vtmu_cube_address_mutant_sign>(9, 0, true, log);
  testing::expect_rtl_caught_with_waveform(r, log.str(), "texsim cosim cube-map --seed 9");
}

// The random items alone catch both too (their edge and corner kind makes exact ties).
TEST(CubeMapCosimTest, RandomItemsAloneCatchTheMutants) {
  {
    std::stringstream log;
    EXPECT_FALSE(run_mutant<Vtmu_cube_address_mutant_tie>(13, 2000, false, log).pass);
  }
  std::stringstream log;
  EXPECT_FALSE(run_mutant<Vtmu_cube_address_mutant_sign>(13, 2000, false, log).pass);
}

TEST(CubeMapCosimTest, InjectedFaultFailsTheRun) {
  CosimOptions o = options(5, 1000, {"hls", "rtl"});
  o.inject_fault = 500;
  std::stringstream log;
  const CosimResult r = run_cosim(make_block(), o, log);
  EXPECT_FALSE(r.pass);
  EXPECT_NE(log.str().find("first at transaction 500"), std::string::npos) << log.str();
}

}  // namespace
}  // namespace tmu::tb
