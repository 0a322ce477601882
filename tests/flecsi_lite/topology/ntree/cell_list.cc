// Tests of the uniform cell list baseline: the same neighbour sets as the brute-force search.
#include "flecsi_lite/topology/ntree/reference/cell_list.hh"
#include "tests/flecsi_lite/topology/ntree/search_checks.hh"

#include <catch2/catch.hpp>

#include <algorithm>

namespace nt = flecsi_lite::topology::ntree;
using namespace ntree_test;

namespace {

template<int D>
void check_cell_list() {
  int set_number = 0;
  for (auto& set : search_sets<D>(nt::curve::hilbert)) {
    ++set_number;
    for (const nt::interaction kind : {nt::interaction::gather, nt::interaction::symmetric}) {
      const nt::search_options options{kind, 2.0, nullptr};
      const auto expected = brute_force(set, nt::domain<D>::open(), options);
      const double h_max = *std::max_element(set.h.begin(), set.h.end());
      nt::cell_list<D> cells;
      cells.build(set.x.data(), set.h.data(), set.size(), options.support * h_max);
      for (std::size_t a = 0; a < set.size(); ++a) {
        std::vector<std::uint32_t> found;
        cells.for_each_neighbour(a, options,
                                 [&](std::size_t, std::size_t b) { found.push_back(static_cast<std::uint32_t>(b)); });
        std::sort(found.begin(), found.end());
        INFO("dimension " << D << ", set " << set_number << ", target " << a);
        const std::vector<std::uint32_t> want(expected.neighbours.begin() + expected.offsets[a],
                                              expected.neighbours.begin() + expected.offsets[a + 1]);
        REQUIRE(found == want);
      }
    }
  }
}

}  // namespace

TEST_CASE("cell list finds the brute-force neighbours", "[ntree][cell_list]") {
  check_cell_list<1>();
  check_cell_list<2>();
  check_cell_list<3>();
}
