// sod: the Sod (1978) shock tube with the SPH specialization: rho 1 / 0.125, P 1 / 0.1, gamma 1.4
// to t = 0.2 with equal-mass particles and fixed wall particles at both ends; writes H5Part and
// prints the L1 errors against the exact Riemann solution (Toro 2009, ch. 4).
//
//   mpirun -np 2 sod apps/sod/sod_1d.par [--set particles=2000] [--check-l1 0.005,0.005,0.02]
#include "sod_problem.hh"

#include "specialization/sph/driver.hh"
#include "specialization/sph/particle_output.hh"

#include "flecsi_lite/control.hh"
#include "flecsi_lite/io/h5part_writer.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

template<int D>
struct sod_run : sph::simulation<D> {
  sod::problem problem;
  std::string parameters_text;
  std::string output_file;
  double output_every = 0;  ///< simulation time between outputs; 0: first and last step only
  double next_output = 0;
  std::unique_ptr<io::h5part_writer> writer;
  sod::l1_errors errors;
};

flecsi_lite::runtime::parameter_schema make_schema() {
  runtime::parameter_schema schema;
  sod::declare_parameters(schema);
  sph::declare_physics_parameters(schema);
  sph::declare_run_parameters(schema, {0.2, 100, 1, "sod.h5part"});
  return schema;
}

template<int D>
void write_step(sod_run<D>& s) {
  if (!s.writer) return;
  sph::write_particles(*s.writer, s);
  s.next_output = s.output_every > 0 ? s.time + s.output_every : s.run.end_time;
}

template<int D>
void open_output(sod_run<D>& s) {
  if (s.output_file == "none") return;
  s.writer = std::make_unique<io::h5part_writer>(s.output_file);
  s.writer->describe_run({"sod", s.parameters_text, D});
  s.writer->set_attribute("gamma", s.physics.eos.ideal.gamma);
  s.writer->set_attribute("rho_left", s.problem.rho_left);
  s.writer->set_attribute("p_left", s.problem.p_left);
  s.writer->set_attribute("rho_right", s.problem.rho_right);
  s.writer->set_attribute("p_right", s.problem.p_right);
  s.writer->set_attribute("x_interface", s.problem.x_interface);
  s.writer->set_attribute("x_min", s.problem.x_min);
  s.writer->set_attribute("x_max", s.problem.x_max);
  s.writer->set_attribute("ranks", static_cast<std::int64_t>(runtime::size()));
  write_step(s);
}

template<int D>
void output(sod_run<D>& s) {
  if (s.writer && (s.finished || s.time >= s.next_output)) write_step(s);
}

template<int D>
void report(sod_run<D>& s) {
  if (s.writer) {
    s.writer->close();
    log::info() << "sod: wrote " << s.writer->steps_written() << " steps to " << s.output_file;
  }
  s.errors = sod::measure_l1_errors(s, s.problem);
  std::ostringstream line;
  line << std::scientific << std::setprecision(4) << "sod: L1 errors at t = " << s.time << " over "
       << s.errors.count << " particles with |x - " << s.problem.x_interface << "| < " << s.problem.window
       << ": density " << s.errors.rho << ", pressure " << s.errors.P << ", velocity " << s.errors.v;
  log::info() << line.str();
  log::info() << "sod: conserved at t = " << s.time << ": " << sph::describe_conserved(s.totals, s.initial_totals);
}

template<int D>
control::control_model<sod_run<D>> make_control_model() {
  auto m = sph::make_control_model<sod_run<D>>();
  m.action("initial_data", "sod_tube", [](sod_run<D>& s) { sod::create_tube(s, s.problem); });
  m.action("initialize", "open_output", open_output<D>);
  m.action("output", "h5part", output<D>);
  m.action("finalize", "report", report<D>);
  return m;
}

/// "a,b,c" -> three numbers.
std::vector<double> numbers(const std::string& text) {
  std::vector<double> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) values.push_back(std::stod(item));
  return values;
}

/// Exit status 1 when a requested check fails.
template<int D>
int check(const sod_run<D>& s, const runtime::options& opts) {
  bool pass = true;
  if (opts.has("check-l1")) {
    const auto bounds = numbers(opts.get("check-l1"));
    if (bounds.size() != 3) throw std::invalid_argument("--check-l1 takes three numbers: density,pressure,velocity");
    const bool ok = s.errors.count > 0 && s.errors.rho <= bounds[0] && s.errors.P <= bounds[1] &&
                    s.errors.v <= bounds[2];
    if (!ok)
      log::error() << "sod: check failed: L1 errors (" << s.errors.rho << ", " << s.errors.P << ", " << s.errors.v
                   << ") exceed (" << bounds[0] << ", " << bounds[1] << ", " << bounds[2] << ")";
    pass = pass && ok;
  }
  if (opts.has("check-conservation")) {
    const auto bounds = numbers(opts.get("check-conservation"));
    if (bounds.size() != 2) throw std::invalid_argument("--check-conservation takes two numbers: momentum,energy");
    const double momentum = std::fabs(s.totals.momentum[0] - s.initial_totals.momentum[0]);
    const double energy = std::fabs(s.totals.total - s.initial_totals.total) / std::fabs(s.initial_totals.total);
    const bool mass = s.totals.mass == s.initial_totals.mass;
    log::info() << std::scientific << std::setprecision(3) << "sod: momentum change " << momentum
                << ", relative energy change " << energy << ", mass " << (mass ? "exact" : "CHANGED");
    const bool ok = mass && momentum <= bounds[0] && energy <= bounds[1];
    if (!ok) log::error() << "sod: conservation check failed (bounds " << bounds[0] << ", " << bounds[1] << ")";
    pass = pass && ok;
  }
  return pass ? 0 : 1;
}
template<int D>
int run(const runtime::parameters& p, const runtime::options& opts) {
  sod_run<D> s;
  s.problem = sod::problem_from(p);
  s.physics = sph::physics_from(p);
  if (s.physics.eos.type != flecsph::physics::eos_type::ideal_gas)
    throw runtime::parameter_error("sod: the exact solution needs eos = ideal_gas");
  s.run.end_time = p.get<double>("end_time");
  s.run.max_steps = p.get<long>("max_steps");
  s.run.progress_every = p.get<long>("progress_every");
  s.run.diagnostics_every = p.get<long>("diagnostics_every");
  s.output_file = p.get<std::string>("output_file");
  s.output_every = p.get<double>("output_every");
  s.parameters_text = p.resolved_text();
  const int status = make_control_model<D>().execute(s);
  if (status || !runtime::current_settings().control_model_file.empty()) return status;
  return check(s, opts);
}
} // namespace

int main(int argc, char** argv) {
  runtime::options options("The Sod shock tube with SPH: H5Part output and L1 errors against the exact solution.");
  options.positional("parameters", "parameter file (key = value lines); without it, the defaults", false)
    .repeated("set", "KEY=VALUE", "override a parameter (after the file)")
    .flag("parameters-help", "list every parameter key and exit")
    .value("check-l1", "RHO,P,V", "exit with status 1 if an L1 error exceeds its bound")
    .value("check-conservation", "DP,DE",
           "exit with status 1 unless mass is exact, |momentum change| <= DP and |energy change|/E <= DE");
  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  const auto schema = make_schema();
  if (rt.opts().has("parameters-help")) {
    if (runtime::rank() == 0) std::cout << schema.help();
    return 0;
  }
  try {
    const auto p = runtime::parameters::load(schema, rt.opts().get("parameters"), rt.opts().all("set"));
    const int dimension = p.get<int>("dimension");
    return dimension == 1 ? run<1>(p, rt.opts()) : dimension == 2 ? run<2>(p, rt.opts()) : run<3>(p, rt.opts());
  } catch (const runtime::parameter_error& e) {
    log::error() << e.what();
    return 2;
  } catch (const std::exception& e) {
    log::error() << "sod: " << e.what();
    return 3;
  }
}
