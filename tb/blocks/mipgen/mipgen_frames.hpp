// The mipmap generator's stimulus as a driver sends it (000 §12): a configuration item with a
// frame format, then whole frames of that format, texel by texel in source order; and the
// golden generator over such a run (MipgenFrames), which holds the rules of the stream.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "harness/txn.hpp"
#include "texram/mipgen_stream.hpp"
#include "texram/mipmap.hpp"

namespace tmu::tb {

// The configuration item of a format, and the format a configuration item writes.
Txn mipgen_config_item(const texram::MipgenConfig& format);
texram::MipgenConfig mipgen_format_of(const Txn& cfg);
// "8 x 4 interlaced, plane 3 of 4", for messages.
std::string mipgen_format_text(const texram::MipgenConfig& format);

// One frame's texel items in source order (interlaced: fields, with the texel above), the first
// marked start.
std::vector<Txn> mipgen_frame_items(const texram::Level8& level0, bool interlaced);
// What a driver sends for one frame of a new format: its configuration item, then the frame
// (whose size must be the format's).
std::vector<Txn> mipgen_items(const texram::MipgenConfig& format, const texram::Level8& level0);
// A frame in which every box of every level is a rounding tie (its mean halfway between two
// 8-bit values) under the default rule of texram/mipmap.hpp.
texram::Level8 mipgen_tie_frame(int log2_w, int log2_h);

// A write as the wr channel carries it, and back.
Txn mipgen_write_txn(const texram::CellWrite& w);
texram::CellWrite mipgen_txn_write(const Txn& t);

// The golden generator over a run: each configuration item starts a new stream of its format;
// texel items step the stream in effect, and a texel marked start begins a new frame of it (the
// frame under way, cut short, is left). Errors (std::runtime_error) for what the unit cannot
// take: a texel before the first configuration, a configuration in the middle of a frame (the
// RTL's source position and partial sums belong to the old format), a format outside the
// unit's (a side above 2^10, a plane beyond the texture's).
class MipgenFrames {
 public:
  void configure(const Txn& cfg);
  void step(const Txn& item, std::vector<texram::CellWrite>& out);

  // The stream in effect (nullptr before the first configuration).
  const texram::MipgenStream* stream() const { return stream_ ? &*stream_ : nullptr; }
  size_t configurations() const { return configurations_; }
  size_t items_since_configuration() const { return since_; }

 private:
  std::optional<texram::MipgenStream> stream_;
  size_t configurations_ = 0;
  size_t since_ = 0;
};

}  // namespace tmu::tb
