#include "render/video_mipgen.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "blocks/mipgen/mipgen_block.hpp"
#include "blocks/mipgen/mipgen_frames.hpp"
#include "texram/mipgen_stream.hpp"

namespace tmu::render {

VideoMipgenCheck check_video_mipgen(const host::Video& video, int frame,
                                    const VideoBuffers& buffers, Level level) {
  if (buffers.shown != frame)
    throw std::logic_error(fmt::format(
        "check_video_mipgen: the front buffer shows frame {}, not {}", buffers.shown, frame));
  const texram::TexramTexture& front = *buffers.buffers[static_cast<size_t>(buffers.front)];
  const texram::video::VideoFormat f = video_format(video);
  const texram::video::VideoFrame planes = video_frame(video, frame);
  const auto block = std::make_shared<tb::MipgenBlock>();
  VideoMipgenCheck out;
  for (int p = 0; p < f.planes; ++p) {
    const texram::MipgenConfig cfg{f.log2_w, f.log2_h, f.interlaced, f.planes, p};
    UnitRun run;
    run.kind = "mipgen";
    attach(run, block);
    run.items = tb::mipgen_items(cfg, planes[static_cast<size_t>(p)]);
    run_unit(run, level, {});
    out.golden_writes += texram::mipgen_frame(cfg, planes[static_cast<size_t>(p)]).size();
    out.cycles += run.result.cycles;
    out.seconds += run.result.seconds;
    for (const tb::Txn& t : run.result.outputs) {
      const texram::CellWrite w = tb::mipgen_txn_write(t);
      ++out.writes;
      out.differing += front.banks[w.cell.bank].at(w.cell.address) != w.value;
    }
  }
  return out;
}

}  // namespace tmu::render
