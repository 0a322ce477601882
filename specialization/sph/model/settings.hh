// The physics and run-control settings of the SPH specialization (kernel, equation of state,
// dissipation, smoothing length, time step; end time and reports) and the parameter-file keys
// that set them, each declared once next to the member it fills, shared by every app (the range
// checks of the quantities a problem derives from its keys are the runtime's: derived_values.hh).
#pragma once

#include "specialization/physics/eos.hh"
#include "specialization/physics/kernels.hh"
#include "specialization/physics/viscosity.hh"
#include "specialization/physics/viscosity_switch.hh"

#include "flecsi_lite/runtime.hh"
#include "flecsi_lite/topology/ntree.hh"

#include <cstdint>
#include <string>

namespace flecsph::sph {

/// The opening criterion of the gravity tree: Barnes-Hut's geometric theta alone, or GADGET-2's
/// relative criterion (Springel 2005, eq. 18) as well, with the previous step's |a|.
enum class gravity_criterion { geometric, relative };

/// The parameter-file names of the criteria ("geometric", "relative").
const flecsi_lite::runtime::name_table<gravity_criterion>& gravity_criterion_names();

/// The parameter-file names of the key orders ("hilbert", "morton") and balances ("count", "work").
const flecsi_lite::runtime::name_table<flecsi_lite::topology::ntree::curve>& key_order_names();
const flecsi_lite::runtime::name_table<flecsi_lite::topology::ntree::balance>& balance_names();
/// The parameter-file names of the neighbour lists' storage ("runs", "packed").
const flecsi_lite::runtime::name_table<flecsi_lite::topology::ntree::shift_storage>& neighbour_list_names();

/// The parameter-file names of the viscosity switch's d(div v)/dt estimates ("acceleration",
/// "difference"), alpha_loc forms ("price", "cullen_dehnen") and starting alphas ("alpha_max",
/// "alpha_min").
const flecsi_lite::runtime::name_table<physics::divergence_rate_estimate>& divergence_rate_names();
const flecsi_lite::runtime::name_table<physics::local_alpha_form>& local_alpha_form_names();
const flecsi_lite::runtime::name_table<physics::initial_alpha>& initial_alpha_names();

/// Self-gravity: softened with the SPH kernel (Price & Monaghan 2007) on the gravity tree, in 3D
/// without periodic axes (no Ewald summation yet).
struct gravity_settings {
  bool enabled = false;
  double constant = 1.0;  ///< G
  double theta = 0.5;     ///< Barnes-Hut opening angle
  gravity_criterion criterion = gravity_criterion::geometric;
  double relative_tolerance = 0.0025;  ///< alpha of the relative criterion
  /// The grad-h gravity term of Price & Monaghan (2007); off only to measure what it does.
  bool grad_h = true;
};

/// The SPH formulation of the forces: "density-energy" (P_a = (gamma - 1) rho_a u_a of each particle,
/// Price 2012) or "pressure-energy" (the smoothed pressure P_bar_a = (gamma - 1) sum_b m_b u_b W_ab(h_a),
/// Hopkins 2013, MNRAS 428, 2840, sec. 2.4), which has no pressure blip at a contact discontinuity.
enum class formulation { density_energy, pressure_energy };

/// The parameter-file names of the formulations ("density_energy", "pressure_energy").
const flecsi_lite::runtime::name_table<formulation>& formulation_names();

/// One time step for all particles (the smallest of their criteria), or each particle its own
/// power-of-two fraction of the run (block time steps, time_bins.hh).
enum class time_stepping { global, individual };

/// The parameter-file names of the time stepping ("global", "individual").
const flecsi_lite::runtime::name_table<time_stepping>& time_stepping_names();

/// Individual time steps (GADGET-2: Springel 2005, MNRAS 364, 1105, sec. 5; SWIFT): each particle
/// in the bin of its own criterion, no step more than `limiter` times its neighbours' (Saitoh &
/// Makino 2009, ApJ 697, L99), at most max_time_step.
struct time_step_settings {
  time_stepping stepping = time_stepping::global;
  /// Largest ratio of a particle's step to its neighbours' (a power of two; 0: no limiter).
  int limiter = 4;
  double max_time_step = 0;  ///< 0: no bound but the run's span
};

struct physics_settings {
  physics::kernel_type kernel = physics::kernel_type::cubic_spline;
  physics::equation_of_state eos{};
  /// Pressure-energy needs an ideal gas and no self-gravity (checked with the keys).
  formulation equations = formulation::density_energy;
  bool pressure_energy() const { return equations == formulation::pressure_energy; }
  /// Monaghan & Gingold (1983) viscosity, seed eqs. (1.10)-(1.11): alpha 1, beta 2, epsilon 0.01.
  physics::viscosity_parameters viscosity{};
  bool balsara = false;  ///< Balsara (1995) switch on the viscosity
  /// Cullen & Dehnen (2010) per-particle alpha (sph/viscosity_switch.hh); off: the constant alpha.
  physics::viscosity_switch_settings viscosity_switch{};
  double conductivity = 1.0;  ///< alpha_u of the Price (2008) artificial conductivity; 0: off
  /// Adaptive h = eta (m/rho)^(1/D) by Newton-Raphson with grad-h terms (Price 2012), or fixed h.
  bool adaptive_smoothing_length = true;
  double eta = 1.2;
  double h_tolerance = 1e-6;          ///< on the relative residual of the h-rho relation
  int h_iterations = 50;              ///< most Newton-Raphson iterations per particle
  double courant = 0.3;               ///< dt <= courant h / v_signal
  double acceleration_factor = 0.25;  ///< dt <= factor sqrt(h / |a|)
  /// The neighbour search reaches 2 (1 + margin) max(h_a, h_b): room for h to grow during the
  /// density iteration before the particles must be searched again.
  double search_margin = 0.05;
  /// Ghosts are selected (1 + skin) times farther than the search reaches, so that the particles
  /// are distributed again only once their motion and the growth of h have used that room up.
  double distribution_skin = 0.5;
  /// Neighbour lists are searched (1 + skin) times farther than the search reach and kept over
  /// the steps until the particles' displacement and the growth of h have used that room up
  /// (list_reuse.hh); 0 keeps them only while nothing moves or grows, i.e. searches every step.
  /// 0 is the fastest for the Sedov blast (the entries beyond the kernel cost the pair loops
  /// more than the searches saved); slow flows gain with 0.1 (benchmarks/sph/README.md,
  /// "Neighbour lists kept over steps").
  double list_skin = 0.0;
  /// How the neighbour lists are kept: as runs of consecutive neighbours (1.2 bytes an entry on
  /// Sedov's lattice) or packed (4 bytes an entry; a step of every particle about 7% faster on one
  /// thread). The pairs, their order and so every result are the same to the bit
  /// (docs/performance.md, "Neighbour lists as runs").
  flecsi_lite::topology::ntree::shift_storage neighbour_lists = flecsi_lite::topology::ntree::shift_storage::runs;
  /// The space-filling curve that orders and distributes the particles (seed section 2.3.1):
  /// Hilbert's domains are more compact than Morton's, so they need fewer ghosts.
  flecsi_lite::topology::ntree::curve key_order = flecsi_lite::topology::ntree::curve::hilbert;
  /// The ranks get equal particle counts, or equal work: each particle weighs its neighbours at the
  /// last search (the seed's neighbour-based balancing, section 2.3.3, as FleCSPH offers).
  flecsi_lite::topology::ntree::balance balance = flecsi_lite::topology::ntree::balance::count;
  gravity_settings gravity{};
  time_step_settings time_steps{};
  bool individual_time_steps() const { return time_steps.stepping == time_stepping::individual; }
  /// div v is read by the Balsara switch and by the individual steps' drift of the inactive
  /// particles' rho and h (the density pass sums it).
  bool velocity_gradients() const { return balsara || individual_time_steps(); }
};

/// A parameter_error naming the key `gravity` unless gravity is off or the problem is 3D with no
/// periodic axis (`periodic`: the domain's periodic axes, as the problem set them).
template<int D, class Periodic>
void check_gravity_domain(const physics_settings& physics, const Periodic& periodic) {
  if (!physics.gravity.enabled) return;
  if (D != 3)
    throw flecsi_lite::runtime::parameter_error("gravity = on needs a 3D problem: this one is " + std::to_string(D) +
                                                "D (the softened potential is that of a 3D kernel)");
  for (int k = 0; k < D; ++k)
    if (periodic[k])
      throw flecsi_lite::runtime::parameter_error(
        "gravity = on with periodic axes (axis " + std::to_string(k) +
        " is periodic): periodic gravity needs Ewald summation, which does not exist yet; set gravity = off or use "
        "an open domain");
}

/// The physics keys (kernel, eos, gamma, ..., distribution_skin), each bound to its member, with
/// the defaults each problem chooses in `defaults` (by default those of physics_settings).
flecsi_lite::runtime::parameter_block<physics_settings> physics_parameters(const physics_settings& defaults = {});

/// How long to run and how often to report.
struct run_settings {
  double end_time = 0;
  long max_steps = 0;          ///< 0: no limit
  long progress_every = 1;     ///< steps between progress lines (0: none until the end)
  long diagnostics_every = 1;  ///< steps between conserved-quantities lines (0: first and last only)
};

/// The run-control keys end_time, max_steps, progress_every and diagnostics_every, with the
/// defaults each problem chooses in `defaults`.
flecsi_lite::runtime::parameter_block<run_settings> run_parameters(const run_settings& defaults = {});

}  // namespace flecsph::sph
