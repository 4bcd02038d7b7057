// FNV-1a, 64 bits: the content key of the tools' caches (Icarus compiles, Yosys figures).
// Not for anything adversarial; a cache only needs distinct inputs to give distinct keys.
#pragma once

#include <cstdint>
#include <string_view>

namespace tmu {

inline constexpr uint64_t kFnv1aBasis = 0xcbf29ce484222325ull;

// Folds `s` into `h`, then an end marker, so that "ab" + "c" and "a" + "bc" differ.
inline uint64_t fnv1a(uint64_t h, std::string_view s) {
  constexpr uint64_t kPrime = 0x100000001b3ull;
  for (const char c : s) {
    h ^= static_cast<unsigned char>(c);
    h *= kPrime;
  }
  return (h ^ 0xFFu) * kPrime;
}

}  // namespace tmu
