#include "texsim/regress_bands.hpp"

#include <filesystem>
#include <map>

#include "common/image.hpp"
#include "render/tiles.hpp"

namespace tmu::texsim {

std::vector<BandMerge> merge_band_groups(const RegressOptions& options,
                                         const std::vector<RegressResult>& results) {
  namespace fs = std::filesystem;
  std::map<std::string, std::vector<const RegressResult*>> groups;
  for (const RegressResult& r : results) {
    if (!r.test.group.empty()) groups[r.test.group].push_back(&r);
  }
  std::vector<BandMerge> out;
  for (const auto& [group, bands] : groups) {
    BandMerge m{group, "", ""};
    std::vector<std::string> images;
    for (const RegressResult* r : bands) {
      if (!r->passed()) {
        m.error = r->test.name + " failed";
        break;
      }
      const fs::path dir = options.out / "renders" / r->test.name;
      for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("render.tile-", 0) == 0 && e.path().extension() == ".png")
          images.push_back(e.path().string());
      }
    }
    if (m.error.empty()) {
      try {
        const fs::path image = options.out / "renders" / (group + ".png");
        write_image(image.string(), render::merge_bands(images));
        m.image = image.string();
      } catch (const std::exception& e) {
        m.error = e.what();
      }
    }
    out.push_back(m);
  }
  return out;
}

}  // namespace tmu::texsim
