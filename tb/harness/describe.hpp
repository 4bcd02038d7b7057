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

namespace tmu::tb {

// A row of a description at compile time: for the op and slot constants.
struct DescRow {
  bool channel;
  ChannelKind kind;  // of a channel row
};
inline constexpr uint64_t kNoOp = ~uint64_t{0};

// The op of channel row r: how many channels before it take an op (kNoOp if it takes none).
template <size_t N>
constexpr uint64_t op_of(const DescRow (&rows)[N], size_t r) {
  if (!takes_op(rows[r].kind)) return kNoOp;
  uint64_t op = 0;
  for (size_t i = 0; i < r; ++i) op += rows[i].channel && takes_op(rows[i].kind);
  return op;
}
// Whether the block's items carry an op field: more than one channel takes one.
template <size_t N>
constexpr bool has_op(const DescRow (&rows)[N]) {
  int n = 0;
  for (const DescRow& row : rows) n += row.channel && takes_op(row.kind);
  return n > 1;
}

}  // namespace tmu::tb

// clang-format off
#define TMU_DESC_NONE_C(kind, ch)
#define TMU_DESC_NONE_F(kind, ch, name, fmt, n)
#define TMU_DESC_INDEX_C(kind, ch) ch##_index_,
#define TMU_DESC_INDEX_F(kind, ch, name, fmt, n) ch##_##name##_index_,
#define TMU_DESC_ROW_C(kind, ch) {true, ::tmu::tb::ChannelKind::k##kind},
#define TMU_DESC_ROW_F(kind, ch, name, fmt, n) {false, {}},
// Elements counted: a field of n elements takes n slots.
#define TMU_DESC_SLOT_C(kind, ch) ch##_slot_,
#define TMU_DESC_SLOT_F(kind, ch, name, fmt, n) \
  ch##_##name##_slot_, ch##_##name##_end_ = ch##_##name##_slot_ + (n) - 1,
#define TMU_DESC_OP_C(kind, ch) \
  static constexpr uint64_t op_##ch = ::tmu::tb::op_of(rows_, ch##_index_);
#define TMU_DESC_FIELD_F(kind, ch, name, fmt, n)                                  \
  static constexpr int ch##_##name = ch##_##name##_slot_ - ch##_slot_ - 1 +       \
      (::tmu::tb::has_op(rows_) && op_##ch != ::tmu::tb::kNoOp ? 1 : 0);

#define TMU_DESCRIBE(block)                                                      \
  namespace tmu::tb::desc {                                                      \
  struct block {                                                                 \
    static const ::tmu::tb::BlockPorts& table() {                                \
      static const ::tmu::tb::BlockPorts t = [] {                                \
        ::tmu::tb::BlockPorts b(#block);                                         \
        TMU_PORTS_##block(TMU_PORTS_BUILD_C, TMU_PORTS_BUILD_F)                  \
        b.finish();                                                              \
        return b;                                                                \
      }();                                                                       \
      return t;                                                                  \
    }                                                                            \
    template <class M>                                                           \
    static std::vector<::tmu::tb::PortRow<::tmu::tb::RtlPorts>> rtl_rows() {     \
      return {TMU_PORTS_##block(TMU_RTL_C, TMU_RTL_F)};                          \
    }                                                                            \
    enum Index_ : int { TMU_PORTS_##block(TMU_DESC_INDEX_C, TMU_DESC_INDEX_F) }; \
    static constexpr ::tmu::tb::DescRow rows_[] = {                              \
        TMU_PORTS_##block(TMU_DESC_ROW_C, TMU_DESC_ROW_F)};                      \
    enum Slot_ : int { TMU_PORTS_##block(TMU_DESC_SLOT_C, TMU_DESC_SLOT_F) };    \
    TMU_PORTS_##block(TMU_DESC_OP_C, TMU_DESC_NONE_F)                            \
    TMU_PORTS_##block(TMU_DESC_NONE_C, TMU_DESC_FIELD_F)                         \
  };                                                                             \
  }
// clang-format on
