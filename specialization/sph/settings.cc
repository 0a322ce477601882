// Parameter-file keys of the SPH physics settings (settings.hh).
#include "specialization/sph/settings.hh"

#include <string>
#include <vector>

namespace flecsph::sph {

void declare_physics_parameters(flecsi_lite::runtime::parameter_schema& schema) {
  const physics_settings d;
  std::vector<std::string> kernels;
  for (const auto type : physics::all_kernel_types) kernels.emplace_back(physics::kernel_name(type));
  schema.choice("kernel", kernels, "smoothing kernel").default_value("cubic_spline");
  schema.choice("eos", {"ideal_gas", "polytropic", "isothermal"}, "equation of state").default_value("ideal_gas");
  schema.real("gamma", "adiabatic index of the ideal gas").default_value(5.0 / 3.0).greater_than(1);
  schema.real("polytropic_constant", "K of the polytrope P = K rho^Gamma").default_value(1.0).greater_than(0);
  schema.real("polytropic_exponent", "Gamma of the polytrope").default_value(2.0).greater_than(1);
  schema.real("isothermal_sound_speed", "sound speed of the isothermal gas").default_value(1.0).greater_than(0);
  schema.real("viscosity_alpha", "alpha of the Monaghan-Gingold viscosity").default_value(d.viscosity.alpha).at_least(0);
  schema.real("viscosity_beta", "beta of the Monaghan-Gingold viscosity").default_value(d.viscosity.beta).at_least(0);
  schema.real("viscosity_epsilon", "epsilon of mu_ab, in units of h^2").default_value(d.viscosity.epsilon).greater_than(0);
  schema.boolean("balsara_switch", "Balsara (1995) switch on the viscosity").default_value(d.balsara);
  schema.real("conductivity_alpha", "alpha_u of the Price (2008) artificial conductivity (0: off)")
    .default_value(d.conductivity).at_least(0);
  schema.boolean("adaptive_smoothing_length", "h = eta (m/rho)^(1/D) with grad-h terms, else h fixed")
    .default_value(d.adaptive_smoothing_length);
  schema.real("eta", "h = eta (m/rho)^(1/D)").default_value(d.eta).greater_than(0);
  schema.real("h_tolerance", "relative residual of the h-rho relation").default_value(d.h_tolerance).greater_than(0);
  schema.integer("h_iterations", "most Newton-Raphson iterations for h").default_value(d.h_iterations).at_least(1);
  schema.real("courant", "Courant factor of the time step").default_value(d.courant).greater_than(0).at_most(1);
  schema.real("acceleration_factor", "dt <= factor sqrt(h/|a|)").default_value(d.acceleration_factor).greater_than(0);
  schema.real("search_margin", "neighbour search reach 2 (1 + margin) h").default_value(d.search_margin).at_least(0);
  schema.real("distribution_skin", "ghosts reach (1 + skin) times the search: distribute when used up")
    .default_value(d.distribution_skin)
    .at_least(0);
}

physics_settings physics_from(const flecsi_lite::runtime::parameters& p) {
  physics_settings s;
  s.kernel = physics::kernel_from_name(p.get<std::string>("kernel"));
  s.eos.type = physics::eos_from_name(p.get<std::string>("eos"));
  s.eos.ideal.gamma = p.get<double>("gamma");
  s.eos.polytrope.polytropic_constant = p.get<double>("polytropic_constant");
  s.eos.polytrope.polytropic_exponent = p.get<double>("polytropic_exponent");
  s.eos.constant_temperature.isothermal_sound_speed = p.get<double>("isothermal_sound_speed");
  s.viscosity.alpha = p.get<double>("viscosity_alpha");
  s.viscosity.beta = p.get<double>("viscosity_beta");
  s.viscosity.epsilon = p.get<double>("viscosity_epsilon");
  s.balsara = p.get<bool>("balsara_switch");
  s.conductivity = p.get<double>("conductivity_alpha");
  s.adaptive_smoothing_length = p.get<bool>("adaptive_smoothing_length");
  s.eta = p.get<double>("eta");
  s.h_tolerance = p.get<double>("h_tolerance");
  s.h_iterations = p.get<int>("h_iterations");
  s.courant = p.get<double>("courant");
  s.acceleration_factor = p.get<double>("acceleration_factor");
  s.search_margin = p.get<double>("search_margin");
  s.distribution_skin = p.get<double>("distribution_skin");
  return s;
}

void declare_run_parameters(flecsi_lite::runtime::parameter_schema& schema, const run_parameter_defaults& defaults) {
  schema.real("end_time", "simulation end time").default_value(defaults.end_time).greater_than(0);
  schema.integer("max_steps", "stop after this many steps (0: no limit)").default_value(0).at_least(0);
  schema.integer("progress_every", "steps between progress lines (0: last only)")
    .default_value(defaults.progress_every)
    .at_least(0);
  schema.integer("diagnostics_every", "steps between conserved-quantity lines (0: first and last)")
    .default_value(defaults.diagnostics_every)
    .at_least(0);
  schema.string("output_file", "H5Part output file (none: no output)").default_value(defaults.output_file);
  schema.real("output_every", "simulation time between outputs (0: first and last step only)")
    .default_value(0.0)
    .at_least(0);
  schema.string("checkpoint_file", "checkpoint (H5Part) for restarts, replaced at each checkpoint")
    .default_value(defaults.checkpoint_file);
  schema.integer("checkpoint_every", "steps between checkpoints (0: none)").default_value(0).at_least(0);
  schema.string("restart_file", "continue the run saved in this checkpoint (none: start at t = 0)")
    .default_value("none");
  schema.string("initial_data", "H5Part file of the initial particles (none: the problem's own)")
    .default_value("none");
  schema.integer("initial_data_step", "Step#k of initial_data to read (-1: the last)").default_value(-1).at_least(-1);
}

run_settings run_settings_from(const flecsi_lite::runtime::parameters& p) {
  run_settings r;
  r.end_time = p.get<double>("end_time");
  r.max_steps = p.get<long>("max_steps");
  r.progress_every = p.get<long>("progress_every");
  r.diagnostics_every = p.get<long>("diagnostics_every");
  return r;
}

io_settings io_settings_from(const flecsi_lite::runtime::parameters& p) {
  io_settings io;
  const auto file = [&p](const char* key) {
    std::string name = p.get<std::string>(key);
    return name == "none" ? std::string() : name;
  };
  io.output_file = file("output_file");
  io.output_every = p.get<double>("output_every");
  io.checkpoint_file = file("checkpoint_file");
  io.checkpoint_every = p.get<long>("checkpoint_every");
  io.restart_file = file("restart_file");
  io.initial_data = file("initial_data");
  io.initial_data_step = p.get<long>("initial_data_step");
  if (!io.restart_file.empty() && !io.initial_data.empty())
    throw flecsi_lite::runtime::parameter_error("restart_file and initial_data are both set: a restart continues "
                                                "the checkpoint's particles; set only one of them");
  if (io.checkpoint_every > 0 && io.checkpoint_file.empty())
    throw flecsi_lite::runtime::parameter_error("checkpoint_every = " + std::to_string(io.checkpoint_every) +
                                                " needs a checkpoint_file (it is none)");
  return io;
}

} // namespace flecsph::sph
