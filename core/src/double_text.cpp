// SPDX-License-Identifier: GPL-3.0-or-later
// fmt 9's layout of "{}" for a double, in its fixed-notation case: fmt's do_write_float
// is general (width, fill, locale, grouping, precision, showpoint) and costs about as
// much as finding the digits; with none of those asked, the layout is a few copies.
#include "double_text.h"

#include <cstdint>
#include <cstring>

#include <fmt/compile.h>
#include <fmt/format.h>

namespace lepp::detail {
namespace {

// "00" to "99": two digits a division.
constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The digits of v < 10^8, exactly 8 of them (leading zeros kept), ending just before `end`.
void eight_digits_before(char* end, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) {
    end -= 2;
    std::memcpy(end, kPairs + 2 * (v % 100), 2);
    v /= 100;
  }
}

// The digits of v < 10^9 without leading zeros, ending just before `end`; returns the
// first digit's place.
char* digits_before(char* end, std::uint32_t v) {
  while (v >= 100) {
    end -= 2;
    std::memcpy(end, kPairs + 2 * (v % 100), 2);
    v /= 100;
  }
  if (v >= 10) {
    end -= 2;
    std::memcpy(end, kPairs + 2 * v, 2);
  } else {
    *--end = static_cast<char>('0' + v);
  }
  return end;
}

// The significand's digits (at most 17) ending just before `end`; returns the first
// digit's place. Its low 8 digits split off once, the rest in 32-bit arithmetic.
char* digits_before(char* end, std::uint64_t v) {
  if (v < 100000000) return digits_before(end, static_cast<std::uint32_t>(v));
  eight_digits_before(end, static_cast<std::uint32_t>(v % 100000000));
  return digits_before(end - 8, static_cast<std::uint32_t>(v / 100000000));
}

}  // namespace

char* write_double(char* at, double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const unsigned biased_exponent = static_cast<unsigned>(bits >> 52) & 0x7ff;
  // Zero and subnormals (field 0), infinities and NaN (field 2047): fmt's own way
  // (to_decimal is for finite values only; subnormals are in exponent notation anyway).
  if (biased_exponent == 0 || biased_exponent == 0x7ff) return fmt::format_to(at, FMT_COMPILE("{}"), x);
  const bool negative = (bits >> 63) != 0;
  const auto dec = fmt::detail::dragonbox::to_decimal(negative ? -x : x);
  // The digits, at most 17, written once into a scratch buffer and then placed.
  char scratch[20];
  char* const scratch_end = scratch + sizeof scratch;
  const char* first = digits_before(scratch_end, dec.significand);
  const int size = static_cast<int>(scratch_end - first);
  // fmt 9's rule for "{}" (float_specs general, no precision): exponent notation when
  // the decimal exponent of the first digit is below -4 or at least 16.
  const int point = dec.exponent + size;  // digits before the decimal point
  if (point - 1 < -4 || point - 1 >= 16) return fmt::format_to(at, FMT_COMPILE("{}"), x);
  if (negative) *at++ = '-';
  if (dec.exponent >= 0) {  // 1234e2 -> 123400, no point
    std::memcpy(at, first, static_cast<std::size_t>(size));
    at += size;
    std::memset(at, '0', static_cast<std::size_t>(dec.exponent));
    return at + dec.exponent;
  }
  if (point > 0) {  // 1234e-2 -> 12.34
    std::memcpy(at, first, static_cast<std::size_t>(point));
    at += point;
    *at++ = '.';
    std::memcpy(at, first + point, static_cast<std::size_t>(size - point));
    return at + (size - point);
  }
  // 1234e-6 -> 0.001234
  std::memcpy(at, "0.0000", 2 + static_cast<std::size_t>(-point));
  at += 2 - point;
  std::memcpy(at, first, static_cast<std::size_t>(size));
  return at + size;
}

}  // namespace lepp::detail
