#include "harness/txn.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace tmu::tb {

Schema::Schema(std::vector<Field> fields) : fields_(std::move(fields)) {
  if (fields_.size() > static_cast<size_t>(kMaxFields)) throw std::logic_error("too many fields");
}

int Schema::index(const std::string& name) const {
  for (size_t i = 0; i < fields_.size(); ++i) {
    if (fields_[i].name == name) return static_cast<int>(i);
  }
  return -1;
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
    if (i) out += ' ';
    out += fields_[i].name + "=" + value_text(static_cast<int>(i), t.f[i]);
  }
  return out;
}

Txn Schema::masked(Txn t) const {
  for (size_t i = 0; i < fields_.size(); ++i) {
    const int w = fields_[i].format.width();
    if (w < 64) t.f[i] &= (uint64_t{1} << w) - 1;
  }
  return t;
}

}  // namespace tmu::tb
