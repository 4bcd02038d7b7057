#include "harness/txn.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace tmu::tb {

Schema::Schema(std::vector<Field> fields) : fields_(std::move(fields)) {
  for (size_t i = 0; i < fields_.size(); ++i) {
    Field& f = fields_[i];
    if (f.slot < 0) f.slot = static_cast<int>(i);
    if (f.slot >= kMaxFields) throw std::logic_error("field " + f.name + ": too many fields");
    if (f.op >= 0) has_op_ = true;
  }
  if (has_op_ && (fields_.empty() || fields_[0].name != "op" || fields_[0].slot != 0)) {
    throw std::logic_error("a schema with per-op fields starts with the op field");
  }
}

int Schema::index(const std::string& name) const {
  for (size_t i = 0; i < fields_.size(); ++i) {
    if (fields_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

bool Schema::carries(size_t index, const Txn& t) const {
  const int op = fields_[index].op;
  return op < 0 || t.f[0] == static_cast<uint64_t>(op);
}

std::string Schema::value_text(int field, uint64_t bits) const {
  const fx::Format& f = fields_[static_cast<size_t>(field)].format;
  const int digits = (f.width() + 3) / 4;
  std::string text = fmt::format("0x{:0{}x}", bits, digits);
  if (f.is_signed || f.frac_bits > 0) {
    const int64_t raw = fx::fit(static_cast<int64_t>(bits), f, fx::Overflow::kWrap);
    text += fmt::format(" ({})",
                        static_cast<double>(raw) / static_cast<double>(int64_t{1} << f.frac_bits));
  }
  return text;
}

std::string Schema::describe(const Txn& t) const {
  std::string out;
  for (size_t i = 0; i < fields_.size(); ++i) {
    if (!carries(i, t)) continue;
    if (!out.empty()) out += ' ';
    const Field& f = fields_[i];
    out += f.name + "=" + value_text(static_cast<int>(i), t.f[static_cast<size_t>(f.slot)]);
  }
  return out;
}

Txn Schema::masked(Txn t) const {
  Txn out;
  for (size_t i = 0; i < fields_.size(); ++i) {
    if (!carries(i, t)) continue;
    const Field& f = fields_[i];
    const int w = f.format.width();
    const auto s = static_cast<size_t>(f.slot);
    out.f[s] = w < 64 ? t.f[s] & ((uint64_t{1} << w) - 1) : t.f[s];
  }
  return out;
}

}  // namespace tmu::tb
