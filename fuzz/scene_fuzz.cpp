// Fuzz target: the scene parser (host/scene/scene.hpp, parse_scene from text, which load_scene
// calls with the file's text). Relative paths resolve against the bundled scenes/ folder, so
// the seeds that name scenes/images/default.png or scenes/models/*.obj parse in full; the
// parser only reads files (the image header, a .ccc file), it never writes. A scene it accepts
// must be one the renderer can set up: a camera whose view basis (glm::lookAt) is finite,
// directional lights with a direction to normalize, objects naming existing materials.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>

#include "common/error.hpp"
#include "formats/formats.hpp"
#include "fuzz_check.hpp"
#include "scene/scene.hpp"

#ifndef TMU_FUZZ_SCENES_DIR
#error "TMU_FUZZ_SCENES_DIR (the scenes/ folder) must be defined"
#endif

namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A unit vector from `v`, as the renderer takes it: finite and of length about 1.
bool normalizable(const glm::dvec3& v) {
  const glm::dvec3 n = glm::normalize(v);
  return finite(n) && std::abs(glm::length(n) - 1) < 1e-6;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string name = "fuzz.json";
  try {
    const tmu::host::Scene s = tmu::host::parse_scene(text, name, TMU_FUZZ_SCENES_DIR);
    const tmu::host::Camera& c = s.camera;
    TMU_FUZZ_CHECK(c.width >= 1 && c.width <= 4096 && c.height >= 1 && c.height <= 4096);
    TMU_FUZZ_CHECK(c.fov_deg > 0 && c.fov_deg < 180 && c.near > 0 && c.far > c.near);
    TMU_FUZZ_CHECK(finite(c.position) && finite(c.target) && finite(c.up));
    const glm::dvec3 forward = c.target - c.position;
    TMU_FUZZ_CHECK(normalizable(forward));
    TMU_FUZZ_CHECK(normalizable(glm::cross(glm::normalize(forward), c.up)));
    for (const tmu::host::Light& l : s.lights) {
      TMU_FUZZ_CHECK(finite(l.vector) && finite(l.colour));
      if (l.kind == tmu::host::Light::Kind::kDirectional) TMU_FUZZ_CHECK(normalizable(l.vector));
    }
    TMU_FUZZ_CHECK(s.materials.size() <= 256);
    for (const tmu::host::Object& o : s.objects) {
      TMU_FUZZ_CHECK(o.material >= 0 && static_cast<size_t>(o.material) < s.materials.size());
    }
  } catch (const tmu::InputError& e) {
    TMU_FUZZ_CHECK(tmu::fuzz::names_file_and_reason(e, name));
    // The reason is the project's words, not nlohmann's exception text (which may quote the
    // input, so only its prefix tells).
    TMU_FUZZ_CHECK(!e.reason().starts_with("[json.exception."));
  }
  return 0;
}
