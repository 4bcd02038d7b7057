// Perspective-correct interpolation over one triangle, set up once and evaluated at any pixel
// position: the general form of 002 eq. 3.7, u = N_u(x, y) / D(x, y) with N_u and D affine in
// the screen position (Olano and Greer's 2D homogeneous rasterization). With the rows of
// M = [X_i Y_i W_i] the vertices in homogeneous pixel coordinates (X = sx * w, Y = sy * w), the
// weights e(x, y) = (x, y, 1) M^-1 are the vertices' barycentric coordinates divided by the
// point's w, so an attribute a is sum(e_i a_i) / sum(e_i). Both sums are affine in (x, y): the
// derivatives of a are exact by the quotient rule, da/dx = (dN_a/dx - a dD/dx) / D.
//
// The setup depends on the whole triangle only, not on how the clipper cut it, so every piece
// of a clipped triangle interpolates the same function.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <optional>

namespace tmu::host {

struct SetupVertex {
  glm::dvec4 clip{0};    // homogeneous clip space (after projection)
  glm::dvec2 uv{0};      // texels of level 0
  glm::dvec3 solid{0};   // object space
  glm::dvec3 world{0};   // world space
  glm::dvec3 normal{0};  // world space
  glm::dvec4 colour{0};  // a vertex colour (004 claims 17, 18), 0..255 per channel
};

struct Interpolated {
  double depth = 0;         // NDC z
  glm::dvec2 uv{0};         // texels
  glm::dvec2 r1{0}, r2{0};  // d(u, v)/dx, d(u, v)/dy
  glm::dvec3 solid{0}, world{0};
  glm::dvec3 normal{0};  // interpolated, not renormalised
  glm::dvec4 colour{0};
};

class TriangleSetup {
 public:
  // Viewport: clip x -1..1 to screen 0..width, clip y 1..-1 to screen 0..height (y down).
  // nullopt when M is singular: a degenerate triangle, or one whose plane contains the eye.
  static std::optional<TriangleSetup> make(const std::array<SetupVertex, 3>& v, int width,
                                           int height);

  double depth(double x, double y) const;
  Interpolated at(double x, double y) const;

 private:
  struct Plane {
    double a = 0, b = 0, c = 0;  // a x + b y + c
    double at(double x, double y) const { return a * x + b * y + c; }
  };
  // Sums over the vertices: of e (the denominator D), of e * w, of e * z (their quotient is
  // the depth), and of e times each attribute.
  enum : size_t {
    kD,
    kW,
    kZ,
    kU,
    kV,
    kSolid,
    kWorld = kSolid + 3,
    kNormal = kWorld + 3,
    kColour = kNormal + 3,
    kCount = kColour + 4
  };
  std::array<Plane, kCount> planes_;
};

}  // namespace tmu::host
