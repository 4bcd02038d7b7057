#include "nurbs/ray_hit.hpp"

#include <cmath>
#include <vector>

#include "nurbs/nurbs_mesh.hpp"
#include "nurbs/patch.hpp"
#include "raster/view.hpp"

namespace tmu::host::nurbs {
namespace {

constexpr int kMaxSteps = 30;
constexpr double kResidual = 1e-9;  // of the object's size (its control net's extent)
// |det J| below this times the product of its columns' lengths: the ray grazes the surface.
constexpr double kSingular = 1e-9;

// The patch whose knot domain holds (s, t); the last one that does (any, where domains touch).
const Patch* patch_at(const std::vector<Patch>& patches, double s, double t) {
  const Patch* found = nullptr;
  for (const Patch& p : patches) {
    if (s >= p.s_min() && s <= p.s_max() && t >= p.t_min() && t <= p.t_max()) found = &p;
  }
  return found;
}

double net_size(const std::vector<Patch>& patches) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const Patch& p : patches) {
    for (const glm::dvec3& q : p.points) {
      lo = glm::min(lo, q);
      hi = glm::max(hi, q);
    }
  }
  return glm::length(hi - lo);
}

}  // namespace

std::optional<PixelHit> hit_through_pixel(const Object& object, const Camera& camera, double x,
                                          double y, glm::dvec2 guess) {
  const glm::dvec4 rect = pc_rectangle(object.patches);
  const glm::dvec2 lo(rect.x, rect.z), extent(rect.y - rect.x, rect.w - rect.z);
  const glm::dmat4 model = object.transform.matrix();
  const glm::dmat4 to_object = glm::inverse(model);
  const auto object_ray = [&](double px, double py) {
    const Ray r = pixel_ray(camera, px, py);
    return Ray{glm::dvec3(to_object * glm::dvec4(r.origin, 1.0)),
               glm::dmat3(to_object) * r.direction};
  };
  const Ray ray = object_ray(x, y);
  const double tolerance = kResidual * net_size(object.patches);

  glm::dvec2 st = lo + guess * extent;
  const Patch* patch = nullptr;
  SurfacePoint e;
  glm::dmat3 jacobian(1.0);
  double lambda = 0;
  bool first = true;
  for (int step = 0;; ++step) {
    patch = patch_at(object.patches, st.x, st.y);
    if (!patch) return std::nullopt;
    e = evaluate(*patch, st.x, st.y);
    if (first) {  // lambda of the point nearest the start on the ray
      lambda =
          glm::dot(e.position - ray.origin, ray.direction) / glm::dot(ray.direction, ray.direction);
      first = false;
    }
    const glm::dvec3 residual = e.position - (ray.origin + lambda * ray.direction);
    jacobian = glm::dmat3(e.d_ds, e.d_dt, -ray.direction);
    const double scale = glm::length(e.d_ds) * glm::length(e.d_dt) * glm::length(ray.direction);
    if (!(std::abs(glm::determinant(jacobian)) > kSingular * scale)) return std::nullopt;
    if (glm::length(residual) <= tolerance) break;
    if (step == kMaxSteps) return std::nullopt;
    const glm::dvec3 delta = glm::inverse(jacobian) * residual;
    st -= glm::dvec2(delta.x, delta.y);
    lambda -= delta.z;
  }

  if (!(lambda > 0)) return std::nullopt;

  // d(s, t, lambda)/dx = J^-1 lambda dd/dx; the direction is affine in the screen point, so a
  // central difference of it is exact up to rounding.
  const glm::dmat3 inverse = glm::inverse(jacobian);
  const glm::dvec3 dd_dx = (object_ray(x + 1, y).direction - object_ray(x - 1, y).direction) * 0.5;
  const glm::dvec3 dd_dy = (object_ray(x, y + 1).direction - object_ray(x, y - 1).direction) * 0.5;
  const glm::dvec3 dx = inverse * (lambda * dd_dx), dy = inverse * (lambda * dd_dy);

  PixelHit hit;
  hit.pc = (st - lo) / extent;
  hit.d_dx = glm::dvec2(dx.x, dx.y) / extent;
  hit.d_dy = glm::dvec2(dy.x, dy.y) / extent;
  const glm::dvec3 n =
      glm::transpose(glm::inverse(glm::dmat3(model))) * unit_normal(*patch, st.x, st.y);
  const double len = glm::length(n);
  if (!(len > 0)) return std::nullopt;
  hit.normal = n / len;
  hit.position = glm::dvec3(model * glm::dvec4(e.position, 1.0));
  return hit;
}

}  // namespace tmu::host::nurbs
