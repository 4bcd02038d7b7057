#include "texsim/regress_join.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <map>

#include "common/image.hpp"
#include "render/tiles.hpp"

namespace tmu::texsim {
namespace {

namespace fs = std::filesystem;

// The files of `dir` whose names start with `prefix` and end in .png.
std::vector<fs::path> pngs(const fs::path& dir, const std::string& prefix) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().filename().string().rfind(prefix, 0) == 0 && e.path().extension() == ".png")
      out.push_back(e.path());
  }
  return out;
}

}  // namespace

std::string GroupJoin::summary() const {
  const char* what = join == Join::kBands ? "bands" : "frames";
  if (!joined()) return fmt::format("{} of {} not joined: {}", what, group, error);
  if (join == Join::kBands) return fmt::format("bands of {} joined: {}", group, output);
  return fmt::format("frames of {} gathered: {} ({} frames)", group, output, frames);
}

std::vector<GroupJoin> join_groups(const RegressOptions& options,
                                   const std::vector<RegressResult>& results) {
  std::map<std::string, std::vector<const RegressResult*>> groups;
  for (const RegressResult& r : results) {
    if (!r.test.group.empty()) groups[r.test.group].push_back(&r);
  }
  std::vector<GroupJoin> out;
  for (const auto& [group, tests] : groups) {
    GroupJoin j;
    j.group = group;
    j.join = tests.front()->test.join;
    std::vector<fs::path> parts;
    for (const RegressResult* r : tests) {
      if (!r->passed()) {
        j.error = r->test.name + " failed";
        break;
      }
      const fs::path dir = options.out / "renders" / r->test.name;
      for (fs::path& p : pngs(dir, j.join == Join::kBands ? "render.tile-" : "flyover.frame-"))
        parts.push_back(std::move(p));
    }
    if (j.joined()) {
      try {
        const fs::path target = options.out / "renders" / group;
        if (j.join == Join::kBands) {
          std::vector<std::string> bands(parts.begin(), parts.end());
          write_image(target.string() + ".png", render::merge_bands(bands));
          j.output = target.string() + ".png";
        } else {
          // The ranges' folders keep their frames (each test's outputs stay where its
          // reproduce command puts them); the group's folder has them all in one sequence.
          fs::create_directories(target);
          for (const fs::path& p : parts)
            fs::copy_file(p, target / p.filename(), fs::copy_options::overwrite_existing);
          j.output = target.string();
          j.frames = parts.size();
        }
      } catch (const std::exception& e) {
        j.error = e.what();
      }
    }
    out.push_back(j);
  }
  return out;
}

}  // namespace tmu::texsim
