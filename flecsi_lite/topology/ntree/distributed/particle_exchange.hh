// Moves particles between ranks with every field they carry: the values of all field storages
// of a topology are packed per destination, sent with one MPI_Alltoallv and unpacked in order of
// source rank (the all-to-all step of FleCSPH's sample sort, seed sec. 2.3.3).
#pragma once

#include "flecsi_lite/data/field_storage.hh"
#include "flecsi_lite/data/topology_base.hh"

#include <mpi.h>

#include <cstddef>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// The storages of `topology` that exist (by field id). Collective: throws std::logic_error on
/// every rank unless all ranks hold storages for the same fields with the same element sizes
/// (a field must be touched on every rank, e.g. by a task, before particles can carry it).
std::vector<data::field_storage_base*> storages_to_move(const data::topology_base& topology, MPI_Comm comm);

/// Particles received by exchange_particles: `counts[r]` came from rank r, in that rank's send
/// order, packed in `bytes` block after block.
struct particle_shipment {
  std::vector<std::byte> bytes;
  std::vector<std::size_t> counts;
  std::size_t total = 0;
  std::size_t bytes_per_particle = 0;  ///< sum of the element sizes of all fields
  std::size_t sent_away = 0;           ///< particles this rank sent to other ranks
};

/// Collective: sends particles order[bounds[r] .. bounds[r + 1]) (owned indices) to rank r, with
/// the values of every storage in `fields`. The storages are only read.
particle_shipment exchange_particles(const std::vector<data::field_storage_base*>& fields,
                                     const std::vector<std::size_t>& order, const std::vector<std::size_t>& bounds,
                                     MPI_Comm comm);

/// Writes the received particles into positions [first, first + shipment.total) of every storage
/// (which must be large enough), source rank after source rank.
void unpack_particles(const std::vector<data::field_storage_base*>& fields, const particle_shipment& shipment,
                      std::size_t first = 0);

}  // namespace flecsi_lite::topology::ntree
