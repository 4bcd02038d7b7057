// `texsim nurbs SCENE`: how a scene's NURBS objects are tessellated (004 claims 8-12, docs/
// nurbs.md): per patch the step counts each criterion asks for, the combined count and claim
// 12's level; the joins; and, with --wireframe, a picture of the triangles seen by the camera.
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <optional>

#include "common/image.hpp"
#include "geometry/mesh.hpp"
#include "nurbs/nurbs_mesh.hpp"
#include "raster/view.hpp"
#include "scene/scene.hpp"
#include "texsim/commands.hpp"

namespace tmu::texsim {
namespace {

struct NurbsArgs {
  std::string scene, wireframe;
  std::optional<double> mc, dc, tc;
};

std::string pair(const std::optional<glm::ivec2>& n) {
  return n ? fmt::format("{} x {}", n->x, n->y) : "-";
}

// The triangles' edges as the camera sees them (front faces only), NURBS objects bright and
// the others dim, on black.
ImageRgb8 wireframe(const host::Scene& scene, const std::vector<host::Mesh>& meshes) {
  const host::Camera& c = scene.camera;
  const glm::dmat4 vp = host::view_projection(c);
  ImageRgb8 image(c.width, c.height);
  for (size_t o = 0; o < meshes.size(); ++o) {
    const bool nurbs = scene.objects[o].shape == host::Object::Shape::kNurbs;
    const Rgb8 ink = nurbs ? Rgb8{255, 220, 90} : Rgb8{70, 80, 110};
    const glm::dmat4 mvp = vp * scene.objects[o].transform.matrix();
    const bool mirrored = glm::determinant(glm::dmat3(scene.objects[o].transform.matrix())) < 0;
    const host::Mesh& m = meshes[o];
    for (const auto& t : m.triangles) {
      glm::dvec2 p[3];
      bool visible = true;
      for (int k = 0; k < 3; ++k) {
        const glm::dvec4 q = mvp * glm::dvec4(m.vertices[t[static_cast<size_t>(k)]].position, 1.0);
        if (q.w <= c.near) visible = false;
        p[k] = host::to_screen(q, c.width, c.height);
      }
      // Counter-clockwise from the eye is a negative area with y down (a mirror flips it).
      const double area =
          (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
      if (!visible || (mirrored ? area <= 0 : area >= 0)) continue;
      for (int k = 0; k < 3; ++k) {
        const glm::dvec2 a = p[k], b = p[(k + 1) % 3];
        const int n =
            static_cast<int>(std::ceil(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)))) + 1;
        for (int i = 0; i <= n && n < 100000; ++i) {
          const glm::dvec2 q = a + (b - a) * (static_cast<double>(i) / n);
          const int x = static_cast<int>(std::floor(q.x)), y = static_cast<int>(std::floor(q.y));
          if (x >= 0 && y >= 0 && x < c.width && y < c.height) image.at(x, y) = ink;
        }
      }
    }
  }
  return image;
}

void run_nurbs(const NurbsArgs& a) {
  host::Scene scene = host::load_scene(a.scene);
  std::vector<glm::ivec2> sizes;
  for (const host::Material& m : scene.materials)
    sizes.push_back({m.texture.width, m.texture.height});
  if (a.mc || a.dc || a.tc) {
    for (host::Object& o : scene.objects) {
      o.tessellation.mc = a.mc;
      o.tessellation.dc = a.dc;
      o.tessellation.tc = a.tc;
    }
  }
  fmt::print(
      "{}: NURBS objects, steps per patch (s x t): by MC or DC, by TC, combined; claim 12's "
      "level (log2 texels per step)\n",
      a.scene);
  size_t triangles = 0;
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    const host::Object& obj = scene.objects[o];
    if (obj.shape != host::Object::Shape::kNurbs) continue;
    const auto m = static_cast<size_t>(obj.material);
    host::nurbs::NurbsStats stats;
    const host::Mesh mesh =
        host::nurbs::tessellate(obj, scene.materials[m], scene.camera, sizes[m], &stats);
    triangles += mesh.triangles.size();
    const host::Tessellation& t = obj.tessellation;
    fmt::print(
        "objects[{}] (material {}): {} patches, {} joins, {} triangles; thresholds mc {} "
        "dc {} tc {}, max {} steps\n",
        o, scene.materials[m].name, obj.patches.size(), stats.joins, mesh.triangles.size(),
        t.mc ? fmt::format("{:g}", *t.mc) : "-", t.dc ? fmt::format("{:g}", *t.dc) : "-",
        t.tc ? fmt::format("{:g}", *t.tc) : "-", t.max_steps);
    for (size_t p = 0; p < stats.patches.size(); ++p) {
      const host::nurbs::PatchSteps& s = stats.patches[p];
      fmt::print("  patch {:3}: MC/DC {:>11}  TC {:>11}  steps {:>9}  level {}\n", p, pair(s.mcdc),
                 pair(s.tc), pair(s.steps),
                 std::isfinite(s.lambda) ? fmt::format("{:.2f}", s.lambda) : "- (no tau)");
    }
  }
  fmt::print("{} NURBS triangles\n", triangles);
  if (!a.wireframe.empty()) {
    write_image(a.wireframe, wireframe(scene, host::make_meshes(scene, sizes)));
    fmt::print("wrote {}\n", a.wireframe);
  }
}

}  // namespace

void add_nurbs_command(CLI::App& app, ExitCode& exit_code) {
  auto* cmd = app.add_subcommand(
      "nurbs",
      "How a scene's NURBS objects are tessellated (004 claims 8-12): per patch the steps the "
      "MC or DC threshold asks for, the steps the TC threshold asks for, the combined count and "
      "claim 12's level; the joins between patches; --wireframe draws the triangles as the "
      "camera sees them. --mc, --dc, --tc replace every object's thresholds (docs/nurbs.md)");
  auto a = std::make_shared<NurbsArgs>();
  cmd->add_option("scene", a->scene, "The scene file")->required()->check(CLI::ExistingFile);
  const auto positive = CLI::PositiveNumber;
  cmd->add_option("--mc", a->mc, "longest step in modelling units")->check(positive);
  cmd->add_option("--dc", a->dc, "longest step in pixels")->check(positive);
  cmd->add_option("--tc", a->tc, "longest step in texels of level 0")->check(positive);
  cmd->add_option("--wireframe", a->wireframe, "Write the triangles' edges as a PNG");
  cmd->callback([a, &exit_code] {
    run_nurbs(*a);
    exit_code.value = 0;
  });
}

}  // namespace tmu::texsim
