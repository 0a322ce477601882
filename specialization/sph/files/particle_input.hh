// Reads SPH particles from one step of an H5Part file in parallel (the seed's "read f in
// parallel"): rank r of p reads the r-th balanced block of the step's particles, then the driver
// distributes them. What is read is every field whose definition has role initial (sph/fields.hh
// and the tree's own), so an output file (or a checkpoint) of any run is valid initial data, and
// so is a file a user makes with h5py:
//
//   required   x (and y in 2D, y z in 3D), m, h, u        (any numeric type: float64, float32, ...)
//   optional   vx vy vz (0), rho (initial guess only), id (the particle's index in the step),
//              kind (0 fluid, 1 wall; default fluid)
//
// Impossible values (no particles, non-finite positions, m <= 0, h <= 0, u < 0, rho < 0, unknown
// kinds: the fields' rules; ids that are not whole numbers >= 0 or not unique: initial_ids.hh) are errors naming the file, the step, the dataset and the first bad
// particle, thrown on every rank alike; so are sets of particles SPH cannot evolve: no fluid
// particle (walls only), two particles at one position (the pair with the smallest ids is named),
// and a single particle with adaptive h (h = eta (m/rho)^(1/D) has no solution without
// neighbours; with adaptive_smoothing_length = false it runs: a particle at rest in its box).
#pragma once

#include "specialization/sph/files/initial_ids.hh"
#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/tasks.hh"
#include "specialization/sph/step/initial_fields.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/io.hh"

#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

namespace flecsph::sph {

/// "'path' Step#12" for messages: the H5Part step `index` of the reader's file.
inline std::string describe_input_step(const flecsi_lite::io::h5part_reader& in, std::int64_t index) {
  return flecsi_lite::data::describe_step(in, index);
}

/// Collective: creates the particles of `s` with this rank's block of step `step` of `in` (fields
/// zero); throws when the step holds no particles. The tree settings must be set.
template<int D>
void create_particles_for(simulation<D>& s, const flecsi_lite::io::h5part_reader& in, std::int64_t step) {
  if (in.particle_count(step) == 0) throw std::invalid_argument(describe_input_step(in, step) + " holds no particles");
  create_particles(s, in.block(step).count);
}

namespace detail {
inline std::uint64_t count_fluid(ro<particle_kind> kind) {
  std::uint64_t count = 0;
  for (std::size_t a = 0; a < kind.size(); ++a) count += kind(a) == particle_kind::fluid;
  return count;
}

/// Collective: the checks of the whole set of particles read from `what` (see the file's head).
/// The coincidence check distributes the particles and searches their neighbours once (the run's
/// first search distributes them again); it costs about one step's search.
template<int D>
void check_particle_set(simulation<D>& s, const std::string& what) {
  using f = fields<D>;
  auto& p = *s.particles;
  const std::uint64_t fluid = flecsi_lite::reduce<count_fluid, flecsi_lite::reduction::sum>(f::kind(p)).get();
  if (fluid == 0)
    throw std::invalid_argument(what + " holds no fluid particles (all " + std::to_string(p.global_size()) +
                                " have kind 1, wall): nothing would move");
  if (p.global_size() == 1 && s.physics.adaptive_smoothing_length)
    throw std::invalid_argument(
      what +
      " holds a single particle: with adaptive_smoothing_length = true its h = eta (m/rho)^(1/D) has no "
      "solution without neighbours; set adaptive_smoothing_length = false to run it with its h");
  p.distribute();
  tracked_neighbourhood<D> neighbours{"coincidence check lists"};
  find_neighbours(p, neighbours, 0.0);
  const auto pair =
    flecsi_lite::reduce<find_coincident<D>, coincident_reduction>(neighbours, f::position()(p), f::id()(p)).get();
  if (!pair.found()) return;
  std::ostringstream message;
  message.precision(17);
  message << what << ": particles with id " << pair.first << " and " << pair.second << " are both at x = (";
  for (int k = 0; k < D; ++k) message << (k ? ", " : "") << pair.x[k];
  message << "): SPH needs distinct positions (move or remove one of them)";
  throw std::invalid_argument(message.str());
}
}  // namespace detail

/// Collective: creates the particles of `s` from step `step` (the index k of Step#k; -1: the last)
/// of `in`, with this rank's block of them and their initial fields. The tree settings (box,
/// periodic axes) must be set. Returns the step index read.
template<int D>
std::int64_t read_particles(simulation<D>& s, const flecsi_lite::io::h5part_reader& in, std::int64_t step = -1) {
  if (step < 0) step = in.last_step();
  create_particles_for(s, in, step);
  // Before the fields: a NaN id must not reach the field reader's conversion on one rank only.
  detail::check_initial_ids(flecsi_lite::io::h5part_step_columns(in, step));
  flecsi_lite::data::read_fields(*s.particles, in, step, flecsi_lite::data::role::initial);
  detail::check_particle_set(s, describe_input_step(in, step));
  return step;
}

}  // namespace flecsph::sph
