// Parallel assembly of neighbour lists (neighbour_lists.hh) by the searches: per-thread chunks of
// consecutive rows written in place into the lists' own arrays, then moved down after the scan of
// the row counts.
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/runtime/job_memory.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/search/neighbour_lists.hh"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// Parallel assembly of neighbour_lists: the targets are cut into chunks of consecutive rows,
/// each worked on by one thread that appends its entries, row after row, and writes the counts of
/// its rows; then the offsets are scanned and each chunk's entries moved to their place.
///
/// Each chunk writes into its own REGION of the lists' arrays, as long as the chunk's entries of
/// the recent searches and a little more; the regions follow each other in chunk order, so after
/// the scan the entries only move down, chunk after chunk, in place. The lists are thus held once,
/// and a steady state allocates nothing (fresh memory costs page faults, and its release costs
/// every thread a TLB flush). A chunk that outgrows its region goes on COUNTING only: finish()
/// then reports that the search must run again, and start() gives every chunk a region for the
/// counts of that pass. The first search of a run thus walks twice, but no search ever holds
/// its lists more than once (a growing buffer per chunk and a gathered copy held them three times).
class neighbour_list_builder {
 public:
  /// How the entries are written: plain indices, with separate shift codes, packed, or packed
  /// and coded as runs (then a chunk's region and sizes are in bytes of neighbour_lists::runs).
  enum class entries { plain, separate_shifts, packed, runs };

  class chunk {
   public:
    /// Appends `count` entries to row `row` (rows come in ascending order): entry i is
    /// neighbour(i), renamed through `rename` when it is set, under shift code shift(i).
    template<class Neighbour, class Shift>
    void append(std::size_t row, std::size_t count, const Neighbour& neighbour, const Shift& shift,
                const std::size_t* rename, entries kind) {
      if (row != row_) start_row(row);
      if (kind == entries::runs) {  // coded when the row is complete (finish_row)
        const std::size_t before = row_entries_.size();
        row_entries_.resize(before + count);
        std::uint32_t* const out = row_entries_.data() + before;
        for (std::size_t i = 0; i < count; ++i)
          out[i] = packed_entry(static_cast<std::uint32_t>(rename ? rename[neighbour(i)] : neighbour(i)), shift(i));
        return;
      }
      if (overflowed_ || size_ + count > capacity_) {  // outgrown: count only, finish() asks for another pass
        overflowed_ = true;
        size_ += count;
        return;
      }
      // Local pointers: the stores below cannot then change the chunk's own members.
      std::uint32_t* const out = neighbours_ + size_;
      const auto index = [&](std::size_t i) {
        return static_cast<std::uint32_t>(rename ? rename[neighbour(i)] : neighbour(i));
      };
      if (kind == entries::packed) {
        for (std::size_t i = 0; i < count; ++i) out[i] = packed_entry(index(i), shift(i));
      } else {
        for (std::size_t i = 0; i < count; ++i) out[i] = index(i);
      }
      if (kind == entries::separate_shifts) {
        shift_code* const codes = shifts_ + size_;
        for (std::size_t i = 0; i < count; ++i) codes[i] = shift(i);
      }
      size_ += count;
    }

    /// Appends the one entry b (shift code `code`) to row `row`.
    void append(std::size_t row, std::uint32_t b, shift_code code, entries kind) {
      append(
        row, 1, [b](std::size_t) { return b; }, [code](std::size_t) { return code; }, nullptr, kind);
    }

   private:
    friend class neighbour_list_builder;
    static constexpr std::size_t no_row = static_cast<std::size_t>(-1);

    void start(entries kind, std::size_t* counts, void* region, shift_code* region_shifts, std::size_t capacity) {
      kind_ = kind;
      counts_ = counts;
      neighbours_ = static_cast<std::uint32_t*>(region);
      run_bytes_ = static_cast<std::uint8_t*>(region);
      shifts_ = region_shifts;
      entries_ = 0;
      capacity_ = capacity;
      size_ = 0;
      row_ = no_row;
      overflowed_ = false;
    }
    void start_row(std::size_t row) {
      if (row_ == no_row)
        first_row_ = row;
      else
        finish_row();
      row_ = row;
      row_begin_ = size_;
    }
    // The size of the row just finished goes to counts_ (one write per row, not per entry); rows
    // kept as runs are coded first, straight into the region when their largest size fits.
    void finish_row() {
      if (kind_ == entries::runs) {
        const std::size_t count = row_entries_.size();
        std::size_t bytes = runs::max_row_bytes(count);
        if (overflowed_ || size_ + bytes > capacity_) bytes = runs::row_bytes(row_entries_.data(), count);
        if (overflowed_ || size_ + bytes > capacity_)
          overflowed_ = true;
        else
          bytes = runs::encode_row(row_entries_.data(), count, run_bytes_ + size_);
        size_ += bytes;
        entries_ += count;
        row_entries_.clear();
      }
      counts_[row_] = size_ - row_begin_;
    }
    void close() {
      if (row_ != no_row) finish_row();
    }
    std::size_t* counts_ = nullptr;  // out.offsets, which hold the counts until the scan
    std::size_t first_row_ = 0;      // row of the chunk's first entry
    std::size_t row_ = no_row, row_begin_ = 0;
    std::size_t size_ = 0, capacity_ = 0;
    entries kind_ = entries::plain;
    std::uint32_t* neighbours_ = nullptr;  // its region of the lists
    std::uint8_t* run_bytes_ = nullptr;    // the same region of runs
    shift_code* shifts_ = nullptr;
    bool overflowed_ = false;                 // counting only since its region was full
    std::vector<std::uint32_t> row_entries_;  // the row being collected (runs)
    std::size_t entries_ = 0;                 // entries of the rows coded as runs
  };

  /// The entries for `layout` on a domain that is periodic or not, for `particles` particles
  /// (packed entries hold at most 2^27).
  static entries entries_for(const list_layout& layout, bool periodic, std::size_t particles) {
    if (layout.shifts == shift_storage::packed || layout.shifts == shift_storage::runs) {
      if (particles > packed_index_mask + std::size_t{1})
        throw std::length_error("ntree: packed neighbour lists hold at most 2^27 particles");
      return layout.shifts == shift_storage::runs ? entries::runs : entries::packed;
    }
    return periodic ? entries::separate_shifts : entries::plain;
  }

  /// Prepares `out` for `rows` rows (all counts zero) and `chunk_count` chunks, each given a
  /// region of out's arrays.
  void start(std::size_t rows, std::size_t chunk_count, neighbour_lists& out, entries kind) {
    out.offsets.assign(rows + 1, 0);
    if (chunks_.size() < chunk_count) chunks_.resize(chunk_count);
    std::vector<std::size_t>& room = room_of(kind);
    if (room.size() < chunk_count) room.resize(chunk_count, 0);
    chunk_count_ = chunk_count;
    std::vector<std::size_t> region(chunk_count + 1, 0);
    for (std::size_t c = 0; c < chunk_count; ++c)
      region[c + 1] = region[c] + room[c] + room[c] / 16 + (room[c] ? 64 : 0);
    const bool with_shifts = kind == entries::separate_shifts, in_runs = kind == entries::runs;
    // The array this kind does not use is freed first: a search may change kinds. Packed rows of
    // a few targets, freed before rows of every target are coded as runs, go back to the system:
    // left in the heap they would add to the peak of the search with the longest lists.
    if (in_runs && out.neighbours.capacity()) {
      fit(out.neighbours, 0);
      runtime::return_free_memory();
    }
    fit(out.shifts, with_shifts ? region[chunk_count] : 0);
    fit(out.runs, in_runs ? region[chunk_count] : 0);
    if (!in_runs) fit(out.neighbours, region[chunk_count]);
    out.in_runs = in_runs;
    out.run_entries = 0;
    for (std::size_t c = 0; c < chunk_count; ++c) {
      void* region_start = in_runs ? static_cast<void*>(out.runs.data() + region[c])
                                   : static_cast<void*>(out.neighbours.data() + region[c]);
      chunks_[c].start(kind, out.offsets.data(), region_start, with_shifts ? out.shifts.data() + region[c] : nullptr,
                       region[c + 1] - region[c]);
    }
  }

  chunk& operator[](std::size_t c) { return chunks_[c]; }

  /// Turns the counts in out.offsets into offsets and moves the chunks' entries to their place;
  /// or, when a chunk outgrew its region, returns false: the lists are then not valid, and the
  /// caller runs the search again from start(), which sizes the regions for this pass's counts.
  [[nodiscard]] bool finish(neighbour_lists& out, entries kind) {
    bool all_in_regions = true;
    std::vector<std::size_t>& room = room_of(kind);
    for (std::size_t c = 0; c < chunk_count_; ++c) {
      chunks_[c].close();
      room[c] = std::max(chunks_[c].size_, room[c] - room[c] / 16);
      all_in_regions = all_in_regions && !chunks_[c].overflowed_;
    }
    if (!all_in_regions) {
      ++repeated_passes_;
      return false;
    }
    const std::size_t rows = out.offsets.size() - 1;
    const std::size_t total =
      flecsi_lite::exclusive_scan(out.offsets.data(), rows + 1, "ntree::neighbour_lists::offsets");
    const bool with_shifts = kind == entries::separate_shifts, in_runs = kind == entries::runs;
    // Chunk c's place starts at the sum of the sizes of the chunks before it, at most where its
    // region starts: moved in chunk order, no entry is overwritten before it moved.
    for (std::size_t c = 0; c < chunk_count_; ++c) {
      const chunk& part = chunks_[c];
      out.run_entries += part.entries_;
      if (part.size_ == 0) continue;
      const std::size_t at = out.offsets[part.first_row_];
      if (in_runs)
        std::memmove(out.runs.data() + at, part.run_bytes_, part.size_);
      else
        std::memmove(out.neighbours.data() + at, part.neighbours_, part.size_ * sizeof(std::uint32_t));
      if (with_shifts) std::memmove(out.shifts.data() + at, part.shifts_, part.size_ * sizeof(shift_code));
    }
    if (in_runs)
      out.runs.resize(total);
    else
      out.neighbours.resize(total);
    out.shifts.resize(with_shifts ? total : 0);
    for (std::size_t c = 0; c < chunk_count_; ++c) chunks_[c].start(kind, nullptr, nullptr, nullptr, 0);
    return true;
  }

  /// Searches that ran twice because a chunk outgrew its region (the first one of a run, and
  /// those whose lists grew beyond the regions' spare room).
  std::size_t repeated_passes() const { return repeated_passes_; }

 private:
  // Room for `size` values: the arrays keep their allocation unless it is too small or more
  // than 1/8 too large (std::vector::resize alone would double the capacity).
  template<class T>
  static void fit(std::vector<T>& values, std::size_t size) {
    if (values.capacity() < size || values.capacity() > size + size / 8) {
      std::vector<T> fitted;
      fitted.reserve(size);
      values.swap(fitted);
    }
    values.resize(size);
  }

  std::vector<chunk> chunks_;
  // Per chunk, the entries its region is made for: the largest of the recent searches, forgotten
  // by 1/16 a search, so that searches of varying targets (individual time steps: a few active
  // particles, then all) rarely walk twice.
  // In the unit of the lists' kind: bytes of runs, or entries. A search may keep its rows as runs
  // and the next one packed (sph: the active particles' searches of few targets), so each kind
  // has its own.
  std::vector<std::size_t> room_, room_in_runs_;
  std::vector<std::size_t>& room_of(entries kind) { return kind == entries::runs ? room_in_runs_ : room_; }
  std::size_t chunk_count_ = 0;
  std::size_t repeated_passes_ = 0;
};

}  // namespace flecsi_lite::topology::ntree
