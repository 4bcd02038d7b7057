// The fuzz targets without libFuzzer: feeds every file of fuzz/corpus/<target>/ to that
// target's LLVMFuzzerTestOneInput (compiled under another name for each target, see
// fuzz/CMakeLists.txt), so the normal build replays the corpus as a test. A crash, a sanitizer
// report (in a sanitizer build), a broken check or an exception other than InputError fails.
//
//   tmu_fuzz_replay CORPUS_DIR              every target on CORPUS_DIR/<target>/*
//   tmu_fuzz_replay TARGET FILE_OR_DIR...   one target on the given files (reproducing a crash)
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <typeinfo>
#include <vector>

extern "C" int tmu_fuzz_ccc(const uint8_t* data, size_t size);
extern "C" int tmu_fuzz_scene(const uint8_t* data, size_t size);
extern "C" int tmu_fuzz_volume_scene(const uint8_t* data, size_t size);
extern "C" int tmu_fuzz_trace(const uint8_t* data, size_t size);
extern "C" int tmu_fuzz_request(const uint8_t* data, size_t size);

namespace {

namespace fs = std::filesystem;

struct Target {
  const char* name;
  int (*run)(const uint8_t*, size_t);
};

constexpr Target kTargets[] = {{"ccc", tmu_fuzz_ccc},
                               {"scene", tmu_fuzz_scene},
                               {"volume_scene", tmu_fuzz_volume_scene},
                               {"trace", tmu_fuzz_trace},
                               {"request", tmu_fuzz_request}};

// The files of `path` (a file, or a directory's regular files), sorted.
std::vector<fs::path> inputs(const fs::path& path) {
  std::vector<fs::path> files;
  if (fs::is_directory(path)) {
    for (const auto& e : fs::directory_iterator(path)) {
      if (e.is_regular_file()) files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
  } else {
    files.push_back(path);
  }
  return files;
}

// Runs one input; false (with a message) when it throws. Crashes and aborts end the process.
bool replay(const Target& t, const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "fuzz replay: cannot open %s\n", file.c_str());
    return false;
  }
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  try {
    t.run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    return true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz replay: %s on %s: uncaught %s: %s\n", t.name, file.c_str(),
                 typeid(e).name(), e.what());
  } catch (...) {
    std::fprintf(stderr, "fuzz replay: %s on %s: uncaught non-standard exception\n", t.name,
                 file.c_str());
  }
  return false;
}

// Replays `paths` through `t`; returns the number of failures.
int replay_all(const Target& t, const std::vector<fs::path>& paths) {
  int files = 0, failed = 0;
  for (const fs::path& p : paths) {
    for (const fs::path& f : inputs(p)) {
      // Printed before the run, so a crash leaves the input that caused it on screen.
      std::fprintf(stderr, "  %s < %s\n", t.name, f.filename().c_str());
      ++files;
      if (!replay(t, f)) ++failed;
    }
  }
  std::printf("fuzz replay: %-8s %3d inputs, %d failed\n", t.name, files, failed);
  if (files == 0) {
    std::printf("fuzz replay: %s has no inputs\n", t.name);
    return 1;
  }
  return failed;
}

int usage() {
  std::fprintf(
      stderr,
      "usage: tmu_fuzz_replay CORPUS_DIR            (every target on CORPUS_DIR/<target>/)\n"
      "       tmu_fuzz_replay TARGET FILE_OR_DIR... (targets: ccc scene volume_scene trace "
      "request)\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string first = argv[1];
  if (first == "-h" || first == "--help") {
    usage();
    return 0;
  }
  int failed = 0;
  if (argc == 2 && fs::is_directory(first)) {
    for (const Target& t : kTargets) failed += replay_all(t, {fs::path(first) / t.name});
  } else {
    const auto t = std::find_if(std::begin(kTargets), std::end(kTargets),
                                [&](const Target& x) { return first == x.name; });
    if (t == std::end(kTargets) || argc < 3) return usage();
    failed = replay_all(*t, std::vector<fs::path>(argv + 2, argv + argc));
  }
  std::printf(failed ? "fuzz replay: FAILED\n" : "fuzz replay: all inputs handled\n");
  return failed ? 1 : 0;
}
