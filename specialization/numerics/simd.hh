// The one portable SIMD layer of the pair loops: std::experimental::simd (Parallelism TS v2, in
// GCC's libstdc++ since GCC 11) with as many double lanes as the build's instruction set holds
// (2 for the x86-64 default, 4 with AVX2, 8 with AVX-512: FLECSPH_NATIVE_ARCH, docs/performance.md),
// and one lane (plain double) where the standard library lacks it or FLECSPH_SCALAR_PAIRS is set.
//
// The physics is written once, as templates over the number type T (double or pack), with the
// helpers below instead of branches: every lane computes the same IEEE operations in the same
// order as the scalar code, so a pair term is bitwise the same whatever the lane count.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

#if !defined(FLECSPH_SCALAR_PAIRS) && defined(__has_include)
#if __has_include(<experimental/simd>)
#include <experimental/simd>
#define FLECSPH_HAVE_STD_SIMD 1
#endif
#endif
#ifndef FLECSPH_HAVE_STD_SIMD
#define FLECSPH_HAVE_STD_SIMD 0
#endif

/// The pack helpers are always inlined: GCC 12 otherwise calls select, maximum and minimum out of
/// line from the large force loop, passing 512-bit packs through memory (8% of a Sedov step).
#if defined(__GNUC__)
#define FLECSPH_SIMD_INLINE [[gnu::always_inline]] inline
#else
#define FLECSPH_SIMD_INLINE inline
#endif

namespace flecsph::physics::simd {

#if FLECSPH_HAVE_STD_SIMD
namespace stdx = std::experimental;
/// The widest pack of doubles of the build's instruction set.
using pack = stdx::native_simd<double>;
/// The pack of at most N lanes (the native one where that is narrower).
template<std::size_t N>
using pack_at_most = stdx::simd<double, stdx::simd_abi::deduce_t<double, std::min(N, pack::size())>>;
#else
using pack = double;
template<std::size_t>
using pack_at_most = double;
#endif

/// Lanes of a number type: 1 for double.
template<class T>
inline constexpr std::size_t lanes = 1;
#if FLECSPH_HAVE_STD_SIMD
template<class A>
inline constexpr std::size_t lanes<stdx::simd<double, A>> = stdx::simd<double, A>::size();
#endif

// Scalar forms: what the helpers are for one lane.
inline double select(bool condition, double yes, double no) { return condition ? yes : no; }
inline double maximum(double a, double b) { return std::max(a, b); }
inline double minimum(double a, double b) { return std::min(a, b); }
inline double element(double x, std::size_t) { return x; }
inline bool any_lane(bool m) { return m; }
inline double largest_lane(double x) { return x; }

#if FLECSPH_HAVE_STD_SIMD
/// yes where `condition`, no elsewhere (lane by lane; both are computed).
template<class A>
FLECSPH_SIMD_INLINE stdx::simd<double, A> select(const typename stdx::simd<double, A>::mask_type& condition,
                                                 const stdx::simd<double, A>& yes, const stdx::simd<double, A>& no) {
  stdx::simd<double, A> result = no;
  stdx::where(condition, result) = yes;
  return result;
}
template<class A>
FLECSPH_SIMD_INLINE stdx::simd<double, A> maximum(const stdx::simd<double, A>& a, const stdx::simd<double, A>& b) {
  return stdx::max(a, b);
}
template<class A>
FLECSPH_SIMD_INLINE stdx::simd<double, A> minimum(const stdx::simd<double, A>& a, const stdx::simd<double, A>& b) {
  return stdx::min(a, b);
}
template<class A>
FLECSPH_SIMD_INLINE double element(const stdx::simd<double, A>& x, std::size_t i) {
  return x[i];
}
template<class A>
FLECSPH_SIMD_INLINE bool any_lane(const stdx::simd_mask<double, A>& m) {
  return stdx::any_of(m);
}
template<class A>
FLECSPH_SIMD_INLINE double largest_lane(const stdx::simd<double, A>& x) {
  return stdx::hmax(x);
}
#endif

/// The pack whose lane i is f(i) (a gather through any index map).
template<class T, class F>
FLECSPH_SIMD_INLINE T generate(F&& f) {
  if constexpr (std::is_same_v<T, double>)
    return f(std::size_t(0));
  else
    return T([&](auto i) { return f(std::size_t(i)); });
}

/// The pack of lanes() consecutive doubles at p.
template<class T>
FLECSPH_SIMD_INLINE T load(const double* p) {
#if FLECSPH_HAVE_STD_SIMD
  if constexpr (!std::is_same_v<T, double>)
    return T(p, stdx::element_aligned);
  else
#endif
    return *p;
}

/// A sum of many terms (a target's list entries, in list order) whose bits do not depend on the
/// lane count: term i goes to stripe i mod 4, each stripe adds its terms in order, and the total
/// is (s0 + s1) + (s2 + s3). Four independent chains of adds instead of one (a lane-by-lane sum
/// waits one add latency per term), and no lane is taken out of a pack: a pack of 4 lanes adds
/// to one accumulator, of 2 to two in turn, of 8 as two halves, one lane (double) to four in
/// turn. A masked term must be +0 or -0, which leaves a stripe unchanged (stripes start at +0).
template<class T>
class striped_sum {
 public:
  static constexpr std::size_t stripes = 4;

  /// The next lanes<T> terms.
  FLECSPH_SIMD_INLINE void add(const T& terms) {
    if constexpr (lanes<T> <= stripes) {
      // Added to the first part, then the parts rotate (register moves, not an indexed store):
      // after n packs, part k holds stripe (k + n) mod parts.
      part_[0] += terms;
      skip();
    } else {
#if FLECSPH_HAVE_STD_SIMD
      for (const auto& piece : stdx::split<accumulator>(terms)) part_[0] += piece;
#endif
    }
  }
  FLECSPH_SIMD_INLINE void subtract(const T& terms) { add(-terms); }
  /// The next lanes<T> terms, all zero (the same as adding them): only the stripes move on.
  FLECSPH_SIMD_INLINE void skip() {
    if constexpr (parts > 1) {
      for (std::size_t p = 1; p < parts; ++p) std::swap(part_[p - 1], part_[p]);
      next_ = next_ + 1 == parts ? 0 : next_ + 1;
    }
  }

  /// (s0 + s1) + (s2 + s3).
  FLECSPH_SIMD_INLINE double total() const {
    double s[stripes];
    for (std::size_t p = 0; p < parts; ++p)
      for (std::size_t i = 0; i < lanes<accumulator>; ++i)
        s[p * lanes<accumulator> + i] = element(part_[(p + parts - next_) % parts], i);
    return (s[0] + s[1]) + (s[2] + s[3]);
  }

 private:
  static_assert(stripes % lanes<T> == 0 || lanes<T> % stripes == 0, "packs of 1, 2, 4, 8, ... lanes");
  /// T itself up to 4 lanes, else a pack of exactly 4.
  using accumulator = std::conditional_t<(lanes<T> <= stripes), T, pack_at_most<stripes>>;
  static constexpr std::size_t parts = stripes / lanes<accumulator>;
  accumulator part_[parts] = {};
  std::size_t next_ = 0;
};

/// Stores the lanes() lanes of x at p.
template<class T>
FLECSPH_SIMD_INLINE void store(const T& x, double* p) {
#if FLECSPH_HAVE_STD_SIMD
  if constexpr (!std::is_same_v<T, double>)
    x.copy_to(p, stdx::element_aligned);
  else
#endif
    *p = x;
}

/// |x| and sqrt(x), lane by lane (found for packs by argument-dependent lookup).
template<class T>
FLECSPH_SIMD_INLINE T absolute(const T& x) {
  using std::fabs;
  return fabs(x);
}
template<class T>
FLECSPH_SIMD_INLINE T square_root(const T& x) {
  using std::sqrt;
  return sqrt(x);
}

}  // namespace flecsph::physics::simd
