// The physics settings of the SPH specialization (kernel, equation of state, dissipation,
// smoothing length, time step), and the parameter-file keys that set them, shared by every app.
#pragma once

#include "specialization/physics/eos.hh"
#include "specialization/physics/kernels.hh"
#include "specialization/physics/viscosity.hh"

#include "flecsi_lite/runtime.hh"

#include <string>

namespace flecsph::sph {

struct physics_settings {
  physics::kernel_type kernel = physics::kernel_type::cubic_spline;
  physics::equation_of_state eos{};
  /// Monaghan & Gingold (1983) viscosity, seed eqs. (1.10)-(1.11): alpha 1, beta 2, epsilon 0.01.
  physics::viscosity_parameters viscosity{};
  bool balsara = false;       ///< Balsara (1995) switch on the viscosity
  double conductivity = 1.0;  ///< alpha_u of the Price (2008) artificial conductivity; 0: off
  /// Adaptive h = eta (m/rho)^(1/D) by Newton-Raphson with grad-h terms (Price 2012), or fixed h.
  bool adaptive_smoothing_length = true;
  double eta = 1.2;
  double h_tolerance = 1e-6;  ///< on the relative residual of the h-rho relation
  int h_iterations = 50;      ///< most Newton-Raphson iterations per particle
  double courant = 0.3;       ///< dt <= courant h / v_signal
  double acceleration_factor = 0.25;  ///< dt <= factor sqrt(h / |a|)
  /// The neighbour search reaches 2 (1 + margin) max(h_a, h_b): room for h to grow during the
  /// density iteration before the particles must be searched again.
  double search_margin = 0.05;
  /// Ghosts are selected (1 + skin) times farther than the search reaches, so that the particles
  /// are distributed again only once their motion and the growth of h have used that room up.
  double distribution_skin = 0.5;
};

/// Declares the physics keys (kernel, eos, gamma, ..., search_margin) with their defaults.
void declare_physics_parameters(flecsi_lite::runtime::parameter_schema& schema);
/// Reads the keys declared by declare_physics_parameters.
physics_settings physics_from(const flecsi_lite::runtime::parameters& p);

/// How long to run and how often to report.
struct run_settings {
  double end_time = 0;
  long max_steps = 0;         ///< 0: no limit
  long progress_every = 1;    ///< steps between progress lines (0: none until the end)
  long diagnostics_every = 1; ///< steps between conserved-quantities lines (0: first and last only)
};

/// Files a run reads and writes; an empty name is "none".
struct io_settings {
  std::string output_file;
  double output_every = 0;  ///< simulation time between outputs; 0: first and last step only
  std::string checkpoint_file;
  long checkpoint_every = 0;  ///< steps between checkpoints; 0: none
  std::string restart_file;   ///< continue the run of this checkpoint
  std::string initial_data;   ///< H5Part file of the initial particles
  long initial_data_step = -1;  ///< its Step#k; -1: the last
};

/// The defaults of the run-control keys, which each problem chooses.
struct run_parameter_defaults {
  double end_time;
  long progress_every, diagnostics_every;
  std::string output_file, checkpoint_file;
};
/// Declares the run-control and file keys every SPH app shares: end_time, max_steps,
/// progress_every, diagnostics_every, output_file, output_every, checkpoint_file,
/// checkpoint_every, restart_file, initial_data, initial_data_step.
void declare_run_parameters(flecsi_lite::runtime::parameter_schema& schema, const run_parameter_defaults& defaults);
/// Reads the run-control keys.
run_settings run_settings_from(const flecsi_lite::runtime::parameters& p);
/// Reads the file keys; contradictory ones (restart_file and initial_data) are parameter errors.
io_settings io_settings_from(const flecsi_lite::runtime::parameters& p);

} // namespace flecsph::sph
