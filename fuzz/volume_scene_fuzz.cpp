// Fuzz target: the volume scene parser (host/volume/volume_scene.hpp, parse_volume_scene from
// text, which load_volume_scene calls with the file's text). Relative paths resolve against the
// bundled scenes/ folder; the parser only reads a data file's size, it never writes. A scene it
// accepts must be one the renderer can set up: a finite camera basis, the data's size in the
// unit's range and on chips whose slabs fit their banks, a step and weight bits in range,
// transfer points in increasing value order with colours and opacities in 0..1, shading only on
// raw data.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>

#include "common/error.hpp"
#include "fuzz_check.hpp"
#include "volume/slabs.hpp"
#include "volume/volume_scene.hpp"

#ifndef TMU_FUZZ_SCENES_DIR
#error "TMU_FUZZ_SCENES_DIR (the scenes/ folder) must be defined"
#endif

namespace {

bool finite_vector(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool unit_after_normalize(const glm::dvec3& v) {
  const glm::dvec3 n = glm::normalize(v);
  return finite_vector(n) && std::abs(glm::length(n) - 1) < 1e-6;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace tmu::host;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string name = "fuzz.json";
  try {
    const VolumeScene s = parse_volume_scene(text, name, TMU_FUZZ_SCENES_DIR);
    const Camera& c = s.camera;
    TMU_FUZZ_CHECK(c.width >= 1 && c.width <= 4096 && c.height >= 1 && c.height <= 4096);
    TMU_FUZZ_CHECK(c.fov_deg > 0 && c.fov_deg < 180);
    TMU_FUZZ_CHECK(unit_after_normalize(c.target - c.position));
    TMU_FUZZ_CHECK(unit_after_normalize(glm::cross(glm::normalize(c.target - c.position), c.up)));
    for (uint32_t n : s.data.size) TMU_FUZZ_CHECK(n >= 2 && n <= 512);
    TMU_FUZZ_CHECK(slab_problem(s.data.size, s.chips, s.slab_axis, volume_mode(s)).empty());
    TMU_FUZZ_CHECK(s.step >= kMinStep && s.step <= kMaxStep);
    TMU_FUZZ_CHECK(s.weight_bits >= 1 && s.weight_bits <= 8);
    const auto& points = s.transfer.points();
    for (size_t i = 0; i < points.size(); ++i) {
      TMU_FUZZ_CHECK(points[i].value >= 0 && points[i].value <= 255);
      TMU_FUZZ_CHECK(points[i].opacity >= 0 && points[i].opacity <= 1);
      TMU_FUZZ_CHECK(i == 0 || points[i].value > points[i - 1].value);
    }
    TMU_FUZZ_CHECK(!points.empty() ||
                   (s.format == VolumeFormat::kRgba && s.data.field == VolumeData::Field::kFile));
    TMU_FUZZ_CHECK(s.lights.empty() || s.format == VolumeFormat::kRaw);
    if (s.termination) {
      TMU_FUZZ_CHECK(s.termination->alpha > 0 && s.termination->alpha <= 1);
      TMU_FUZZ_CHECK(s.termination->segment >= 1);
    }
  } catch (const tmu::InputError& e) {
    TMU_FUZZ_CHECK(tmu::fuzz::names_file_and_reason(e, name));
    TMU_FUZZ_CHECK(!e.reason().starts_with("[json.exception."));
  }
  return 0;
}
