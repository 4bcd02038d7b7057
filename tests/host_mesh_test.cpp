// Meshes: every built-in shape has unit normals pointing outward, triangles counter-clockwise
// seen from outside, texture coordinates over the documented range, and (where closed) no
// holes; OBJ files in each vertex form, and their errors naming the line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>

#include "common/error.hpp"
#include "geometry/mesh.hpp"

namespace tmu::host {
namespace {

namespace fs = std::filesystem;

// A scratch file removed at the end of the test.
class TempFile {
 public:
  explicit TempFile(const std::string& text) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = (fs::temp_directory_path() / ("tmu_host_" + std::to_string(::getpid()) + "_" +
                                          info->name() + "_" + std::to_string(counter_++) + ".obj"))
                .string();
    std::ofstream(path_) << text;
  }
  ~TempFile() { fs::remove(path_); }
  const std::string& path() const { return path_; }

 private:
  static inline int counter_ = 0;
  std::string path_;
};

glm::dvec3 face_vector(const Mesh& m, const std::array<uint32_t, 3>& t) {
  const glm::dvec3& a = m.vertices[t[0]].position;
  return glm::cross(m.vertices[t[1]].position - a, m.vertices[t[2]].position - a);
}

// Checks unit normals and that each triangle turns counter-clockwise seen from the side its
// vertex normals point to.
void expect_consistent(const Mesh& m) {
  ASSERT_FALSE(m.triangles.empty());
  for (const Vertex& v : m.vertices) EXPECT_NEAR(glm::length(v.normal), 1.0, 1e-12);
  for (const auto& t : m.triangles) {
    const glm::dvec3 g = face_vector(m, t);
    ASSERT_GT(glm::length(g), 0) << "degenerate triangle";
    for (uint32_t i : t) {
      ASSERT_LT(i, m.vertices.size());
      EXPECT_GT(glm::dot(g, m.vertices[i].normal), 0) << "clockwise seen from outside";
    }
  }
}

// The signed volume by the divergence theorem: positive when the faces point outward, and
// the sum of the area vectors is zero when the surface is closed.
double volume(const Mesh& m, glm::dvec3* area_sum = nullptr) {
  double v = 0;
  glm::dvec3 sum(0);
  for (const auto& t : m.triangles) {
    v += glm::dot(m.vertices[t[0]].position, face_vector(m, t)) / 6.0;
    sum += face_vector(m, t);
  }
  if (area_sum) *area_sum = sum;
  return v;
}

// Every edge, by position, used once in each direction: closed and consistently oriented.
void expect_watertight(const Mesh& m) {
  using Key = std::array<double, 6>;
  std::map<Key, int> edges;
  for (const auto& t : m.triangles) {
    for (int i = 0; i < 3; ++i) {
      const glm::dvec3 a = m.vertices[t[static_cast<size_t>(i)]].position;
      const glm::dvec3 b = m.vertices[t[static_cast<size_t>((i + 1) % 3)]].position;
      // Round away the last bits: seam vertices are computed from different angles.
      const auto r = [](double x) { return std::round(x * 1e9) / 1e9; };
      ++edges[{r(a.x), r(a.y), r(a.z), r(b.x), r(b.y), r(b.z)}];
    }
  }
  for (const auto& [k, n] : edges) {
    EXPECT_EQ(n, 1) << "edge used twice in one direction";
    const Key rev = {k[3], k[4], k[5], k[0], k[1], k[2]};
    EXPECT_EQ(edges.count(rev), 1u) << "open edge";
  }
}

void expect_uv_range(const Mesh& m, glm::dvec2 lo, glm::dvec2 hi) {
  glm::dvec2 mn(1e9), mx(-1e9);
  for (const Vertex& v : m.vertices) {
    mn = glm::min(mn, v.uv);
    mx = glm::max(mx, v.uv);
  }
  EXPECT_NEAR(mn.x, lo.x, 1e-12);
  EXPECT_NEAR(mn.y, lo.y, 1e-12);
  EXPECT_NEAR(mx.x, hi.x, 1e-12);
  EXPECT_NEAR(mx.y, hi.y, 1e-12);
}

// --- shapes ----------------------------------------------------------------------------------

TEST(HostMeshTest, PlaneFacesUpWithUvAlongXAndZ) {
  Object o;
  o.shape = Object::Shape::kPlane;
  o.size = {8, 1, 4};
  o.uv_repeat = {4, 2};
  const Mesh m = make_mesh(o);
  expect_consistent(m);
  for (const Vertex& v : m.vertices) {
    EXPECT_EQ(v.normal, glm::dvec3(0, 1, 0));
    EXPECT_EQ(v.position.y, 0);
    // u along x, v along z, 0..repeat across the plane.
    EXPECT_NEAR(v.uv.x, (v.position.x / 8 + 0.5) * 4, 1e-12);
    EXPECT_NEAR(v.uv.y, (v.position.z / 4 + 0.5) * 2, 1e-12);
  }
  for (const auto& t : m.triangles) EXPECT_GT(face_vector(m, t).y, 0);
  expect_uv_range(m, {0, 0}, {4, 2});
  glm::dvec3 area;
  volume(m, &area);
  EXPECT_NEAR(area.y, 2 * 32, 1e-12);  // twice the area, all facing +Y
}

TEST(HostMeshTest, BoxIsClosedWithOutwardFaces) {
  Object o;
  o.shape = Object::Shape::kBox;
  o.size = {1, 2, 3};
  o.uv_repeat = {2, 3};
  const Mesh m = make_mesh(o);
  expect_consistent(m);
  EXPECT_EQ(m.triangles.size(), 12u);
  expect_watertight(m);
  EXPECT_NEAR(volume(m), 6.0, 1e-12);
  for (const Vertex& v : m.vertices) {
    // The normal is the axis of the face the vertex is on.
    const glm::dvec3 on_face = v.position * v.normal * 2.0;
    EXPECT_NEAR(on_face.x + on_face.y + on_face.z, glm::dot(glm::abs(v.normal), o.size), 1e-12);
  }
  expect_uv_range(m, {0, 0}, {2, 3});
  // On the front face (+Z) u runs along +X and v down (-Y): upright, unmirrored.
  for (const Vertex& v : m.vertices) {
    if (v.normal != glm::dvec3(0, 0, 1)) continue;
    EXPECT_NEAR(v.uv.x, (v.position.x + 0.5) * 2, 1e-12);
    EXPECT_NEAR(v.uv.y, (1 - v.position.y) / 2 * 3, 1e-12);
  }
}

TEST(HostMeshTest, SphereNormalsPointOutwardAndUvSpansPoleToPole) {
  for (glm::ivec2 seg : {glm::ivec2(3, 2), glm::ivec2(4, 3), glm::ivec2(32, 16)}) {
    Object o;
    o.shape = Object::Shape::kSphere;
    o.radius = 2;
    o.segments = seg;
    const Mesh m = make_mesh(o);
    SCOPED_TRACE(testing::Message() << "segments " << seg.x << "x" << seg.y);
    expect_consistent(m);
    expect_watertight(m);
    // around * (up - 2) quads and 2 * around pole triangles.
    EXPECT_EQ(m.triangles.size(), static_cast<size_t>(2 * seg.x * (seg.y - 1)));
    for (const Vertex& v : m.vertices) {
      EXPECT_NEAR(glm::length(v.position), 2, 1e-12);
      EXPECT_NEAR(glm::length(v.normal - v.position / 2.0), 0, 1e-12);
      // v runs from the north pole (+Y) to the south pole.
      EXPECT_NEAR(v.uv.y, std::acos(std::clamp(v.position.y / 2, -1.0, 1.0)) / std::numbers::pi,
                  1e-9);
    }
    const double v = volume(m);
    EXPECT_GT(v, 0);
    EXPECT_LT(v, 4.0 / 3.0 * std::numbers::pi * 8);
    expect_uv_range(m, {0, 0}, {1, 1});
  }
}

TEST(HostMeshTest, SphereUvRunsEastwardFromTheSeamAtMinusZ) {
  Object o;
  o.shape = Object::Shape::kSphere;
  o.segments = {8, 4};
  o.uv_repeat = {3, 2};
  const Mesh m = make_mesh(o);
  for (const Vertex& v : m.vertices) {
    if (std::abs(v.position.y) > 0.999) continue;  // the poles
    const double u = v.uv.x / 3;
    const double phi = 2 * std::numbers::pi * u - std::numbers::pi;
    const double r = std::hypot(v.position.x, v.position.z);
    EXPECT_NEAR(v.position.x, r * std::sin(phi), 1e-12);
    EXPECT_NEAR(v.position.z, r * std::cos(phi), 1e-12);
  }
  expect_uv_range(m, {0, 0}, {3, 2});
}

TEST(HostMeshTest, TorusNormalsPointAwayFromTheRing) {
  Object o;
  o.shape = Object::Shape::kTorus;
  o.radius = 2;
  o.tube = 0.5;
  o.segments = {24, 12};
  const Mesh m = make_mesh(o);
  expect_consistent(m);
  expect_watertight(m);
  EXPECT_EQ(m.triangles.size(), 2u * 24 * 12);
  for (const Vertex& v : m.vertices) {
    const glm::dvec3 ring = 2.0 * glm::normalize(glm::dvec3(v.position.x, 0, v.position.z));
    EXPECT_NEAR(glm::length(v.position - ring), 0.5, 1e-12);
    EXPECT_NEAR(glm::length(v.normal - (v.position - ring) / 0.5), 0, 1e-12);
  }
  // Volume 2 pi^2 R r^2, less the polygon's shortfall.
  const double exact = 2 * std::numbers::pi * std::numbers::pi * 2 * 0.25;
  EXPECT_GT(volume(m), 0.9 * exact);
  EXPECT_LT(volume(m), exact);
  expect_uv_range(m, {0, 0}, {1, 1});
}

// --- OBJ -------------------------------------------------------------------------------------

TEST(HostMeshTest, ObjVertexFormsAndNegativeIndices) {
  const TempFile f(
      "# a unit square in two faces, every vertex form\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "vn 0 0 2\n"  // normalised on load
      "o square\ng g1\ns off\nusemtl m\n"
      "f 1/1/1 2/2/1 3/3/1\n"
      "f -4//-1 -2//-1 -1//-1   # v//vn and negative indices: 1, 3, 4\n");
  const Mesh m = load_obj(f.path());
  ASSERT_EQ(m.triangles.size(), 2u);
  const auto& t1 = m.triangles[1];
  EXPECT_EQ(m.vertices[t1[0]].position, glm::dvec3(0, 0, 0));
  EXPECT_EQ(m.vertices[t1[1]].position, glm::dvec3(1, 1, 0));
  EXPECT_EQ(m.vertices[t1[2]].position, glm::dvec3(0, 1, 0));
  EXPECT_EQ(m.vertices[t1[2]].uv, glm::dvec2(0, 0));  // no vt: 0
  for (const Vertex& v : m.vertices) EXPECT_EQ(v.normal, glm::dvec3(0, 0, 1));
  EXPECT_EQ(m.vertices[m.triangles[0][2]].uv, glm::dvec2(1, 0));  // vt 1 1, v flipped
  // Same v/vt/vn is one vertex: 3 from the first face, 3 new (different vt) from the second.
  EXPECT_EQ(m.vertices.size(), 6u);
}

TEST(HostMeshTest, ObjPolygonsAreFannedAndMissingNormalsAreFaceNormals) {
  const TempFile f(
      "v 0 0 0\nv 2 0 0\nv 2 0 -2\nv 0 0 -2\nv 1 1 -1\n"
      "vt 0.5 0.25\n"
      "f 1/1 2/1 3/1 4/1\n"  // a quad in the XZ plane, counter-clockwise from above
      "f 1 5 2\n");
  const Mesh m = load_obj(f.path());
  ASSERT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.triangles[0][0], m.triangles[1][0]);  // fanned from the first vertex
  for (int i = 0; i < 2; ++i) {
    for (uint32_t k : m.triangles[static_cast<size_t>(i)]) {
      EXPECT_EQ(m.vertices[k].normal, glm::dvec3(0, 1, 0));
      EXPECT_EQ(m.vertices[k].uv, glm::dvec2(0.5, 0.75));  // vt 0.5 0.25, v flipped
    }
  }
  const glm::dvec3 n = glm::normalize(face_vector(m, m.triangles[2]));
  for (uint32_t k : m.triangles[2]) EXPECT_NEAR(glm::length(m.vertices[k].normal - n), 0, 1e-12);
  expect_consistent(m);
}

void expect_obj_error(const std::string& text, const std::string& field,
                      const std::string& reason) {
  const TempFile f(text);
  try {
    load_obj(f.path());
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), f.path());
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
  }
}

TEST(HostMeshTest, ObjErrorsNameTheLine) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_obj_error(tri + "f 1 2 4\n", "line 4", "v index 4 out of range (3 v defined so far)");
  expect_obj_error(tri + "f 1 2 0\n", "line 4", "v index 0");
  expect_obj_error(tri + "f -4 1 2\n", "line 4", "v index -4 out of range");
  expect_obj_error(tri + "f 1/1 2 3\n", "line 4", "vt index 1 out of range (0 vt");
  expect_obj_error(tri + "vn 0 0 1\nf 1//2 2//1 3//1\n", "line 5", "vn index 2 out of range");
  expect_obj_error(tri + "f 1 2\n", "line 4", "at least 3 vertices, got 2");
  expect_obj_error("v 0 abc 0\n", "line 1", "expected a number, got 'abc'");
  expect_obj_error("v 0 0\n", "line 1", "v needs 3 to 6 numbers, got 2");
  expect_obj_error("# c\nvt 0.5 x\n", "line 2", "expected a number, got 'x'");
  expect_obj_error("vn 0 0 nan\n", "line 1", "expected a number");
  expect_obj_error("vn 0 0 0\n", "line 1", "zero vector");
  expect_obj_error(tri + "f 1 2 x\n", "line 4", "expected a v index, got 'x'");
  expect_obj_error(tri + "f 1/2/3/4 2 3\n", "line 4", "bad face vertex");
  expect_obj_error(tri, "", "no faces");
}

TEST(HostMeshTest, BundledModelsLoadClosedAndOutward) {
  const std::string dir = std::string(TMU_SOURCE_DIR) + "/scenes/models/";
  const Mesh ico = load_obj(dir + "icosahedron.obj");
  EXPECT_EQ(ico.vertices.size(), 12u);
  EXPECT_EQ(ico.triangles.size(), 20u);
  expect_consistent(ico);
  expect_watertight(ico);
  for (const Vertex& v : ico.vertices) {
    EXPECT_NEAR(glm::length(v.position), 1, 1e-6);
    EXPECT_GE(v.uv.x, 0);
    EXPECT_LE(v.uv.x, 1);
    EXPECT_GE(v.uv.y, 0);
    EXPECT_LE(v.uv.y, 1);
  }
  EXPECT_NEAR(volume(ico), 2.5362, 1e-3);  // the regular icosahedron of circumradius 1

  const Mesh pot = load_obj(dir + "teapot.obj");
  expect_consistent(pot);  // face normals agree with each (planar) face's winding
  EXPECT_EQ(pot.triangles.size(), 5u + 70 * 2 + 2 * 6);
  EXPECT_GT(volume(pot), 0);
}

TEST(HostMeshTest, MeshObjectAppliesUvRepeat) {
  const TempFile f("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 1\nvt 1 0\nvt 0 0.25\nf 1/1 2/2 3/3\n");
  Object o;
  o.shape = Object::Shape::kMesh;
  o.file = f.path();
  o.uv_repeat = {2, 4};
  const Mesh m = make_mesh(o);
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.vertices[0].uv, glm::dvec2(1, 0));  // vt 0.5 1 -> (0.5, 0) x (2, 4)
  EXPECT_EQ(m.vertices[2].uv, glm::dvec2(0, 3));  // vt 0 0.25 -> (0, 0.75) x (2, 4)
}

}  // namespace
}  // namespace tmu::host
