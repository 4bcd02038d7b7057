// Fixed-point layer shared by the golden and hls models.
//
// A Format is Qm.n with a signedness: width = int_bits + frac_bits, and for signed formats
// the sign bit is one of the int_bits (SQ16.8 is 24 bits wide and spans [-2^15, 2^15)).
// Values are plain int64_t "raw" integers scaled by 2^-frac_bits, because golden arithmetic
// must run at native-integer speed (sc_fixed costs hundreds of ns per operation).
//
// Every narrowing names its rounding and its overflow behaviour; nothing narrows implicitly.
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace tmu::fx {

struct Format {
  bool is_signed;
  int int_bits;  // includes the sign bit when is_signed
  int frac_bits;

  constexpr int width() const { return int_bits + frac_bits; }
  constexpr int64_t min_raw() const { return is_signed ? -(int64_t{1} << (width() - 1)) : 0; }
  constexpr int64_t max_raw() const {
    return is_signed ? (int64_t{1} << (width() - 1)) - 1 : (int64_t{1} << width()) - 1;
  }
  constexpr bool holds(int64_t raw) const { return raw >= min_raw() && raw <= max_raw(); }
  constexpr bool operator==(const Format&) const = default;
};

constexpr Format SQ(int int_bits, int frac_bits) { return {true, int_bits, frac_bits}; }
constexpr Format UQ(int int_bits, int frac_bits) { return {false, int_bits, frac_bits}; }

// Raw values live in int64_t; one bit of headroom keeps products of two 31-bit values exact.
constexpr int kMaxWidth = 62;

std::string to_string(const Format& f);  // "SQ16.8" / "UQ0.8"

// How dropped fraction bits are resolved when a value loses precision.
enum class Round {
  kFloor,       // drop the bits (toward -infinity); free in hardware
  kTowardZero,  // truncate the magnitude
  kHalfUp,      // nearest, ties toward +infinity: add half an LSB, then floor
  kHalfEven,    // nearest, ties to even (unbiased)
};

// What happens when a value does not fit the integer range of the target format.
enum class Overflow {
  kWrap,      // keep the low bits (two's complement), as plain hardware does
  kSaturate,  // clamp to the format's min or max
  kTrap,      // an internal invariant: throw std::logic_error
};

// Shift right by `shift` bits (>= 0) resolving the dropped bits with `round`.
// Exact for every int64_t input whose result fits; shift >= 63 is resolved as a shift of 62.
constexpr int64_t shift_right_round(int64_t v, int shift, Round round) {
  if (shift <= 0) return v;
  if (shift > 62) shift = 62;
  const int64_t one = int64_t{1} << shift;
  const int64_t floor_q = v >> shift;     // arithmetic shift: floor division
  const int64_t rem = v - floor_q * one;  // 0 <= rem < one
  const int64_t half = one >> 1;
  switch (round) {
    case Round::kFloor:
      return floor_q;
    case Round::kTowardZero:
      return (v < 0 && rem != 0) ? floor_q + 1 : floor_q;
    case Round::kHalfUp:
      return rem >= half ? floor_q + 1 : floor_q;
    case Round::kHalfEven:
      if (rem > half) return floor_q + 1;
      if (rem < half) return floor_q;
      return (floor_q & 1) ? floor_q + 1 : floor_q;
  }
  return floor_q;
}

// Bring `raw` into the integer range of `f` as `overflow` says.
inline int64_t fit(int64_t raw, const Format& f, Overflow overflow) {
  if (f.holds(raw)) return raw;
  switch (overflow) {
    case Overflow::kSaturate:
      return raw < f.min_raw() ? f.min_raw() : f.max_raw();
    case Overflow::kWrap: {
      const uint64_t mask = (uint64_t{1} << f.width()) - 1;
      uint64_t low = static_cast<uint64_t>(raw) & mask;
      if (f.is_signed && (low >> (f.width() - 1)) != 0) low |= ~mask;  // sign-extend
      return static_cast<int64_t>(low);
    }
    case Overflow::kTrap:
      break;
  }
  throw std::logic_error("fixed-point overflow: " + std::to_string(raw) + " does not fit " +
                         to_string(f));
}

// Re-express `raw` in format `from` as format `to`: shift the binary point, then fit.
inline int64_t convert_raw(int64_t raw, const Format& from, const Format& to, Round round,
                           Overflow overflow) {
  const int shift = from.frac_bits - to.frac_bits;
  const int64_t scaled =
      shift >= 0 ? shift_right_round(raw, shift, round) : raw * (int64_t{1} << -shift);
  return fit(scaled, to, overflow);
}

// A value of format F. Construction from raw bits is checked; arithmetic results carry the
// exact (full-precision) format, so only explicit narrow() calls lose information.
template <Format F>
class Fixed {
  static_assert(F.width() >= 1 && F.width() <= kMaxWidth, "format width out of range");

 public:
  static constexpr Format format = F;

  constexpr Fixed() = default;

  // Raw bits as they appear on a port; out of range is an internal error.
  static Fixed from_raw(int64_t raw) {
    if (!F.holds(raw)) {
      throw std::logic_error("raw value " + std::to_string(raw) + " outside " + to_string(F));
    }
    Fixed x;
    x.raw_ = raw;
    return x;
  }

  // Nearest representable value under `round`, saturated to the range (NaN gives 0).
  static Fixed from_double(double v, Round round = Round::kHalfEven) {
    const double scaled = std::ldexp(v, F.frac_bits);
    double q = 0.0;
    switch (round) {
      case Round::kFloor:
        q = std::floor(scaled);
        break;
      case Round::kTowardZero:
        q = std::trunc(scaled);
        break;
      case Round::kHalfUp:
        q = std::floor(scaled + 0.5);
        break;
      case Round::kHalfEven: {
        q = std::floor(scaled);
        const double rem = scaled - q;
        if (rem > 0.5 || (rem == 0.5 && std::fmod(q, 2.0) != 0.0)) q += 1.0;
        break;
      }
    }
    if (std::isnan(q)) q = 0.0;
    if (q <= static_cast<double>(F.min_raw())) return from_raw(F.min_raw());
    if (q >= static_cast<double>(F.max_raw())) return from_raw(F.max_raw());
    return from_raw(static_cast<int64_t>(q));
  }

  constexpr int64_t raw() const { return raw_; }
  constexpr double to_double() const {
    return static_cast<double>(raw_) / static_cast<double>(int64_t{1} << F.frac_bits);
  }
  // Two's-complement bits of the value, as a port of F.width() bits carries them.
  constexpr uint64_t bits() const {
    return static_cast<uint64_t>(raw_) & ((uint64_t{1} << F.width()) - 1);
  }
  // Inverse of bits(): interpret the low F.width() bits.
  static Fixed from_bits(uint64_t b) {
    return from_raw(
        fit(static_cast<int64_t>(b & ((uint64_t{1} << F.width()) - 1)), F, Overflow::kWrap));
  }

  friend constexpr bool operator==(Fixed a, Fixed b) { return a.raw_ == b.raw_; }

 private:
  int64_t raw_ = 0;
};

// Result formats of exact arithmetic.
constexpr Format sum_format(Format a, Format b) {
  const bool s = a.is_signed || b.is_signed;
  // An unsigned operand mixed with a signed one needs a sign bit of its own.
  const int ia = a.int_bits + (s && !a.is_signed ? 1 : 0);
  const int ib = b.int_bits + (s && !b.is_signed ? 1 : 0);
  return {s, (ia > ib ? ia : ib) + 1, a.frac_bits > b.frac_bits ? a.frac_bits : b.frac_bits};
}
constexpr Format diff_format(Format a, Format b) {
  Format f = sum_format(a, b);
  if (!f.is_signed) f = {true, f.int_bits + 1, f.frac_bits};  // a - b of unsigned may go negative
  return f;
}
constexpr Format product_format(Format a, Format b) {
  return {a.is_signed || b.is_signed, a.int_bits + b.int_bits, a.frac_bits + b.frac_bits};
}

namespace detail {
inline int64_t align(int64_t raw, int from_frac, int to_frac) {
  return raw * (int64_t{1} << (to_frac - from_frac));
}
}  // namespace detail

// Exact sum; result format sum_format(A, B).
template <Format A, Format B>
Fixed<sum_format(A, B)> add(Fixed<A> a, Fixed<B> b) {
  constexpr Format R = sum_format(A, B);
  return Fixed<R>::from_raw(detail::align(a.raw(), A.frac_bits, R.frac_bits) +
                            detail::align(b.raw(), B.frac_bits, R.frac_bits));
}

// Exact difference; always signed.
template <Format A, Format B>
Fixed<diff_format(A, B)> sub(Fixed<A> a, Fixed<B> b) {
  constexpr Format R = diff_format(A, B);
  return Fixed<R>::from_raw(detail::align(a.raw(), A.frac_bits, R.frac_bits) -
                            detail::align(b.raw(), B.frac_bits, R.frac_bits));
}

// Exact product; result format product_format(A, B).
template <Format A, Format B>
Fixed<product_format(A, B)> mul(Fixed<A> a, Fixed<B> b) {
  return Fixed<product_format(A, B)>::from_raw(a.raw() * b.raw());
}

// The one narrowing operation: to format To with named rounding and overflow.
template <Format To, Format From>
Fixed<To> narrow(Fixed<From> x, Round round, Overflow overflow) {
  return Fixed<To>::from_raw(convert_raw(x.raw(), From, To, round, overflow));
}

}  // namespace tmu::fx
