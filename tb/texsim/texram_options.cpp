#include "texsim/texram_options.hpp"

#include <charconv>
#include <filesystem>
#include <stdexcept>

#include "ccc/ccc_texture.hpp"
#include "common/error.hpp"
#include "common/image.hpp"

namespace tmu::texsim {

uint32_t parse_rgba_option(const std::string& option, const std::string& s) {
  const bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
  uint64_t v = 0;
  auto [p, ec] = std::from_chars(s.data() + (hex ? 2 : 0), s.data() + s.size(), v, hex ? 16 : 10);
  if (ec != std::errc() || p != s.data() + s.size() || v > 0xFFFFFFFFull) {
    throw InputError(option, "", "'" + s + "' is not an RGBA value like 0xFF8000FF");
  }
  return static_cast<uint32_t>(v);
}

texram::Border parse_border_option(const std::string& option, const std::string& s) {
  if (auto b = texram::parse_border(s)) return *b;
  throw InputError(option, "", "'" + s + "' is not a border mode (wrap, clamp, border, mirror)");
}

texram::Widths parse_widths_option(const std::string& option, const std::string& s) {
  int w[3] = {0, 0, 0};
  if (std::sscanf(s.c_str(), "%d,%d,%d", &w[0], &w[1], &w[2]) != 3 || w[0] < 1 || w[0] > 8 ||
      w[1] < 1 || w[1] > 8 || w[2] < 1 || w[2] > 8) {
    throw InputError(option, "", "'" + s + "' is not three widths 1..8 like 8,8,8");
  }
  return {w[0], w[1], w[2]};
}

void add_texram_options(CLI::App& cmd, TexramOptions& o) {
  cmd.add_option(
         "--config", o.config,
         "Texel configuration: luminance | index | rgba | single | ccc (a .ccc texture is ccc)")
      ->check(CLI::IsMember({"luminance", "index", "rgba", "single", "ccc"}))
      ->capture_default_str();
  cmd.add_option("--channel", o.channel, "single: the component the texture holds, r | g | b | a")
      ->check(CLI::IsMember({"r", "g", "b", "a"}))
      ->capture_default_str();
  cmd.add_option("--filter", o.filter, "nearest | bilinear | trilinear")
      ->check(CLI::IsMember({"nearest", "bilinear", "trilinear"}))
      ->capture_default_str();
  cmd.add_option("--border", o.border, "Border mode of both axes: wrap | clamp | border | mirror")
      ->capture_default_str();
  cmd.add_option("--border-u", o.border_u, "Border mode of u (overrides --border)");
  cmd.add_option("--border-v", o.border_v, "Border mode of v (overrides --border)");
  cmd.add_option("--border-colour", o.border_colour, "Border colour, 0xRRGGBBAA")
      ->capture_default_str();
  cmd.add_option("--combine", o.combine,
                 "Eq. 5: one | constant | shade (the requests' shade column)")
      ->check(CLI::IsMember({"one", "constant", "shade"}))
      ->capture_default_str();
  cmd.add_option("--constant", o.constant, "k_T of eq. 5, 0xRRGGBBAA")->capture_default_str();
  cmd.add_option("--widths", o.widths,
                 "Internal widths S,W,L: sub-texel, weight and lambda-fraction bits, 1..8")
      ->capture_default_str();
}

texram::SamplerConfig sampler_config(const TexramOptions& o) {
  texram::SamplerConfig c;
  c.kind = *texram::parse_texel_kind(o.config);
  c.single_channel = static_cast<int>(std::string("rgba").find(o.channel));
  c.filter = *texram::parse_filter(o.filter);
  c.border_u = parse_border_option("--border-u", o.border_u.empty() ? o.border : o.border_u);
  c.border_v = parse_border_option("--border-v", o.border_v.empty() ? o.border : o.border_v);
  c.border_rgba = parse_rgba_option("--border-colour", o.border_colour);
  c.combine = *texram::parse_combine(o.combine);
  c.constant_rgba = parse_rgba_option("--constant", o.constant);
  c.widths = parse_widths_option("--widths", o.widths);
  return c;
}

texram::TexramTexture load_texram_texture(const std::string& path, const TexramOptions& o) {
  try {
    if (std::filesystem::path(path).extension() == ".ccc") {
      if (o.config != "ccc" && o.config != "rgba") {
        throw InputError(path, "--config", "a .ccc texture is sampled in the ccc configuration");
      }
      return texram::import_ccc(ccc::read_ccc(path));
    }
    const texram::SamplerConfig c = sampler_config(o);
    return texram::import_image(read_image(path), c.kind, c.single_channel);
  } catch (const std::invalid_argument& e) {
    throw InputError(path, "size", e.what());
  }
}

}  // namespace tmu::texsim
