// NURBS objects in scenes (004): every key checked with a clear error; the tessellation's step
// counts (claims 8-11) and claim 12's level; watertight joins between patches with different
// step counts; the hard cases (collapsed poles, C0 joints, extreme weights, a folded tau, the
// seam of a closed surface, a patch smaller than a pixel); identity tau on a flat bilinear patch
// rendering the plane object's fragments.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "common/error.hpp"
#include "geometry/mesh.hpp"
#include "nurbs/conics.hpp"
#include "nurbs/nurbs_mesh.hpp"
#include "raster/rasterizer.hpp"
#include "scene/scene.hpp"

namespace tmu::host {
namespace {

using Json = nlohmann::ordered_json;

// A camera above the origin looking down (-Y), a checker material, and the objects given.
Json scene_with(const Json& objects, const Json& material_extra = Json::object()) {
  Json j = Json::parse(R"({
    "camera": {"position": [0, 4, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 50,
               "resolution": [96, 96]},
    "materials": {"m": {"texture": {"pattern": "checker", "size": [64, 64], "cell": 8}}}
  })");
  for (const auto& [k, v] : material_extra.items()) j["materials"]["m"][k] = v;
  j["objects"] = objects;
  return j;
}

// A degree-1 patch over [x0, x1] x [z0, z1] at height 0, its knots [a, a, b, b] along s and t.
// Its front, S_s x S_t (s along x, t along z), faces -Y; the objects below mirror it in y
// (kFaceUp, which leaves a flat patch in place) to face the camera above, as the plane object
// does: the plane's (u, v, normal) is a left-handed frame, a patch's (s, t, front) right-handed.
Json bilinear_patch(double x0, double x1, double z0, double z1, double s0 = 0, double s1 = 1,
                    double t0 = 0, double t1 = 1) {
  return Json{{"degree", {1, 1}},
              {"knots_s", {s0, s0, s1, s1}},
              {"knots_t", {t0, t0, t1, t1}},
              {"points", {{{x0, 0, z0}, {x1, 0, z0}}, {{x0, 0, z1}, {x1, 0, z1}}}}};
}

const Json kFaceUp = {{"scale", {1, -1, 1}}};

Scene parse(const Json& j) { return parse_scene(j.dump(), "test.json", "."); }

void expect_error(const Json& j, const std::string& field, const std::string& reason) {
  try {
    parse(j);
    ADD_FAILURE() << "no error; expected " << field << ": " << reason;
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
  }
}

std::vector<Fragment> render(const Scene& scene) {
  const std::vector<glm::ivec2> sizes(scene.materials.size(), glm::ivec2(64, 64));
  return rasterize(scene, make_meshes(scene, sizes), sizes);
}

// Pixels no triangle covers although both horizontal or both vertical neighbours are covered:
// a crack (a convex silhouette has none).
int pinholes(const std::vector<Fragment>& frags, int w, int h) {
  std::set<std::pair<int, int>> covered;
  for (const Fragment& f : frags) covered.insert({f.x, f.y});
  const auto at = [&](int x, int y) { return covered.count({x, y}) > 0; };
  int holes = 0;
  for (int y = 1; y + 1 < h; ++y) {
    for (int x = 1; x + 1 < w; ++x) {
      if (!at(x, y) && ((at(x - 1, y) && at(x + 1, y)) || (at(x, y - 1) && at(x, y + 1)))) ++holes;
    }
  }
  return holes;
}

TEST(HostNurbsSceneTest, EveryKeyIsCheckedWithAClearError) {
  Json bad = scene_with(
      {{{"type", "nurbs"}, {"material", "m"}, {"patches", {bilinear_patch(-1, 1, -1, 1)}}}});
  Json j = bad;
  j["objects"][0]["patches"][0]["knots_s"] = {0, 1, 0.5, 1};
  expect_error(j, "objects[0].patches[0]", "knots_s: not non-decreasing");
  j = bad;
  j["objects"][0]["patches"][0]["points"][1] = {{0, 0, 1}};
  expect_error(j, "objects[0].patches[0].points[1]", "the net is a rectangle");
  j = bad;
  j["objects"][0]["patches"][0]["points"][0][1] = {1, 0, -1, 0};
  expect_error(j, "objects[0].patches[0].points[0][1][3]", "a weight must be > 0");
  j = bad;
  j["objects"][0]["patches"][0]["points"][0][1] = {1, 0, -1, -2};
  expect_error(j, "objects[0].patches[0].points[0][1][3]", "a weight must be > 0");
  j = bad;
  j["objects"][0]["patches"][0]["degree"] = {4, 1};
  expect_error(j, "objects[0].patches[0].degree[0]", "");
  j = bad;
  j["objects"][0]["patches"][0]["degree"] = {2, 1};
  expect_error(j, "objects[0].patches[0]", "count_s: 2 control points, expected at least");
  j = bad;
  j["objects"][0]["patches"][0]["knots_t"] = {0, 0, 1};
  expect_error(j, "objects[0].patches[0]", "knots_t");
  j = bad;
  j["objects"][0]["tessellation"] = {{"dc", 0}};
  expect_error(j, "objects[0].tessellation.dc", "must be > 0");
  j = bad;
  j["objects"][0]["tessellation"] = {{"combine", "median"}};
  expect_error(j, "objects[0].tessellation.combine", "");
  j = bad;
  j["objects"][0]["surface"] = "sphere";
  expect_error(j, "objects[0].patches", "give either surface or patches");
  // The tau keys: only on nurbs objects, lod tc not with pc, grids rectangular.
  j = scene_with({{{"type", "plane"}, {"material", "m"}}}, {{"order", "pc"}});
  expect_error(j, "objects[0].material", "needs a nurbs object");
  j = bad;
  j["materials"]["m"]["order"] = "pc";
  j["materials"]["m"]["lod"] = "tc";
  expect_error(j, "materials.m.lod", "lod tc (claim 12) applies");
  j = bad;
  j["materials"]["m"]["tau"] = {
      {"map", "grid"}, {"nodes", Json::parse("[[[0, 0], [1, 0]], [[0, 1], [1, 1], [2, 1]]]")}};
  expect_error(j, "materials.m.tau.nodes[1]", "the grid is a rectangle");
  j = bad;
  j["materials"]["m"]["tau"] = {{"map", "affine"}, {"cells", {0, 4}}};
  expect_error(j, "materials.m.tau.cells[0]", "");
}

TEST(HostNurbsSceneTest, ConicsAndTauKeysParse) {
  const Scene s = parse(scene_with(
      {{{"type", "nurbs"}, {"material", "m"}, {"surface", "torus"}, {"radius", 2}, {"tube", 0.5}}},
      {{"tau",
        {{"map", "wave"}, {"amplitude", 0.1}, {"cells", {4, 8}}, {"interpolation", "spline"}}},
       {"order", "pc"}}));
  ASSERT_EQ(s.objects[0].patches.size(), 1u);
  EXPECT_EQ(s.objects[0].patches[0].count_s, 9);
  EXPECT_EQ(*s.objects[0].tessellation.dc, 4);  // the default threshold
  ASSERT_TRUE(s.materials[0].tau);
  EXPECT_EQ(s.materials[0].tau->kind, nurbs::TauMap::Kind::kWave);
  EXPECT_EQ(s.materials[0].tau->cells, glm::ivec2(4, 8));
  EXPECT_EQ(s.materials[0].tau->interp, tau::Interp::kSpline);
  EXPECT_EQ(s.materials[0].order, Material::Order::kPc);
}

// Claims 8-11: the counts follow n = ceil(bound * span / threshold), combined and capped.
TEST(HostNurbsStepsTest, CountsFollowTheThresholds) {
  nurbs::Patch flat = nurbs::sphere(1);  // any patch: replaced by a 4 x 2 bilinear sheet
  flat.degree_s = flat.degree_t = 1;
  flat.count_s = flat.count_t = 2;
  flat.knots_s = flat.knots_t = {0, 0, 1, 1};
  flat.points = {{0, 0, 0}, {4, 0, 0}, {0, 0, 2}, {4, 0, 2}};
  flat.weights = {1, 1, 1, 1};
  Tessellation t;
  t.mc = 0.5;
  nurbs::StepContext c;
  nurbs::PatchSteps p = nurbs::patch_steps(flat, {0, 1, 0, 1}, t, c);
  EXPECT_EQ(p.steps, glm::ivec2(8, 4));  // 4 / 0.5, 2 / 0.5: the bilinear bound is exact
  // TC: an identity tau on a 64 x 32 texture: 64 and 32 texels across; 8 texels a step.
  nurbs::TauMap id;
  c.tau = &id;
  c.texture_size = {64, 32};
  t.tc = 8;
  p = nurbs::patch_steps(flat, {0, 1, 0, 1}, t, c);
  EXPECT_EQ(*p.tc, glm::ivec2(8, 4));
  t.tc = 2;  // n_T = (32, 16), n_N = (8, 4): the mean (20, 10)
  p = nurbs::patch_steps(flat, {0, 1, 0, 1}, t, c);
  EXPECT_EQ(p.steps, glm::ivec2(20, 10));
  EXPECT_NEAR(p.lambda, std::log2(64.0 / 20), 1e-12);  // claim 12: texels per step
  t.combine = Tessellation::Combine::kMax;
  EXPECT_EQ(nurbs::patch_steps(flat, {0, 1, 0, 1}, t, c).steps, glm::ivec2(32, 16));
  t.combine = Tessellation::Combine::kGeometric;
  EXPECT_EQ(nurbs::patch_steps(flat, {0, 1, 0, 1}, t, c).steps, glm::ivec2(16, 8));
  t.max_steps = 12;
  EXPECT_EQ(nurbs::patch_steps(flat, {0, 1, 0, 1}, t, c).steps, glm::ivec2(12, 8));
  // Half the object's parameter rectangle: tau's texels over the patch halve.
  t = {};
  t.tc = 8;
  EXPECT_EQ(*nurbs::patch_steps(flat, {0, 0.5, 0, 1}, t, c).tc, glm::ivec2(4, 4));
}

// DC (claim 10): every step of the tessellated patch is at most d_dc pixels on the screen.
TEST(HostNurbsStepsTest, DcThresholdBoundsEveryStepOnTheScreen) {
  const Scene s = parse(scene_with({{{"type", "nurbs"},
                                     {"material", "m"},
                                     {"surface", "sphere"},
                                     {"tessellation", {{"dc", 3}, {"max_steps", 1024}}}}}));
  const Mesh m = make_meshes(s, {{64, 64}})[0];
  const Camera& c = s.camera;
  const double focal = c.height / (2 * std::tan(glm::radians(c.fov_deg) / 2));
  double longest = 0;
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 a = m.vertices[t[k]].position, b = m.vertices[t[(k + 1) % 3]].position;
      // Depth along -Y from the eye at y = 4: the sphere's points are 3..5 away.
      const auto screen = [&](glm::dvec3 p) { return glm::dvec2(p.x, p.z) * focal / (4 - p.y); };
      longest = std::max(longest, glm::length(screen(a) - screen(b)));
    }
  }
  // A step is at most 3 pixels; a triangle's diagonal at most sqrt(2) steps.
  EXPECT_LE(longest, 3 * std::sqrt(2.0) + 1e-9);
  // The bound is conservative (the sphere's derivative bound is 2-2.6 times its largest
  // derivative, and the perspective factor adds 1.2 at the frame's corner), not absurd.
  EXPECT_GT(longest, 3.0 / 8);
}

// Two patches sharing a curved edge (bulging toward +x), the second one cut finer along it
// (4 steps against 3: its far edge is longer): the join takes the finer count on both sides.
// Without it the coarse side's chords would leave a crack about a pixel wide along the bulge.
TEST(HostNurbsMeshTest, JoinsStayWatertightWithDifferentStepCounts) {
  const Json patches = Json::parse(R"([
    {"degree": [1, 2], "knots_s": [0, 0, 1, 1], "knots_t": [0, 0, 0, 1, 1, 1],
     "points": [[[-1.5, 0, -1.2], [0.1, 0, -1.2]], [[-1.5, 0, 0], [0.9, 0, 0]],
                [[-1.5, 0, 1.2], [0.1, 0, 1.2]]]},
    {"degree": [1, 2], "knots_s": [1, 1, 2, 2], "knots_t": [0, 0, 0, 1, 1, 1],
     "points": [[[0.1, 0, -1.2], [1.5, 0, -2]], [[0.9, 0, 0], [1.5, 0, 0]],
                [[0.1, 0, 1.2], [1.5, 0, 2]]]}])");
  Json object = {{"type", "nurbs"}, {"material", "m"}, {"transform", kFaceUp}};
  object["patches"] = patches;
  object["tessellation"] = {{"mc", 1.0}};
  const Scene s = parse(scene_with(Json::array({object})));
  nurbs::NurbsStats stats;
  nurbs::tessellate(s.objects[0], s.materials[0], s.camera, {64, 64}, &stats);
  EXPECT_EQ(stats.joins, 1u);
  EXPECT_EQ(stats.patches[0].steps.y, 3);
  EXPECT_EQ(stats.patches[1].steps.y, 4);
  const std::vector<Fragment> frags = render(s);
  EXPECT_GT(frags.size(), 3000u);
  EXPECT_EQ(pinholes(frags, 96, 96), 0);
}

// Claim 15/16 against the plane object: a flat bilinear patch with the identity tau renders
// exactly the plane's fragments when it is one step each way (the same two triangles), and the
// same pixels with the same texture coordinates (to rounding) when cut finer.
TEST(HostNurbsMeshTest, IdentityTauOnAFlatBilinearPatchRendersThePlane) {
  const Json plane = {{{"type", "plane"}, {"size", {2, 2}}, {"material", "m"}}};
  const std::vector<Fragment> want = render(parse(scene_with(plane)));
  for (double mc : {100.0, 0.1}) {
    const Json patch = {{{"type", "nurbs"},
                         {"material", "m"},
                         {"transform", kFaceUp},
                         {"patches", {bilinear_patch(-1, 1, -1, 1)}},
                         {"tessellation", {{"mc", mc}}}}};
    const std::vector<Fragment> got =
        render(parse(scene_with(patch, {{"tau", {{"map", "identity"}}}})));
    ASSERT_EQ(got.size(), want.size()) << mc;
    for (size_t i = 0; i < got.size(); ++i) {
      ASSERT_EQ(got[i].x, want[i].x);
      ASSERT_EQ(got[i].y, want[i].y);
      if (mc == 100.0) {
        EXPECT_EQ(quantize(got[i]), quantize(want[i]));
      } else {
        EXPECT_NEAR(got[i].uv.x, want[i].uv.x, 1e-9);
        EXPECT_NEAR(got[i].uv.y, want[i].uv.y, 1e-9);
      }
    }
  }
}

// The hard cases: each renders finite fragments without cracks.
TEST(HostNurbsMeshTest, HardCasesStayFiniteAndClosed) {
  const auto finite = [](const std::vector<Fragment>& frags) {
    for (const Fragment& f : frags) {
      if (!std::isfinite(f.uv.x) || !std::isfinite(f.uv.y) || !std::isfinite(f.lambda) ||
          !std::isfinite(f.normal.x) || !std::isfinite(f.r1.x) || !std::isfinite(f.r2.y))
        return false;
    }
    return true;
  };
  // Closed surfaces: the sphere's collapsed poles and seam, the torus's two seams, the
  // cylinder's seam; seen from above and from the side.
  for (const char* surface : {"sphere", "torus", "cylinder"}) {
    Json object = {{"type", "nurbs"}, {"material", "m"}, {"surface", surface}};
    object["transform"]["rotate"] = {30, 10, 0};
    const Json j = scene_with(Json::array({object}));
    const std::vector<Fragment> frags = render(parse(j));
    EXPECT_GT(frags.size(), 500u) << surface;
    EXPECT_TRUE(finite(frags)) << surface;
    EXPECT_EQ(pinholes(frags, 96, 96), 0) << surface;
  }
  // The sphere's poles: every normal unit length (the collapsed edge's limit normal).
  const Scene sphere =
      parse(scene_with({{{"type", "nurbs"}, {"material", "m"}, {"surface", "sphere"}}}));
  const Mesh sphere_mesh = make_meshes(sphere, {{64, 64}})[0];
  for (const Vertex& v : sphere_mesh.vertices) EXPECT_NEAR(glm::length(v.normal), 1.0, 1e-9);
  // C0 joints (a repeated interior knot) and weights from 1e-3 to 1e3 in one net.
  const Json c0_patch = Json::parse(R"({
    "degree": [2, 1], "knots_s": [0, 0, 0, 0.5, 0.5, 1, 1, 1], "knots_t": [0, 0, 1, 1],
    "points": [
      [[-1.5, 0, -1, 1], [-0.5, 0.5, -1, 1e3], [0, 0, -1, 1e-3], [0.5, 0.3, -1, 1], [1.5, 0, -1, 1]],
      [[-1.5, 0, 1, 1], [-0.5, 0.5, 1, 1e-3], [0, 0, 1, 1e3], [0.5, 0.3, 1, 1], [1.5, 0, 1, 1]]]})");
  Json c0_object = {{"type", "nurbs"}, {"material", "m"}, {"transform", kFaceUp}};
  c0_object["patches"] = Json::array({c0_patch});
  const Json c0 = scene_with(Json::array({c0_object}));
  std::vector<Fragment> frags = render(parse(c0));
  EXPECT_GT(frags.size(), 500u);
  EXPECT_TRUE(finite(frags));
  // A folded tau (the Jacobian's determinant below zero over half the surface).
  const Json folded_nodes = Json::parse("[[[0, 0], [1, 0], [0, 0]], [[0, 1], [1, 1], [0, 1]]]");
  Json fold = scene_with({{{"type", "nurbs"},
                           {"material", "m"},
                           {"transform", kFaceUp},
                           {"patches", {bilinear_patch(-1, 1, -1, 1)}}}},
                         {{"tau", {{"map", "grid"}, {"nodes", folded_nodes}}}});
  frags = render(parse(fold));
  EXPECT_GT(frags.size(), 500u);
  EXPECT_TRUE(finite(frags));
  // A patch smaller than a pixel: at most a couple of fragments, none lost to an error.
  Json tiny = scene_with({{{"type", "nurbs"},
                           {"material", "m"},
                           {"transform", kFaceUp},
                           {"patches", {bilinear_patch(-1e-3, 1e-3, -1e-3, 1e-3)}}}});
  frags = render(parse(tiny));
  EXPECT_LE(frags.size(), 2u);
  EXPECT_TRUE(finite(frags));
}

}  // namespace
}  // namespace tmu::host
