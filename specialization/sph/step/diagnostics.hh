// What an SPH run reports: the conserved totals (exact sums, conserved.hh) at a cadence, the
// progress line (time, step, throughput, mean neighbour count), memory per particle and the
// closing summary.
#pragma once

#include "specialization/sph/model/conserved.hh"
#include "specialization/sph/model/simulation.hh"

#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime.hh"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>

namespace flecsph::sph {

/// The exact totals now (collective; waits for the launches they depend on; runs the deferred walk
/// of the inactive particles' gravity first, complete_deferred_fields).
template<int D>
conserved_totals<D> measure_conserved(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  complete_deferred_fields(s);
  if (s.physics.gravity.enabled)
    return flecsi_lite::reduce<conserved_quantities_with_gravity<D>, conserved_reduction>(
             f::position()(p), f::velocity(p), f::mass()(p), f::internal_energy(p), f::kind(p),
             f::boundary_impulse(p).only_if(s.has_walls), f::boundary_work(p).only_if(s.has_walls),
             f::gravitational_potential(p))
      .get()
      .totals();
  return flecsi_lite::reduce<conserved_quantities<D>, conserved_reduction>(
           f::position()(p), f::velocity(p), f::mass()(p), f::internal_energy(p), f::kind(p),
           f::boundary_impulse(p).only_if(s.has_walls), f::boundary_work(p).only_if(s.has_walls))
    .get()
    .totals();
}

template<int D>
std::string describe_conserved(const conserved_totals<D>& t, const conserved_totals<D>& initial) {
  std::ostringstream out;
  out << std::setprecision(12) << "mass " << t.mass << "  momentum (";
  for (int k = 0; k < D; ++k) out << (k ? ", " : "") << t.momentum[k];
  out << ")";
  if constexpr (angular_components < D >> 0) {
    out << "  angular momentum (";
    for (int k = 0; k < angular_components<D>; ++k) out << (k ? ", " : "") << t.angular_momentum[k];
    out << ")";
  }
  out << "  kinetic " << t.kinetic << "  internal " << t.internal;
  if (t.potential != 0) out << "  potential " << t.potential;
  out << "  total " << t.total;
  if (t.boundary != 0) out << " (walls " << t.boundary << ")";
  out << std::setprecision(3) << "  relative energy change "
      << (initial.total != 0 ? (t.total - initial.total) / std::fabs(initial.total) : t.total - initial.total);
  return out.str();
}

template<int D>
void conserved_diagnostics(simulation<D>& s) {
  const long every = s.run.diagnostics_every;
  const bool first = s.totals_step < 0;
  if (!(first || s.finished || (every > 0 && s.step % every == 0))) return;
  s.totals = measure_conserved(s);
  s.totals_step = s.step;
  if (first && !s.restarted) s.initial_totals = s.totals;  // a restart keeps the run's initial totals
  flecsi_lite::log::info() << "conserved: step " << s.step << "  t " << std::setprecision(8) << s.time << "  "
                           << describe_conserved(s.totals, s.initial_totals);
}

/// Throughput of this run since the cycle started (a restart counts from its own first step).
template<int D>
double particle_steps_per_second(const simulation<D>& s) {
  const double steps = static_cast<double>(s.step - s.started_step);
  return s.elapsed > 0 ? static_cast<double>(s.particles->global_size()) * steps / s.elapsed : 0.0;
}

/// Neighbour-list entries per particle over all ranks (with individual time steps, per active
/// particle: the lists hold their rows only). Collective.
template<int D>
double mean_list_length(const simulation<D>& s) {
  if (s.physics.individual_time_steps() && s.active_targets.valid()) {
    const active_count active = s.active_targets.get();
    return active.targets > 0 ? active.entries / active.targets : 0.0;
  }
  const double total = flecsi_lite::reduce<neighbour_total<D>, flecsi_lite::reduction::sum>(s.neighbours).get();
  return s.particles->global_size() ? total / double(s.particles->global_size()) : 0.0;
}

template<int D>
void progress_line(simulation<D>& s) {
  s.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - s.started).count();
  const long every = s.run.progress_every;
  if (!(s.finished || (every > 0 && s.step % every == 0))) return;
  s.mean_neighbours = mean_list_length(s);
  const double fraction = s.run.end_time > 0 ? s.time / s.run.end_time : 1.0;
  const double rate = particle_steps_per_second(s);
  std::ostringstream line;
  line << "step " << std::setw(6) << s.step << "  t " << std::setw(10) << std::setprecision(6) << s.time << "  dt "
       << std::setw(10) << s.dt << "  " << std::fixed << std::setprecision(1) << std::setw(5) << 100 * fraction
       << "%  ETA " << std::setprecision(1)
       << (s.time > s.started_time ? s.elapsed * (s.run.end_time - s.time) / (s.time - s.started_time) : 0.0) << " s  "
       << std::scientific << std::setprecision(3) << rate << " particle-steps/s  " << std::fixed << std::setprecision(1)
       << s.mean_neighbours << " neighbours";
  if (s.physics.individual_time_steps() && s.active_targets.valid())
    line << "  " << std::setprecision(0) << s.active_targets.get().targets << " active";
  flecsi_lite::log::info() << line.str();
}

/// Memory of this rank per owned particle: every field's storage (owned and ghost entries), and
/// the neighbour lists.
struct memory_use {
  double fields = 0;
  double neighbour_lists = 0;
};

template<int D>
memory_use measure_memory(const simulation<D>& s) {
  memory_use result;
  const double owned = static_cast<double>(std::max<std::size_t>(1, s.particles->owned_size()));
  for (const auto& storage : s.particles->storages())
    if (storage) result.fields += static_cast<double>(storage->element_size() * storage->size());
  const auto& n = s.neighbours.host();  // what is allocated, spare room included
  result.neighbour_lists = static_cast<double>(n.bytes());
  result.fields /= owned;
  result.neighbour_lists /= owned;
  return result;
}

/// The closing line of a run: steps, throughput, distributions and memory per particle.
template<int D>
void run_summary(simulation<D>& s) {
  const memory_use bytes = measure_memory(s);
  flecsi_lite::log::info() << "sph: " << s.step << " steps to t = " << s.time << " in " << std::setprecision(4)
                           << s.elapsed << " s: " << particle_steps_per_second(s) << " particle-steps/s, "
                           << s.distributions << " distributions, " << s.repeated_searches << " repeated searches, "
                           << s.searches
                           << " neighbour searches; bytes per owned particle (rank 0): " << std::setprecision(3)
                           << bytes.fields << " in fields, " << bytes.neighbour_lists << " in neighbour lists";
  if (s.physics.individual_time_steps()) {
    const double steps = static_cast<double>(std::max(1L, s.step - s.started_step));
    const double particles = static_cast<double>(std::max<std::uint64_t>(1, s.particles->global_size()));
    flecsi_lite::log::info() << "sph: individual time steps: " << std::setprecision(6) << s.particle_updates
                             << " particle updates in " << s.step - s.started_step << " steps (" << std::setprecision(4)
                             << s.particle_updates / steps << " per step, "
                             << 100 * s.particle_updates / (steps * particles) << "% of the particles; "
                             << (s.elapsed > 0 ? s.particle_updates / s.elapsed : 0.0) << " updates/s), "
                             << std::setprecision(6) << s.woken << " woken by the limiter";
  }
  s.balance.settle();
  if (s.balance.distributions > 0)
    flecsi_lite::log::info() << "sph: balance (" << balance_names().name(s.physics.balance) << ", "
                             << key_order_names().name(s.physics.key_order) << " keys) over " << s.balance.distributions
                             << " distributions, max / mean per rank: work (neighbour "
                             << "list entries) " << std::setprecision(4) << s.balance.work_mean() << " mean, "
                             << s.balance.work_max << " largest; particles " << s.balance.count_mean() << " mean, "
                             << s.balance.count_max << " largest";
  if (!s.physics.gravity.enabled) return;
  const double owned = static_cast<double>(std::max<std::size_t>(1, s.particles->owned_size()));
  flecsi_lite::log::info() << "sph: gravity in the last step (rank 0): " << std::setprecision(4)
                           << double(s.last_gravity.node_interactions) / owned << " node and "
                           << double(s.last_gravity.particle_interactions) / owned
                           << " particle interactions per owned particle; " << s.last_gravity.imported_nodes
                           << " nodes and " << s.last_gravity.imported_particles << " particles imported";
}

}  // namespace flecsph::sph
