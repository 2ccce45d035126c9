// Sorted subset coding: gaps g = p_i - p_{i-1} - 1 (p_{-1} = -1), each split
// by a Golomb parameter m into a quotient, in unary with adaptive bits, and a
// remainder, in truncated binary (Golomb 1966; the choice of m for a
// geometric source follows Gallager & Van Voorhis 1975).
//
// A set of more than half the universe is coded as its complement.
//
// Both sides know b and u, hence, before each gap, the largest gap that still
// leaves room for the positions after it: g_max = u - k - (p_{i-1} + 1) with
// k positions left including this one. The quotient stops at g_max / m
// without a terminating 0 and the last remainder's alphabet shrinks to what
// g_max allows, so a decoder cannot leave [0, u) whatever it reads, its
// unary loops are bounded, and b = u costs nothing.
#include "entropy/subset_coder.h"

#include <algorithm>

namespace gab {
namespace {

// Unary positions beyond this share the last model.
constexpr int kQuotientModels = 16;

// For gaps geometric with P(next position is in the set) = q = b/u, the
// Gallager-Van Voorhis parameter is about ln2/q - 0.85; this is
// floor(ln2 * u/b + 0.15) in 16.16 fixed point, so both sides agree on
// every platform (no libm). At least 1, at most u.
uint32_t golomb_parameter(uint32_t count, uint32_t universe) {
  if (count == 0) return 1;
  const uint64_t ln2 = 45426;    // ln 2 * 2^16
  const uint64_t bias = 10027;   // 0.153 * 2^16
  const uint64_t m = (ln2 * universe + bias * count) / (uint64_t{count} << 16);
  return static_cast<uint32_t>(std::min<uint64_t>(std::max<uint64_t>(m, 1), universe));
}

int floor_log2(uint64_t n) {
  int k = -1;
  while (n != 0) {
    ++k;
    n >>= 1;
  }
  return k;
}

// r in [0, n), n >= 1: the first 2^(k+1) - n values in k bits, the others in
// k + 1 bits, k = floor(log2 n).
void encode_truncated(RangeEncoder* enc, uint32_t r, uint64_t n) {
  const int k = floor_log2(n);
  const uint64_t short_codes = (uint64_t{2} << k) - n;
  if (r < short_codes) {
    enc->encode_raw(r, k);
  } else {
    enc->encode_raw(static_cast<uint32_t>(r + short_codes), k + 1);
  }
}

uint32_t decode_truncated(RangeDecoder* dec, uint64_t n) {
  const int k = floor_log2(n);
  const uint64_t short_codes = (uint64_t{2} << k) - n;
  uint64_t x = dec->decode_raw(k);
  if (x >= short_codes) x = ((x << 1) | dec->decode_raw(1)) - short_codes;  // < n
  return static_cast<uint32_t>(x);
}

}  // namespace

namespace {

void encode_sparse(RangeEncoder* enc, const std::vector<uint32_t>& sorted, uint32_t universe) {
  const uint32_t count = static_cast<uint32_t>(sorted.size());
  const uint32_t m = golomb_parameter(count, universe);
  BitModel quotient_models[kQuotientModels];
  int64_t previous = -1;
  for (uint32_t i = 0; i < count; ++i) {
    const int64_t gap_max = int64_t{universe} - (count - i) - (previous + 1);
    // Out-of-contract input (unsorted, >= universe) is clamped, never UB.
    const int64_t gap = std::min(std::max(int64_t{sorted[i]} - previous - 1, int64_t{0}), gap_max);
    const uint64_t quotient = static_cast<uint64_t>(gap) / m;
    const uint64_t quotient_max = static_cast<uint64_t>(gap_max) / m;
    for (uint64_t j = 0; j < quotient; ++j) {
      enc->encode(&quotient_models[std::min<uint64_t>(j, kQuotientModels - 1)], 1);
    }
    if (quotient < quotient_max) {
      enc->encode(&quotient_models[std::min<uint64_t>(quotient, kQuotientModels - 1)], 0);
    }
    const uint64_t remainder_max = std::min<uint64_t>(m - 1, gap_max - quotient * m);
    encode_truncated(enc, static_cast<uint32_t>(gap - quotient * m), remainder_max + 1);
    previous += gap + 1;
  }
}

bool decode_sparse(RangeDecoder* dec, uint32_t count, uint32_t universe, std::vector<uint32_t>* sorted) {
  // Grow as decoding goes: a corrupt stream stops at its overrun, long
  // before a lying count is reached.
  sorted->reserve(std::min<uint32_t>(count, 1u << 16));
  const uint32_t m = golomb_parameter(count, universe);
  BitModel quotient_models[kQuotientModels];
  int64_t previous = -1;
  for (uint32_t i = 0; i < count; ++i) {
    const int64_t gap_max = int64_t{universe} - (count - i) - (previous + 1);
    const uint64_t quotient_max = static_cast<uint64_t>(gap_max) / m;
    uint64_t quotient = 0;
    while (quotient < quotient_max &&
           dec->decode(&quotient_models[std::min<uint64_t>(quotient, kQuotientModels - 1)])) {
      ++quotient;
    }
    const uint64_t remainder_max = std::min<uint64_t>(m - 1, gap_max - quotient * m);
    const int64_t gap = static_cast<int64_t>(quotient * m + decode_truncated(dec, remainder_max + 1));
    previous += gap + 1;
    if (dec->overrun()) return false;
    // Cannot fail by construction; kept as the documented last line of defence.
    if (previous >= int64_t{universe}) return false;
    sorted->push_back(static_cast<uint32_t>(previous));
  }
  return true;
}

// Positions of [0, universe) not in `sorted`. O(universe).
std::vector<uint32_t> complement(const std::vector<uint32_t>& sorted, uint32_t universe) {
  std::vector<uint32_t> out;
  out.reserve(universe - std::min<size_t>(sorted.size(), universe));
  size_t i = 0;
  for (uint32_t p = 0; p < universe; ++p) {
    if (i < sorted.size() && sorted[i] == p) {
      ++i;
    } else {
      out.push_back(p);
    }
  }
  return out;
}

// More than half the universe: the complement is the sparser set, and
// gap-coding it pays adaptation and rounding costs on u - b gaps, not b.
bool use_complement(uint32_t count, uint32_t universe) { return uint64_t{count} * 2 > universe; }

}  // namespace

void encode_subset(RangeEncoder* enc, const std::vector<uint32_t>& sorted, uint32_t universe) {
  const uint32_t count = static_cast<uint32_t>(sorted.size());
  if (count == 0 || count > universe) return;  // nothing to code / contract broken
  if (use_complement(count, universe)) {
    encode_sparse(enc, complement(sorted, universe), universe);
  } else {
    encode_sparse(enc, sorted, universe);
  }
}

bool decode_subset(RangeDecoder* dec, uint32_t count, uint32_t universe, std::vector<uint32_t>* sorted) {
  sorted->clear();
  if (count > universe) return false;
  if (!use_complement(count, universe)) return decode_sparse(dec, count, universe, sorted);
  std::vector<uint32_t> missing;
  if (!decode_sparse(dec, universe - count, universe, &missing)) return false;
  *sorted = complement(missing, universe);
  return true;
}

}  // namespace gab
