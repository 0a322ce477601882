// Entries of neighbour lists that pack the neighbour b with its image shift code in 4 bytes
// (shift_storage::packed), and rows of them coded as runs (shift_storage::runs): a row of
// packed entries (b, shift code) in ascending b is mostly runs of consecutive neighbours b,
// b + 1, ... under one shift (the particles of a leaf, in key order). A run of up to 8 entries
// takes 3 bytes, its (length, shift code) in one and its jump from the end of the previous run in
// two (four more for the rare longer jump): 1.2 bytes an entry on Sedov's lattice instead of 4
// (issue 36 item 4; run-length and delta coding as in compressed neighbour lists, e.g. Thaler &
// Keller 2026). Fixed widths, not variable-length integers, so that decoding a run neither waits
// for the previous run's length in bytes nor branches on it (decoding takes 2% of a step's
// samples, coding 6%; docs/performance.md, "Neighbour lists as runs"). Decoding gives back the
// packed entries bit for bit and in their order, whatever that order is (a jump backwards is
// coded too), so sums over a decoded row are the plain row's.
#pragma once

#include "flecsi_lite/topology/ntree/periodic.hh"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace flecsi_lite::topology::ntree {

inline constexpr int packed_index_bits = 27;
inline constexpr std::uint32_t packed_index_mask = (std::uint32_t{1} << packed_index_bits) - 1;
static_assert(shift_code_count<3> <= (1 << (32 - packed_index_bits)), "shift codes must fit the top bits");

/// A packed entry: neighbour b (< 2^27) and its shift code.
inline std::uint32_t packed_entry(std::uint32_t b, shift_code code) {
  return b | static_cast<std::uint32_t>(code) << packed_index_bits;
}
inline std::uint32_t packed_neighbour(std::uint32_t entry) { return entry & packed_index_mask; }
inline shift_code packed_shift(std::uint32_t entry) { return static_cast<shift_code>(entry >> packed_index_bits); }

}  // namespace flecsi_lite::topology::ntree

namespace flecsi_lite::topology::ntree::runs {

/// A row is, in bytes: its entry count (7 bits a byte, LEB128), then per run one byte
/// ((length - 1) << 5 | shift code) and two for the jump (zigzag coded), or 0xffff and the jump
/// in the four bytes after them.
inline constexpr std::size_t longest_run = 8;
/// The most bytes one row of `count` entries takes (every entry a run with a long jump).
inline constexpr std::size_t max_row_bytes(std::size_t count) { return 5 + 7 * count; }
/// Decoding writes whole runs of longest_run entries: room for this many entries past a row.
inline constexpr std::size_t decode_padding = longest_run;

namespace detail {
inline constexpr int shift_bits = 32 - packed_index_bits;
inline constexpr std::uint32_t long_jump = 0xffff;

inline std::size_t put_count(std::uint32_t v, std::uint8_t* out) {
  std::size_t n = 0;
  for (; v >= 0x80; v >>= 7) out[n++] = static_cast<std::uint8_t>(v | 0x80);
  out[n] = static_cast<std::uint8_t>(v);
  return n + 1;
}
inline std::size_t count_bytes(std::uint32_t v) {
  std::size_t n = 1;
  for (; v >= 0x80; v >>= 7) ++n;
  return n;
}
inline std::uint32_t get_count(const std::uint8_t*& in) {
  std::uint32_t v = *in & 0x7f;
  for (int bits = 7; *in++ & 0x80; bits += 7) v |= static_cast<std::uint32_t>(*in & 0x7f) << bits;
  return v;
}

// Jumps of either sign as small unsigned numbers: 0, -1, 1, -2, ... -> 0, 1, 2, 3, ...
inline std::uint32_t zigzag(std::int64_t jump) {
  return static_cast<std::uint32_t>(jump < 0 ? ((-jump) << 1) - 1 : jump << 1);
}
inline std::int64_t unzigzag(std::uint32_t z) {
  return (z & 1) ? -static_cast<std::int64_t>((z >> 1) + 1) : static_cast<std::int64_t>(z >> 1);
}

// Codes the row (Write) or counts its bytes. The run starts are found as bits, 64 entries a word,
// without a branch per entry (a branch on each run's end would be mispredicted about once a run);
// plain locals, no callbacks: the byte stores could otherwise alias the loop's state.
template<bool Write>
std::size_t code_row(const std::uint32_t* entries, std::size_t count, std::uint8_t* out) {
  std::size_t bytes =
    Write ? put_count(static_cast<std::uint32_t>(count), out) : count_bytes(static_cast<std::uint32_t>(count));
  std::int64_t expected = 0;  // the neighbour after the previous run
  std::size_t first = 0;      // the current run's first entry
  for (std::size_t base = 0; base <= count; base += 64) {
    const std::size_t end = std::min(count, base + 64);
    std::uint64_t starts = 0;
    for (std::size_t i = std::max<std::size_t>(base, 1); i < end; ++i)
      starts |= std::uint64_t{entries[i] != entries[i - 1] + 1} << (i - base);
    if (count < base + 64) starts |= std::uint64_t{1} << (count - base);  // the row's end closes a run
    for (; starts; starts &= starts - 1) {
      const std::size_t next = base + static_cast<std::size_t>(__builtin_ctzll(starts));
      for (std::size_t i = first; i < next; i += longest_run) {  // runs longer than longest_run are cut
        const std::size_t length = std::min(longest_run, next - i);
        const std::int64_t b = packed_neighbour(entries[i]);
        const std::uint32_t jump = zigzag(b - expected);
        expected = b + static_cast<std::int64_t>(length);
        if constexpr (Write) {
          out[bytes] = static_cast<std::uint8_t>((length - 1) << shift_bits | packed_shift(entries[i]));
          const std::uint16_t short_jump = static_cast<std::uint16_t>(jump < long_jump ? jump : long_jump);
          std::memcpy(out + bytes + 1, &short_jump, 2);
          if (jump >= long_jump) std::memcpy(out + bytes + 3, &jump, 4);
        }
        bytes += jump < long_jump ? 3 : 7;
      }
      first = next;
    }
  }
  return bytes;
}
}  // namespace detail

/// The bytes the `count` packed entries at `entries` take as one row.
inline std::size_t row_bytes(const std::uint32_t* entries, std::size_t count) {
  return detail::code_row<false>(entries, count, nullptr);
}

/// Codes the `count` packed entries at `entries` as one row at `out`; returns its bytes,
/// row_bytes(entries, count), at most max_row_bytes(count).
inline std::size_t encode_row(const std::uint32_t* entries, std::size_t count, std::uint8_t* out) {
  return detail::code_row<true>(entries, count, out);
}

/// The entry count of the row coded at `in`.
inline std::size_t row_count(const std::uint8_t* in) { return detail::get_count(in); }

/// Decodes the row coded at `in` into out[0 .. count) and returns count (row_count(in)); writes
/// up to decode_padding entries past them.
inline std::size_t decode_row(const std::uint8_t* in, std::uint32_t* out) {
  using namespace detail;
  const std::size_t count = get_count(in);
  std::int64_t expected = 0;
  for (std::size_t n = 0; n < count;) {
    const std::uint32_t length_and_code = in[0];
    std::uint16_t short_jump;
    std::memcpy(&short_jump, in + 1, 2);
    in += 3;
    std::uint32_t jump = short_jump;
    if (jump == long_jump) {  // rare: predicted
      std::memcpy(&jump, in, 4);
      in += 4;
    }
    const std::int64_t first = expected + unzigzag(jump);
    const std::uint32_t start = static_cast<std::uint32_t>(first) | (length_and_code & ((1u << shift_bits) - 1))
                                                                      << packed_index_bits;
    for (std::size_t i = 0; i < longest_run; ++i) out[n + i] = start + static_cast<std::uint32_t>(i);  // one store
    const std::size_t length = (length_and_code >> shift_bits) + 1;
    n += length;
    expected = first + static_cast<std::int64_t>(length);
  }
  return count;
}

}  // namespace flecsi_lite::topology::ntree::runs
