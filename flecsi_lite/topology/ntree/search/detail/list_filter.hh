// The last step of the group walk (seed Algorithm 2, APPLY_SUB_TREE): the entries of a group's
// interaction list within reach of one target, selected without a branch per entry (whether an
// entry is a neighbour is data the branch predictor cannot learn): eight entries at a time with
// AVX-512 (a native build), compressed in a register; four with AVX2 (a native build on a CPU
// without AVX-512, e.g. AMD Zen 2/3); else two at a time with SSE2 where the compiler targets it.
#pragma once

#include "flecsi_lite/topology/ntree/space.hh"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#if defined(__AVX512F__) && defined(__AVX512VL__)
#include <immintrin.h>
#define FLECSI_LITE_LIST_FILTER_AVX512 1
#elif defined(__AVX2__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace flecsi_lite::topology::ntree {

/// Writes to `hits` the indices j < length, ascending, of the entries with
///   |x - source_j|^2 < max(reach_squared, source_reach_squared[j])
/// (source_reach_squared null: < reach_squared), and returns their number. The squared distance
/// is summed axis by axis in the order of distance_squared, so the selection is bit for bit that
/// of the exact pair criterion. `source` holds the entries' coordinates axis by axis.
template<int D>
std::size_t within_reach(const point<D>& x, const std::array<const double*, D>& source, std::size_t length,
                         double reach_squared, const double* source_reach_squared, std::uint32_t* hits) {
  std::size_t count = 0, j = 0;
#if defined(FLECSI_LITE_LIST_FILTER_AVX512)
  // The same operations lane by lane as the scalar loop below. The 8 compressed indices are
  // stored whole: count <= j, so they stay within the first j + 8 <= length entries of hits.
  const __m512d own_reach = _mm512_set1_pd(reach_squared);
  __m256i index = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i step = _mm256_set1_epi32(8);
  for (; j + 8 <= length; j += 8) {
    __m512d r2 = _mm512_setzero_pd();
    for (int k = 0; k < D; ++k) {
      const __m512d d = _mm512_sub_pd(_mm512_set1_pd(x[k]), _mm512_loadu_pd(source[k] + j));
      r2 = _mm512_add_pd(r2, _mm512_mul_pd(d, d));
    }
    const __m512d limit =
      source_reach_squared ? _mm512_max_pd(own_reach, _mm512_loadu_pd(source_reach_squared + j)) : own_reach;
    const __mmask8 inside = _mm512_cmp_pd_mask(r2, limit, _CMP_LT_OQ);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(hits + count), _mm256_maskz_compress_epi32(inside, index));
    count += static_cast<std::size_t>(__builtin_popcount(inside));
    index = _mm256_add_epi32(index, step);
  }
#elif defined(__AVX2__)
  // Four entries at a time (AVX2 has no compress): each index is written, and counted when in.
  const __m256d own_reach = _mm256_set1_pd(reach_squared);
  for (; j + 4 <= length; j += 4) {
    __m256d r2 = _mm256_setzero_pd();
    for (int k = 0; k < D; ++k) {
      const __m256d d = _mm256_sub_pd(_mm256_set1_pd(x[k]), _mm256_loadu_pd(source[k] + j));
      r2 = _mm256_add_pd(r2, _mm256_mul_pd(d, d));
    }
    const __m256d limit =
      source_reach_squared ? _mm256_max_pd(own_reach, _mm256_loadu_pd(source_reach_squared + j)) : own_reach;
    const int inside = _mm256_movemask_pd(_mm256_cmp_pd(r2, limit, _CMP_LT_OQ));
    for (int i = 0; i < 4; ++i) {
      hits[count] = static_cast<std::uint32_t>(j + i);
      count += (inside >> i) & 1;
    }
  }
#elif defined(__SSE2__)
  const __m128d own_reach = _mm_set1_pd(reach_squared);
  for (; j + 2 <= length; j += 2) {
    __m128d r2 = _mm_setzero_pd();
    for (int k = 0; k < D; ++k) {
      const __m128d d = _mm_sub_pd(_mm_set1_pd(x[k]), _mm_loadu_pd(source[k] + j));
      r2 = _mm_add_pd(r2, _mm_mul_pd(d, d));
    }
    const __m128d limit =
      source_reach_squared ? _mm_max_pd(own_reach, _mm_loadu_pd(source_reach_squared + j)) : own_reach;
    const int inside = _mm_movemask_pd(_mm_cmplt_pd(r2, limit));
    hits[count] = static_cast<std::uint32_t>(j);
    count += inside & 1;
    hits[count] = static_cast<std::uint32_t>(j + 1);
    count += inside >> 1;
  }
#endif
  for (; j < length; ++j) {
    double r2 = 0;
    for (int k = 0; k < D; ++k) {
      const double d = x[k] - source[k][j];
      r2 += d * d;
    }
    const double limit = source_reach_squared ? std::max(reach_squared, source_reach_squared[j]) : reach_squared;
    hits[count] = static_cast<std::uint32_t>(j);
    count += r2 < limit;
  }
  return count;
}

}  // namespace flecsi_lite::topology::ntree
