// The SPH step's and the app frame's function templates are compiled once per dimension, in the
// library (instances_1d.cc, instances_2d.cc, instances_3d.cc), instead of in every app, test and
// tutorial that builds a control model: each of those translation units took 50-170 s to compile
// (about half of CI's build). The lists below are the entry points the control models call;
// what they call in turn is instantiated with them. The headers that define these templates
// declare them `extern` for D = 1, 2, 3 (sph_model.hh, app.hh); other dimensions instantiate
// implicitly as before.
//
// EXTERN is `extern` for the declarations and empty for the definitions.
#pragma once

/// The physics steps of driver.hh's control model (steps.hh, diagnostics.hh, time_bins.hh).
#define FLECSPH_SPH_STEP_INSTANCES(EXTERN, D)                            \
  EXTERN template void update_neighbours<D>(simulation<D>&, bool);       \
  EXTERN template void update_density<D>(simulation<D>&);                \
  EXTERN template void update_pressure<D>(simulation<D>&);               \
  EXTERN template void update_forces<D>(simulation<D>&);                 \
  EXTERN template void first_kick_and_drift<D>(simulation<D>&);          \
  EXTERN template void second_kick<D>(simulation<D>&);                   \
  EXTERN template void choose_time_step<D>(simulation<D>&, bool);        \
  EXTERN template void start_timeline<D>(simulation<D>&);                \
  EXTERN template void update_viscosity_switch<D>(simulation<D>&, bool); \
  EXTERN template void conserved_diagnostics<D>(simulation<D>&);         \
  EXTERN template void progress_line<D>(simulation<D>&);                 \
  EXTERN template void run_summary<D>(simulation<D>&);

/// The app frame of run/app.hh: configuration, initial data, self-gravity, output and checkpoints.
#define FLECSPH_SPH_APP_INSTANCES(EXTERN, D)                                              \
  EXTERN template void configure<D>(app_state<D>&, const flecsi_lite::app::run_context&); \
  EXTERN template gravity_record update_gravity<D>(simulation<D>&);                       \
  EXTERN template void detail::write_output_step<D>(app_state<D>&);                       \
  EXTERN template void detail::open_output<D>(app_state<D>&);                             \
  EXTERN template void detail::read_initial_particles<D>(app_state<D>&);                  \
  EXTERN template void detail::restart<D>(app_state<D>&);                                 \
  EXTERN template void detail::describe_particles<D>(app_state<D>&);                      \
  EXTERN template void detail::open_statistics<D>(app_state<D>&);                         \
  EXTERN template void detail::statistics_row<D>(app_state<D>&);                          \
  EXTERN template void detail::check_run_limits<D>(app_state<D>&);                        \
  EXTERN template void detail::checkpoint<D>(app_state<D>&);                              \
  EXTERN template void detail::close_output<D>(app_state<D>&);
