#include "tasks/shortest.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>

// The shortest decimal that reads back as the same double, written as std::to_chars(…,
// chars_format::general) writes it, in about three fifths of its time (the 10 kHz CSV's two
// million numbers; docs/speed.md "Writing the output").
//
// The digits are found by Schubfach (R. Giulietti, "The Schubfach way to render doubles", 2020,
// cited on that page): v = c·2^q is scaled by 10^−k so that the interval of reals that round
// to v is between 1 and 10 units wide; the one multiple of 10 in it, if any, gives the shortest
// digits, else the nearer of the two integers around v·10^−k that lie in it. The scaled values
// are computed with 10^−k rounded up to 126 bits and the product rounded to odd, which the paper
// shows is exact enough for every comparison made, once products that are exactly whole are
// seen to (roundOdd). The digits are turned into characters eight
// at a time in the bytes of one 64-bit word.
namespace tasks {
namespace {

using u64 = std::uint64_t;
using u128 = unsigned __int128;

// ⌊log10(2^e)⌋, ⌊log10(3/4·2^e)⌋ and ⌊log2(10^e)⌋ by fixed-point logarithms (log10 2 and
// log10 4/3 times 2^41, log2 10 times 2^38, rounded), right for every exponent a double has: the
// tests write every power of two and its neighbours, whose digits a wrong k would change.
constexpr int floorLog10Pow2(int e) {
  return static_cast<int>((static_cast<std::int64_t>(e) * 661971961083) >> 41);
}
constexpr int floorLog10ThreeQuartersPow2(int e) {
  return static_cast<int>((static_cast<std::int64_t>(e) * 661971961083 - 274743187321) >> 41);
}
constexpr int floorLog2Pow10(int e) {
  return static_cast<int>((static_cast<std::int64_t>(e) * 913124641741) >> 38);
}

constexpr int kMinK = -324;  // ⌊log10(2^−1074)⌋
constexpr int kMaxK = 292;   // ⌊log10(2^971)⌋

// A number of up to 20 64-bit words, enough for 2^1202, for the table made at compile time.
struct Big {
  std::array<u64, 20> w{};
  constexpr void times10() {
    u64 carry = 0;
    for (u64& x : w) {
      const u128 p = static_cast<u128>(x) * 10 + carry;
      x = static_cast<u64>(p);
      carry = static_cast<u64>(p >> 64);
    }
  }
  constexpr void over10() {
    u64 rest = 0;
    for (int i = 19; i >= 0; --i) {
      const u128 n = (static_cast<u128>(rest) << 64) | w[i];
      w[i] = static_cast<u64>(n / 10);
      rest = static_cast<u64>(n % 10);
    }
  }
  constexpr int bits() const {
    for (int i = 19; i >= 0; --i)
      if (w[i]) return 64 * i + 64 - std::countl_zero(w[i]);
    return 0;
  }
  // Whether any of the lowest n bits is set.
  constexpr bool anyBelow(int n) const {
    for (int b = 0; b < n; ++b)
      if ((w[b / 64] >> (b % 64)) & 1) return true;
    return false;
  }
  // ⌊this / 2^n⌋'s low 128 bits (n ≥ 0).
  constexpr u128 shiftedDown(int n) const {
    u128 out = 0;
    for (int b = 0; b < 128; ++b) {
      const int at = n + b;
      if (at / 64 < 20 && ((w[at / 64] >> (at % 64)) & 1)) out |= static_cast<u128>(1) << b;
    }
    return out;
  }
};

// g(k) = ⌈10^−k · 2^(125 − β)⌉ with β = ⌊log2(10^−k)⌋: 10^−k rounded up to 126 bits (exact
// where it fits),
// made from 10^e and ⌊2^1216 / 10^m⌋, each from the one before (nested floors: ⌊⌊x/10⌋/10⌋ is
// ⌊x/100⌋).
struct Scales {
  std::array<u64, kMaxK - kMinK + 1> hi{}, lo{};
  constexpr void put(int k, u128 g) {
    hi[k - kMinK] = static_cast<u64>(g >> 64);
    lo[k - kMinK] = static_cast<u64>(g);
  }
};
constexpr Scales makeScales() {
  Scales s;
  Big power;  // 10^e
  power.w[0] = 1;
  for (int e = 0; e <= -kMinK; ++e, power.times10()) {
    const int beta = power.bits() - 1;
    if (beta <= 125) {
      s.put(-e, power.shiftedDown(0) << (125 - beta));  // exact
    } else {
      const int cut = beta - 125;
      s.put(-e, power.shiftedDown(cut) + (power.anyBelow(cut) ? 1 : 0));
    }
  }
  constexpr int kN = 1216;
  Big reciprocal;  // ⌊2^1216 / 10^m⌋
  reciprocal.w[kN / 64] = u64{1} << (kN % 64);
  power = Big{};
  power.w[0] = 1;
  for (int m = 1; m <= kMaxK; ++m) {
    reciprocal.over10();
    power.times10();
    // 10^−m = 1 / 10^m: β = −bits(10^m), as 10^m is not a power of two.
    s.put(m, reciprocal.shiftedDown(kN - 125 - power.bits()) + 1);
  }
  return s;
}
constexpr Scales kScales = makeScales();

// 5^k for k ≤ 23, the powers below 2^55.
constexpr std::array<u64, 24> kFives = [] {
  std::array<u64, 24> p{};
  p[0] = 1;
  for (std::size_t i = 1; i < p.size(); ++i) p[i] = p[i - 1] * 5;
  return p;
}();

// ⌊g·x / 2^128⌋ rounded to odd (its lowest bit set when anything below was cut), for x = c'·2^h
// with c' < 2^55. g is 10^−k rounded up, so the product is a little too large; that matters only
// when the exact product c'·2^(q+2)·10^−k is a whole number, which 10^−k inexact (k > 0) allows
// only for 5^k dividing c' (k ≤ 23); for k ≤ 0 either g is exact or c'·2^q·10^−k would need more
// than 55 factors of two in c'.
inline u64 roundOdd(u64 ghi, u64 glo, u64 x, int k) {
  const u128 low = static_cast<u128>(glo) * x;
  const u128 high = static_cast<u128>(ghi) * x + static_cast<u64>(low >> 64);
  const u64 whole = static_cast<u64>(high >> 64);
  u64 cut = (static_cast<u64>(high) | static_cast<u64>(low)) != 0;
  if (static_cast<unsigned>(k - 1) < 23u && x % kFives[k] == 0) [[unlikely]]
    cut = 0;  // exact: the excess was all there was below
  return whole | cut;
}

// Eight digits of x < 10^8 as characters, the first in the lowest byte.
inline u64 eightDigits(u64 x) {
  u64 v = (x / 10000) | ((x % 10000) << 32);        // two lanes of 4 digits
  u64 q = ((v * 5243) >> 19) & 0x0000007F0000007F;  // y / 100 for y < 10000
  v = q | ((v - 100 * q) << 16);                    // four lanes of 2 digits
  q = ((v * 103) >> 10) & 0x000F000F000F000F;       // z / 10 for z < 100
  return q | ((v - 10 * q) << 8);                   // eight digits, 0–9 a byte
}

// e±XX (two digits at least), as %g writes it.
char* writeExponent(char* at, int exponent) {
  const int e = exponent < 0 ? -exponent : exponent;
  at[0] = 'e';
  at[1] = exponent < 0 ? '-' : '+';
  at += 2;
  if (e >= 100) *at++ = static_cast<char>('0' + e / 100);
  at[0] = static_cast<char>('0' + e / 10 % 10);
  at[1] = static_cast<char>('0' + e % 10);
  return at + 2;
}

// Fewer than 16 digits (whole numbers, subnormals): through a buffer of the 17 digits.
[[gnu::noinline]] char* writeFewDigits(char* at, u64 digits, int k) {
  // digits < 10^17 (or a whole number < 2^53 < 10^16): 17 characters, leading zeros included.
  const u64 upper = digits / 100000000;
  const u64 first = upper / 100000000;  // 0 … 9
  const u64 middle = eightDigits(upper % 100000000);
  const u64 last = eightDigits(digits % 100000000);
  char text[48];  // 17 digits, and room for the fixed-size copies below
  text[0] = static_cast<char>('0' + first);
  const u64 zeros = 0x3030303030303030;
  const u64 m = middle | zeros, l = last | zeros;
  std::memcpy(text + 1, &m, 8);
  std::memcpy(text + 9, &l, 8);
  // Where the digits begin and end (trailing zeros dropped into k).
  int lead;
  if (first)
    lead = 0;
  else if (middle)
    lead = 1 + std::countr_zero(middle) / 8;
  else
    lead = 9 + std::countr_zero(last) / 8;
  int end;  // one past the last non-zero digit
  if (last)
    end = 17 - std::countl_zero(last) / 8;
  else if (middle)
    end = 9 - std::countl_zero(middle) / 8;
  else
    end = 1;
  const int count = end - lead;
  k += 17 - end;
  const int exponent = k + count - 1;  // of the first digit
  const char* d = text + lead;

  if (exponent < -4 || exponent >= 6) {  // scientific, as %g with its precision 6
    *at++ = d[0];
    if (count > 1) {
      *at++ = '.';
      std::memcpy(at, d + 1, 16);
      at += count - 1;
    }
    return writeExponent(at, exponent);
  }
  if (exponent < 0) {  // 0.000ddd
    std::memcpy(at, "0.0000", 6);
    at += 1 - exponent;
    std::memcpy(at, d, 17);
    return at + count;
  }
  // ddd.ddd or ddd000
  if (count <= exponent + 1) {
    std::memcpy(at, d, 17);
    at += count;
    std::memcpy(at, "000000", 6);
    return at + (exponent + 1 - count);
  }
  std::memcpy(at, d, 8);  // exponent ≤ 5
  at += exponent + 1;
  *at++ = '.';
  std::memcpy(at, d + exponent + 1, 16);
  return at + (count - exponent - 1);
}

// The shortest decimal d·10^k in the interval of reals that round to c·2^q (c ≥ 1, not a whole
// number below 2^53), and of those the nearest. Without branches on the digits: which case
// applies is as good as random from one number to the next.
struct Decimal {
  u64 digits;
  int k;
};
inline Decimal shortest(u64 c, int q, bool nearerBelow) {
  const u64 cb = c << 2;
  const u64 cbr = cb + 2;
  u64 cbl;
  int k;
  if (!nearerBelow) {
    cbl = cb - 2;
    k = floorLog10Pow2(q);
  } else {  // c = 2^52: the lower neighbour is nearer, at a quarter of the ulp below
    cbl = cb - 1;
    k = floorLog10ThreeQuartersPow2(q);
  }
  const int h = q + floorLog2Pow10(-k) + 3;  // 3 … 6
  const u64 ghi = kScales.hi[k - kMinK], glo = kScales.lo[k - kMinK];
  const u64 vb = roundOdd(ghi, glo, cb << h, k);
  const u64 vbl = roundOdd(ghi, glo, cbl << h, k);
  const u64 vbr = roundOdd(ghi, glo, cbr << h, k);
  const u64 out = c & 1;  // an odd c's interval leaves out its ends
  // The one multiple of 10 in the interval, if there is one: the shortest.
  const u64 s = vb >> 2;
  const u64 sp10 = s / 10 * 10;
  const u64 tp10 = sp10 + 10;
  const bool upin = vbl + out <= sp10 << 2;
  const bool wpin = (tp10 << 2) + out <= vbr;
  const bool ten = (s >= 10) & (upin != wpin);
  const u64 tens = upin ? sp10 : tp10;
  // Else s or s + 1, whichever lies in it, or the nearer (an even s on a tie).
  const u64 t = s + 1;
  const bool uin = vbl + out <= s << 2;
  const bool win = (t << 2) + out <= vbr;
  const std::int64_t cmp = static_cast<std::int64_t>(vb - (s + t) * 2);
  const bool nearerS = (cmp < 0) | ((cmp == 0) & ((s & 1) == 0));
  const u64 units = t - (uin & (!win | nearerS));
  return {units ^ ((units ^ tens) & (u64{0} - ten)), k};
}

}  // namespace

char* writeShortest(char* at, double value) {
  const u64 bits = std::bit_cast<u64>(value);
  *at = '-';
  at += bits >> 63;
  const u64 fraction = bits & ((u64{1} << 52) - 1);
  const int biased = static_cast<int>((bits >> 52) & 0x7FF);
  if (biased == 0 && fraction == 0) {
    *at = '0';
    return at + 1;
  }
  const u64 c = biased ? fraction | (u64{1} << 52) : fraction;
  const int q = biased ? biased - 1075 : -1074;
  u64 digits;  // value = digits·10^k
  int k;
  if (q <= 0 && q > -53 && (c & ((u64{1} << -q) - 1)) == 0) {
    // A whole number below 2^53: itself, as no decimal as short is within half an ulp of it.
    digits = c >> -q;
    k = 0;
  } else {
    const Decimal d = shortest(c, q, fraction == 0 && biased > 1);
    digits = d.digits;
    k = d.k;
  }

  if (digits < 1000000000000000) [[unlikely]]
    return writeFewDigits(at, digits, k);
  // 16 or 17 digits (every value not a whole number below 2^53, and not subnormal): as
  // characters in three words, the first digit in the lowest byte, and stored straight into the
  // output at the places the form wants (not copied out of a buffer just stored, whose loads
  // would wait for those stores).
  const u64 upper = digits / 100000000;
  const u64 first = digits / 10000000000000000;  // 0 … 9
  const u64 middle = eightDigits(upper - first * 100000000);
  const u64 last = eightDigits(digits - upper * 100000000);
  const int trailing = last     ? std::countl_zero(last) / 8
                       : middle ? 8 + std::countl_zero(middle) / 8
                                : 16;
  const bool seventeen = first != 0;
  const int count = 16 + seventeen - trailing;
  k += trailing;
  const int exponent = k + count - 1;  // of the first digit
  const u64 zeros = 0x3030303030303030;
  const u64 m = middle | zeros, l = last | zeros;
  const u64 w0 = seventeen ? ('0' + first) | (m << 8) : m;
  const u64 w1 = seventeen ? (m >> 56) | (l << 8) : l;
  const u64 w2 = seventeen ? l >> 56 : 0;
  const auto put = [](char* to, u64 word) { std::memcpy(to, &word, 8); };
  if (exponent < -4 || exponent >= 6) [[unlikely]] {  // scientific, as %g with its precision 6
    at[0] = static_cast<char>(w0);
    at[1] = '.';
    put(at + 2, (w0 >> 8) | (w1 << 56));
    put(at + 10, (w1 >> 8) | (w2 << 56));
    at += count + (count > 1);
    return writeExponent(at, exponent);
  }
  if (exponent < 0) {             // 0.000ddd
    put(at, 0x3030303030302E30);  // "0.000000"
    at += 1 - exponent;
    put(at, w0);
    put(at + 8, w1);
    at[16] = static_cast<char>(w2);
    return at + count;
  }
  // ddd.ddd: the point after the units (p ≤ 6 digits; more follow, as this is no whole number)
  const int p = exponent + 1;
  put(at, w0);
  at[p] = '.';
  put(at + p + 1, (w0 >> 8 * p) | (w1 << (64 - 8 * p)));
  put(at + p + 9, (w1 >> 8 * p) | (w2 << (64 - 8 * p)));
  return at + count + 1;
}

}  // namespace tasks
