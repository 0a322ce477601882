// Tests of the ntree keys: Morton interleaving against a bit-by-bit reference, Hilbert curve
// adjacency (exhaustive at small levels) and hierarchy, encode/decode round trips, and the
// parent/child/level arithmetic against the geometry of the cells.
#include "flecsi_lite/topology/ntree/sfc/keys.hh"

#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <vector>

namespace nt = flecsi_lite::topology::ntree;

namespace {

template<int D>
using cell_coordinates = std::array<std::uint64_t, D>;

// Interleaving written bit by bit: axis 0 is the most significant bit of each digit.
template<int D>
std::uint64_t reference_morton(const cell_coordinates<D>& c, int bits) {
  std::uint64_t index = 0;
  for (int j = bits - 1; j >= 0; --j)
    for (int k = 0; k < D; ++k) index = index << 1 | (c[k] >> j & 1);
  return index;
}

template<int D>
cell_coordinates<D> random_cell(std::mt19937_64& random, int bits) {
  cell_coordinates<D> c;
  for (int k = 0; k < D; ++k) c[k] = bits == 64 ? random() : random() & ((std::uint64_t{1} << bits) - 1);
  return c;
}

template<int D>
bool face_neighbours(const cell_coordinates<D>& a, const cell_coordinates<D>& b) {
  std::uint64_t manhattan = 0;
  for (int k = 0; k < D; ++k) manhattan += a[k] > b[k] ? a[k] - b[k] : b[k] - a[k];
  return manhattan == 1;
}

template<int D>
void check_morton() {
  std::mt19937_64 random(7);
  for (int trial = 0; trial < 2000; ++trial) {
    const auto c = random_cell<D>(random, nt::max_level<D>);
    const std::uint64_t index = nt::morton_index<D>(c);
    REQUIRE(index == reference_morton<D>(c, nt::max_level<D>));
    REQUIRE(nt::morton_cell<D>(index) == c);
  }
}

// Every cell of the curve of order `bits` is visited once, consecutive cells share a face,
// and hilbert_index inverts hilbert_cell.
template<int D>
void check_hilbert_exhaustive(int bits) {
  const std::uint64_t count = std::uint64_t{1} << (D * bits);
  std::set<cell_coordinates<D>> seen;
  cell_coordinates<D> previous{};
  for (std::uint64_t i = 0; i < count; ++i) {
    const auto c = nt::hilbert_cell<D>(i, bits);
    for (int k = 0; k < D; ++k) REQUIRE(c[k] < (std::uint64_t{1} << bits));
    REQUIRE(nt::hilbert_index<D>(c, bits) == i);
    if (i > 0) REQUIRE(face_neighbours<D>(previous, c));
    seen.insert(c);
    previous = c;
  }
  REQUIRE(seen.size() == count);
}

// At full depth: random consecutive indices are face neighbours, and the Hilbert index of a
// cell's ancestor at any level is the prefix of the cell's index (keys are hierarchical).
template<int D>
void check_hilbert_deep() {
  constexpr int bits = nt::max_level<D>;
  std::mt19937_64 random(11);
  for (int trial = 0; trial < 500; ++trial) {
    const std::uint64_t i = random() & ((std::uint64_t{1} << (D * bits)) - 2);
    REQUIRE(face_neighbours<D>(nt::hilbert_cell<D>(i, bits), nt::hilbert_cell<D>(i + 1, bits)));
    const auto c = random_cell<D>(random, bits);
    const std::uint64_t index = nt::hilbert_index<D>(c, bits);
    for (int l = 0; l <= bits; ++l) {
      cell_coordinates<D> coarse;
      for (int k = 0; k < D; ++k) coarse[k] = c[k] >> (bits - l);
      REQUIRE(nt::hilbert_index<D>(coarse, l) == index >> (D * (bits - l)));
    }
  }
}

template<int D>
void check_key_arithmetic(nt::curve order) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(0, 1);
  nt::box<D> domain;
  for (int k = 0; k < D; ++k) {
    domain.lo[k] = -1.5 + k;
    domain.hi[k] = 2.0 + 2 * k;
  }
  for (int trial = 0; trial < 500; ++trial) {
    nt::point<D> x;
    for (int k = 0; k < D; ++k) x[k] = domain.lo[k] + unit(random) * (domain.hi[k] - domain.lo[k]);
    const nt::key_type key = nt::key_of<D>(order, domain, x);
    REQUIRE(nt::is_valid<D>(key));
    REQUIRE(nt::level<D>(key) == nt::max_level<D>);

    // Round trip: decode then encode gives the key back, at every level of its ancestry.
    for (int l = 0; l <= nt::max_level<D>; ++l) {
      const nt::key_type ancestor = nt::ancestor<D>(key, l);
      REQUIRE(nt::level<D>(ancestor) == l);
      const nt::cell<D> c = nt::decode<D>(order, ancestor);
      REQUIRE(c.level == l);
      REQUIRE(nt::encode<D>(order, c.coordinates, l) == ancestor);
      if (l > 0) {
        REQUIRE(nt::parent<D>(ancestor) == nt::ancestor<D>(key, l - 1));
        REQUIRE(nt::child<D>(nt::parent<D>(ancestor), nt::last_digit<D>(ancestor)) == ancestor);
        // The parent cell is the child cell's coordinates halved.
        const nt::cell<D> up = nt::decode<D>(order, nt::parent<D>(ancestor));
        for (int k = 0; k < D; ++k) REQUIRE(up.coordinates[k] == c.coordinates[k] / 2);
      }
    }
    // The cells along the ancestry contain x (up to the rounding of the box edges).
    for (int l = 0; l <= std::min(nt::max_level<D>, 20); ++l) {
      const nt::box<D> cell = nt::cell_box<D>(order, nt::ancestor<D>(key, l), domain);
      for (int k = 0; k < D; ++k) {
        const double slack = 1e-12 * (domain.hi[k] - domain.lo[k]);
        REQUIRE(x[k] >= cell.lo[k] - slack);
        REQUIRE(x[k] <= cell.hi[k] + slack);
      }
    }
  }
}

// The children of a cell are the 2^D distinct half-size cells inside it.
template<int D>
void check_children_tile_parent(nt::curve order) {
  std::mt19937_64 random(5);
  for (int trial = 0; trial < 200; ++trial) {
    const int l = static_cast<int>(random() % nt::max_level<D>);
    const auto c = random_cell<D>(random, l);
    const nt::key_type key = nt::encode<D>(order, c, l);
    std::set<cell_coordinates<D>> children;
    for (unsigned digit = 0; digit < nt::children_per_cell<D>; ++digit) {
      const nt::cell<D> sub = nt::decode<D>(order, nt::child<D>(key, digit));
      REQUIRE(sub.level == l + 1);
      for (int k = 0; k < D; ++k) REQUIRE(sub.coordinates[k] / 2 == c[k]);
      children.insert(sub.coordinates);
    }
    REQUIRE(children.size() == nt::children_per_cell<D>);
  }
}

}  // namespace

TEST_CASE("depth limits and the root key", "[ntree][keys]") {
  STATIC_REQUIRE(nt::max_level<1> == 63);
  STATIC_REQUIRE(nt::max_level<2> == 31);
  STATIC_REQUIRE(nt::max_level<3> == 21);
  STATIC_REQUIRE(nt::level<3>(nt::root_key) == 0);
  STATIC_REQUIRE(nt::level<3>(nt::child<3>(nt::root_key, 5)) == 1);
  STATIC_REQUIRE(nt::child<2>(nt::root_key, 3) == 0b111);
  REQUIRE_FALSE(nt::is_valid<3>(0b11));  // one bit after the root is not a 3D digit
  REQUIRE(nt::is_valid<1>(0b11));
  // The deepest keys use all 64 bits in 1D and 3D, 63 in 2D.
  REQUIRE(nt::encode<3>(nt::curve::morton, {0, 0, 0}) == std::uint64_t{1} << 63);
  REQUIRE(nt::encode<2>(nt::curve::morton, {0, 0}) == std::uint64_t{1} << 62);
  REQUIRE(nt::encode<1>(nt::curve::morton, {0}) == std::uint64_t{1} << 63);
}

TEST_CASE("Morton interleaving matches the bit-by-bit definition", "[ntree][keys]") {
  check_morton<1>();
  check_morton<2>();
  check_morton<3>();
}

TEST_CASE("Hilbert curve: bijective and face-adjacent at small levels", "[ntree][keys]") {
  for (int bits = 1; bits <= 6; ++bits) check_hilbert_exhaustive<2>(bits);
  for (int bits = 1; bits <= 4; ++bits) check_hilbert_exhaustive<3>(bits);
}

TEST_CASE("Hilbert curve: adjacency and hierarchy at full depth", "[ntree][keys]") {
  check_hilbert_deep<2>();
  check_hilbert_deep<3>();
  // In 1D the Hilbert order is the Morton order.
  for (std::uint64_t i : {0ull, 1ull, 12345ull, (1ull << 62) + 7})
    REQUIRE(nt::hilbert_index<1>({i}, 63) == nt::morton_index<1>({i}));
}

TEST_CASE("Morton curve is not face-adjacent (sanity of the adjacency test)", "[ntree][keys]") {
  // Cells 1 -> 2 of the 2D Morton curve at level 1 are diagonal, so the Hilbert test above
  // would catch a curve that is only Morton.
  REQUIRE_FALSE(face_neighbours<2>(nt::morton_cell<2>(1), nt::morton_cell<2>(2)));
}

TEST_CASE("keys: encode/decode, parent/child and cell geometry", "[ntree][keys]") {
  for (const nt::curve order : {nt::curve::morton, nt::curve::hilbert}) {
    check_key_arithmetic<1>(order);
    check_key_arithmetic<2>(order);
    check_key_arithmetic<3>(order);
    check_children_tile_parent<1>(order);
    check_children_tile_parent<2>(order);
    check_children_tile_parent<3>(order);
  }
}

TEST_CASE("keys of positions outside the box are clamped to boundary cells", "[ntree][keys]") {
  nt::box<2> domain{{0, 0}, {1, 1}};
  const auto last = (std::uint64_t{1} << nt::max_level<2>)-1;
  const auto c = nt::deepest_cell<2>(domain, {-0.5, 1.5});
  REQUIRE(c[0] == 0);
  REQUIRE(c[1] == last);
  REQUIRE(nt::deepest_cell<2>(domain, {1.0, 0.0})[0] == last);
}

// compute_keys computes Hilbert keys eight at a time (vector lanes); they must be key_of's bit
// for bit, also for a last block of fewer particles and for positions outside the box or NaN.
template<int D>
void check_parallel_keys(nt::curve order) {
  std::mt19937_64 random(9);
  std::uniform_real_distribution<double> beyond(-0.2, 1.2);
  std::vector<nt::point<D>> x(1003);
  for (auto& p : x)
    for (int k = 0; k < D; ++k) p[k] = beyond(random);
  x[5][0] = std::numeric_limits<double>::quiet_NaN();
  x[1002][D - 1] = 1.0;
  nt::box<D> domain;
  for (int k = 0; k < D; ++k) {
    domain.lo[k] = 0;
    domain.hi[k] = 1;
  }
  for (const std::size_t n : {std::size_t(1003), std::size_t(8), std::size_t(3), std::size_t(0)}) {
    std::vector<nt::key_type> keys(n);
    nt::compute_keys<D>(order, domain, x.data(), n, keys.data());
    for (std::size_t i = 0; i < n; ++i) REQUIRE(keys[i] == nt::key_of<D>(order, domain, x[i]));
  }
}

TEST_CASE("keys computed in parallel equal the scalar function", "[ntree][keys]") {
  for (const nt::curve order : {nt::curve::hilbert, nt::curve::morton}) {
    check_parallel_keys<1>(order);
    check_parallel_keys<2>(order);
    check_parallel_keys<3>(order);
  }
}
