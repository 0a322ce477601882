// Compares the last steps of two H5Part files bit by bit: the same datasets, the same element
// types and lengths, identical values, and the same time. Exit status 0 when identical, 1 with the
// first differences listed otherwise (the rank-count invariance check of the validation tests).
//
//   compare_h5part a.h5part b.h5part
#include "flecsi_lite/io/h5part_reader.hh"
#include "flecsi_lite/runtime.hh"

#include <cstdint>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace {
using namespace flecsi_lite;

/// Number of elements whose bytes differ; prints the first few.
template<class T>
std::size_t differences(const io::h5part_reader& a, const io::h5part_reader& b, const std::string& name) {
  const auto x = a.read<T>(a.last_step(), name, {0, a.particle_count(a.last_step())});
  const auto y = b.read<T>(b.last_step(), name, {0, b.particle_count(b.last_step())});
  std::size_t count = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (std::memcmp(&x[i], &y[i], sizeof(T)) != 0 && count++ < 3)
      std::cout << "  " << name << "[" << i << "]: " << x[i] << " != " << y[i] << "\n";
  return count;
}
}  // namespace

int main(int argc, char** argv) {
  runtime::options options("Compares the last steps of two H5Part files bit by bit.");
  options.positional("first", "H5Part file").positional("second", "H5Part file");
  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  try {
    const io::h5part_reader a(rt.opts().get("first")), b(rt.opts().get("second"));
    const auto step_a = a.last_step(), step_b = b.last_step();
    bool same = true;
    const auto time_a = a.step_information(step_a).time, time_b = b.step_information(step_b).time;
    if (std::memcmp(&time_a, &time_b, sizeof(double)) != 0) {
      std::cout << "times differ: " << time_a << " != " << time_b << "\n";
      same = false;
    }
    if (a.datasets(step_a) != b.datasets(step_b) || a.particle_count(step_a) != b.particle_count(step_b)) {
      std::cout << "the last steps hold different datasets or particle counts\n";
      return 1;
    }
    std::size_t compared = 0;
    for (const auto& name : a.datasets(step_a)) {
      const auto type = a.dataset_type(step_a, name);
      if (type != b.dataset_type(step_b, name)) {
        std::cout << name << ": element types differ\n";
        same = false;
        continue;
      }
      std::size_t n = 0;
      switch (type) {
        case io::element_type::float64:
          n = differences<double>(a, b, name);
          break;
        case io::element_type::float32:
          n = differences<float>(a, b, name);
          break;
        case io::element_type::int64:
          n = differences<std::int64_t>(a, b, name);
          break;
        case io::element_type::uint64:
          n = differences<std::uint64_t>(a, b, name);
          break;
        case io::element_type::int32:
          n = differences<std::int32_t>(a, b, name);
          break;
        case io::element_type::unsupported:
          std::cout << name << ": unsupported type\n";
          same = false;
          continue;
      }
      if (n) {
        std::cout << name << ": " << n << " of " << a.particle_count(step_a) << " values differ\n";
        same = false;
      }
      ++compared;
    }
    std::cout << (same ? "identical" : "DIFFERENT") << ": " << compared << " datasets of " << a.particle_count(step_a)
              << " particles at t = " << time_a << "\n";
    return same ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "compare_h5part: " << e.what() << "\n";
    return 2;
  }
}
