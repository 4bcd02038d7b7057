// TMU_DESCRIBE(block), after a block's TMU_PORTS_<block> rows (harness/ports.hpp), defines the
// struct tmu::tb::desc::block:
//   table()          the BlockPorts of the rows
//   rtl_rows<M>()    their accessors on any Verilated model M with those ports
//   <ch>_<field>     the Txn slot of each field (of an input item, output or request)
//   op_<ch>          the op of each stimulus channel and of the Cfg channel
// so that a block's own code reads item.f[desc::noise::in_u], not a number of its own.
#pragma once

#include "harness/ports.hpp"
#include "harness/rtl_ports.hpp"

#define TMU_DESC_NONE_C(kind, ch)
#define TMU_DESC_NONE_F(kind, ch, name, fmt, n)
#define TMU_DESC_ROW_C(kind, ch) ch##_row_,
#define TMU_DESC_ROW_F(kind, ch, name, fmt, n) \
  ch##_##name##_row_, ch##_##name##_end_ = ch##_##name##_row_ + (n)-1,
#define TMU_DESC_OPS_C(kind, ch) +(::tmu::tb::takes_op(::tmu::tb::ChannelKind::k##kind) ? 1 : 0)
#define TMU_DESC_BASE_C(kind, ch)   \
  static constexpr int ch##_base_ = \
      ::tmu::tb::takes_op(::tmu::tb::ChannelKind::k##kind) && kOps_ > 1 ? 1 : 0;
#define TMU_DESC_SLOT_F(kind, ch, name, fmt, n) \
  static constexpr int ch##_##name = ch##_##name##_row_ - ch##_row_ - 1 + ch##_base_;
#define TMU_DESC_OP_C(kind, ch) TMU_DESC_OP_C_##kind(ch)
#define TMU_DESC_OP_C_Sample(ch) op_##ch,
#define TMU_DESC_OP_C_Write(ch) op_##ch,
#define TMU_DESC_OP_C_Stream(ch) op_##ch,
#define TMU_DESC_OP_C_CombIn(ch) op_##ch,
#define TMU_DESC_OP_C_Cfg(ch) op_##ch,
#define TMU_DESC_OP_C_Result(ch)
#define TMU_DESC_OP_C_MemRequest(ch)
#define TMU_DESC_OP_C_MemRequestNoReady(ch)
#define TMU_DESC_OP_C_MemResponse(ch)
#define TMU_DESC_OP_C_CombOut(ch)
#define TMU_DESC_OP_C_Stat(ch)

#define TMU_DESCRIBE(block)                                                            \
  namespace tmu::tb::desc {                                                            \
  struct block {                                                                       \
    static const ::tmu::tb::BlockPorts& table() {                                      \
      static const ::tmu::tb::BlockPorts t = [] {                                      \
        ::tmu::tb::BlockPorts b(#block);                                               \
        TMU_PORTS_##block(TMU_PORTS_BUILD_C, TMU_PORTS_BUILD_F) b.finish();            \
        return b;                                                                      \
      }();                                                                             \
      return t;                                                                        \
    }                                                                                  \
    template <class M>                                                                 \
    static std::vector<::tmu::tb::PortRow<M>> rtl_rows() {                             \
      return {TMU_PORTS_##block(TMU_RTL_C, TMU_RTL_F)};                                \
    }                                                                                  \
    enum Row_ : int { TMU_PORTS_##block(TMU_DESC_ROW_C, TMU_DESC_ROW_F) };             \
    static constexpr int kOps_ = 0 TMU_PORTS_##block(TMU_DESC_OPS_C, TMU_DESC_NONE_F); \
    TMU_PORTS_##block(TMU_DESC_BASE_C, TMU_DESC_NONE_F) TMU_PORTS_                     \
        ##block(TMU_DESC_NONE_C, TMU_DESC_SLOT_F) enum Op : uint64_t {                 \
          TMU_PORTS_##block(TMU_DESC_OP_C, TMU_DESC_NONE_F)                            \
        };                                                                             \
  };                                                                                   \
  }
