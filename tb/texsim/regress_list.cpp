#include "texsim/regress_list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "common/error.hpp"
#include "render/flyover.hpp"

namespace tmu::texsim {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// "A..B" with 0 <= A <= B; throws std::invalid_argument with the reason.
std::pair<uint64_t, uint64_t> seed_range(const std::string& text) {
  const size_t dots = text.find("..");
  if (dots == std::string::npos) throw std::invalid_argument("'" + text + "' is not A..B");
  size_t end_a = 0, end_b = 0;
  const std::string a = text.substr(0, dots), b = text.substr(dots + 2);
  uint64_t first = 0, last = 0;
  try {
    first = std::stoull(a, &end_a);
    last = std::stoull(b, &end_b);
  } catch (const std::exception&) {
    throw std::invalid_argument("'" + text + "' is not A..B of whole numbers");
  }
  if (end_a != a.size() || end_b != b.size() || a[0] == '-' || b[0] == '-')
    throw std::invalid_argument("'" + text + "' is not A..B of whole numbers");
  if (first > last) throw std::invalid_argument("'" + text + "' is empty (A > B)");
  return {first, last};
}

// A count after option w[i]: 1..max; throws InputError naming the option.
int count_after(const std::vector<std::string>& w, size_t i, int max, const std::string& path,
                const std::string& where) {
  size_t end = 0;
  int n = 0;
  try {
    if (i + 1 < w.size()) n = std::stoi(w[i + 1], &end);
  } catch (const std::exception&) {
  }
  if (i + 1 == w.size() || end != w[i + 1].size() || n < 1 || n > max)
    throw InputError(path, where, fmt::format("{} needs a count 1..{}", w[i], max));
  return n;
}

// A render line's tests: one, the bands of --bands N, or a fly-over's frames in ranges of
// --frames-per-test K.
template <typename Add>
void add_render_tests(const fs::path& scene, const std::string& name, std::vector<std::string> w,
                      const std::string& path, const std::string& where, Add add) {
  std::vector<std::string> rest;
  int bands = 0, per_test = 0;
  std::string frames;
  for (size_t i = 0; i < w.size(); ++i) {
    if (w[i] == "--bands") {
      bands = count_after(w, i++, 256, path, where);
    } else if (w[i] == "--frames-per-test") {
      per_test = count_after(w, i++, 1024, path, where);
    } else if (w[i] == "--frames" && i + 1 < w.size()) {
      frames = w[++i];
    } else {
      rest.push_back(w[i]);
    }
  }
  const auto has = [&](const char* option) {
    return std::find(rest.begin(), rest.end(), option) != rest.end();
  };
  if (bands > 0 && has("--tile"))
    throw InputError(path, where, "--bands sets each band's --tile: not both");
  const auto test = [&](const std::string& test_name, Join join) {
    RegressTest t{
        test_name, {"render", scene.string()}, "render", join == Join::kNone ? "" : name, join};
    t.args.insert(t.args.end(), rest.begin(), rest.end());
    return t;
  };
  if (per_test == 0) {
    if (!frames.empty()) rest.insert(rest.end(), {"--frames", frames});
    if (bands == 0) add(test(name, Join::kNone), where);
    for (int b = 0; b < bands; ++b) {
      RegressTest t = test(name + ".band" + std::to_string(b), Join::kBands);
      t.args.insert(t.args.end(), {"--tile", fmt::format("{}/{}", b, bands)});
      add(std::move(t), where);
    }
    return;
  }
  if (bands > 0) throw InputError(path, where, "--frames-per-test with --bands: one of the two");
  if (!render::is_flyover(scene.string()))
    throw InputError(path, where, "--frames-per-test is for a fly-over scene");
  render::FrameRange range;
  try {
    if (!frames.empty()) range = render::parse_frame_range(frames);
    range = render::frames_of_path(range, render::load_flyover(scene.string(), "").frames());
  } catch (const InputError& e) {
    throw InputError(path, where, e.what());
  }
  for (int a = range.first; a <= range.last; a += per_test) {
    const int b = std::min(a + per_test - 1, range.last);
    RegressTest t = test(fmt::format("{}.frames{}-{}", name, a, b), Join::kFrames);
    t.args.insert(t.args.end(), {"--frames", fmt::format("{}-{}", a, b)});
    add(std::move(t), where);
  }
}

}  // namespace

std::vector<RegressTest> read_regress_list(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot read the regression list");
  const fs::path folder = fs::absolute(path).parent_path();
  std::vector<RegressTest> tests;
  std::set<std::string> names;
  int number = 0;
  const auto add = [&](RegressTest t, const std::string& where) {
    if (!names.insert(t.name).second) throw InputError(path, where, "test " + t.name + " twice");
    tests.push_back(std::move(t));
  };
  for (std::string line; std::getline(in, line);) {
    ++number;
    const std::string where = "line " + std::to_string(number);
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::vector<std::string> w = words(line);
    if (w.empty()) continue;
    if (w[0] == "cosim") {
      if (w.size() < 2 || w[1].rfind("--", 0) == 0)
        throw InputError(path, where, "cosim needs a block: cosim BLOCK [--seeds A..B] ...");
      std::pair<uint64_t, uint64_t> seeds{1, 1};
      std::vector<std::string> rest;
      for (size_t i = 2; i < w.size(); ++i) {
        if (w[i] == "--seed")
          throw InputError(path, where, "use --seeds A..B (the runner sets each --seed)");
        if (w[i] != "--seeds") {
          rest.push_back(w[i]);
          continue;
        }
        if (i + 1 == w.size()) throw InputError(path, where, "--seeds needs A..B");
        try {
          seeds = seed_range(w[++i]);
        } catch (const std::invalid_argument& e) {
          throw InputError(path, where, std::string("--seeds: ") + e.what());
        }
      }
      for (uint64_t s = seeds.first; s <= seeds.second; ++s) {
        RegressTest t{"cosim." + w[1] + ".seed" + std::to_string(s),
                      {"cosim", w[1], "--seed", std::to_string(s)},
                      "cosim",
                      "",
                      Join::kNone};
        t.args.insert(t.args.end(), rest.begin(), rest.end());
        add(std::move(t), where);
      }
    } else if (w[0] == "render") {
      if (w.size() < 2 || w[1].rfind("--", 0) == 0)
        throw InputError(path, where, "render needs a scene: render SCENE ...");
      const fs::path scene = fs::path(w[1]).is_absolute() ? fs::path(w[1]) : folder / w[1];
      if (!fs::exists(scene)) throw InputError(path, where, "no scene " + scene.string());
      const std::string name = "render." + scene.stem().string() + "." + std::to_string(number);
      add_render_tests(scene, name, {w.begin() + 2, w.end()}, path, where, add);
    } else {
      throw InputError(path, where, "unknown command '" + w[0] + "' (cosim or render)");
    }
  }
  if (tests.empty()) throw InputError(path, "", "no tests in the list");
  return tests;
}

}  // namespace tmu::texsim
