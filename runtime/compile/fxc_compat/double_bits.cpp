#include "double_bits.h"

namespace fx::detail {

bool calls_asuint_of_a_double(const std::vector<Token>& toks) {
  for (size_t i = 0; i + 1 < toks.size(); ++i) {
    if (!toks[i].is_identifier("asuint") || !toks[i + 1].is(TokenKind::l_paren)) continue;
    if (i > 0 && toks[i - 1].is(TokenKind::period)) continue;
    int depth = 0, commas = 0;
    for (size_t j = i + 1; j < toks.size(); ++j) {
      const TokenKind k = toks[j].kind;
      if (k == TokenKind::l_paren || k == TokenKind::l_square || k == TokenKind::l_brace) ++depth;
      else if (k == TokenKind::r_paren || k == TokenKind::r_square || k == TokenKind::r_brace) {
        if (--depth == 0) break;
      } else if (k == TokenKind::comma && depth == 1) ++commas;
    }
    if (commas == 2) return true;
  }
  return false;
}

std::string_view asuint_of_a_double() {
  // The biased exponent is found bit by bit, comparing with powers of two that asdouble
  // builds exactly; the fraction is then scaled to an integer below 2^52 and split at 2^32 (times 2^-32).
  // Every step is exact in double precision (multiplications by powers of two, and a
  // difference of two integers below 2^53; the literals are powers of two). glslang evaluates
  // floor, isinf and isnan on the double converted to float, so a truncating conversion and
  // the fraction's range stand in for them.
  return R"(// fxkit: fxc's asuint(double, out uint, out uint)
void asuint(double d, out uint low, out uint high)
{
    double a = abs(d);
    uint sign = asuint((float)d) & 0x80000000u;
    uint biased = 0u;
    [unroll] for (int k = 10; k >= 0; --k)
    {
        uint trial = biased | (1u << k);
        if (trial < 2047u && asdouble(0u, trial << 20) <= a) biased = trial;
    }
    // The fraction as an integer: a * 2^(52 - e) - 2^52 for exponent e, the scale split in two
    // powers of two that are normal doubles (a division by 2^e is not exact on every device).
    double fraction;
    if (biased == 0u) fraction = a * asdouble(0u, 0x7FD00000u) * 4503599627370496.0;
    else
    {
        int e = (int)biased - 1023, half = e / 2;
        double first = asdouble(0u, (uint)(1023 - half) << 20);
        double second = asdouble(0u, (uint)(1023 + 52 - e + half) << 20);
        fraction = a * first * second - 4503599627370496.0;
    }
    if (!(fraction < 4503599627370496.0))
    {
        // Only an infinity (a fraction of infinity) or a NaN (no order) leaves [0, 2^52).
        fraction = fraction > 0.0 ? 0.0 : 2251799813685248.0;
        biased = 2047u;
    }
    uint upper = (uint)(fraction * asdouble(0u, 0x3DF00000u));
    low = (uint)(fraction - (double)upper * 4294967296.0);
    high = sign | (biased << 20) | upper;
}
)";
}

}  // namespace fx::detail
