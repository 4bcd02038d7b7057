#include "texsim/model_levels.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "blocks/registry.hpp"
#include "blocks/trilinear/trilinear_block.hpp"
#include "common/image.hpp"
#include "harness/cosim.hpp"
#include "harness/scoreboard.hpp"
#include "render/render.hpp"

namespace tmu::texsim {
namespace {

// The trilinear workload is fixed rather than drawn from the seed, so that its figures are
// comparable from run to run: a true-colour 256² smooth texture, trilinear, wrap.
tb::BlockOptions options_of(const std::string& block, uint64_t seed) {
  tb::BlockOptions o;
  o.seed = seed;
  if (block == "trilinear") {
    o.tri_kind = texram::TexelKind::kTrueColour;
    o.tri_filter = texram::Filter::kTrilinear;
    o.tri_border_u = o.tri_border_v = texram::Border::kWrap;
    o.tri_combine = texram::Combine::kOne;
    o.tri_log2_w = o.tri_log2_h = 8;
    o.tri_pattern = "smooth";
  }
  return o;
}

// The scoreboard's verdict (harness/scoreboard.hpp): every output, memory request and counter.
std::string compare(const tb::Block& block, const tb::RunResult& golden, const tb::RunResult& run) {
  const tb::Comparison c = tb::compare(block.outputs(), golden, run, block.request_schemas());
  if (c.match()) return "yes";
  if (c.first) {
    const tb::Mismatch& m = *c.first;
    if (!m.got || m.fields.empty())
      return fmt::format("NO: output {} missing or extra", m.output_index);
    return fmt::format("NO: output {} field {}", m.output_index,
                       block.outputs().field(static_cast<size_t>(m.fields.front())).name);
  }
  if (!c.requests.empty()) {
    return fmt::format("NO: memory request {} of channel {}", c.requests.front().first.output_index,
                       c.requests.front().channel);
  }
  if (!c.counter_diffs.empty()) return "NO: counter " + c.counter_diffs.front();
  return "NO: " + c.error;
}

// The least total time a level is measured for (see measure_levels).
constexpr double kMinSeconds = 0.25;

}  // namespace

BlockLevels measure_levels(const std::string& block_name, size_t count, uint64_t seed,
                           std::ostream& log, int64_t inject_fault) {
  const auto block = tb::make_block(block_name, options_of(block_name, seed));
  tb::CosimOptions stimulus;
  stimulus.seed = seed;
  stimulus.count = count;
  stimulus.directed = false;
  const std::vector<tb::Txn> items = tb::build_stimulus(*block, stimulus);

  BlockLevels result{block_name, fmt::format("{} random items, seed {}", count, seed), {}};
  if (const auto* tri = dynamic_cast<const tb::TrilinearBlock*>(block.get())) {
    result.workload += "; " + tri->describe();
  }
  tb::RunResult golden;
  for (const std::string& level : kModelLevels) {
    LevelRun row{level, 0, 0, "-", ""};
    const std::string engine_level = level == "rtl-fst" ? "rtl" : level;  // traced below
    std::unique_ptr<tb::Engine> engine;
    try {
      engine = block->engine(engine_level);
    } catch (const std::invalid_argument& e) {
      row.note = e.what();
      result.runs.push_back(row);
      continue;
    }
    tb::RunOptions options;  // no stalls: every level at full rate
    std::filesystem::path fst;
    if (level == "rtl-fst") {
      fst = std::filesystem::temp_directory_path() / fmt::format("tmu_levels_{}.fst", block_name);
      options.trace = tb::TraceOptions{fst.string()};  // every cycle
    }
    log << fmt::format("  {} {} ...", block_name, level) << std::flush;
    tb::RunResult run = engine->run(items, options);
    if (level != "golden" && inject_fault >= 0 &&
        static_cast<size_t>(inject_fault) < run.outputs.size()) {
      run.outputs[static_cast<size_t>(inject_fault)].f[0] ^= 1;
    }
    row.transactions = run.outputs.size();
    row.seconds = run.seconds;
    // A run of a few milliseconds is timed mostly by the clock's granularity and the caches:
    // short runs are repeated, each on a fresh engine, until they add up to kMinSeconds, and
    // the mean is reported.
    int repeats = 1;
    for (double total = run.seconds; run.error.empty() && total < kMinSeconds && repeats < 1000;
         ++repeats) {
      total += block->engine(engine_level)->run(items, options).seconds;
      row.seconds = total / (repeats + 1);
    }
    if (!run.error.empty()) {
      row.verdict = "NO: " + run.error;
    } else if (level == "golden") {
      golden = run;
    } else if (level != "ideal") {
      row.verdict = compare(*block, golden, run);
    }
    if (!fst.empty() && std::filesystem::exists(fst)) {
      row.note = fmt::format("FST of every signal, {:.1f} MB",
                             static_cast<double>(std::filesystem::file_size(fst)) / 1e6);
      std::filesystem::remove(fst);
    }
    if (repeats > 1)
      row.note += fmt::format("{}mean of {} runs", row.note.empty() ? "" : "; ", repeats);
    log << fmt::format(" {:.3g} s\n", row.seconds);
    result.runs.push_back(row);
  }
  return result;
}

// A level's figures are a C++ model's (ideal, golden), or a simulation's compared with golden.
Mark mark_of_level(const std::string& level) {
  return level == "ideal" || level == "golden" ? Mark::kModel : Mark::kSim;
}

SweepTable levels_table(const std::vector<BlockLevels>& results) {
  SweepTable table({"block",
                    "level",
                    {"transactions", Mark::kSim},
                    {"seconds per run", Mark::kSim},
                    {"transactions/s", Mark::kSim},
                    {"vs golden", Mark::kSim},
                    {"= golden", Mark::kSim},
                    "note"});
  for (const BlockLevels& b : results) {
    double golden_rate = 0;
    for (const LevelRun& r : b.runs) {
      if (r.level == "golden" && r.seconds > 0)
        golden_rate = static_cast<double>(r.transactions) / r.seconds;
    }
    for (const LevelRun& r : b.runs) {
      if (r.transactions == 0) {
        table.add({b.block, r.level, "-", "-", "-", "-", "-", r.note});
        continue;
      }
      const double rate = r.seconds > 0 ? static_cast<double>(r.transactions) / r.seconds : 0;
      const Mark m = mark_of_level(r.level);
      table.add({b.block,
                 r.level,
                 {std::to_string(r.transactions), m},
                 {fmt::format("{:.3g}", r.seconds), m},
                 {fmt::format("{:.3g}", rate), m},
                 {golden_rate > 0 ? fmt::format("{:.3g}", rate / golden_rate) : "-", m},
                 r.verdict,
                 r.note});
    }
  }
  return table;
}

std::vector<SceneLevel> measure_scene_levels(const std::string& scene, const std::string& out_dir,
                                             std::ostream& log) {
  std::vector<SceneLevel> out;
  for (const render::Level level :
       {render::Level::kIdeal, render::Level::kGolden, render::Level::kHls, render::Level::kRtl}) {
    render::RenderOptions options;
    options.level = level;
    options.out_dir = out_dir + "/" + std::string(render::name(level));
    options.progress = false;
    render::RenderReport report;
    std::ostringstream text;  // the renders' own reports are not this table's
    log << fmt::format("  render {} at {} ...", scene, render::name(level)) << std::flush;
    if (render::render_scene(scene, options, text, &report) != 0) {
      throw std::runtime_error("render of " + scene + " failed at " +
                               std::string(render::name(level)) + ":\n" + text.str());
    }
    log << fmt::format(" {:.2f} s\n", report.total_s);
    out.push_back({std::string(render::name(level)), report.total_s, report.units_s, "-"});
  }
  // hls and rtl against golden: their frames pixel for pixel (a --check would add golden's
  // render to their wall time).
  const auto frame = [&](const std::string& engine) {
    return read_image(out_dir + "/" + engine + "/render.png");
  };
  const ImageRgb8 golden = frame("golden");
  for (SceneLevel& r : out) {
    if (r.engine == "hls" || r.engine == "rtl")
      r.frame_verdict = frame(r.engine).pixels == golden.pixels ? "yes" : "NO";
  }
  return out;
}

SweepTable scene_levels_table(const std::vector<SceneLevel>& results) {
  double golden = 0;
  for (const SceneLevel& r : results) {
    if (r.engine == "golden") golden = r.seconds;
  }
  SweepTable table({"engine",
                    {"wall s", Mark::kSim},
                    {"units s", Mark::kSim},
                    {"vs golden", Mark::kSim},
                    {"frame = golden", Mark::kSim}});
  for (const SceneLevel& r : results) {
    const Mark m = mark_of_level(r.engine);
    table.add({r.engine,
               {fmt::format("{:.2f}", r.seconds), m},
               {fmt::format("{:.2f}", r.units_seconds), m},
               {golden > 0 ? fmt::format("{:.2f}", r.seconds / golden) : "-", m},
               r.frame_verdict});
  }
  return table;
}

}  // namespace tmu::texsim
