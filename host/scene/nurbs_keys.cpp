// The scene keys of NURBS objects and of the tau mapping (scenes/README.md, "nurbs").
#include <fmt/format.h>

#include <cmath>

#include "nurbs/conics.hpp"
#include "scene/scene_parts.hpp"

namespace tmu::host {
namespace {

// Steps per patch and direction: above this a typo (a threshold of 1e-9) would quietly cost
// minutes.
constexpr int kMaxSteps = 1024;

std::vector<double> numbers(const JsonNode& node) {
  node.expect_array();
  std::vector<double> v;
  for (size_t i = 0; i < node.size(); ++i) {
    const double x = node[i].number();
    if (!std::isfinite(x)) node[i].fail("must be finite");
    v.push_back(x);
  }
  return v;
}

// "points": count_t rows of count_s control points [x, y, z] or [x, y, z, w] (w the weight,
// default 1; the point is Euclidean, not premultiplied).
void parse_net(const JsonNode& node, nurbs::Patch& p) {
  node.expect_array();
  if (node.size() == 0) node.fail("expected rows of control points");
  p.count_t = static_cast<int>(node.size());
  p.count_s = -1;
  for (size_t j = 0; j < node.size(); ++j) {
    const JsonNode row = node[j];
    row.expect_array();
    if (p.count_s < 0) p.count_s = static_cast<int>(row.size());
    if (static_cast<int>(row.size()) != p.count_s) {
      row.fail(fmt::format("{} control points, but row 0 has {}: the net is a rectangle",
                           row.size(), p.count_s));
    }
    for (size_t i = 0; i < row.size(); ++i) {
      const JsonNode pt = row[i];
      pt.expect_array();
      if (pt.size() != 3 && pt.size() != 4) pt.fail("expected [x, y, z] or [x, y, z, w]");
      const std::vector<double> c = numbers(pt);
      p.points.emplace_back(c[0], c[1], c[2]);
      if (c.size() == 4 && !(c[3] > 0)) pt[3].fail("a weight must be > 0");
      p.weights.push_back(c.size() == 4 ? c[3] : 1.0);
    }
  }
}

nurbs::Patch parse_patch(const JsonNode& node) {
  node.expect_object();
  node.allow_keys({"degree", "knots_s", "knots_t", "points"});
  nurbs::Patch p;
  const JsonNode degree = node.at("degree");
  degree.expect_array();
  if (degree.size() != 2) degree.fail("expected [degree along s, degree along t]");
  p.degree_s = static_cast<int>(degree[0].integer(1, 3));
  p.degree_t = static_cast<int>(degree[1].integer(1, 3));
  parse_net(node.at("points"), p);
  p.knots_s = numbers(node.at("knots_s"));
  p.knots_t = numbers(node.at("knots_t"));
  // Everything else (knot counts and order, net size against degree, an empty domain).
  const std::string reason = nurbs::invalid_reason(p);
  if (!reason.empty()) node.fail(reason);
  return p;
}

Tessellation parse_tessellation(const JsonNode& node) {
  node.expect_object();
  node.allow_keys({"mc", "dc", "tc", "combine", "max_steps"});
  Tessellation t;
  if (auto v = node.find("mc")) t.mc = v->positive();
  if (auto v = node.find("dc")) t.dc = v->positive();
  if (auto v = node.find("tc")) t.tc = v->positive();
  if (auto c = node.find("combine")) {
    const std::string g = c->one_of({"mean", "geometric", "max"});
    t.combine = g == "mean"        ? Tessellation::Combine::kMean
                : g == "geometric" ? Tessellation::Combine::kGeometric
                                   : Tessellation::Combine::kMax;
  }
  if (auto m = node.find("max_steps")) t.max_steps = static_cast<int>(m->integer(1, kMaxSteps));
  if (!t.mc && !t.dc && !t.tc) t.dc = 4;
  return t;
}

glm::ivec2 cells(const JsonNode& node) {
  node.expect_array();
  if (node.size() != 2) node.fail("expected [cells along s, cells along t]");
  return {static_cast<int>(node[0].integer(1, tau::kMaxCells)),
          static_cast<int>(node[1].integer(1, tau::kMaxCells))};
}

// "nodes": (cells_t + 1) rows of (cells_s + 1) nodes [u, v].
void parse_nodes(const JsonNode& node, nurbs::TauMap& tau) {
  node.expect_array();
  const auto max_nodes = static_cast<size_t>(tau::kMaxCells) + 1;
  if (node.size() < 2 || node.size() > max_nodes)
    node.fail(fmt::format("expected 2..{} rows of nodes", max_nodes));
  const size_t width = node[0].size();
  for (size_t j = 0; j < node.size(); ++j) {
    const JsonNode row = node[j];
    row.expect_array();
    if (row.size() < 2 || row.size() > max_nodes)
      row.fail(fmt::format("expected 2..{} nodes [u, v]", max_nodes));
    if (row.size() != width)
      row.fail(
          fmt::format("{} nodes, but row 0 has {}: the grid is a rectangle", row.size(), width));
    for (size_t i = 0; i < row.size(); ++i) {
      const glm::dvec2 uv = row[i].vec2();
      if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) row[i].fail("must be finite");
      tau.nodes.push_back(uv);
    }
  }
  tau.cells = {static_cast<int>(width) - 1, static_cast<int>(node.size()) - 1};
}

}  // namespace

void parse_nurbs_object(const JsonNode& node, Object& o) {
  node.allow_keys({"type", "material", "transform", "surface", "radius", "tube", "height",
                   "patches", "tessellation"});
  o.shape = Object::Shape::kNurbs;
  if (auto surface = node.find("surface")) {
    if (node.has("patches")) node.at("patches").fail("give either surface or patches");
    const std::string kind = surface->one_of({"sphere", "torus", "cylinder"});
    const double radius = node.has("radius") ? node.at("radius").positive() : 1.0;
    if (kind == "sphere") o.patches = {nurbs::sphere(radius)};
    if (kind == "torus")
      o.patches = {nurbs::torus(radius, node.has("tube") ? node.at("tube").positive() : 0.25)};
    if (kind == "cylinder")
      o.patches = {
          nurbs::cylinder(radius, node.has("height") ? node.at("height").positive() : 2.0)};
  } else {
    for (std::string_view key : {"radius", "tube", "height"}) {
      if (auto k = node.find(key)) k->fail("applies to a surface (sphere, torus, cylinder) only");
    }
    const JsonNode patches = node.at("patches");
    patches.expect_array();
    if (patches.size() == 0) patches.fail("expected at least one patch");
    for (size_t i = 0; i < patches.size(); ++i) o.patches.push_back(parse_patch(patches[i]));
  }
  if (auto t = node.find("tessellation")) {
    o.tessellation = parse_tessellation(*t);
  } else {
    o.tessellation.dc = 4;
  }
}

void parse_tau(const JsonNode& node, Material& m) {
  if (auto t = node.find("tau")) {
    t->expect_object();
    nurbs::TauMap tau;
    const std::string map = t->at("map").one_of({"identity", "affine", "wave", "grid"});
    if (map == "identity") {
      t->allow_keys({"map", "cells", "interpolation"});
    } else if (map == "affine") {
      t->allow_keys({"map", "matrix", "offset", "cells", "interpolation"});
      tau.kind = nurbs::TauMap::Kind::kAffine;
      if (auto mx = t->find("matrix")) {
        mx->expect_array();
        if (mx->size() != 2) mx->fail("expected rows [[du/ds, du/dt], [dv/ds, dv/dt]]");
        const glm::dvec2 r0 = (*mx)[0].vec2(), r1 = (*mx)[1].vec2();
        tau.matrix = glm::dmat2(r0.x, r1.x, r0.y, r1.y);  // columns d/ds, d/dt
      }
      if (auto off = t->find("offset")) tau.offset = off->vec2();
    } else if (map == "wave") {
      t->allow_keys({"map", "amplitude", "frequency", "cells", "interpolation"});
      tau.kind = nurbs::TauMap::Kind::kWave;
      if (auto a = t->find("amplitude")) tau.amplitude = a->number();
      if (auto f = t->find("frequency")) tau.frequency = f->positive();
    } else {
      t->allow_keys({"map", "nodes", "interpolation"});
      tau.kind = nurbs::TauMap::Kind::kGrid;
      parse_nodes(t->at("nodes"), tau);
    }
    if (auto c = t->find("cells")) tau.cells = cells(*c);
    if (auto i = t->find("interpolation")) {
      tau.interp =
          i->one_of({"linear", "spline"}) == "linear" ? tau::Interp::kLinear : tau::Interp::kSpline;
    }
    m.tau = tau;
  }
  if (auto o = node.find("order")) {
    const std::string order = o->one_of({"pc", "tc", "texture", "composed"});
    m.order = order == "pc"        ? Material::Order::kPc
              : order == "tc"      ? Material::Order::kTc
              : order == "texture" ? Material::Order::kTexture
                                   : Material::Order::kComposed;
    if (m.order != Material::Order::kTc &&
        (m.unit == Material::Unit::kLowcost || m.uses_normal() || m.bump)) {
      o->fail("order " + order +
              " drives the trilinear unit or the footprint marcher: not "
              "with the lowcost unit, shading maps, bump or environment maps");
    }
  }
  if (auto l = node.find("lod")) {
    if (l->one_of({"pixel", "tc"}) == "tc") {
      if (m.order == Material::Order::kPc)
        l->fail(
            "with order pc the tau unit computes lambda per pixel; lod tc (claim 12) applies "
            "to the orders tc, texture and composed");
      m.lod = Material::Lod::kTc;
    }
  }
  // A tau of its own is the identity: order and lod work on the object's (s, t).
  if (!m.tau && (node.has("order") || node.has("lod"))) m.tau = nurbs::TauMap{};
}

}  // namespace tmu::host
