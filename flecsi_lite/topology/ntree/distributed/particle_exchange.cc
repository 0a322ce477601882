// All-to-all exchange of particles and all their fields as bytes (one MPI datatype of one
// particle's bytes, so that counts stay within int for any particle count below 2^31 per rank).
#include "flecsi_lite/topology/ntree/distributed/particle_exchange.hh"

#include "flecsi_lite/runtime/context.hh"

#include <climits>
#include <stdexcept>
#include <string>

namespace flecsi_lite::topology::ntree {
namespace {

// A datatype of `bytes` contiguous bytes, freed at scope exit.
class particle_type {
 public:
  explicit particle_type(std::size_t bytes) {
    runtime::check_mpi(MPI_Type_contiguous(static_cast<int>(bytes), MPI_BYTE, &type_), "MPI_Type_contiguous");
    MPI_Type_commit(&type_);
  }
  particle_type(const particle_type&) = delete;
  particle_type& operator=(const particle_type&) = delete;
  ~particle_type() { MPI_Type_free(&type_); }
  MPI_Datatype get() const { return type_; }

 private:
  MPI_Datatype type_ = MPI_DATATYPE_NULL;
};

int checked_int(std::size_t value, const char* what) {
  if (value > static_cast<std::size_t>(INT_MAX))
    throw std::length_error(std::string("ntree particle exchange: too many particles ") + what);
  return static_cast<int>(value);
}

}  // namespace

std::vector<data::field_storage_base*> storages_to_move(const data::topology_base& topology, MPI_Comm comm) {
  const auto& all = topology.storages();
  long count = static_cast<long>(all.size()), longest = 0;
  MPI_Allreduce(&count, &longest, 1, MPI_LONG, MPI_MAX, comm);
  // Element size per field id (0: no storage here); every rank must agree on all of them.
  std::vector<long> sizes(static_cast<std::size_t>(longest), 0), smallest(sizes.size()), largest(sizes.size());
  for (std::size_t f = 0; f < all.size(); ++f)
    if (all[f]) sizes[f] = static_cast<long>(all[f]->element_size());
  MPI_Allreduce(sizes.data(), smallest.data(), static_cast<int>(sizes.size()), MPI_LONG, MPI_MIN, comm);
  MPI_Allreduce(sizes.data(), largest.data(), static_cast<int>(sizes.size()), MPI_LONG, MPI_MAX, comm);
  for (std::size_t f = 0; f < sizes.size(); ++f)
    if (smallest[f] != largest[f])
      throw std::logic_error("ntree: field " + std::to_string(f) +
                             " has storage on some ranks only (or differing types); use every field "
                             "on every rank (e.g. in a task) before distributing particles");
  std::vector<data::field_storage_base*> result;
  for (const auto& s : all)
    if (s) result.push_back(s.get());
  return result;
}

particle_shipment exchange_particles(const std::vector<data::field_storage_base*>& fields,
                                     const std::vector<std::size_t>& order, const std::vector<std::size_t>& bounds,
                                     MPI_Comm comm) {
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  if (bounds.size() != static_cast<std::size_t>(size) + 1)
    throw std::invalid_argument("exchange_particles: bounds needs one entry per rank plus one");

  particle_shipment shipment;
  for (const auto* f : fields) shipment.bytes_per_particle += f->element_size();
  const std::size_t per_particle = shipment.bytes_per_particle;

  std::vector<int> send_counts(size), send_offsets(size), receive_counts(size), receive_offsets(size);
  for (int r = 0; r < size; ++r) {
    send_counts[r] = checked_int(bounds[r + 1] - bounds[r], "to send");
    send_offsets[r] = checked_int(bounds[r], "to send");
    if (r != rank) shipment.sent_away += bounds[r + 1] - bounds[r];
  }
  runtime::check_mpi(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm),
                     "ntree particle exchange: counts");
  shipment.counts.resize(size);
  for (int r = 0; r < size; ++r) {
    receive_offsets[r] = checked_int(shipment.total, "to receive");
    shipment.counts[r] = static_cast<std::size_t>(receive_counts[r]);
    shipment.total += shipment.counts[r];
  }
  checked_int(shipment.total, "to receive");

  // Block of destination r: the values of each field in turn for its particles (SoA).
  std::vector<std::byte> send(bounds.back() * per_particle);
  for (int r = 0; r < size; ++r) {
    std::byte* out = send.data() + bounds[r] * per_particle;
    const std::size_t count = bounds[r + 1] - bounds[r];
    for (const auto* f : fields) {
      f->pack(order.data() + bounds[r], count, out);
      out += count * f->element_size();
    }
  }
  shipment.bytes.resize(shipment.total * per_particle);
  if (per_particle == 0) return shipment;
  const particle_type type(per_particle);
  runtime::check_mpi(
    MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), type.get(), shipment.bytes.data(),
                  receive_counts.data(), receive_offsets.data(), type.get(), comm),
    "ntree particle exchange: particles");
  return shipment;
}

void unpack_particles(const std::vector<data::field_storage_base*>& fields, const particle_shipment& shipment,
                      std::size_t first) {
  std::size_t at = first;
  const std::byte* in = shipment.bytes.data();
  for (const std::size_t count : shipment.counts) {
    for (auto* f : fields) {
      f->unpack(in, at, count);
      in += count * f->element_size();
    }
    at += count;
  }
}

}  // namespace flecsi_lite::topology::ntree
