// A 4x4 float matrix stored as four 16-byte registers, for the per-object matrix path
// (fx/model/draw_state.h): the value is written only when a bit differs from what the registers
// hold, in the order they hold it (the app's own order or its transpose). SSE2 where the
// target has it, plain C++ elsewhere. Internal to fxkit (namespace detail).
#pragma once
#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

namespace fxkit::detail::matrix_registers {

#if defined(__SSE2__)
// Stores four 16-byte registers one after another at `to` (16 words, any alignment).
inline void store(void* to, __m128 r0, __m128 r1, __m128 r2, __m128 r3) {
  float* f = static_cast<float*>(to);
  _mm_storeu_ps(f, r0);
  _mm_storeu_ps(f + 4, r1);
  _mm_storeu_ps(f + 8, r2);
  _mm_storeu_ps(f + 12, r3);
}
#endif

// Writes the 16 floats at `v` (transposed when `transpose`) over the 64 bytes at `to`
// (any alignment, not overlapping `v`); false, writing nothing, when every bit is equal.
inline bool store_if_changed(uint8_t* to, const float* v, bool transpose) {
#if defined(__SSE2__)
  __m128 r0 = _mm_loadu_ps(v), r1 = _mm_loadu_ps(v + 4), r2 = _mm_loadu_ps(v + 8), r3 = _mm_loadu_ps(v + 12);
  if (transpose) _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
  auto differs = [&](__m128 r, int at) {
    return _mm_xor_si128(_mm_castps_si128(r), _mm_loadu_si128(reinterpret_cast<const __m128i*>(to + at)));
  };
  const __m128i diff =
      _mm_or_si128(_mm_or_si128(differs(r0, 0), differs(r1, 16)), _mm_or_si128(differs(r2, 32), differs(r3, 48)));
  if (_mm_movemask_epi8(_mm_cmpeq_epi32(diff, _mm_setzero_si128())) == 0xFFFF) return false;
  store(to, r0, r1, r2, r3);
#else
  float ordered[16];
  for (uint32_t r = 0; r < 4; ++r)
    for (uint32_t c = 0; c < 4; ++c) ordered[r * 4 + c] = transpose ? v[c * 4 + r] : v[r * 4 + c];
  if (std::memcmp(to, ordered, sizeof ordered) == 0) return false;
  std::memcpy(to, ordered, sizeof ordered);
#endif
  return true;
}

}  // namespace fxkit::detail::matrix_registers
