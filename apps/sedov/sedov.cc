// sedov: the Sedov-Taylor blast wave (energy 1 at the centre of a uniform cold medium, gamma 5/3)
// in 2D or 3D with the SPH specialization; writes H5Part and compares the shock radius and the
// energy with the similarity solution (Sedov 1959; Kamm & Timmes 2007).
//
//   mpirun -np 2 sedov apps/sedov/sedov_3d.par [--set particles_per_side=64] [--check 0.05,1e-3]
#include "sedov_problem.hh"

#include "specialization/sph/driver.hh"
#include "specialization/sph/particle_output.hh"

#include "flecsi_lite/control.hh"
#include "flecsi_lite/io/h5part_writer.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

template<int D>
struct sedov_run : sph::simulation<D> {
  sedov::problem problem;
  std::string parameters_text, output_file;
  double output_every = 0, next_output = 0;
  std::unique_ptr<io::h5part_writer> writer;
  sedov::blast_comparison blast;
};

runtime::parameter_schema make_schema() {
  runtime::parameter_schema schema;
  sedov::declare_parameters(schema);
  sph::declare_physics_parameters(schema);
  sph::declare_run_parameters(schema, {0.05, 10, 10, "sedov.h5part"});
  return schema;
}

template<int D>
void write_step(sedov_run<D>& s) {
  if (!s.writer) return;
  sph::write_particles(*s.writer, s);
  s.next_output = s.output_every > 0 ? s.time + s.output_every : s.run.end_time;
}

template<int D>
void open_output(sedov_run<D>& s) {
  if (s.output_file == "none") return;
  s.writer = std::make_unique<io::h5part_writer>(s.output_file);
  s.writer->describe_run({"sedov", s.parameters_text, D});
  s.writer->set_attribute("gamma", s.physics.eos.ideal.gamma);
  s.writer->set_attribute("blast_energy", s.problem.energy);
  s.writer->set_attribute("rho0", s.problem.rho0);
  s.writer->set_attribute("ranks", static_cast<std::int64_t>(runtime::size()));
  write_step(s);
}

template<int D>
void report(sedov_run<D>& s) {
  if (s.writer) {
    s.writer->close();
    log::info() << "sedov: wrote " << s.writer->steps_written() << " steps to " << s.output_file;
  }
  s.blast = sedov::compare_with_sedov_taylor(s, s.problem);
  std::ostringstream line;
  line << std::setprecision(4) << "sedov: at t = " << s.time << " the shock front (half height) is at r = "
       << s.blast.front_radius << ", Sedov-Taylor shock radius " << s.blast.shock_radius << ", relative difference "
       << s.blast.relative_error() << "; the density peaks at r = " << s.blast.peak_radius << " (mean "
       << s.blast.peak_density << "; strong shock " << s.blast.analytic_peak << "); relative energy change "
       << (s.totals.total - s.initial_totals.total) / s.initial_totals.total;
  log::info() << line.str();
}

template<int D>
int run(const runtime::parameters& p, const runtime::options& opts) {
  sedov_run<D> s;
  s.problem = sedov::problem_from(p);
  s.physics = sph::physics_from(p);
  if (s.physics.eos.type != flecsph::physics::eos_type::ideal_gas)
    throw runtime::parameter_error("sedov: the similarity solution needs eos = ideal_gas");
  s.run.end_time = p.get<double>("end_time");
  s.run.max_steps = p.get<long>("max_steps");
  s.run.progress_every = p.get<long>("progress_every");
  s.run.diagnostics_every = p.get<long>("diagnostics_every");
  s.output_file = p.get<std::string>("output_file");
  s.output_every = p.get<double>("output_every");
  s.parameters_text = p.resolved_text();

  auto m = sph::make_control_model<sedov_run<D>>();
  m.action("initial_data", "lattice", [](sedov_run<D>& state) { sedov::create_lattice(state, state.problem); });
  m.action("initialize", "open_output", open_output<D>);
  m.action("output", "h5part", [](sedov_run<D>& state) {
    if (state.writer && (state.finished || state.time >= state.next_output)) write_step(state);
  });
  m.action("finalize", "report", report<D>);
  const int status = m.execute(s);
  if (status || !runtime::current_settings().control_model_file.empty() || !opts.has("check")) return status;
  std::stringstream bounds(opts.get("check"));
  double radius_bound = 0, energy_bound = 0;
  char comma = 0;
  if (!(bounds >> radius_bound >> comma >> energy_bound) || comma != ',')
    throw std::invalid_argument("--check takes two numbers: radius,energy");
  const double energy = std::fabs(s.totals.total - s.initial_totals.total) / s.initial_totals.total;
  const bool pass = std::fabs(s.blast.relative_error()) <= radius_bound && energy <= energy_bound;
  if (!pass) log::error() << "sedov: check failed (bounds: radius " << radius_bound << ", energy " << energy_bound << ")";
  return pass ? 0 : 1;
}
} // namespace

int main(int argc, char** argv) {
  runtime::options options("The Sedov-Taylor blast wave with SPH: H5Part output and the shock radius against the "
                           "similarity solution.");
  options.positional("parameters", "parameter file (key = value lines); without it, the defaults", false)
    .repeated("set", "KEY=VALUE", "override a parameter (after the file)")
    .flag("parameters-help", "list every parameter key and exit")
    .value("check", "DR,DE", "exit with status 1 unless |shock radius error| <= DR and |energy change|/E <= DE");
  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  const auto schema = make_schema();
  if (rt.opts().has("parameters-help")) {
    if (runtime::rank() == 0) std::cout << schema.help();
    return 0;
  }
  try {
    const auto p = runtime::parameters::load(schema, rt.opts().get("parameters"), rt.opts().all("set"));
    return p.get<int>("dimension") == 2 ? run<2>(p, rt.opts()) : run<3>(p, rt.opts());
  } catch (const runtime::parameter_error& e) {
    log::error() << e.what();
    return 2;
  } catch (const std::exception& e) {
    log::error() << "sedov: " << e.what();
    return 3;
  }
}
