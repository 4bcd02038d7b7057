// The report of a render: what was built and run, how long it took, and the verdicts. Written
// as JSON (for scripts) and as a readable text summary (printed and saved).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "harness/engine.hpp"
#include "raster/rasterizer.hpp"
#include "render/tiles.hpp"
#include "render/units.hpp"

namespace tmu::render {

struct UnitReport {
  std::string name, kind;
  uint64_t transactions = 0, cycles = 0;
  bool predicted = false;  // untimed golden: the memory periods the page model predicts
  double seconds = 0;
  tb::Counters counters;
};

struct Mismatch {
  int x = 0, y = 0;
  std::string fragment;  // the fragment record, readable
  uint32_t expected = 0, got = 0;
};

struct CheckReport {
  std::string against;                   // the engine compared with
  uint64_t compared = 0, differing = 0;  // fragments
  std::vector<Mismatch> first;
  // Unit by unit (render/unit_check.hpp): outputs, memory requests and counters.
  uint64_t units_compared = 0;
  std::vector<std::string> unit_differences;
  std::string waveform;  // FST around the first mismatch, when written
  bool match() const { return differing == 0 && unit_differences.empty(); }
};

struct CompareReport {
  double psnr = 0, max_error = 0, mean_error = 0;  // golden against ideal, 8-bit levels
};

struct RenderReport {
  std::string scene, engine;
  Band band;
  host::RasterStats raster;
  uint64_t pixels = 0;  // of the band
  std::vector<UnitReport> units;
  std::vector<HostWork> host_work;  // the documents' stages the host computed, and why
  // With --chips: per material "NAME: chip C, DRF 1 -> 2" or "NAME: separate units: why".
  std::vector<std::string> chips;
  double front_end_s = 0, textures_s = 0, units_s = 0, total_s = 0;
  std::optional<CheckReport> check;
  std::optional<CompareReport> compare;
  std::vector<std::string> files;  // written

  uint64_t unit_cycles() const;  // all units
  std::string text() const;
  std::string json() const;
};

}  // namespace tmu::render
