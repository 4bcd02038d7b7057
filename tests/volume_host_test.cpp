// The host side of volume rendering (host/volume/): volume scenes and their errors (each names
// the file, the field path and the reason), the transfer function, the engine scan, ray set-up
// against the volume's box with its hard cases, compositing and the bound of early termination,
// and the slabs: every location through the chip that owns it equals the single chip's resample
// bit for bit.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "common/error.hpp"
#include "volume/compositing.hpp"
#include "volume/ct_scan.hpp"
#include "volume/ray_setup.hpp"
#include "volume/sample_shading.hpp"
#include "volume/slabs.hpp"
#include "volume/sources.hpp"
#include "volume/transfer_function.hpp"
#include "volume/unit.hpp"
#include "volume/volume_data.hpp"
#include "volume/volume_scene.hpp"

namespace tmu::host {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// ---- scenes --------------------------------------------------------------------------------

Json base_volume() {
  return Json::parse(R"({
    "volume": {
      "data": {"field": "marschner_lobb", "size": [32, 32, 32]},
      "transfer": [{"value": 0, "colour": [1, 1, 1], "opacity": 0},
                   {"value": 128, "colour": [1, 0.5, 0], "opacity": 0.8}]
    },
    "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 40,
               "resolution": [32, 24]}
  })");
}

VolumeScene parse(const Json& j, const std::string& folder = ".") {
  return parse_volume_scene(j.dump(2), "test.json", folder);
}

void expect_error(const Json& j, const std::string& field, const std::string& reason,
                  const std::string& folder = ".") {
  try {
    parse(j, folder);
    ADD_FAILURE() << "no error; expected " << field << ": " << reason;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "test.json");
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
  }
}

TEST(VolumeSceneTest, AValidSceneGivesBackItsFields) {
  Json j = base_volume();
  j["volume"]["step"] = 0.5;
  j["volume"]["weight_bits"] = 6;
  j["volume"]["chips"] = 4;
  j["volume"]["slab_axis"] = "z";
  j["volume"]["early_termination"] = {{"alpha", 0.9}, {"segment", 8}};
  j["lights"] = Json::parse(R"([{"type": "ambient", "colour": [0.2, 0.2, 0.2]}])");
  const VolumeScene s = parse(j);
  EXPECT_EQ(s.format, VolumeFormat::kRaw);
  EXPECT_EQ(s.data.field, VolumeData::Field::kMarschnerLobb);
  EXPECT_EQ(s.data.size, (std::array<uint32_t, 3>{32, 32, 32}));
  EXPECT_EQ(s.step, 0.5);
  EXPECT_EQ(s.weight_bits, 6);
  EXPECT_EQ(s.chips, 4);
  EXPECT_EQ(s.slab_axis, 2);
  ASSERT_TRUE(s.termination);
  EXPECT_EQ(s.termination->alpha, 0.9);
  EXPECT_EQ(s.termination->segment, 8u);
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.camera.width, 32);
  EXPECT_EQ(s.transfer.points().size(), 2u);
  // Defaults: early termination on at 255/256, one chip, step 1, W = 8.
  const VolumeScene d = parse(base_volume());
  ASSERT_TRUE(d.termination);
  EXPECT_EQ(d.termination->alpha, 255.0 / 256);
  EXPECT_EQ(d.chips, 1);
  EXPECT_EQ(d.step, 1);
  EXPECT_EQ(d.weight_bits, 8);
  Json off = base_volume();
  off["volume"]["early_termination"] = false;
  EXPECT_FALSE(parse(off).termination);
}

TEST(VolumeSceneTest, MistakesNameTheFieldAndTheReason) {
  auto with = [](const std::function<void(Json&)>& change) {
    Json j = base_volume();
    change(j);
    return j;
  };
  expect_error(with([](Json& j) { j["volume"]["colour"] = 1; }), "volume.colour",
               "unknown key (expected one of: data, format, transfer");
  expect_error(with([](Json& j) { j["volume"].erase("transfer"); }), "volume",
               "missing required key 'transfer'");
  expect_error(with([](Json& j) { j["volume"]["data"]["file"] = "x.raw"; }), "volume.data",
               "give one of field and file");
  expect_error(with([](Json& j) {
                 j["volume"]["data"]["size"] = {1, 32, 32};
               }),
               "volume.data.size[0]", "must be an integer in 2..512");
  expect_error(with([](Json& j) {
                 j["volume"]["data"]["size"] = {32, 32};
               }),
               "volume.data.size", "expected a list of 3 integers");
  expect_error(with([](Json& j) { j["volume"]["data"]["field"] = "cube"; }), "volume.data.field",
               "unknown value 'cube'");
  expect_error(with([](Json& j) { j["volume"]["data"]["radius"] = 3; }), "volume.data.radius",
               "unknown key (expected one of: field, size, f_m, alpha)");
  expect_error(with([](Json& j) { j["volume"]["transfer"][1]["value"] = 0; }),
               "volume.transfer[1].value", "values must increase");
  expect_error(with([](Json& j) { j["volume"]["transfer"][1]["value"] = 300; }),
               "volume.transfer[1].value", "0..255");
  expect_error(with([](Json& j) { j["volume"]["transfer"][0]["opacity"] = 1.5; }),
               "volume.transfer[0].opacity", "must be in 0..1");
  expect_error(with([](Json& j) { j["volume"]["transfer"] = Json::array(); }), "volume.transfer",
               "at least one point");
  expect_error(with([](Json& j) { j["volume"]["step"] = 0; }), "volume.step", "voxels");
  expect_error(with([](Json& j) { j["volume"]["step"] = 5; }), "volume.step", "voxels");
  expect_error(with([](Json& j) { j["volume"]["weight_bits"] = 9; }), "volume.weight_bits", "1..8");
  expect_error(with([](Json& j) { j["volume"]["format"] = "grey"; }), "volume.format",
               "unknown value 'grey'");
  expect_error(with([](Json& j) { j["volume"]["chips"] = 17; }), "volume.chips",
               "each chip owns at least 2");
  expect_error(with([](Json& j) { j["volume"]["slab_axis"] = "w"; }), "volume.slab_axis",
               "unknown value 'w'");
  expect_error(with([](Json& j) {
                 j["volume"]["early_termination"] = {{"alpha", 0}};
               }),
               "volume.early_termination.alpha", "(0, 1]");
  expect_error(with([](Json& j) { j["volume"]["early_termination"] = 3; }),
               "volume.early_termination", "expected false, true or");
  expect_error(with([](Json& j) {
                 j["volume"]["format"] = "rgba";
                 j["lights"] = Json::array();
               }),
               "lights", "raw data only");
  expect_error(with([](Json& j) { j["camera"]["near"] = 0.1; }), "camera.near",
               "rays start at the eye");
  expect_error(with([](Json& j) { j.erase("camera"); }), "camera", "missing required key");
  // Too large for one chip's banks (2^21 cells a bank): a slab problem, with the way out.
  expect_error(with([](Json& j) {
                 j["volume"]["data"]["size"] = {512, 512, 512};
               }),
               "volume.data.size", "give \"chips\"");
}

TEST(VolumeSceneTest, FileSizeAndPreclassifiedFiles) {
  const fs::path dir = fs::temp_directory_path() / ("tmu_volume_scene_" + std::to_string(getpid()));
  fs::create_directories(dir);
  {
    std::ofstream f(dir / "v.raw", std::ios::binary);
    f << std::string(1000, 'x');
  }
  Json j = base_volume();
  j["volume"]["data"] = {{"file", "v.raw"}, {"size", {10, 10, 10}}};
  EXPECT_EQ(parse(j, dir.string()).data.field, VolumeData::Field::kFile);
  j["volume"]["data"]["size"] = {10, 10, 11};
  expect_error(j, "volume.data.file", "holds 1000 bytes", dir.string());
  j["volume"]["data"]["file"] = "missing.raw";
  expect_error(j, "volume.data.file", "file not found", dir.string());
  // A pre-classified file: four bytes a voxel, no transfer function.
  j["volume"]["data"] = {{"file", "v.raw"}, {"size", {10, 10, 10}}};
  j["volume"]["format"] = "rgba";
  expect_error(j, "volume.data.file", "RGBA voxels are 4000 bytes", dir.string());
  {
    std::ofstream f(dir / "v4.raw", std::ios::binary);
    f << std::string(4000, 'x');
  }
  j["volume"]["data"]["file"] = "v4.raw";
  expect_error(j, "volume.transfer", "needs no transfer function", dir.string());
  j["volume"].erase("transfer");
  const VolumeScene s = parse(j, dir.string());
  const auto grids = volume_grids(s);
  ASSERT_EQ(grids.size(), 4u);
  EXPECT_EQ(grids[2].at(9, 9, 9), 'x');
  fs::remove_all(dir);
}

// ---- transfer function, pre-classification, phantom -------------------------------------

TEST(VolumeTransferTest, LinearBetweenPointsConstantBeyond) {
  const TransferFunction tf({{50, {0, 0, 0}, 0}, {150, {1, 0.5, 0}, 0.8}});
  EXPECT_EQ(tf(0).opacity, 0);
  EXPECT_EQ(tf(50).opacity, 0);
  EXPECT_DOUBLE_EQ(tf(100).opacity, 0.4);
  EXPECT_DOUBLE_EQ(tf(100).colour.g, 0.25);
  EXPECT_EQ(tf(150).opacity, 0.8);
  EXPECT_EQ(tf(255).colour.r, 1);
  // Pre-classified voxels carry the opacity-weighted colour: round(255 (r a, g a, b a, a)).
  EXPECT_EQ(preclassify(tf, 200), (std::array<uint8_t, 4>{204, 102, 0, 204}));
  EXPECT_EQ(preclassify(tf, 10), (std::array<uint8_t, 4>{0, 0, 0, 0}));
}

TEST(VolumeTransferTest, EngineScanIsReproducibleAndLooksLikeAScan) {
  const volume::VoxelGrid a = engine_scan(32, 32, 32, 1), b = engine_scan(32, 32, 32, 1);
  EXPECT_EQ(a.voxels, b.voxels);
  EXPECT_NE(a.voxels, engine_scan(32, 32, 32, 2).voxels);  // the noise is the seed's
  // The levels of the header within the noise: air in the corner, aluminium in the block's
  // wall, steel in the shaft's end outside the block.
  EXPECT_NEAR(a.at(0, 0, 0), 20, 12);
  EXPECT_NEAR(a.at(16, 13, 18), 110, 15);  // x 0.03, y -0.16, z 0.16: the wall between the bores
  EXPECT_EQ(engine_density(0, 0, 0.1), 0.45);      // the block
  EXPECT_EQ(engine_density(0.38, 0, 0.1), 0);      // a bore
  EXPECT_EQ(engine_density(0.38, 0.2, 0.1), 1);    // its liner
  EXPECT_EQ(engine_density(0.38, 0, -0.1), 0.45);  // a piston
  EXPECT_EQ(engine_density(0.9, 0, -0.38), 1);     // the crankshaft out of the block
  EXPECT_EQ(engine_density(0, 0.12, -0.38), 0);    // the crankcase around it
  EXPECT_EQ(engine_density(0.9, 0.9, 0.9), 0);     // air
}

// ---- ray set-up ----------------------------------------------------------------------------

constexpr std::array<uint32_t, 3> k8 = {8, 8, 8};  // the box [0, 7]^3

TEST(VolumeRaySetupTest, AxisParallelRay) {
  const RaySetup r = set_up_ray(k8, {-5, 3, 4}, {1, 0, 0}, 1);
  EXPECT_EQ(r.count, 8u);  // x = 0, 1, .., 7: both faces included
  EXPECT_EQ(r.start, glm::dvec3(0, 3, 4));
  EXPECT_EQ(r.ray.start, (volume::Position{0, 3 << 16, 4 << 16}));
  EXPECT_EQ(r.ray.step, (volume::Position{1 << 16, 0, 0}));
  EXPECT_EQ(r.ray.count, 8u);
  // Backwards along z at half a voxel: z = 7, 6.5, .., 0.
  const RaySetup b = set_up_ray(k8, {2, 2, 20}, {0, 0, -1}, 0.5);
  EXPECT_EQ(b.count, 15u);
  EXPECT_EQ(b.ray.start[2], 7 << 16);
  EXPECT_EQ(b.ray.step[2], -(1 << 15));
}

TEST(VolumeRaySetupTest, RaysMissingTheBox) {
  EXPECT_EQ(set_up_ray(k8, {-5, 10, 4}, {1, 0, 0}, 1).count, 0u);  // beside it, parallel
  EXPECT_EQ(set_up_ray(k8, {-5, 3, 4}, {-1, 0, 0}, 1).count, 0u);  // pointing away
  EXPECT_EQ(set_up_ray(k8, {-1, 9, 3}, glm::normalize(glm::dvec3(1, 1, 0)), 1).count, 0u);
  // Past a corner by a hair: at x = y = 0 it is 1e-7 below the box.
  EXPECT_EQ(set_up_ray(k8, {-1, -1, 0.9999999}, glm::normalize(glm::dvec3(1, 1, -1)), 1).count, 0u);
  // A hair the other way it meets the edge x = y = 0 at z = 1e-7: one location there.
  EXPECT_EQ(set_up_ray(k8, {-1, -1, 1.0000001}, glm::normalize(glm::dvec3(1, 1, -1)), 1).count, 1u);
}

TEST(VolumeRaySetupTest, RayStartingInside) {
  const RaySetup r = set_up_ray(k8, {3.5, 3.5, 3.5}, {0, 0, 1}, 1);
  EXPECT_EQ(r.start, glm::dvec3(3.5, 3.5, 3.5));  // at the eye
  EXPECT_EQ(r.count, 4u);                         // 3.5, 4.5, 5.5, 6.5 (7.5 is outside)
  // An eye on the far face looking out: one location, the eye.
  EXPECT_EQ(set_up_ray(k8, {7, 3, 3}, {1, 0, 0}, 1).count, 1u);
}

TEST(VolumeRaySetupTest, GrazingFacesEdgesAndCorners) {
  // Along a face (y = 0, in its plane): the whole row of voxels on the face.
  const RaySetup face = set_up_ray(k8, {-1, 0, 3}, {1, 0, 0}, 1);
  EXPECT_EQ(face.count, 8u);
  EXPECT_EQ(face.ray.start, (volume::Position{0, 0, 3 << 16}));
  // Along an edge (y = 0, z = 7).
  EXPECT_EQ(set_up_ray(k8, {-1, 0, 7}, {1, 0, 0}, 1).count, 8u);
  // Touching the edge x = 0, y = 0 from outside: entry = exit, one location on the edge.
  const RaySetup edge = set_up_ray(k8, {-1, 1, 3}, glm::normalize(glm::dvec3(1, -1, 0)), 1);
  ASSERT_EQ(edge.count, 1u);
  EXPECT_EQ(edge.ray.start, (volume::Position{0, 0, 3 << 16}));
  // Touching the corner (0, 0, 0) from outside.
  const RaySetup corner = set_up_ray(k8, {-1, -1, 1}, glm::normalize(glm::dvec3(1, 1, -1)), 1);
  ASSERT_EQ(corner.count, 1u);
  EXPECT_EQ(corner.ray.start, (volume::Position{0, 0, 0}));
  // Through two opposite corners: 7 sqrt(3) long, 13 locations of one voxel.
  const RaySetup diagonal = set_up_ray(k8, {10, 10, 10}, -glm::normalize(glm::dvec3(1)), 1);
  EXPECT_EQ(diagonal.count, 13u);
  EXPECT_EQ(diagonal.ray.start, (volume::Position{7 << 16, 7 << 16, 7 << 16}));
}

// Random rays: every location within the box (1e-9 of a step), the next one past the exit, the
// unit's locations within the quantisation's bound of the real ones.
TEST(VolumeRaySetupTest, LocationsFillTheSegmentInsideTheBox) {
  std::mt19937_64 rng(20);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::array<uint32_t, 3> size = {17, 9, 30};
  const glm::dvec3 hi(16, 8, 29);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 origin = glm::dvec3(8, 4, 15) + glm::dvec3(u(rng), u(rng), u(rng)) * 40.0;
    const glm::dvec3 dir =
        glm::normalize(glm::dvec3(8, 4, 15) + glm::dvec3(u(rng), u(rng), u(rng)) * 12.0 - origin);
    const double step = 0.25 + 2 * (u(rng) + 1);
    const RaySetup r = set_up_ray(size, origin, dir, step);
    if (r.count == 0) continue;
    ++hits;
    for (uint32_t n : {0u, r.count - 1}) {
      const glm::dvec3 p = r.start + r.step * double(n);
      for (int a = 0; a < 3; ++a) {
        EXPECT_GE(p[a], -1e-9 * step) << i;
        EXPECT_LE(p[a], hi[a] + 1e-9 * step) << i;
        const double unit = (r.ray.start[a] + double(r.ray.step[a]) * n) / 65536.0;
        EXPECT_LE(std::abs(unit - p[a]), (1 + n) * 0x1p-17 + 1e-12) << i;
      }
    }
    const glm::dvec3 beyond = r.start + r.step * double(r.count);
    bool outside = false;
    for (int a = 0; a < 3; ++a) outside |= beyond[a] < -1e-9 || beyond[a] > hi[a] + 1e-9;
    EXPECT_TRUE(outside) << i;
  }
  EXPECT_GT(hits, 500);
}

// ---- compositing ---------------------------------------------------------------------------

TEST(VolumeCompositingTest, FrontToBack) {
  RayCompositor c;
  c.add({{0.5, 0, 0}, 0.5});  // half-opaque red
  c.add({{0, 0, 1}, 1});      // opaque blue behind it
  EXPECT_EQ(c.colour(), glm::dvec3(0.5, 0, 0.5));
  EXPECT_EQ(c.alpha(), 1);
  EXPECT_EQ(c.over({1, 1, 1}), glm::dvec3(0.5, 0, 0.5));
  RayCompositor empty;
  EXPECT_EQ(empty.over({0.1, 0.2, 0.3}), glm::dvec3(0.1, 0.2, 0.3));
}

TEST(VolumeCompositingTest, OpacityCorrectionMakesTheStepInvisible) {
  // Two half steps through a uniform material block as much as one whole step.
  const TransferFunction tf({{0, {1, 1, 1}, 0.6}});
  const SampleShading whole(tf, {}, 1, k8), half(tf, {}, 0.5, k8);
  RayCompositor a, b;
  a.add(whole.raw(100, {}, {}));
  b.add(half.raw(100, {}, {}));
  b.add(half.raw(100, {}, {}));
  EXPECT_NEAR(a.alpha(), b.alpha(), 1e-15);
  EXPECT_NEAR(a.colour().r, b.colour().r, 1e-15);
}

TEST(VolumeCompositingTest, ShadingFromTheGradient) {
  std::vector<Light> lights = {{Light::Kind::kAmbient, {}, glm::dvec3(0.2)},
                               {Light::Kind::kDirectional, {0, 0, -1}, glm::dvec3(0.8)}};
  const SampleShading s(TransferFunction({{0, {1, 1, 1}, 1}}), lights, 1, k8);
  // The values fall towards +z (denser below): the normal is +z, facing the light.
  EXPECT_EQ(s.light({0, 0, -5}, {}), glm::dvec3(1.0));
  EXPECT_EQ(s.light({0, 0, 5}, {}), glm::dvec3(0.2));  // facing away: ambient
  EXPECT_NEAR(s.light({5, 0, -5}, {}).r, 0.2 + 0.8 / std::sqrt(2), 1e-12);
  EXPECT_EQ(s.light({0, 0, 0}, {}), glm::dvec3(1.0));  // no gradient: unshaded
}

// Early termination at t against none: per channel within 1 - A at the stop, <= 1 - t.
TEST(VolumeCompositingTest, EarlyTerminationWithinItsThreshold) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (double t : {0.5, 0.9, 0.99, 255.0 / 256, 1.0}) {
    double worst = 0;
    for (int ray = 0; ray < 2000; ++ray) {
      RayCompositor full, stopped(t);
      const glm::dvec3 bg(u(rng), u(rng), u(rng));
      const int n = 1 + static_cast<int>(u(rng) * 200);
      double stop_alpha = 0;
      for (int i = 0; i < n; ++i) {
        const double a = u(rng) < 0.7 ? 0.05 * u(rng) : u(rng);
        const Contribution c{glm::dvec3(u(rng), u(rng), u(rng)) * a, a};
        full.add(c);
        if (!stopped.terminated()) {
          stopped.add(c);
          stop_alpha = stopped.alpha();
        }
      }
      for (int ch = 0; ch < 3; ++ch) {
        const double d = std::abs(full.over(bg)[ch] - stopped.over(bg)[ch]);
        EXPECT_LE(d, 1 - stop_alpha + 1e-15);
        if (stopped.terminated()) {
          EXPECT_LE(d, 1 - t + 1e-15);
        }
        worst = std::max(worst, d);
      }
    }
    if (t == 1.0) {
      EXPECT_LE(worst, 1e-15);  // stops only when nothing more can be added
    }
  }
}

// ---- slabs ---------------------------------------------------------------------------------

TEST(VolumeSlabTest, PlansAndGhostPlanes) {
  const SlabPlan raw = plan_slabs({64, 32, 32}, 4, 0, volume::Mode::kRaw);
  ASSERT_EQ(raw.slabs.size(), 4u);
  EXPECT_EQ(raw.ghost_before, 1u);
  EXPECT_EQ(raw.ghost_after, 2u);
  EXPECT_EQ(raw.slabs[0].begin, 0u);
  EXPECT_EQ(raw.slabs[0].end, 18u);
  EXPECT_EQ(raw.slabs[1].own_begin, 16u);
  EXPECT_EQ(raw.slabs[1].begin, 15u);
  EXPECT_EQ(raw.slabs[1].end, 34u);
  EXPECT_EQ(raw.slabs[3].end, 64u);
  const SlabPlan value = plan_slabs({64, 32, 33}, 3, 2, volume::Mode::kValue);
  EXPECT_EQ(value.ghost_before, 0u);
  EXPECT_EQ(value.ghost_after, 1u);
  EXPECT_EQ(value.slabs[0].own_end, 11u);
  EXPECT_EQ(value.slabs[0].end, 12u);
  EXPECT_EQ(value.slabs[2].end, 33u);
  EXPECT_NE(slab_problem({64, 8, 8}, 5, 1, volume::Mode::kRaw), "");
  EXPECT_EQ(slab_problem({64, 8, 8}, 4, 1, volume::Mode::kRaw), "");
  // 512^3 fits no chip; on 32 it does (18 planes a slab: 2 x 64 x 32 bricks, 2^21 cells a bank),
  // on 16 not (34 planes: 3 bricks along x).
  EXPECT_NE(slab_problem({512, 512, 512}, 1, 0, volume::Mode::kRaw), "");
  EXPECT_NE(slab_problem({512, 512, 512}, 16, 0, volume::Mode::kRaw), "");
  EXPECT_EQ(slab_problem({512, 512, 512}, 32, 0, volume::Mode::kRaw), "");
}

volume::Ray random_ray(std::mt19937_64& rng, const std::array<uint32_t, 3>& n) {
  std::uniform_real_distribution<double> u(0, 1);
  volume::Ray r;
  const int kind = static_cast<int>(u(rng) * 4);
  for (size_t a = 0; a < 3; ++a) {
    // Starts inside and a little outside the box (clamped locations), on planes exactly at
    // times; steps of any sign up to 2.5 voxels, axis-parallel at times.
    double start = -2 + u(rng) * (n[a] + 3);
    if (kind == 0) start = std::floor(start);
    r.start[a] = volume::quantise(start);
    double step = (u(rng) - 0.5) * 5;
    if (kind == 1 && a != 0) step = 0;
    if (kind == 2) step = std::round(step);
    r.step[a] = volume::quantise(step);
  }
  r.count = 1 + static_cast<uint32_t>(u(rng) * 60);
  return r;
}

// The seam proof: every location of random rays resampled by the chip that owns it (its own
// voxels, its own memory and layout) equals the single chip's resample, in both modes, for
// several chip counts and every axis, on sizes that do not divide evenly.
TEST(VolumeSlabTest, EveryChipResamplesWhatTheSingleChipWould) {
  const std::array<uint32_t, 3> size = {23, 18, 29};
  volume::VoxelGrid g(size[0], size[1], size[2]);
  std::mt19937_64 rng(12);
  for (auto& v : g.voxels) v = static_cast<uint8_t>(rng());
  const volume::VolumeMemory whole = volume::load(g);
  size_t compared = 0;
  for (volume::Mode mode : {volume::Mode::kValue, volume::Mode::kRaw}) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int chips : {2, 3, 4, 7}) {
        const SlabPlan plan = plan_slabs(size, chips, axis, mode);
        std::vector<volume::VolumeMemory> memories;
        for (size_t c = 0; c < plan.slabs.size(); ++c)
          memories.push_back(volume::load(slab_grid(g, plan, c)));
        const volume::Config config{mode, 7};
        for (int i = 0; i < 150; ++i) {
          volume::Ray ray = random_ray(rng, size);
          if (!volume::ray_in_range(ray)) continue;
          const auto want = volume::cast(whole, config, ray);
          std::vector<volume::Resample> got;
          uint32_t next = 0;
          for (const ChipRun& run : split_by_chip(plan, ray, 0, ray.count)) {
            ASSERT_EQ(run.first, next);
            next += run.count;
            const auto part = volume::cast(memories[run.chip], config,
                                           chip_ray(plan, run.chip, ray, run.first, run.count));
            got.insert(got.end(), part.begin(), part.end());
          }
          ASSERT_EQ(got, want) << "mode " << int(mode) << " axis " << axis << " chips " << chips
                               << " ray " << i;
          compared += got.size();
        }
      }
    }
  }
  EXPECT_GT(compared, 50000u);
}

// A ray along the split axis crosses every seam: each chip takes a contiguous run and the runs
// go chip after chip (backwards for a negative step).
TEST(VolumeSlabTest, RaysAlongTheAxisCrossEverySeamInOrder) {
  const SlabPlan plan = plan_slabs({64, 8, 8}, 4, 0, volume::Mode::kRaw);
  const volume::Ray up{{0, 3 << 16, 3 << 16}, {1 << 15, 0, 0}, 127};  // x = 0, 0.5, .., 63
  const auto runs = split_by_chip(plan, up, 0, up.count);
  ASSERT_EQ(runs.size(), 4u);
  for (size_t c = 0; c < 4; ++c) {
    EXPECT_EQ(runs[c].chip, c);
    EXPECT_EQ(runs[c].count, c < 3 ? 32u : 31u);  // x = 16 c .. 16 c + 15.5 (63 alone: 31)
  }
  // Chip 1's ray starts at its own x = 16 - 15 = 1.
  EXPECT_EQ(chip_ray(plan, 1, up, runs[1].first, runs[1].count).start[0], 1 << 16);
  const volume::Ray down{{63 << 16, 3 << 16, 3 << 16}, {-(1 << 16), 0, 0}, 64};
  const auto back = split_by_chip(plan, down, 0, down.count);
  ASSERT_EQ(back.size(), 4u);
  EXPECT_EQ(back[0].chip, 3u);
  EXPECT_EQ(back[3].chip, 0u);
  // A part of the ray: locations 20..39 of `up` are x = 10 .. 19.5: chips 0 and 1.
  const auto part = split_by_chip(plan, up, 20, 20);
  ASSERT_EQ(part.size(), 2u);
  EXPECT_EQ(part[0].count, 12u);
  EXPECT_EQ(part[1].first, 32u);
}

}  // namespace
}  // namespace tmu::host
