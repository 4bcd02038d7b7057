// Command-line options that configure the TEXRAM trilinear unit, shared by the commands that
// drive it (sample, sweep), and loading a texture in the chosen configuration.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "texram/sampler_config.hpp"
#include "texram/texture.hpp"

namespace tmu::texsim {

struct TexramOptions {
  std::string config = "rgba";
  std::string channel = "r";
  std::string filter = "trilinear";
  std::string border = "wrap";
  std::string border_u, border_v;  // override --border per axis
  std::string border_colour = "0x00000000";
  std::string combine = "one";
  std::string constant = "0xFFFFFFFF";
  std::string widths = "8,8,8";
};

void add_texram_options(CLI::App& cmd, TexramOptions& options);

// Throws InputError naming the option and the reason.
texram::SamplerConfig sampler_config(const TexramOptions& options);

// The parsers behind it, for commands that take single options (each throws InputError).
uint32_t parse_rgba_option(const std::string& option, const std::string& text);  // 0xRRGGBBAA
texram::Border parse_border_option(const std::string& option, const std::string& text);
texram::Widths parse_widths_option(const std::string& option, const std::string& text);  // S,W,L

// An image imported in the configuration, or a .ccc file (configuration ccc). Throws
// InputError naming the file and the reason (missing, corrupt, not a power of two, ...).
texram::TexramTexture load_texram_texture(const std::string& path, const TexramOptions& options);

}  // namespace tmu::texsim
