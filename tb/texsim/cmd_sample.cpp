// `texsim sample`: a request file through the TEXRAM trilinear unit at any model level; the
// results as a CSV a hardware engineer can diff, and a report of memory accesses and timing.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>

#include "blocks/trilinear/trilinear_block.hpp"
#include "ccc/ccc_texture.hpp"
#include "common/error.hpp"
#include "texram/page_model.hpp"
#include "texram/trilinear.hpp"
#include "texram/trilinear_ideal.hpp"
#include "texsim/commands.hpp"
#include "texsim/ideal_rgba.hpp"
#include "texsim/request_file.hpp"
#include "texsim/texram_options.hpp"

namespace tmu::texsim {
namespace {

texram::Request port_request(const SampleRequest& r) {
  using formats::Lod;
  using formats::TexCoord;
  return {static_cast<int32_t>(TexCoord::from_double(r.u).raw()),
          static_cast<int32_t>(TexCoord::from_double(r.v).raw()),
          static_cast<int32_t>(Lod::from_double(r.lambda).raw()), r.shade};
}

struct Run {
  std::vector<uint32_t> rgba;
  std::optional<texram::PageStats> memory;  // predicted by the page model (golden)
  uint64_t cycles = 0;                      // measured (rtl, hls)
  double seconds = 0;
};

Run run_engine(const std::string& engine, const texram::TexramTexture& tex,
               const texram::SamplerConfig& config, const std::vector<SampleRequest>& requests) {
  Run run;
  const auto t0 = std::chrono::steady_clock::now();
  if (engine == "ideal") {
    const texram::IdealTexture ideal = texram::ideal_texture(tex.source);
    for (const SampleRequest& r : requests) {
      run.rgba.push_back(
          round_rgba(texram::ideal_sample(ideal, config, r.u, r.v, r.lambda, r.shade)));
    }
  } else if (engine == "golden") {
    texram::PageModel pages;
    for (const SampleRequest& r : requests) {
      texram::SamplePlan plan;
      run.rgba.push_back(texram::sample(tex, config, port_request(r), &plan));
      for (int p = 0; p < plan.planes; ++p) {
        std::array<std::optional<uint32_t>, 8> addresses = plan.bank_address;
        for (auto& a : addresses) {
          if (a) *a += static_cast<uint32_t>(p);
        }
        pages.access(addresses);
      }
    }
    run.memory = pages.stats();
  } else {  // hls, rtl: the trilinear block's engines, the configuration (and CLUT) first
    const tb::TrilinearBlock block(
        tb::BlockOptions{}, {std::make_shared<const texram::TexramTexture>(tex), config, "sample"});
    std::vector<tb::Txn> items = block.setup_items();
    for (const SampleRequest& r : requests) {
      const texram::Request p = port_request(r);
      items.push_back(tb::trilinear_sample_item(p.u, p.v, p.lambda, p.shade));
    }
    const tb::RunResult result = block.engine(engine)->run(items, tb::RunOptions{});
    if (!result.error.empty()) throw std::runtime_error(engine + " run failed: " + result.error);
    for (const tb::Txn& t : result.outputs) run.rgba.push_back(static_cast<uint32_t>(t.f[0]));
    texram::PageStats m;
    m.accesses = tb::counter_value(result.counters, "accesses").value_or(0);
    m.bank_reads = tb::counter_value(result.counters, "bank_reads").value_or(0);
    m.page_faults = tb::counter_value(result.counters, "page_faults").value_or(0);
    m.slow_accesses = tb::counter_value(result.counters, "slow_accesses").value_or(0);
    run.memory = m;
    run.cycles = result.cycles;
    run.seconds = result.seconds;
    return run;
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return run;
}

// "page_faults 12 against 13, ..." for each counter that differs; empty when all agree.
std::string memory_difference(const texram::PageStats& a, const texram::PageStats& b) {
  std::string d;
  const auto add = [&](const char* name, uint64_t x, uint64_t y) {
    if (x != y) d += fmt::format("{}{} {} against {}", d.empty() ? "" : ", ", name, x, y);
  };
  add("accesses", a.accesses, b.accesses);
  add("bank_reads", a.bank_reads, b.bank_reads);
  add("page_faults", a.page_faults, b.page_faults);
  add("slow_accesses", a.slow_accesses, b.slow_accesses);
  return d;
}

// The hardware's results against the ideal model, unrounded: how far apart, per channel, in
// 8-bit levels.
void print_error_against_ideal(const texram::TexramTexture& tex,
                               const texram::SamplerConfig& config,
                               const std::vector<SampleRequest>& requests,
                               const std::vector<uint32_t>& hardware) {
  const texram::IdealTexture ideal_tex = texram::ideal_texture(tex.source);
  double max_err = 0, sum = 0;
  for (size_t i = 0; i < requests.size(); ++i) {
    const SampleRequest& r = requests[i];
    const auto ideal = texram::ideal_sample(ideal_tex, config, r.u, r.v, r.lambda, r.shade);
    for (int ch = 0; ch < 4; ++ch) {
      const double e = std::abs(texram::channel(hardware[i], ch) - ideal[static_cast<size_t>(ch)]);
      max_err = std::max(max_err, e);
      sum += e;
    }
  }
  fmt::print("  error against ideal: max {:.3f}, mean {:.4f} (8-bit levels)\n", max_err,
             sum / (4.0 * static_cast<double>(requests.size())));
}

// Two engines' results bit for bit, and their memory counters (golden's page model predicts
// what the hls and rtl memories count): MATCH or MISMATCH, printed. Not for ideal, which
// counts no memory.
bool bit_exact(const Run& run, const Run& other, const std::string& engine,
               const std::string& check) {
  if (other.rgba != run.rgba) {
    size_t differ = 0;
    for (size_t i = 0; i < run.rgba.size(); ++i) differ += run.rgba[i] != other.rgba[i];
    fmt::print("MISMATCH: {} of {} results differ between {} and {}\n", differ, run.rgba.size(),
               engine, check);
    return false;
  }
  if (const std::string d = memory_difference(*run.memory, *other.memory); !d.empty()) {
    fmt::print("MISMATCH: the memory counters differ between {} and {}: {}\n", engine, check, d);
    return false;
  }
  fmt::print("MATCH: {} = {}, all {} results bit-exact, and the memory counters\n", engine, check,
             run.rgba.size());
  return true;
}

void report(const Run& run, size_t n) {
  if (run.cycles) {
    const double per_clock = static_cast<double>(n) / static_cast<double>(run.cycles);
    fmt::print(
        "  measured: {} clock cycles (with the configuration, CLUT load and pipeline fill) -> "
        "{:.3f} samples per "
        "clock, {:.2f} M samples/s at {:.1f} "
        "MHz\n",
        run.cycles, per_clock, per_clock * texram::kUnitClockMhz, texram::kUnitClockMhz);
  }
  if (run.memory) {
    const texram::PageStats& m = *run.memory;
    const uint64_t periods = m.accesses + m.slow_accesses;
    fmt::print(
        "  memory: {} accesses, {} bank reads, {} page faults; {} accesses took two periods "
        "({:.1f} %)\n",
        m.accesses, m.bank_reads, m.page_faults, m.slow_accesses,
        100.0 * static_cast<double>(m.slow_accesses) /
            static_cast<double>(std::max<uint64_t>(m.accesses, 1)));
    const double per_clock =
        static_cast<double>(n) / static_cast<double>(std::max<uint64_t>(periods, 1));
    fmt::print(
        "  page model: {} periods of {} ns -> {:.3f} samples per clock, {:.2f} M samples/s at "
        "{:.1f} "
        "MHz\n",
        periods, texram::kAccessNs, per_clock, per_clock * texram::kUnitClockMhz,
        texram::kUnitClockMhz);
  }
  fmt::print("  wall time {:.3f} s ({:.2f} M samples/s simulated)\n", run.seconds,
             static_cast<double>(n) / std::max(run.seconds, 1e-9) / 1e6);
}

}  // namespace

void add_sample_command(CLI::App& app, ExitCode& exit_code) {
  auto* cmd = app.add_subcommand(
      "sample",
      "Sample a texture through the TEXRAM trilinear unit (000 §2, §5, §6) for every request of a\n"
      "request file; write the results as r,g,b,a. The request and result formats are in the "
      "README.");
  struct Args {
    std::string texture, requests, out, engine = "golden", check;
    TexramOptions texram;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("--texture", a->texture,
                  "Texture: an image (power-of-two sides up to 1024) or a .ccc file")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--requests", a->requests,
                  "Request file (CSV: u,v,lambda[,shade][,dudx,dvdx,dudy,dvdy])")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", a->out, "Result file (CSV: r,g,b,a), written atomically")->required();
  cmd->add_option("--engine", a->engine, "ideal | golden | hls | rtl")
      ->check(CLI::IsMember({"ideal", "golden", "hls", "rtl"}))
      ->capture_default_str();
  cmd->add_option("--check", a->check,
                  "Also run this engine and compare: ideal -> error statistics, else bit for bit")
      ->check(CLI::IsMember({"ideal", "golden", "hls", "rtl"}));
  add_texram_options(*cmd, a->texram);
  cmd->callback([a, &exit_code] {
    const texram::SamplerConfig config = sampler_config(a->texram);
    const texram::TexramTexture tex = load_texram_texture(a->texture, a->texram);
    const std::vector<SampleRequest> requests = read_requests(a->requests);
    fmt::print(
        "sample: {} requests, {} ({}x{}, {} levels, {}), {} filter, border {}/{}, engine {}\n",
        requests.size(), a->texture, tex.geometry.texel_width(0), tex.geometry.texel_height(0),
        tex.geometry.levels(), texram::name(tex.kind), texram::name(config.filter),
        texram::name(config.border_u), texram::name(config.border_v), a->engine);
    const Run run = run_engine(a->engine, tex, config, requests);
    report(run, requests.size());
    if (a->check == "ideal" || (a->engine == "ideal" && !a->check.empty())) {
      print_error_against_ideal(
          tex, config, requests,
          a->engine == "ideal" ? run_engine(a->check, tex, config, requests).rgba : run.rgba);
    } else if (!a->check.empty() &&
               !bit_exact(run, run_engine(a->check, tex, config, requests), a->engine, a->check)) {
      exit_code.value = 1;
      return;
    }
    write_results(a->out, run.rgba);
    fmt::print("wrote {}\n", a->out);
  });
}

}  // namespace tmu::texsim
