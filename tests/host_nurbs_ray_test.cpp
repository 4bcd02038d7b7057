// nurbs::hit_through_pixel, the reference of `texsim sweep nurbs`: on a flat patch it agrees
// with the rasterizer's perspective-correct interpolation, which is exact there; on a sphere the
// point lies on the sphere and the screen derivatives equal the hits' differences; Newton
// crosses from one patch's domain into its neighbour's; a ray past the object finds nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "geometry/mesh.hpp"
#include "nurbs/patch.hpp"
#include "nurbs/ray_hit.hpp"
#include "raster/rasterizer.hpp"
#include "scene/scene.hpp"

namespace tmu::host::nurbs {
namespace {

using Json = nlohmann::ordered_json;

// A camera looking down at the origin from above and a little to the side (so the perspective
// is not symmetric), a checker material, and the objects given.
Scene scene_of(const Json& objects) {
  Json j = Json::parse(R"({
    "camera": {"position": [0.7, 3, 1.5], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 50,
               "resolution": [64, 48]},
    "materials": {"m": {"texture": {"pattern": "checker", "size": [64, 64], "cell": 8}}}
  })");
  j["objects"] = objects;
  return parse_scene(j.dump(), "test.json", ".");
}

// A flat degree-1 patch over [x0, x1] x [-1, 1] at height 0, knots [s0, s0, s1, s1] and
// [0, 0, 1, 1], facing +Y through a mirror in y (as tests/host_nurbs_mesh_test.cpp explains).
Json flat_patch(double x0, double x1, double s0, double s1) {
  return Json{{"degree", {1, 1}},
              {"knots_s", {s0, s0, s1, s1}},
              {"knots_t", {0, 0, 1, 1}},
              {"points", {{{x0, 0, -1}, {x1, 0, -1}}, {{x0, 0, 1}, {x1, 0, 1}}}}};
}

Json nurbs_object(const Json& patches) {
  return Json{{"type", "nurbs"},
              {"material", "m"},
              {"transform", {{"scale", {1, -1, 1}}}},
              {"patches", patches},
              {"tessellation", {{"dc", 2}}}};
}

std::vector<Fragment> fragments_of(const Scene& scene) {
  const std::vector<glm::ivec2> sizes(scene.materials.size(), glm::ivec2(1, 1));
  return rasterize(scene, make_meshes(scene, sizes), sizes);
}

TEST(HostNurbsRayTest, FlatPatchAgreesWithTheRasterizerFromAFarStart) {
  const Scene scene = scene_of(Json::array({nurbs_object(Json::array({flat_patch(-1, 1, 0, 1)}))}));
  const std::vector<Fragment> frags = fragments_of(scene);
  ASSERT_GT(frags.size(), 500u);
  for (const Fragment& f : frags) {
    // uv is the normalised (s, t) here (no tau, texture scale 1): start a fifth of the patch off.
    const glm::dvec2 guess = glm::clamp(f.uv + glm::dvec2(0.2, -0.2), 0.0, 1.0);
    const auto hit = hit_through_pixel(scene.objects[0], scene.camera, f.x + 0.5, f.y + 0.5, guess);
    ASSERT_TRUE(hit) << f.x << ", " << f.y;
    EXPECT_NEAR(hit->pc.x, f.uv.x, 1e-9);
    EXPECT_NEAR(hit->pc.y, f.uv.y, 1e-9);
    for (int c = 0; c < 2; ++c) {
      EXPECT_NEAR(hit->d_dx[c], f.r1[c], 1e-9 + 1e-7 * glm::length(f.r1));
      EXPECT_NEAR(hit->d_dy[c], f.r2[c], 1e-9 + 1e-7 * glm::length(f.r2));
    }
    EXPECT_NEAR(std::abs(hit->normal.y), 1.0, 1e-12);
  }
}

// Whether normalised (s, t) lies within `d` of a knot inside the patch's domain.
bool near_inner_knot(const Patch& p, glm::dvec2 pc, double d) {
  const auto near = [d](const std::vector<double>& knots, double lo, double hi, double x) {
    for (double k : knots) {
      if (k > lo && k < hi && std::abs((k - lo) / (hi - lo) - x) < d) return true;
    }
    return false;
  };
  return near(p.knots_s, p.s_min(), p.s_max(), pc.x) || near(p.knots_t, p.t_min(), p.t_max(), pc.y);
}

TEST(HostNurbsRayTest, SphereHitsLieOnTheSphereWithTheirDifferencesAsDerivatives) {
  const Scene scene = scene_of(Json::array(
      {{{"type", "nurbs"}, {"material", "m"}, {"surface", "sphere"}, {"radius", 1.0}}}));
  const Object& sphere = scene.objects[0];
  const std::vector<Fragment> frags = fragments_of(scene);
  ASSERT_GT(frags.size(), 300u);
  size_t checked = 0;
  for (const Fragment& f : frags) {
    const double x = f.x + 0.5, y = f.y + 0.5;
    const auto hit = hit_through_pixel(sphere, scene.camera, x, y, f.uv);
    if (!hit) continue;  // a ray grazing the silhouette
    ++checked;
    EXPECT_NEAR(glm::length(hit->position), 1.0, 1e-9);
    EXPECT_NEAR(glm::dot(hit->normal, hit->position), 1.0, 1e-6);  // outward and unit
    // Central differences over 1e-5 of a pixel, started from the hit itself; not across an
    // inner knot, where the standard nets are only G1 (the speed along s or t jumps). Near the
    // silhouette (s, t) bend so fast that 1e-3 of a pixel is already off by 0.6 %.
    constexpr double h = 1e-5;
    if (near_inner_knot(sphere.patches[0], hit->pc, 1e-3)) continue;
    const auto at = [&](double px, double py) {
      const auto g = hit_through_pixel(sphere, scene.camera, px, py, hit->pc);
      return g ? g->pc : glm::dvec2(NAN);
    };
    const glm::dvec2 dx = (at(x + h, y) - at(x - h, y)) / (2 * h);
    const glm::dvec2 dy = (at(x, y + h) - at(x, y - h)) / (2 * h);
    if (!std::isfinite(dx.x + dx.y + dy.x + dy.y)) continue;
    const double scale = glm::length(hit->d_dx) + glm::length(hit->d_dy);
    // The quotient's error: h^2 / 6 times the third derivative, and Newton's residual (1e-9 of
    // the sphere at most, mostly far less) over 2 h: below 1e-4 of the derivatives' size.
    EXPECT_NEAR(hit->d_dx.x, dx.x, 1e-4 * scale) << x << ", " << y;
    EXPECT_NEAR(hit->d_dx.y, dx.y, 1e-4 * scale) << x << ", " << y;
    EXPECT_NEAR(hit->d_dy.x, dy.x, 1e-4 * scale) << x << ", " << y;
    EXPECT_NEAR(hit->d_dy.y, dy.y, 1e-4 * scale) << x << ", " << y;
  }
  EXPECT_GT(checked, frags.size() * 9 / 10);
}

TEST(HostNurbsRayTest, NewtonCrossesIntoTheNeighbouringPatch) {
  // Two patches side by side, s in [0, 1] on x in [-1, 0] and [1, 2] on [0, 1]: normalised
  // s = 0.5 is the join.
  const Scene scene = scene_of(
      Json::array({nurbs_object(Json::array({flat_patch(-1, 0, 0, 1), flat_patch(0, 1, 1, 2)}))}));
  const std::vector<Fragment> frags = fragments_of(scene);
  size_t crossed = 0;
  for (const Fragment& f : frags) {
    const double s = f.uv.x;
    if (s < 0.6) continue;  // on the right patch: start in the left one
    const auto hit = hit_through_pixel(scene.objects[0], scene.camera, f.x + 0.5, f.y + 0.5,
                                       glm::dvec2(0.25, f.uv.y));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->pc.x, f.uv.x, 1e-9);
    EXPECT_NEAR(hit->pc.y, f.uv.y, 1e-9);
    ++crossed;
  }
  EXPECT_GT(crossed, 100u);
}

TEST(HostNurbsRayTest, ARayPastTheObjectFindsNothing) {
  const Scene scene =
      scene_of(Json::array({nurbs_object(Json::array({flat_patch(-0.2, 0.2, 0, 1)}))}));
  // The frame's corner sees the plane y = 0 far outside the narrow patch.
  EXPECT_FALSE(hit_through_pixel(scene.objects[0], scene.camera, 0.5, 0.5, glm::dvec2(0.5)));
  // A ray that misses everything: the sky above the horizon is not in view here, so look the
  // other way: a camera under the patch looking down.
  Scene below = scene;
  below.camera.position = glm::dvec3(0, -1, 0.001);
  below.camera.target = glm::dvec3(0, -3, 0);
  EXPECT_FALSE(hit_through_pixel(below.objects[0], below.camera, 32, 24, glm::dvec2(0.5)));
}

}  // namespace
}  // namespace tmu::host::nurbs
