#include "texsim/regress_list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "common/error.hpp"

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
                      ""};
        t.args.insert(t.args.end(), rest.begin(), rest.end());
        add(std::move(t), where);
      }
    } else if (w[0] == "render") {
      if (w.size() < 2 || w[1].rfind("--", 0) == 0)
        throw InputError(path, where, "render needs a scene: render SCENE ...");
      const fs::path scene = fs::path(w[1]).is_absolute() ? fs::path(w[1]) : folder / w[1];
      if (!fs::exists(scene)) throw InputError(path, where, "no scene " + scene.string());
      const std::string name = "render." + scene.stem().string() + "." + std::to_string(number);
      std::vector<std::string> rest;
      int bands = 0;
      for (size_t i = 2; i < w.size(); ++i) {
        if (w[i] != "--bands") {
          rest.push_back(w[i]);
          continue;
        }
        size_t end = 0;
        try {
          if (i + 1 < w.size()) bands = std::stoi(w[i + 1], &end);
        } catch (const std::exception&) {
        }
        if (i + 1 == w.size() || end != w[i + 1].size() || bands < 1 || bands > 256)
          throw InputError(path, where, "--bands needs a count 1..256");
        ++i;
      }
      if (bands > 0 && std::find(rest.begin(), rest.end(), "--tile") != rest.end())
        throw InputError(path, where, "--bands sets each band's --tile: not both");
      for (int b = 0; b < std::max(bands, 1); ++b) {
        RegressTest t{bands ? name + ".band" + std::to_string(b) : name,
                      {"render", scene.string()},
                      "render",
                      bands ? name : ""};
        t.args.insert(t.args.end(), rest.begin(), rest.end());
        if (bands) t.args.insert(t.args.end(), {"--tile", fmt::format("{}/{}", b, bands)});
        add(std::move(t), where);
      }
    } else {
      throw InputError(path, where, "unknown command '" + w[0] + "' (cosim or render)");
    }
  }
  if (tests.empty()) throw InputError(path, "", "no tests in the list");
  return tests;
}

}  // namespace tmu::texsim
