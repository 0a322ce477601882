// Parameter-file keys of the SPH physics and run-control settings (settings.hh), each declared
// once: name, member, bounds and help; the defaults are the structs' own. The upper bounds of the
// numerical keys are far beyond any useful value: they keep absurd input from overflowing.
#include "specialization/sph/model/settings.hh"

#include <cmath>
#include <sstream>
#include <string>

namespace flecsph::sph {

namespace {
using flecsi_lite::runtime::member;
using flecsi_lite::runtime::parameter_block;
using physics::equation_of_state;
using physics::viscosity_parameters;
using physics_block = parameter_block<physics_settings>;

physics_block declare_physics(const physics_settings& defaults) {
  physics_block p(defaults);
  p.choice("kernel", &physics_settings::kernel, physics::kernel_names(), "smoothing kernel");
  p.choice("eos", member(&physics_settings::eos, &equation_of_state::type), physics::eos_names(), "equation of state");
  p.choice("formulation", &physics_settings::equations, formulation_names(),
           "SPH forces: density_energy (P = (gamma-1) rho u per particle) or pressure_energy (smoothed P_bar, "
           "Hopkins 2013: no pressure blip at contacts; ideal gas without gravity)");
  p.real("gamma", member(&physics_settings::eos, &equation_of_state::ideal, &physics::ideal_gas::gamma),
         "adiabatic index of the ideal gas")
    .greater_than(1);
  p.real("polytropic_constant",
         member(&physics_settings::eos, &equation_of_state::polytrope, &physics::polytropic::polytropic_constant),
         "K of the polytrope P = K rho^Gamma")
    .greater_than(0);
  p.real("polytropic_exponent",
         member(&physics_settings::eos, &equation_of_state::polytrope, &physics::polytropic::polytropic_exponent),
         "Gamma of the polytrope")
    .greater_than(1);
  p.real("isothermal_sound_speed",
         member(&physics_settings::eos, &equation_of_state::constant_temperature,
                &physics::isothermal::isothermal_sound_speed),
         "sound speed of the isothermal gas")
    .greater_than(0);
  p.real("viscosity_alpha", member(&physics_settings::viscosity, &viscosity_parameters::alpha),
         "alpha of the Monaghan-Gingold viscosity")
    .range(0, 100);
  p.real("viscosity_beta", member(&physics_settings::viscosity, &viscosity_parameters::beta),
         "beta of the Monaghan-Gingold viscosity")
    .range(0, 100);
  p.real("viscosity_epsilon", member(&physics_settings::viscosity, &viscosity_parameters::epsilon),
         "epsilon of mu_ab, in units of h^2")
    .greater_than(0)
    .at_most(1);
  p.boolean("balsara_switch", &physics_settings::balsara, "Balsara (1995) switch on the viscosity");
  using physics::viscosity_switch_settings;
  p.boolean("viscosity_switch", member(&physics_settings::viscosity_switch, &viscosity_switch_settings::enabled),
            "Cullen & Dehnen (2010) time-dependent alpha per particle (off: constant viscosity_alpha)");
  p.real("viscosity_alpha_min", member(&physics_settings::viscosity_switch, &viscosity_switch_settings::alpha_min),
         "viscosity switch: the smallest alpha")
    .range(0, 100);
  p.real("viscosity_alpha_max", member(&physics_settings::viscosity_switch, &viscosity_switch_settings::alpha_max),
         "viscosity switch: the largest alpha (and the alpha at t = 0 unless viscosity_switch_start = alpha_min)")
    .range(0, 100);
  p.real("viscosity_decay_length",
         member(&physics_settings::viscosity_switch, &viscosity_switch_settings::decay_length),
         "viscosity switch: l of the decay time h_support / (2 l v_signal)")
    .greater_than(0)
    .at_most(10);
  p.choice("viscosity_switch_rate", member(&physics_settings::viscosity_switch, &viscosity_switch_settings::rate),
           divergence_rate_names(),
           "viscosity switch: d(div v)/dt from the accelerations (CD10, Phantom) or the difference of div v "
           "between updates (SPHENIX)");
  p.choice("viscosity_switch_form", member(&physics_settings::viscosity_switch, &viscosity_switch_settings::form),
           local_alpha_form_names(),
           "viscosity switch: alpha_loc = min(10 h^2 A / c^2, alpha_max) (price: Price et al. 2018) or "
           "alpha_max H^2 A / (v_sig^2 + H^2 A) (cullen_dehnen: CD10 eq. 13)");
  p.choice("viscosity_switch_start", member(&physics_settings::viscosity_switch, &viscosity_switch_settings::start),
           initial_alpha_names(),
           "viscosity switch: alpha at the start of a run, alpha_max (a shock at t = 0) or alpha_min (Phantom: a "
           "smooth flow is not damped while alpha decays)");
  p.real("conductivity_alpha", &physics_settings::conductivity,
         "alpha_u of the Price (2008) artificial conductivity (0: off)")
    .range(0, 100);
  p.boolean("adaptive_smoothing_length", &physics_settings::adaptive_smoothing_length,
            "h = eta (m/rho)^(1/D) with grad-h terms, else h fixed");
  p.real("eta", &physics_settings::eta, "h = eta (m/rho)^(1/D)").greater_than(0).at_most(10);
  p.real("h_tolerance", &physics_settings::h_tolerance, "relative residual of the h-rho relation")
    .greater_than(0)
    .at_most(0.1);
  p.integer("h_iterations", &physics_settings::h_iterations, "most Newton-Raphson iterations for h").range(1, 10000);
  p.real("courant", &physics_settings::courant, "Courant factor of the time step").greater_than(0).at_most(1);
  p.real("acceleration_factor", &physics_settings::acceleration_factor, "dt <= factor sqrt(h/|a|)")
    .greater_than(0)
    .at_most(10);
  p.real("search_margin", &physics_settings::search_margin, "neighbour search reach 2 (1 + margin) h").range(0, 10);
  p.real("distribution_skin", &physics_settings::distribution_skin,
         "ghosts reach (1 + skin) times the search: distribute when used up")
    .range(0, 10);
  p.real("list_skin", &physics_settings::list_skin,
         "neighbour lists reach (1 + skin) times the search: search again when used up")
    .range(0, 10);
  p.choice("neighbour_lists", &physics_settings::neighbour_lists, neighbour_list_names(),
           "neighbour lists as runs (about a third of the memory) or packed (a few percent faster)");
  p.choice("key_order", &physics_settings::key_order, key_order_names(),
           "space-filling curve of the distribution (hilbert: compact domains, fewer ghosts)");
  p.choice("balance", &physics_settings::balance, balance_names(),
           "distribute equal particle counts, or equal work (neighbours at the last search)");
  p.boolean("gravity", member(&physics_settings::gravity, &gravity_settings::enabled),
            "self-gravity softened with the kernel (Price & Monaghan 2007), 3D without periodic axes");
  p.real("gravitational_constant", member(&physics_settings::gravity, &gravity_settings::constant),
         "G of the self-gravity")
    .greater_than(0)
    .at_most(1e50);
  p.real("gravity_theta", member(&physics_settings::gravity, &gravity_settings::theta),
         "opening angle of the gravity tree (Barnes-Hut)")
    .greater_than(0)
    .at_most(1.5);
  p.choice("gravity_criterion", member(&physics_settings::gravity, &gravity_settings::criterion),
           gravity_criterion_names(), "opening criterion: theta alone, or GADGET-2's relative one as well");
  p.real("gravity_relative_tolerance", member(&physics_settings::gravity, &gravity_settings::relative_tolerance),
         "alpha of the relative criterion (force error relative to the last |a|)")
    .greater_than(0)
    .at_most(1);
  p.boolean("gravity_grad_h", member(&physics_settings::gravity, &gravity_settings::grad_h),
            "grad-h gravity term of Price & Monaghan (2007) (off only to measure its effect)");
  p.choice("time_steps", member(&physics_settings::time_steps, &time_step_settings::stepping), time_stepping_names(),
           "one step for all particles, or each particle its own (block time steps)");
  p.integer("time_step_limiter", member(&physics_settings::time_steps, &time_step_settings::limiter),
            "individual steps: largest ratio of a particle's step to its neighbours' (power of two; 0: off)")
    .range(0, 1 << 20);
  p.real("max_time_step", member(&physics_settings::time_steps, &time_step_settings::max_time_step),
         "individual steps: the largest step (0: the run's span)")
    .range(0, 1e50);
  p.check([](const physics_settings& s) {
    if (s.individual_time_steps() && s.list_skin > 0)
      throw flecsi_lite::runtime::parameter_error(
        "list_skin = " + std::to_string(s.list_skin) +
        " with time_steps = individual: individual steps search the active particles of every step (their lists "
        "only), so lists are never kept; set list_skin = 0");
    if (s.viscosity_switch.enabled) {
      const auto& w = s.viscosity_switch;
      if (s.balsara)
        throw flecsi_lite::runtime::parameter_error(
          "viscosity_switch = on with balsara_switch = on: the Cullen & Dehnen switch has its own limiter against "
          "shear (which replaces Balsara's factor); set balsara_switch = off");
      if (w.alpha_min > w.alpha_max)
        throw flecsi_lite::runtime::parameter_error("viscosity_alpha_min = " + std::to_string(w.alpha_min) +
                                                    " exceeds viscosity_alpha_max = " + std::to_string(w.alpha_max));
      if (!(s.viscosity.alpha > 0))
        throw flecsi_lite::runtime::parameter_error(
          "viscosity_alpha = 0 with viscosity_switch = on: the switch keeps beta / viscosity_alpha as its ratio of "
          "beta to alpha, so viscosity_alpha must be > 0");
    }
    if (s.pressure_energy() && s.eos.type != physics::eos_type::ideal_gas)
      throw flecsi_lite::runtime::parameter_error(
        "formulation = pressure_energy with eos = " + std::string(physics::eos_name(s.eos.type)) +
        ": the smoothed pressure P_bar = (gamma-1) sum_b m_b u_b W_ab weighs the neighbours' internal energies, "
        "which only an ideal gas has; set eos = ideal_gas or formulation = density_energy");
    if (s.pressure_energy() && s.gravity.enabled)
      throw flecsi_lite::runtime::parameter_error(
        "formulation = pressure_energy with gravity = on: the grad-h gravity term and the force pass with "
        "gravity exist for density_energy only; set formulation = density_energy or gravity = off");
    const int v = s.time_steps.limiter;
    if (v != 0 && (v < 2 || (v & (v - 1)) != 0))
      throw flecsi_lite::runtime::parameter_error("time_step_limiter = " + std::to_string(v) +
                                                  " must be 0 (off) or a power of two >= 2 (2, 4, 8, ...)");
  });
  return p;
}
}  // namespace

const flecsi_lite::runtime::name_table<formulation>& formulation_names() {
  static const flecsi_lite::runtime::name_table<formulation> table{
    "formulation",
    {{"density_energy", formulation::density_energy}, {"pressure_energy", formulation::pressure_energy}}};
  return table;
}

const flecsi_lite::runtime::name_table<time_stepping>& time_stepping_names() {
  static const flecsi_lite::runtime::name_table<time_stepping> table{
    "time stepping", {{"global", time_stepping::global}, {"individual", time_stepping::individual}}};
  return table;
}

const flecsi_lite::runtime::name_table<physics::divergence_rate_estimate>& divergence_rate_names() {
  using physics::divergence_rate_estimate;
  static const flecsi_lite::runtime::name_table<divergence_rate_estimate> table{
    "divergence rate estimate",
    {{"acceleration", divergence_rate_estimate::acceleration}, {"difference", divergence_rate_estimate::difference}}};
  return table;
}

const flecsi_lite::runtime::name_table<physics::local_alpha_form>& local_alpha_form_names() {
  using physics::local_alpha_form;
  static const flecsi_lite::runtime::name_table<local_alpha_form> table{
    "alpha_loc form", {{"price", local_alpha_form::price}, {"cullen_dehnen", local_alpha_form::cullen_dehnen}}};
  return table;
}

const flecsi_lite::runtime::name_table<physics::initial_alpha>& initial_alpha_names() {
  using physics::initial_alpha;
  static const flecsi_lite::runtime::name_table<initial_alpha> table{
    "starting alpha", {{"alpha_max", initial_alpha::alpha_max}, {"alpha_min", initial_alpha::alpha_min}}};
  return table;
}

const flecsi_lite::runtime::name_table<gravity_criterion>& gravity_criterion_names() {
  static const flecsi_lite::runtime::name_table<gravity_criterion> table{
    "gravity criterion", {{"geometric", gravity_criterion::geometric}, {"relative", gravity_criterion::relative}}};
  return table;
}

const flecsi_lite::runtime::name_table<flecsi_lite::topology::ntree::curve>& key_order_names() {
  using flecsi_lite::topology::ntree::curve;
  static const flecsi_lite::runtime::name_table<curve> table{"key order",
                                                             {{"hilbert", curve::hilbert}, {"morton", curve::morton}}};
  return table;
}

const flecsi_lite::runtime::name_table<flecsi_lite::topology::ntree::balance>& balance_names() {
  using flecsi_lite::topology::ntree::balance;
  static const flecsi_lite::runtime::name_table<balance> table{"balance",
                                                               {{"count", balance::count}, {"work", balance::work}}};
  return table;
}

const flecsi_lite::runtime::name_table<flecsi_lite::topology::ntree::shift_storage>& neighbour_list_names() {
  using flecsi_lite::topology::ntree::shift_storage;
  static const flecsi_lite::runtime::name_table<shift_storage> table{
    "neighbour lists", {{"runs", shift_storage::runs}, {"packed", shift_storage::packed}}};
  return table;
}

parameter_block<physics_settings> physics_parameters(const physics_settings& defaults) {
  return declare_physics(defaults);
}

parameter_block<run_settings> run_parameters(const run_settings& defaults) {
  parameter_block<run_settings> run(defaults);
  run.real("end_time", &run_settings::end_time, "simulation end time").greater_than(0);
  run.integer("max_steps", &run_settings::max_steps, "stop after this many steps (0: no limit)").at_least(0);
  run.integer("progress_every", &run_settings::progress_every, "steps between progress lines (0: last only)")
    .at_least(0);
  run
    .integer("diagnostics_every", &run_settings::diagnostics_every,
             "steps between conserved-quantity lines (0: first and last)")
    .at_least(0);
  return run;
}

}  // namespace flecsph::sph
