// The options of `texsim cosim`, in one place: the command defines them with
// add_cosim_options, and parse_cosim_line reads a printed command (a reproduce line, a
// variant's options in rtl/blocks.cmake) exactly as the command would.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "blocks/registry.hpp"
#include "harness/cosim.hpp"

namespace tmu::texsim {

// What a `texsim cosim` command line asks for.
struct CosimRequest {
  std::string block;
  tb::CosimOptions cosim;
  tb::BlockOptions block_options;
};

class CosimArgs;

// Defines the block argument and every option on `cmd`; call finish() on the result after
// parsing. Throws CLI::ValidationError for values the options' own checks cannot reject.
std::shared_ptr<CosimArgs> add_cosim_options(CLI::App& cmd);
CosimRequest finish(const CosimArgs& args);

// A command line after "texsim cosim" (e.g. "trilinear --seed 3 --widths 6,6,6"), parsed as the
// command parses it; throws CLI::ParseError (or std::invalid_argument) naming what is wrong.
CosimRequest parse_cosim_line(const std::string& line);

}  // namespace tmu::texsim
