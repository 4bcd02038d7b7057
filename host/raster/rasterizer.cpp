// The front end, per frame (or band of rows):
//  1. per object: model, view and projection (GLM, double, right-handed, depth 0..1), each
//     vertex to clip space once, so shared positions give bit-identical clip coordinates;
//  2. per triangle: back-face culling in clip space, Sutherland-Hodgman clipping against the
//     view volume (clip.hpp), the perspective divide and viewport, the clipped polygon fanned
//     and snapped to 1/256 pixel, coverage by exact edge functions with the top-left rule
//     (coverage.hpp);
//  3. the depth test per covered pixel (nearest wins; on equal depth the first drawn wins:
//     objects in scene order, triangles in mesh order), remembering only the winning triangle;
//  4. per visible pixel: the winner's perspective-correct attributes and exact derivatives at
//     the pixel centre (triangle_setup.hpp), LOD, normal, view vector and shade.
// Attributes are evaluated only for the visible fragments; every value of a pixel depends on
// that pixel and the scene only, so a band of rows gives exactly the whole frame's fragments.
#include "raster/rasterizer.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <stdexcept>

#include "raster/clip.hpp"
#include "raster/coverage.hpp"
#include "raster/shading.hpp"
#include "raster/triangle_setup.hpp"
#include "raster/view.hpp"

namespace tmu::host {
namespace {

struct Winner {
  double depth = std::numeric_limits<double>::infinity();
  uint32_t triangle = std::numeric_limits<uint32_t>::max();  // into the setups; max: none
};

struct DrawnTriangle {
  TriangleSetup setup;
  int object, material;
  glm::dvec3 face_normal;  // world, unit: the fallback where interpolated normals cancel
  double lod;              // a fixed lambda (004 claim 12), or NaN: per pixel
};

struct Frame {
  int width, height;
  glm::dmat4 view_projection;
  glm::dvec3 eye;
};

Frame make_frame(const Camera& c) { return {c.width, c.height, view_projection(c), c.position}; }

// det [x y w] of the clip-space rows: proportional (with a positive factor) to the triple
// product of the eye-space vertices with the eye at the origin, so its sign says which side
// of the triangle's plane the eye is on, also for triangles reaching behind the eye. > 0: the
// triangle is counter-clockwise as seen from the eye.
double facing(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c) {
  return a.x * (b.y * c.w - b.w * c.y) - a.y * (b.x * c.w - b.w * c.x) +
         a.w * (b.x * c.y - b.y * c.x);
}

class Rasterizer {
 public:
  Rasterizer(const Scene& scene, int row_begin, int row_end)
      : scene_(scene),
        frame_(make_frame(scene.camera)),
        row_begin_(row_begin),
        row_end_(row_end),
        winners_(static_cast<size_t>(scene.camera.width) *
                 static_cast<size_t>(row_end - row_begin)) {}

  void draw(int object_index, const Mesh& mesh, const glm::ivec2& texture_size) {
    const Object& object = scene_.objects[static_cast<size_t>(object_index)];
    const glm::dmat4 model = object.transform.matrix();
    const glm::dmat3 linear(model);
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
    // A mirroring transform (an odd number of negative scales) turns counter-clockwise faces
    // clockwise: swap the winding back so that outside stays front.
    const bool mirrored = glm::determinant(linear) < 0;
    const glm::dmat4 mvp = frame_.view_projection * model;
    const glm::dvec2 texels(texture_size);

    std::vector<SetupVertex> vs(mesh.vertices.size());
    for (size_t i = 0; i < vs.size(); ++i) {
      const Vertex& v = mesh.vertices[i];
      const glm::dvec4 p(v.position, 1.0);
      const glm::dvec3 n = normal_matrix * v.normal;
      const double len = glm::length(n);
      vs[i] = {mvp * p, v.uv * texels, v.position, glm::dvec3(model * p), len > 0 ? n / len : n,
               v.colour};
    }
    for (const auto& t : mesh.triangles) {
      std::array<SetupVertex, 3> tri = {vs[t[0]], vs[t[1]], vs[t[2]]};
      if (mirrored) std::swap(tri[1], tri[2]);
      draw_triangle(tri, object_index, object.material, mesh.vertices[t[0]].lod);
    }
  }

  std::vector<Fragment> fragments(RasterStats* stats) const {
    std::vector<Fragment> out;
    for (int y = row_begin_; y < row_end_; ++y) {
      for (int x = 0; x < frame_.width; ++x) {
        const Winner& w = winner(x, y);
        if (w.triangle == std::numeric_limits<uint32_t>::max()) continue;
        out.push_back(fragment(x, y, drawn_[w.triangle]));
      }
    }
    if (stats) {
      stats->triangles = triangles_;
      stats->fragments = covered_;
      stats->visible = out.size();
    }
    return out;
  }

 private:
  Winner& winner(int x, int y) {
    return winners_[static_cast<size_t>(y - row_begin_) * static_cast<size_t>(frame_.width) +
                    static_cast<size_t>(x)];
  }
  const Winner& winner(int x, int y) const {
    return winners_[static_cast<size_t>(y - row_begin_) * static_cast<size_t>(frame_.width) +
                    static_cast<size_t>(x)];
  }

  void draw_triangle(const std::array<SetupVertex, 3>& tri, int object, int material, double lod) {
    // Back faces (and triangles seen edge-on, and degenerate ones) are culled: front faces
    // are counter-clockwise seen from the eye, as the meshes are from outside.
    if (!(facing(tri[0].clip, tri[1].clip, tri[2].clip) > 0)) return;
    const ClipPolygon poly = clip_triangle(tri[0].clip, tri[1].clip, tri[2].clip);
    if (poly.count < 3) return;
    std::array<SubpixelPoint, ClipPolygon::kCapacity> s{};
    for (size_t i = 0; i < static_cast<size_t>(poly.count); ++i)
      s[i] = snap(to_screen(poly.v[i], frame_.width, frame_.height));

    std::optional<uint32_t> id;  // set up on the first piece that reaches the band
    for (size_t i = 1; i + 1 < static_cast<size_t>(poly.count); ++i) {
      // A front face turns counter-clockwise on the screen too, which in y-down coordinates
      // is a negative twice_area: coverage gets each piece reversed. A piece that snapping
      // flipped or flattened (a sliver far below a pixel) covers nothing.
      const SubpixelPoint &a = s[0], &b = s[i + 1], &c = s[i];
      if (twice_area(a, b, c) <= 0) continue;
      const int64_t top = std::min({a.y, b.y, c.y}), bottom = std::max({a.y, b.y, c.y});
      if (bottom < int64_t{row_begin_} * kSubpixel || top > int64_t{row_end_} * kSubpixel) continue;
      if (!id) {
        const std::optional<TriangleSetup> setup =
            TriangleSetup::make(tri, frame_.width, frame_.height);
        if (!setup) return;
        const glm::dvec3 g = glm::cross(tri[1].world - tri[0].world, tri[2].world - tri[0].world);
        const double len = glm::length(g);
        drawn_.push_back({*setup, object, material, len > 0 ? g / len : glm::dvec3(0, 0, 1), lod});
        id = static_cast<uint32_t>(drawn_.size() - 1);
      }
      ++triangles_;
      const TriangleSetup& setup = drawn_[*id].setup;
      for_each_covered_pixel(a, b, c, frame_.width, row_begin_, row_end_, [&](int x, int y) {
        ++covered_;
        const double depth = setup.depth(x + 0.5, y + 0.5);
        Winner& w = winner(x, y);
        if (depth < w.depth) w = {depth, *id};
      });
    }
  }

  Fragment fragment(int x, int y, const DrawnTriangle& t) const {
    const Interpolated v = t.setup.at(x + 0.5, y + 0.5);
    Fragment f;
    f.x = x;
    f.y = y;
    f.object = t.object;
    f.material = t.material;
    f.depth = v.depth;
    f.uv = v.uv;
    f.r1 = v.r1;
    f.r2 = v.r2;
    f.lambda = std::isnan(t.lod)
                   ? std::log2(std::max({glm::length(v.r1), glm::length(v.r2), kMinFootprint}))
                   : t.lod;
    f.solid = v.solid * scene_.materials[static_cast<size_t>(t.material)].solid_scale;
    const double n = glm::length(v.normal);
    f.normal = n > 0 && std::isfinite(n) ? v.normal / n : t.face_normal;
    const glm::dvec3 to_eye = frame_.eye - v.world;
    const double e = glm::length(to_eye);
    f.view = e > 0 && std::isfinite(e) ? to_eye / e : -t.face_normal;
    f.shade = shade(scene_.lights, f.normal, v.world);
    f.colour = v.colour;
    return f;
  }

  const Scene& scene_;
  Frame frame_;
  int row_begin_, row_end_;
  std::vector<Winner> winners_;
  std::vector<DrawnTriangle> drawn_;
  uint64_t triangles_ = 0, covered_ = 0;
};

}  // namespace

glm::dmat4 view_projection(const Camera& c) {
  const glm::dmat4 view = glm::lookAtRH(c.position, c.target, c.up);
  const glm::dmat4 projection = glm::perspectiveRH_ZO(
      glm::radians(c.fov_deg), static_cast<double>(c.width) / static_cast<double>(c.height), c.near,
      c.far);
  return projection * view;
}

glm::dvec2 to_screen(const glm::dvec4& clip, int width, int height) {
  return {(clip.x / clip.w + 1.0) * 0.5 * width, (1.0 - clip.y / clip.w) * 0.5 * height};
}

Ray pixel_ray(const Camera& camera, double x, double y) {
  const glm::dvec4 ndc(2.0 * x / camera.width - 1.0, 1.0 - 2.0 * y / camera.height, 1.0, 1.0);
  const glm::dvec4 far = glm::inverse(view_projection(camera)) * ndc;
  return {camera.position, glm::dvec3(far) / far.w - camera.position};
}

std::vector<Fragment> rasterize(const Scene& scene, const std::vector<Mesh>& meshes,
                                const std::vector<glm::ivec2>& texture_sizes, int row_begin,
                                int row_end, RasterStats* stats) {
  const int height = scene.camera.height;
  if (row_end < 0) row_end = height;
  if (row_begin < 0 || row_begin > row_end || row_end > height) {
    throw std::invalid_argument("rasterize: rows [" + std::to_string(row_begin) + ", " +
                                std::to_string(row_end) + ") outside the frame's 0.." +
                                std::to_string(height));
  }
  if (meshes.size() != scene.objects.size()) {
    throw std::invalid_argument("rasterize: one mesh per object needed");
  }
  if (texture_sizes.size() < scene.materials.size()) {
    throw std::invalid_argument("rasterize: one texture size per material needed");
  }
  for (const Object& o : scene.objects) {
    if (o.material < 0 || static_cast<size_t>(o.material) >= scene.materials.size()) {
      throw std::invalid_argument("rasterize: an object's material is not in the scene");
    }
  }
  Rasterizer r(scene, row_begin, row_end);
  for (size_t i = 0; i < meshes.size(); ++i) {
    const Object& o = scene.objects[i];
    r.draw(static_cast<int>(i), meshes[i], texture_sizes[static_cast<size_t>(o.material)]);
  }
  return r.fragments(stats);
}

}  // namespace tmu::host
