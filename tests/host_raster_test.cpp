// The front end: exact coverage (top-left rule, no gaps or double hits), clipping, the depth
// test, perspective-correct attributes against ray casting, exact derivatives against finite
// differences, bands, degenerate and invisible input, lighting; quantize() into the port
// formats.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <random>
#include <set>

#include "formats/formats.hpp"
#include "geometry/mesh.hpp"
#include "raster/coverage.hpp"
#include "raster/fragment.hpp"
#include "raster/rasterizer.hpp"
#include "raster/triangle_setup.hpp"

namespace tmu::host {
namespace {

// A scene with `materials` materials and no objects; objects come with their meshes.
struct World {
  Scene scene;
  std::vector<Mesh> meshes;
  std::vector<glm::ivec2> sizes;

  World(glm::dvec3 eye, glm::dvec3 target, double fov, int width, int height, int materials = 2) {
    scene.camera.position = eye;
    scene.camera.target = target;
    scene.camera.up = {0, 1, 0};
    scene.camera.fov_deg = fov;
    scene.camera.width = width;
    scene.camera.height = height;
    for (int i = 0; i < materials; ++i) {
      Material m;
      m.name = fmt::format("m{}", i);
      scene.materials.push_back(m);
      sizes.push_back({256, 128});
    }
  }
  void add(const Mesh& mesh, int material = 0, const Transform& t = {}) {
    Object o;
    o.shape = Object::Shape::kMesh;
    o.material = material;
    o.transform = t;
    scene.objects.push_back(o);
    meshes.push_back(mesh);
  }
  void add_shape(Object o) {
    meshes.push_back(make_mesh(o));
    scene.objects.push_back(o);
  }
  std::vector<Fragment> render(RasterStats* stats = nullptr, int begin = 0, int end = -1) const {
    return rasterize(scene, meshes, sizes, begin, end, stats);
  }
};

// A parallelogram corner, corner + eu, corner + eu + ev, corner + ev with uv (0,0) (1,0)
// (1,1) (0,1), counter-clockwise seen from the side cross(eu, ev) points to.
Mesh quad(glm::dvec3 corner, glm::dvec3 eu, glm::dvec3 ev) {
  const glm::dvec3 n = glm::normalize(glm::cross(eu, ev));
  Mesh m;
  m.vertices = {{corner, n, {0, 0}},
                {corner + eu, n, {1, 0}},
                {corner + eu + ev, n, {1, 1}},
                {corner + ev, n, {0, 1}}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

Mesh triangle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  const glm::dvec3 g = glm::cross(b - a, c - a);
  const glm::dvec3 n = glm::length(g) > 0 ? glm::normalize(g) : glm::dvec3(0, 1, 0);
  Mesh m;
  m.vertices = {{a, n, {0, 0}}, {b, n, {1, 0}}, {c, n, {0, 1}}};
  m.triangles = {{0, 1, 2}};
  return m;
}

bool finite(const Fragment& f) {
  const double v[] = {f.depth,    f.uv.x,     f.uv.y,    f.r1.x,    f.r1.y,    f.r2.x,
                      f.r2.y,     f.lambda,   f.solid.x, f.solid.y, f.solid.z, f.normal.x,
                      f.normal.y, f.normal.z, f.view.x,  f.view.y,  f.view.z,  f.shade.x};
  for (double x : v) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

bool identical(const Fragment& a, const Fragment& b) {
  return a.x == b.x && a.y == b.y && a.material == b.material && a.depth == b.depth &&
         a.uv == b.uv && a.r1 == b.r1 && a.r2 == b.r2 && a.lambda == b.lambda &&
         a.solid == b.solid && a.normal == b.normal && a.view == b.view && a.shade == b.shade;
}

// The ray from the eye through screen point (sx, sy), built from the camera's definition
// (not from the rasterizer's matrices).
struct Ray {
  glm::dvec3 origin, dir;
};
Ray camera_ray(const Camera& c, double sx, double sy) {
  const glm::dvec3 f = glm::normalize(c.target - c.position);
  const glm::dvec3 r = glm::normalize(glm::cross(f, c.up));
  const glm::dvec3 u = glm::cross(r, f);
  const double t = std::tan(glm::radians(c.fov_deg) / 2);
  const double aspect = static_cast<double>(c.width) / c.height;
  const double nx = sx / c.width * 2 - 1, ny = 1 - sy / c.height * 2;
  return {c.position, f + nx * t * aspect * r + ny * t * u};
}

// Where the ray meets the plane through p with normal n.
glm::dvec3 hit(const Ray& ray, glm::dvec3 p, glm::dvec3 n) {
  const double t = glm::dot(p - ray.origin, n) / glm::dot(ray.dir, n);
  return ray.origin + t * ray.dir;
}

// --- coverage ------------------------------------------------------------------------------

TEST(HostRasterTest, PlaneFacingTheCameraFillsExactPixelsWithExactAttributes) {
  // 90 degrees, 64 x 64 from 1 unit away: one pixel is 1/32 unit at z = 0, and screen x is
  // (X + 1) * 32. The quad's edges lie on pixel centres: x 16.5 .. 48.5, y 8.5 .. 40.5, and
  // its diagonal runs through centres too, so every tie of the fill rule occurs.
  World w({0, 0, 1}, {0, 0, 0}, 90, 64, 64);
  const double x0 = 16.5 / 32 - 1, y0 = 1 - 40.5 / 32;
  w.add(quad({x0, y0, 0}, {1, 0, 0}, {0, 1, 0}));
  RasterStats stats;
  const std::vector<Fragment> frags = w.render(&stats);
  // Top and left edges are in, bottom and right out: columns 16..47, rows 8..39.
  ASSERT_EQ(frags.size(), 32u * 32u);
  EXPECT_EQ(stats.visible, 1024u);
  EXPECT_EQ(stats.fragments, 1024u);  // the shared diagonal: no pixel drawn twice
  EXPECT_EQ(stats.triangles, 2u);
  const Camera& c = w.scene.camera;
  const double z_ndc = c.far * (1 - c.near) / (c.far - c.near);
  for (size_t i = 0; i < frags.size(); ++i) {
    const Fragment& f = frags[i];
    ASSERT_EQ(f.x, 16 + static_cast<int>(i % 32));
    ASSERT_EQ(f.y, 8 + static_cast<int>(i / 32));
    const double X = (f.x + 0.5) / 32 - 1, Y = 1 - (f.y + 0.5) / 32;
    EXPECT_NEAR(f.uv.x, (X - x0) * 256, 1e-9);
    EXPECT_NEAR(f.uv.y, (Y - y0) * 128, 1e-9);
    EXPECT_NEAR(f.r1.x, 8, 1e-9);  // 256 texels over 32 pixels
    EXPECT_NEAR(f.r1.y, 0, 1e-9);
    EXPECT_NEAR(f.r2.x, 0, 1e-9);
    EXPECT_NEAR(f.r2.y, -4, 1e-9);  // v grows upward, y downward
    EXPECT_NEAR(f.lambda, 3, 1e-9);
    EXPECT_NEAR(f.depth, z_ndc, 1e-12);
    EXPECT_NEAR(glm::length(f.solid - glm::dvec3(X, Y, 0)), 0, 1e-12);
    EXPECT_EQ(f.normal, glm::dvec3(0, 0, 1));
    EXPECT_NEAR(glm::length(f.view - glm::normalize(glm::dvec3(-X, -Y, 1))), 0, 1e-12);
    EXPECT_EQ(f.shade, glm::dvec3(1));  // no lights
    EXPECT_EQ(f.material, 0);
  }
}

// Random triangulated grids with vertices on pixel centres, corners and half-way points:
// every pixel centre inside the grid's interior is covered exactly once.
TEST(HostRasterTest, SharedEdgesCoverEachPixelExactlyOnce) {
  const uint32_t seed = 12345;
  std::mt19937 rng(seed);
  constexpr int kCells = 12, kSpacing = 5;  // pixels
  constexpr int kSize = kCells * kSpacing + 2;
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE(testing::Message() << "seed " << seed << " trial " << trial);
    // Grid vertex (i, j) at (1 + kSpacing i, 1 + kSpacing j) pixels plus a jitter of a multiple
    // of half a pixel, up to +-1 pixel.
    std::vector<SubpixelPoint> p((kCells + 1) * (kCells + 1));
    for (int j = 0; j <= kCells; ++j) {
      for (int i = 0; i <= kCells; ++i) {
        const auto jitter = [&] {
          return static_cast<int64_t>(rng() % 5) * (kSubpixel / 2) - kSubpixel;
        };
        const bool inner = i > 0 && j > 0 && i < kCells && j < kCells;
        p[static_cast<size_t>(j * (kCells + 1) + i)] = {
            (1 + kSpacing * i) * kSubpixel + (inner ? jitter() : 0),
            (1 + kSpacing * j) * kSubpixel + (inner ? jitter() : 0)};
      }
    }
    // Pieces of the triangulation in their common orientation; a jitter that flips a
    // triangle makes an invalid mesh: such a trial is skipped.
    std::vector<std::array<SubpixelPoint, 3>> pieces;
    for (int j = 0; j < kCells; ++j) {
      for (int i = 0; i < kCells; ++i) {
        const auto at = [&](int di, int dj) {
          return p[static_cast<size_t>((j + dj) * (kCells + 1) + i + di)];
        };
        if (rng() & 1) {
          pieces.push_back({at(0, 0), at(1, 0), at(1, 1)});
          pieces.push_back({at(0, 0), at(1, 1), at(0, 1)});
        } else {
          pieces.push_back({at(0, 0), at(1, 0), at(0, 1)});
          pieces.push_back({at(1, 0), at(1, 1), at(0, 1)});
        }
      }
    }
    bool valid = true;
    for (const auto& t : pieces) valid = valid && twice_area(t[0], t[1], t[2]) > 0;
    if (!valid) continue;
    ++checked;
    std::vector<int> count(kSize * kSize, 0);
    for (const auto& t : pieces) {
      for_each_covered_pixel(t[0], t[1], t[2], kSize, 0, kSize,
                             [&](int x, int y) { ++count[static_cast<size_t>(y * kSize + x)]; });
    }
    // The outer boundary is the unjittered square from pixel 1 to 1 + kCells * kSpacing.
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const double cx = x + 0.5, cy = y + 0.5;
        const bool inside =
            cx > 1 && cy > 1 && cx < 1 + kCells * kSpacing && cy < 1 + kCells * kSpacing;
        ASSERT_EQ(count[static_cast<size_t>(y * kSize + x)], inside ? 1 : 0)
            << "pixel " << x << ", " << y;
      }
    }
  }
  EXPECT_GE(checked, 30);
}

TEST(HostRasterTest, FanAroundAPixelCentreCoversItOnce) {
  // 16 triangles around a vertex exactly on the centre of pixel (20, 20).
  const SubpixelPoint centre{20 * kSubpixel + kSubpixel / 2, 20 * kSubpixel + kSubpixel / 2};
  std::vector<SubpixelPoint> ring;
  for (int k = 0; k < 16; ++k) {
    const double a = 2 * 3.14159265358979 * k / 16;
    ring.push_back(snap({20.5 + 10 * std::cos(a), 20.5 + 10 * std::sin(a)}));
  }
  std::vector<int> count(48 * 48, 0);
  for (size_t k = 0; k < ring.size(); ++k) {
    SubpixelPoint b = ring[k], c = ring[(k + 1) % ring.size()];
    if (twice_area(centre, b, c) < 0) std::swap(b, c);
    for_each_covered_pixel(centre, b, c, 48, 0, 48,
                           [&](int x, int y) { ++count[static_cast<size_t>(y * 48 + x)]; });
  }
  EXPECT_EQ(count[20 * 48 + 20], 1);
  for (int y = 14; y < 27; ++y) {
    for (int x = 14; x < 27; ++x)
      EXPECT_EQ(count[static_cast<size_t>(y * 48 + x)], 1) << x << ", " << y;
  }
}

TEST(HostRasterTest, ClosedMeshFrontFacesNeverOverlap) {
  World w({0.3, 0.4, 4}, {0, 0, 0}, 50, 120, 90);
  Object sphere;
  sphere.shape = Object::Shape::kSphere;
  sphere.segments = {24, 12};
  w.add_shape(sphere);
  RasterStats stats;
  const std::vector<Fragment> frags = w.render(&stats);
  EXPECT_GT(frags.size(), 1000u);
  EXPECT_EQ(stats.fragments, stats.visible);  // back faces culled, front faces tile
  for (const Fragment& f : frags) {
    ASSERT_TRUE(finite(f));
    // Facing the eye, up to smoothing: a vertex normal is at most one 15-degree segment
    // away from the face's normal.
    EXPECT_GT(glm::dot(f.normal, f.view), -std::sin(glm::radians(15.0)));
  }
}

// --- clipping --------------------------------------------------------------------------------

TEST(HostRasterTest, TriangleThroughTheNearPlaneIsClipped) {
  // The eye at the origin looking down -Z; a floor triangle half a unit below, one vertex
  // 2 units behind the eye.
  World w({0, 0, 0}, {0, 0, -1}, 90, 64, 48);
  const glm::dvec3 a(-1, -0.5, -3), b(0, -0.5, 2), c(1, -0.5, -3);  // counter-clockwise from above
  w.add(triangle(a, b, c));
  RasterStats stats;
  const std::vector<Fragment> frags = w.render(&stats);
  ASSERT_GT(frags.size(), 100u);
  EXPECT_EQ(stats.fragments, stats.visible);
  EXPECT_GE(stats.triangles, 2u);  // the clipped quadrilateral (or more), fanned
  bool bottom_row = false;
  for (const Fragment& f : frags) {
    ASSERT_TRUE(finite(f));
    // Every fragment is in front of the eye, beyond the near plane.
    EXPECT_LE(f.solid.z, -w.scene.camera.near * (1 - 1e-9));
    EXPECT_GE(f.depth, -1e-12);
    EXPECT_LE(f.depth, 1 + 1e-12);
    // And where the pixel's ray meets the plane.
    const glm::dvec3 p = hit(camera_ray(w.scene.camera, f.x + 0.5, f.y + 0.5), a, {0, 1, 0});
    EXPECT_NEAR(glm::length(f.solid - p), 0, 1e-9 * glm::length(p));
    bottom_row = bottom_row || f.y == 47;
  }
  EXPECT_TRUE(bottom_row);  // the floor reaches the bottom of the picture
}

TEST(HostRasterTest, ObjectsOutsideTheViewProduceNothing) {
  World w({0, 0, 0}, {0, 0, -1}, 60, 64, 64);
  w.scene.camera.far = 100;
  const glm::dvec3 ex(1, 0, 0), ey(0, 1, 0);
  w.add(quad({-0.5, -0.5, 3}, ex, ey));      // behind the eye
  w.add(quad({-0.5, -0.5, -200}, ex, ey));   // beyond far
  w.add(quad({50, -0.5, -5}, ex, ey));       // far to the right
  w.add(quad({-0.5, 20, -5}, ex, ey));       // above
  w.add(quad({-0.5, -0.5, -0.01}, ex, ey));  // nearer than near
  RasterStats stats;
  EXPECT_TRUE(w.render(&stats).empty());
  EXPECT_EQ(stats.triangles, 0u);
  EXPECT_EQ(stats.fragments, 0u);
}

TEST(HostRasterTest, DegenerateTrianglesProduceNothing) {
  World w({0, 0, 2}, {0, 0, 0}, 60, 64, 64);
  w.add(triangle({0, 0, 0}, {0.5, 0.5, 0}, {1, 1, 0}));          // collinear
  w.add(triangle({0, 0, 0}, {0, 0, 0}, {0.5, 0, 0}));            // repeated vertex
  w.add(triangle({0.1, 0.1, 0}, {0.1, 0.1, 0}, {0.1, 0.1, 0}));  // a point
  w.add(triangle({-1, 0, 0}, {1, 0, 0}, {0, 0, -1}));      // edge-on (contains the eye's plane)
  w.add(triangle({0, 0, 0}, {1e-7, 0, 0}, {0, 1e-7, 0}));  // far below a pixel
  Mesh empty;
  w.add(empty);
  RasterStats stats;
  EXPECT_TRUE(w.render(&stats).empty());
  EXPECT_EQ(stats.fragments, 0u);
}

TEST(HostRasterTest, BackFacesAreCulledAndMirroringKeepsTheOutside) {
  World w({0, 0, 3}, {0, 0, 0}, 60, 64, 64);
  w.add(quad({-0.5, -0.5, 0}, {0, 1, 0}, {1, 0, 0}));  // faces -Z: away from the eye
  EXPECT_TRUE(w.render().empty());

  World box({0.5, 0.7, 3}, {0, 0, 0}, 60, 64, 64);
  Object o;
  o.shape = Object::Shape::kBox;
  o.transform.scale = {-1, 1, 1};  // mirrored: windings flip, the outside must stay visible
  box.add_shape(o);
  RasterStats stats;
  const std::vector<Fragment> frags = box.render(&stats);
  ASSERT_FALSE(frags.empty());
  EXPECT_EQ(stats.fragments, stats.visible);
  for (const Fragment& f : frags) EXPECT_GT(glm::dot(f.normal, f.view), 0);
}

// --- depth -------------------------------------------------------------------------------------

TEST(HostRasterTest, NearerWinsAndTiesGoToTheEarlierObject) {
  for (bool near_first : {false, true}) {
    World w({0, 0, 3}, {0, 0, 0}, 60, 48, 48);
    const Mesh near = quad({-0.5, -0.5, 0.5}, {1, 0, 0}, {0, 1, 0});
    const Mesh far = quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0});
    if (near_first) {
      w.add(near, 1);
      w.add(far, 0);
    } else {
      w.add(far, 0);
      w.add(near, 1);
    }
    RasterStats stats;
    const std::vector<Fragment> frags = w.render(&stats);
    size_t near_count = 0;
    for (const Fragment& f : frags) {
      // The near quad covers the middle; where it does, it wins.
      const glm::dvec3 p =
          hit(camera_ray(w.scene.camera, f.x + 0.5, f.y + 0.5), {0, 0, 0.5}, {0, 0, 1});
      const bool in_near = std::abs(p.x) < 0.49 && std::abs(p.y) < 0.49;
      if (in_near) {
        EXPECT_EQ(f.material, 1);
      }
      near_count += f.material == 1;
    }
    EXPECT_GT(near_count, 100u);
    EXPECT_GT(stats.fragments, stats.visible);  // overdraw happened
  }
  // Two identical quads at the same depth: the first object in the scene wins everywhere.
  for (int first : {0, 1}) {
    World w({0.2, 0.1, 3}, {0, 0, 0}, 60, 48, 48);
    const Mesh q = quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0});
    w.add(q, first);
    w.add(q, 1 - first);
    const std::vector<Fragment> frags = w.render();
    ASSERT_FALSE(frags.empty());
    for (const Fragment& f : frags) ASSERT_EQ(f.material, first);
  }
}

// --- perspective and derivatives ----------------------------------------------------------

// A textured floor under a tilted camera: uv from the ray through each pixel centre.
struct TiltedFloor {
  World w{{0.4, 2, 3}, {0, 0, -1}, 60, 96, 64};
  Transform t;
  TiltedFloor() {
    Object o;
    o.shape = Object::Shape::kPlane;
    o.size = {6, 1, 8};
    o.uv_repeat = {3, 2};
    t.rotate_deg = {0, 30, 0};
    t.translate = {0.2, 0, -1};
    o.transform = t;
    w.add_shape(o);
  }
  // uv (texels) where the ray through screen point (sx, sy) meets the floor.
  glm::dvec2 uv_at(double sx, double sy) const {
    const glm::dmat4 m = t.matrix();
    const glm::dvec3 p = hit(camera_ray(w.scene.camera, sx, sy), glm::dvec3(m[3]), {0, 1, 0});
    const glm::dvec3 local(glm::inverse(m) * glm::dvec4(p, 1));
    return glm::dvec2((local.x / 6 + 0.5) * 3 * 256, (local.z / 8 + 0.5) * 2 * 128);
  }
};

TEST(HostRasterTest, UvIsPerspectiveCorrect) {
  const TiltedFloor floor;
  const std::vector<Fragment> frags = floor.w.render();
  ASSERT_GT(frags.size(), 1000u);
  double worst = 0;
  for (const Fragment& f : frags) {
    const glm::dvec2 expected = floor.uv_at(f.x + 0.5, f.y + 0.5);
    worst = std::max(worst, glm::length(f.uv - expected));
  }
  EXPECT_LT(worst, 1e-9) << "largest uv error in texels";
}

TEST(HostRasterTest, DerivativesAreTheExactDerivativesOfTheMapping) {
  const TiltedFloor floor;
  const std::vector<Fragment> frags = floor.w.render();
  ASSERT_GT(frags.size(), 1000u);
  const double h = 1e-3;  // central differences: error O(h^2)
  for (const Fragment& f : frags) {
    const double x = f.x + 0.5, y = f.y + 0.5;
    const glm::dvec2 fd_x = (floor.uv_at(x + h, y) - floor.uv_at(x - h, y)) / (2 * h);
    const glm::dvec2 fd_y = (floor.uv_at(x, y + h) - floor.uv_at(x, y - h)) / (2 * h);
    const double scale = std::max(1.0, glm::length(fd_x) + glm::length(fd_y));
    ASSERT_LT(glm::length(f.r1 - fd_x), 1e-6 * scale) << f.x << ", " << f.y;
    ASSERT_LT(glm::length(f.r2 - fd_y), 1e-6 * scale) << f.x << ", " << f.y;
    ASSERT_EQ(f.lambda, std::log2(std::max(glm::length(f.r1), glm::length(f.r2))));
  }
}

TEST(HostRasterTest, SetupDerivativesMatchFiniteDifferencesOfItsOwnInterpolation) {
  const uint32_t seed = 7;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> any(-1, 1);  // test data only: platform spread is fine
  for (int trial = 0; trial < 200; ++trial) {
    std::array<SetupVertex, 3> v;
    for (SetupVertex& s : v) {
      const double w = 0.5 + 4 * std::abs(any(rng));
      s.clip = {any(rng) * w, any(rng) * w, 0.5 * w, w};
      s.uv = {300 * any(rng), 300 * any(rng)};
    }
    const std::optional<TriangleSetup> setup = TriangleSetup::make(v, 200, 100);
    ASSERT_TRUE(setup);
    const double x = 100 + 50 * any(rng), y = 50 + 25 * any(rng), h = 1e-4;
    const Interpolated at = setup->at(x, y);
    const glm::dvec2 fd_x = (setup->at(x + h, y).uv - setup->at(x - h, y).uv) / (2 * h);
    const glm::dvec2 fd_y = (setup->at(x, y + h).uv - setup->at(x, y - h).uv) / (2 * h);
    const double scale = std::max(1.0, glm::length(fd_x) + glm::length(fd_y));
    EXPECT_LT(glm::length(at.r1 - fd_x), 1e-6 * scale) << "seed " << seed << " trial " << trial;
    EXPECT_LT(glm::length(at.r2 - fd_y), 1e-6 * scale) << "seed " << seed << " trial " << trial;
  }
}

TEST(HostRasterTest, ConstantUvClampsLambdaToAFiniteValue) {
  World w({0, 0, 2}, {0, 0, 0}, 60, 32, 32);
  Mesh q = quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0});
  for (Vertex& v : q.vertices) v.uv = {0.25, 0.5};
  w.add(q);
  const std::vector<Fragment> frags = w.render();
  ASSERT_FALSE(frags.empty());
  for (const Fragment& f : frags) {
    EXPECT_EQ(f.r1, glm::dvec2(0));
    EXPECT_EQ(f.lambda, -40);  // log2 of the 2^-40 clamp
    EXPECT_EQ(quantize(f).lambda, formats::kLod.min_raw());
  }
}

// --- bands -------------------------------------------------------------------------------------

TEST(HostRasterTest, BandsGiveExactlyTheWholeFramesFragments) {
  World w({1, 2.5, 5}, {0, 0.3, 0}, 55, 160, 100);
  w.scene.lights = {{Light::Kind::kAmbient, {}, {0.2, 0.2, 0.2}},
                    {Light::Kind::kDirectional, {-1, -2, -1}, {0.7, 0.6, 0.5}},
                    {Light::Kind::kPoint, {2, 3, 1}, {0.5, 0.5, 0.5}}};
  Object floor;
  floor.shape = Object::Shape::kPlane;
  floor.size = {20, 1, 20};
  floor.uv_repeat = {8, 8};
  w.add_shape(floor);
  Object ball;
  ball.shape = Object::Shape::kSphere;
  ball.material = 1;
  ball.transform.translate = {0, 1, 0};
  w.add_shape(ball);
  Object ring;
  ring.shape = Object::Shape::kTorus;
  ring.transform = {{1.5, 0.5, 0.5}, {60, 20, 0}, {1, 1, 1}};
  w.add_shape(ring);
  Object box;
  box.shape = Object::Shape::kBox;
  box.material = 1;
  box.transform = {{-1.5, 0.5, 0}, {0, 30, 0}, {1, 1, 1}};
  w.add_shape(box);

  const std::vector<Fragment> whole = w.render();
  ASSERT_GT(whole.size(), 10000u);
  for (size_t i = 1; i < whole.size(); ++i) {
    ASSERT_TRUE(std::make_pair(whole[i - 1].y, whole[i - 1].x) <
                std::make_pair(whole[i].y, whole[i].x));
  }
  const std::vector<std::pair<int, int>> bands = {{0, 1},    {0, 37},  {37, 38}, {38, 99},
                                                  {99, 100}, {50, 50}, {0, 100}};
  for (const auto& [a, b] : bands) {
    std::vector<Fragment> expected;
    for (const Fragment& f : whole) {
      if (f.y >= a && f.y < b) expected.push_back(f);
    }
    const std::vector<Fragment> band = w.render(nullptr, a, b);
    ASSERT_EQ(band.size(), expected.size()) << "band " << a << ".." << b;
    for (size_t i = 0; i < band.size(); ++i) {
      ASSERT_TRUE(identical(band[i], expected[i]))
          << "band " << a << ".." << b << " fragment " << i;
    }
  }
  EXPECT_THROW(w.render(nullptr, 5, 101), std::invalid_argument);
  EXPECT_THROW(w.render(nullptr, 6, 5), std::invalid_argument);
}

// --- lighting ----------------------------------------------------------------------------------

TEST(HostRasterTest, ShadeSumsTheLightsAndClamps) {
  World w({0, 3, 0.01}, {0, 0, 0}, 40, 16, 16);
  Object floor;
  floor.shape = Object::Shape::kPlane;
  floor.size = {4, 1, 4};
  w.add_shape(floor);
  const auto centre_shade = [&] {
    const std::vector<Fragment> f = w.render();
    EXPECT_EQ(f.size(), 256u);
    return f.empty() ? glm::dvec3(-1) : f[8 * 16 + 8].shade;
  };
  w.scene.lights = {{Light::Kind::kAmbient, {}, {0.1, 0.2, 0.3}}};
  EXPECT_EQ(centre_shade(), glm::dvec3(0.1, 0.2, 0.3));
  // Straight down at any length of the direction vector: n . -d = 1.
  w.scene.lights.push_back({Light::Kind::kDirectional, {0, -5, 0}, {0.5, 0.5, 0.5}});
  glm::dvec3 s = centre_shade();
  EXPECT_NEAR(s.x, 0.6, 1e-12);
  EXPECT_NEAR(s.z, 0.8, 1e-12);
  // A point light 45 degrees off: cos = 1/sqrt(2); the sum clamps at 1.
  w.scene.lights = {{Light::Kind::kPoint, {100, 100, 0}, {1, 1, 2}}};
  s = centre_shade();
  EXPECT_NEAR(s.x, std::sqrt(0.5), 1e-3);  // the centre pixel is not exactly at the origin
  EXPECT_EQ(s.z, 1);
  // A light from below does not light the top.
  w.scene.lights = {{Light::Kind::kDirectional, {0, 1, 0}, {1, 1, 1}}};
  EXPECT_EQ(centre_shade(), glm::dvec3(0));
}

// --- quantize ----------------------------------------------------------------------------------

TEST(HostQuantizeTest, RoundsToNearestEvenAndSaturatesEachFormat) {
  Fragment f;
  f.x = 4095;
  f.y = 17;
  f.material = 255;
  f.uv = {1.5 / 256, 2.5 / 256};  // ties: 1.5 -> 2, 2.5 -> 2
  f.lambda = -40;                 // below SQ6.8
  f.shade = {0.5, 1.5, -0.25};    // 127.5 -> 128; saturate; clamp
  f.r1 = {1e9, -1e9};
  f.r2 = {3.75 / 256, -3.5 / 256};      // 3.75 -> 4, -3.5 -> -4
  f.solid = {2048, -2048, 1.0 / 8192};  // SQ12.12 spans [-2048, 2048); half an LSB -> 0
  f.normal = {1, -1, 2};                // SQ2.14: 16384, -16384, saturate to 32767
  f.view = {-2.5, 0.5 / 16384, 1.5 / 16384};
  const FragmentRecord r = quantize(f);
  EXPECT_EQ(r.x, 4095);
  EXPECT_EQ(r.y, 17);
  EXPECT_EQ(r.material, 255);
  EXPECT_EQ(r.u, 2);
  EXPECT_EQ(r.v, 2);
  EXPECT_EQ(r.lambda, -8192);
  EXPECT_EQ(r.shade, 0x80FF00FFu);
  EXPECT_EQ(r.r1[0], 8388607);
  EXPECT_EQ(r.r1[1], -8388608);
  EXPECT_EQ(r.r2[0], 4);
  EXPECT_EQ(r.r2[1], -4);
  EXPECT_EQ(r.solid[0], 8388607);
  EXPECT_EQ(r.solid[1], -8388608);
  EXPECT_EQ(r.solid[2], 0);
  EXPECT_EQ(r.normal[0], 16384);
  EXPECT_EQ(r.normal[1], -16384);
  EXPECT_EQ(r.normal[2], 32767);
  EXPECT_EQ(r.view[0], -32768);
  EXPECT_EQ(r.view[1], 0);
  EXPECT_EQ(r.view[2], 2);

  // The other ends of each range.
  Fragment g;
  g.x = -3;
  g.y = 5000;
  g.material = 300;
  g.uv = {-1e9, 1e9};
  g.lambda = 31.99609375;  // the largest SQ6.8
  g.shade = {0, 1, 1.0 / 255};
  const FragmentRecord q = quantize(g);
  EXPECT_EQ(q.x, 0);
  EXPECT_EQ(q.y, 4095);
  EXPECT_EQ(q.material, 255);
  EXPECT_EQ(q.u, formats::kTexCoord.min_raw());
  EXPECT_EQ(q.v, formats::kTexCoord.max_raw());
  EXPECT_EQ(q.lambda, formats::kLod.max_raw());
  EXPECT_EQ(q.shade, 0x00FF01FFu);
  g.lambda = 1e9;
  EXPECT_EQ(quantize(g).lambda, formats::kLod.max_raw());
  g.lambda = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(quantize(g).lambda, 0);
}

TEST(HostQuantizeTest, RenderedFragmentsFitTheirFormats) {
  const TiltedFloor floor;
  for (const Fragment& f : floor.w.render()) {
    const FragmentRecord r = quantize(f);
    EXPECT_EQ(r.x, f.x);
    EXPECT_EQ(r.y, f.y);
    EXPECT_EQ(r.u, static_cast<int32_t>(std::nearbyint(f.uv.x * 256)));
    EXPECT_LE(std::abs(r.normal[0]), 16384);
    EXPECT_LE(std::abs(r.view[2]), 16384);
    EXPECT_EQ(r.shade & 0xFF, 0xFFu);
  }
}

}  // namespace
}  // namespace tmu::host
