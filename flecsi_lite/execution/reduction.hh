// Reduction operations for reduce<task, op>(...). Every rank's value is gathered and combined
// in rank order, so the result is bitwise identical on every rank and from run to run.
// exact_sum (values of util::exact_sum or double) is moreover the same on any rank count.
#pragma once

#include "flecsi_lite/util/exact_sum.hh"

#include <algorithm>

namespace flecsi_lite::reduction {

struct sum {
  template<class T>
  static T combine(const T& a, const T& b) {
    return a + b;
  }
};
struct min {
  template<class T>
  static T combine(const T& a, const T& b) {
    return std::min(a, b);
  }
};
struct max {
  template<class T>
  static T combine(const T& a, const T& b) {
    return std::max(a, b);
  }
};
/// Exact sum: a task returns a double (its own exact partial sum, e.g. from util::exact_sum)
/// or a util::exact_sum accumulator; the result is the double nearest the exact total.
struct exact_sum {
  static util::exact_sum combine(util::exact_sum a, const util::exact_sum& b) { return a += b; }
};

namespace detail {
/// How op Op carries values of type T between ranks, and what the future finally holds.
template<class Op, class T>
struct carrier {
  using transported = T;
  using result = T;
  static transported pack(const T& v) { return v; }
  static result unpack(const transported& v) { return v; }
};
template<class T>
struct carrier<exact_sum, T> {
  using transported = util::exact_sum;
  using result = double;
  static transported pack(const T& v) {
    if constexpr (std::is_same_v<T, util::exact_sum>)
      return v;
    else
      return util::exact_sum(static_cast<double>(v));
  }
  static result unpack(const transported& v) { return v.value(); }
};
}  // namespace detail

}  // namespace flecsi_lite::reduction
