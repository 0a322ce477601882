// fluid: weakly compressible SPH for liquids (Tait EOS, continuity density with delta-SPH, laminar
// or artificial viscosity, gravity, Adami et al. 2012 dummy walls) on four 2D problems: a still
// tank, Poiseuille and Couette flow against their series solutions, and the dam break of Martin &
// Moyce (1952) against the experiment's surge front (martin_moyce_1952.txt), also in 3D
// (dimension = 3: the column spans a tank periodic along z).
//
//   mpirun -np 2 fluid apps/fluid/dam_break.par [--set particles=50] [--check-dam-break 0.1,0.01]
#include "fluid_problem.hh"
#include "martin_moyce.hh"

#include "specialization/analytic.hh"
#include "specialization/fluid.hh"
#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"
#include "flecsi_lite/util.hh"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;
namespace fl = flecsph::fluid;
using fluid_app::problem_type;

/// One row of the run's series (every analyze step).
struct sample_row {
  double t, front, energy, density_deviation, speed, channel_error;
};

template<int D>
struct fluid_run : fl::fluid_state<D> {
  fluid_app::problem problem;
  fluid_app::layout layout;
  std::vector<sample_row> series;
  std::vector<double> check_times;                        ///< channels: when the transient is compared
  std::vector<std::pair<double, double>> channel_errors;  ///< (t, max |v - v_exact| / v_max)
  double min_x = std::numeric_limits<double>::max(), max_x = -std::numeric_limits<double>::max();
  double min_y = std::numeric_limits<double>::max();
  double bottom_pressure = 0;  ///< at the end: mean P + rho0 |g| y over the lowest fluid row
  fl::gauge_settings gauge_keys;
  std::vector<std::vector<sph::vector<D>>> gauge_points;  ///< each gauge's samples (code units)
  fl::gauge_file gauges;
};

/// What the measuring task sums and bounds over the fluid particles.
struct sample {
  double min_x = std::numeric_limits<double>::max(), max_x = -std::numeric_limits<double>::max();
  double min_y = std::numeric_limits<double>::max();
  double speed = 0, density_deviation = 0, channel_error = 0;
  util::exact_sum energy, bottom_pressure, bottom_count;
};
struct sample_reduction {
  static sample combine(sample a, const sample& b) {
    a.min_x = std::min(a.min_x, b.min_x), a.max_x = std::max(a.max_x, b.max_x), a.min_y = std::min(a.min_y, b.min_y);
    a.speed = std::max(a.speed, b.speed);
    a.density_deviation = std::max(a.density_deviation, b.density_deviation);
    a.channel_error = std::max(a.channel_error, b.channel_error);
    a.energy += b.energy, a.bottom_pressure += b.bottom_pressure, a.bottom_count += b.bottom_count;
    return a;
  }
};

/// The inputs of the measurement that are not fields.
struct sample_input {
  problem_type type;
  double time, length, dx, lid_velocity;
  fl::fluid_settings fluid;
};

/// Exact velocity of the channel problems at (y, t); 0 for the others.
double exact_velocity(const sample_input& in, double y) {
  const double nu = in.fluid.kinematic_viscosity();
  if (in.type == problem_type::poiseuille)
    return flecsph::analytic::poiseuille_velocity(y, in.time, in.length, in.fluid.body_force[0], nu);
  if (in.type == problem_type::couette)
    return flecsph::analytic::couette_velocity(y, in.time, in.length, in.lid_velocity, nu);
  return 0;
}

/// Elastic energy per unit mass of the Tait liquid, int_rho0^rho P / rho^2 (P_b = 0 part).
double elastic_energy(const flecsph::physics::tait& eos, double rho) {
  const double x = rho / eos.reference_density;
  return eos.stiffness() / eos.reference_density * ((std::pow(x, 6) - 1) / 6 + (1 / x - 1));
}

template<int D>
sample measure_task(sample_input in, sph::ro<sph::vector<D>> x, sph::ro<sph::vector<D>> v, sph::ro<double> m,
                    sph::ro<double> rho, sph::ro<double> P, sph::ro<sph::particle_kind> kind) {
  sample s;
  const double rho0 = in.fluid.eos.reference_density, g = -in.fluid.body_force[1];
  for (std::size_t a = 0; a < x.size(); ++a) {
    if (kind(a) != sph::particle_kind::fluid) continue;
    const auto& p = x(a);
    s.min_x = std::min(s.min_x, p[0]), s.max_x = std::max(s.max_x, p[0]), s.min_y = std::min(s.min_y, p[1]);
    double v2 = 0, gx = 0;
    for (int k = 0; k < D; ++k) v2 += v(a)[k] * v(a)[k], gx += in.fluid.body_force[k] * p[k];
    s.speed = std::max(s.speed, std::sqrt(v2));
    s.density_deviation = std::max(s.density_deviation, std::fabs(rho(a) / rho0 - 1));
    s.energy.add(m(a) * (0.5 * v2 - gx + elastic_energy(in.fluid.eos, rho(a))));
    if (p[1] < in.dx) {
      s.bottom_pressure.add(P(a) + rho0 * g * p[1]);
      s.bottom_count.add(1.0);
    }
    if (in.type == problem_type::poiseuille || in.type == problem_type::couette)
      s.channel_error = std::max(s.channel_error, std::fabs(v(a)[0] - exact_velocity(in, p[1])));
  }
  return s;
}

template<int D>
double channel_speed_scale(const fluid_run<D>& s) {
  return s.layout.speed_scale;
}

/// The surge front (surge_front.hh): the largest x of a fluid particle at most front_height above
/// the floor with at least two fluid neighbours within 2 dx, plus dx/2; NaN when none qualifies.
template<int D>
double surge_front(fluid_run<D>& s) {
  using f = sph::fields<D>;
  auto& p = *s.particles;
  const fl::surge_front_settings settings{s.layout.tank_lo[1], s.gauge_keys.front_height * s.problem.length,
                                          2 * s.layout.dx};
  const double x =
    reduce<fl::surge_front_task<D>, reduction::max>(s.neighbours, settings, f::position()(p), f::kind(p)).get();
  return x > -std::numeric_limits<double>::max() ? x + 0.5 * s.layout.dx : std::numeric_limits<double>::quiet_NaN();
}

template<int D>
void measure(fluid_run<D>& s) {
  using f = sph::fields<D>;
  auto& p = *s.particles;
  const sample_input in{s.problem.type, s.time, s.problem.length, s.layout.dx, s.problem.lid_velocity, s.fluid};
  const sample r = reduce<measure_task<D>, sample_reduction>(in, f::position()(p), f::velocity(p), f::mass()(p),
                                                             f::density(p), f::pressure(p), f::kind(p))
                     .get();
  const double error = r.channel_error / channel_speed_scale(s);
  s.series.push_back({s.time, surge_front(s), r.energy.value(), r.density_deviation, r.speed, error});
  s.min_x = std::min(s.min_x, r.min_x), s.max_x = std::max(s.max_x, r.max_x), s.min_y = std::min(s.min_y, r.min_y);
  s.bottom_pressure = r.bottom_count.value() > 0 ? r.bottom_pressure.value() / r.bottom_count.value() : 0;
  // Channels: the first step at or after each check time (compared with the series at that time).
  while (!s.check_times.empty() && s.time >= s.check_times.front() * (1 - 1e-12)) {
    s.channel_errors.push_back({s.time, error});
    s.check_times.erase(s.check_times.begin());
  }
}

template<int D>
void set_domain(fluid_run<D>& s) {
  const auto& l = s.layout;
  const double margin = double(l.layers + 2) * l.dx;
  sph::tree::box<D> box;
  if constexpr (D == 3) {
    // The 3D dam break: periodic along the span z, the box around the tank and its walls (the
    // water stays below the column's height 2 L, inside the tank 3 L high, to T = 2.8).
    box.lo = {l.tank_lo[0] - margin, l.tank_lo[1] - margin, l.tank_lo[2]};
    box.hi = {l.tank_hi[0] + margin, l.tank_hi[1] + margin, l.tank_hi[2]};
    s.tree_settings.fixed_box = box;
    s.tree_settings.periodic = {false, false, true};
  } else {
    if (!l.periodic_x) return;  // the tank: the box follows the particles
    box.lo = {l.tank_lo[0], l.tank_lo[1] - margin};
    box.hi = {l.tank_hi[0], l.tank_hi[1] + margin};
    s.tree_settings.fixed_box = box;
    s.tree_settings.periodic = {true, false};
  }
}

template<int D>
void set_wall_velocities(const std::vector<sph::vector<D>>& values, sph::wo<sph::vector<D>> wall_velocity) {
  for (std::size_t a = 0; a < wall_velocity.size(); ++a) wall_velocity(a) = values[a];
}

template<int D>
void create(fluid_run<D>& s) {
  set_domain(s);
  const auto all = fluid_app::particles_of(s.problem, s.layout, s.fluid);
  const auto block = io::block_slice(all.size(), runtime::rank(), runtime::size());
  sph::create_particles(s, block.count);
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<D>& p) {
    const auto& q = all[block.offset + i];
    for (int k = 0; k < D; ++k) p.x[k] = q.x[k];
    p.id = block.offset + i;
    p.m = q.m;
    p.h = s.layout.h;
    p.kind = q.wall ? sph::particle_kind::wall : sph::particle_kind::fluid;
    p.rho = q.rho;
  });
  std::vector<sph::vector<D>> walls(block.count);
  for (std::size_t i = 0; i < block.count; ++i)
    for (int k = 0; k < D; ++k) walls[i][k] = all[block.offset + i].wall_velocity[k];
  execute<set_wall_velocities<D>>(walls, fl::fluid_fields<D>::wall_velocity(*s.particles)).wait();
}

/// The samples of every gauge: the faces of the key `gauges` scaled by the reference length; a
/// face on or beyond a wall is moved onto the wall's surface (the tank's inner box), where the
/// sensors of an experiment sit. 3D: at the middle of the span.
template<int D>
void place_gauges(fluid_run<D>& s) {
  const auto& l = s.layout;
  const auto onto_tank = [&](std::array<double, 2> q) {
    for (int k = 0; k < 2; ++k) q[k] *= s.problem.length;
    if (!l.periodic_x) q[0] = std::clamp(q[0], l.tank_lo[0], l.tank_hi[0]);
    q[1] = std::clamp(q[1], l.tank_lo[1], l.periodic_x ? l.tank_hi[1] : std::numeric_limits<double>::max());
    return q;
  };
  for (const auto& face : s.gauge_keys.faces())
    s.gauge_points.push_back(
      fl::gauge_samples<D>(onto_tank(face.first), onto_tank(face.last), s.gauge_keys.samples, 0.5 * l.tank_hi[2]));
}

/// One row of the gauge file: step, t, the surge front (surge_front.hh), each gauge's P and v.
template<int D>
std::string gauge_row(fluid_run<D>& s) {
  const double front = surge_front(s);
  const auto readings = fl::read_gauges<D>(s, s.gauge_points, s.gauge_keys.smoothing);
  std::ostringstream row;
  row << std::setprecision(12) << s.step << "," << s.time << ",";
  if (std::isfinite(front))
    row << front;
  else
    row << "nan";
  for (const auto& r : readings) {
    row << "," << r.pressure;
    for (int k = 0; k < D; ++k) row << "," << r.velocity[k];
  }
  return row.str();
}

/// Opens the gauge file (a restart continues it) and writes the first row of a new run.
template<int D>
void open_gauges(fluid_run<D>& s) {
  if (s.gauge_keys.file.empty()) return;
  place_gauges(s);
  std::ostringstream header;
  header << std::setprecision(6) << "# " << s.program << " gauges, " << fluid_app::problem_names().name(s.problem.type)
         << ": length " << s.problem.length << " m, dx " << s.layout.dx << " m, rho0 " << s.fluid.eos.reference_density
         << ", g " << std::fabs(s.fluid.body_force[1]) << "\n"
         << "# front_x: the largest x of a fluid particle at most " << s.gauge_keys.front_height * s.problem.length
         << " m above the floor with at least two fluid neighbours within 2 dx, plus dx/2 (m)\n";
  for (std::size_t g = 0; g < s.gauge_points.size(); ++g) {
    const auto& q = s.gauge_points[g];
    header << "# gauge " << g + 1 << ": " << q.size() << " samples from (" << q.front()[0] << ", " << q.front()[1]
           << ") to (" << q.back()[0] << ", " << q.back()[1] << ") m; p_" << g + 1
           << " the mean Shepard-interpolated pressure (Pa; dry samples 0), v its velocity (m/s)";
    if (s.gauge_keys.smoothing != 1) header << "; smoothing length " << s.gauge_keys.smoothing << " h";
    header << "\n";
  }
  header << "# step,t,front_x";
  const char* axes[] = {"vx", "vy", "vz"};
  for (std::size_t g = 0; g < s.gauge_points.size(); ++g) {
    header << ",p_" << g + 1;
    for (int k = 0; k < D; ++k) header << "," << axes[k] << "_" << g + 1;
  }
  header << "\n";
  s.gauges.open(s.gauge_keys.file, header.str(), s.restarted ? std::optional<long>(s.step) : std::nullopt);
  if (!s.restarted) s.gauges.write(gauge_row(s));
}

template<int D>
void write_gauges(fluid_run<D>& s) {
  if (s.gauges.is_open() && s.step % s.gauge_keys.every == 0) s.gauges.write(gauge_row(s));
}

/// The surge front Z/L (surge_front.hh) at time T = t sqrt(2 g / L), interpolated in time.
template<int D>
double front_at(const fluid_run<D>& s, double T) {
  const double scale = std::sqrt(-2 * s.fluid.body_force[1] / s.problem.length);
  for (std::size_t i = 1; i < s.series.size(); ++i) {
    const double T0 = s.series[i - 1].t * scale, T1 = s.series[i].t * scale;
    if (T1 >= T) {
      const double w = T1 > T0 ? (T - T0) / (T1 - T0) : 1;
      const double z = (1 - w) * s.series[i - 1].front + w * s.series[i].front;
      return z / s.problem.length;
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

struct dam_break_result {
  double mean_error = 0, max_error = 0;
  int points = 0;
  double largest_rise = 0;  ///< largest increase of the mechanical energy between samples, over |E0|
};

template<int D>
dam_break_result dam_break_errors(const fluid_run<D>& s) {
  dam_break_result r;
  for (const auto& point : fluid_app::martin_moyce_front()) {
    if (point.T < 1 || point.T > 2.8) continue;
    const double z = front_at(s, point.T);
    if (!std::isfinite(z)) continue;
    const double e = std::fabs(z - point.Z) / point.Z;
    r.mean_error += e, r.max_error = std::max(r.max_error, e), ++r.points;
  }
  if (r.points) r.mean_error /= r.points;
  const double E0 = std::fabs(s.series.front().energy);
  for (std::size_t i = 1; i < s.series.size(); ++i)
    r.largest_rise = std::max(r.largest_rise, (s.series[i].energy - s.series[i - 1].energy) / E0);
  return r;
}

template<int D>
double largest_density_deviation(const fluid_run<D>& s) {
  double d = 0;
  for (const auto& row : s.series) d = std::max(d, row.density_deviation);
  return d;
}

template<int D>
void report(fluid_run<D>& s) {
  std::ostringstream line;
  line << std::scientific << std::setprecision(4) << s.program << ": "
       << fluid_app::problem_names().name(s.problem.type) << " at t = " << s.time << ", dx = " << s.layout.dx
       << ", largest |rho/rho0 - 1| " << largest_density_deviation(s) << ", largest speed " << s.series.back().speed;
  const double g = std::fabs(s.fluid.body_force[1]);
  switch (s.problem.type) {
    case problem_type::still_tank:
      line << " = " << s.series.back().speed / std::sqrt(g * s.problem.length) << " sqrt(g H); bottom pressure "
           << s.bottom_pressure << " = " << s.bottom_pressure / (s.fluid.eos.reference_density * g * s.problem.length)
           << " rho0 g H; fluid within x [" << s.min_x << ", " << s.max_x << "], y >= " << s.min_y;
      break;
    case problem_type::poiseuille:
    case problem_type::couette:
      for (const auto& [t, e] : s.channel_errors)
        line << "; at t = " << t << " (" << t * s.fluid.kinematic_viscosity() / (s.problem.length * s.problem.length)
             << " L^2/nu) max |v - v_exact| = " << e << " v_max";
      break;
    case problem_type::dam_break: {
      if (s.problem.column_width != 1 || s.problem.column_height != 2) {
        line << "; surge front " << s.series.back().front << " (Martin & Moyce's column is 1 x 2: "
             << "apps/fluid/dam_break_fronts.py reads the gauge file)";
        break;
      }
      const auto r = dam_break_errors(s);
      line << "; front against Martin & Moyce (1952) over 1 <= T <= 2.8 (" << r.points
           << " points): mean relative error " << r.mean_error << ", largest " << r.max_error
           << "; largest rise of the mechanical energy " << r.largest_rise << " |E0|";
      break;
    }
  }
  log::info() << line.str();
  if (runtime::rank() != 0 || s.files.output_file.empty()) return;
  const std::string path = app::beside_output(s.files.output_file, s.program, ".series.txt");
  std::ofstream out(path);
  out << "# " << s.program << " " << fluid_app::problem_names().name(s.problem.type) << ": L = " << s.problem.length
      << ", dx = " << s.layout.dx << ", g = " << g << "\n# t surge_front mechanical_energy max|rho/rho0-1| max_speed "
      << "max|v-v_exact|/v_max\n";
  out << std::setprecision(10);
  for (const auto& row : s.series)
    out << row.t << " " << row.front << " " << row.energy << " " << row.density_deviation << " " << row.speed << " "
        << row.channel_error << "\n";
}

template<int D>
int check(const fluid_run<D>& s, const app::check_values& checks) {
  bool pass = true;
  const auto fail = [&](const std::string& what) {
    log::error() << s.program << ": check failed: " << what;
    pass = false;
  };
  const double g = std::fabs(s.fluid.body_force[1]);
  if (checks.has("check-still-tank")) {
    const auto& b = checks.bounds("check-still-tank");
    const double speed = s.series.back().speed / std::sqrt(g * s.problem.length);
    const double pressure = s.bottom_pressure / (s.fluid.eos.reference_density * g * s.problem.length);
    if (!(speed <= b[0])) fail("largest speed " + std::to_string(speed) + " sqrt(g H) above " + std::to_string(b[0]));
    if (!(std::fabs(pressure - 1) <= b[1])) fail("bottom pressure " + std::to_string(pressure) + " rho0 g H");
    const auto& l = s.layout;
    if (!(s.min_x >= l.tank_lo[0] && s.max_x <= l.tank_hi[0] && s.min_y >= l.tank_lo[1]))
      fail("a fluid particle crossed a wall");
  }
  if (checks.has("check-channel")) {
    const auto& b = checks.bounds("check-channel");  // steady, transient
    if (s.channel_errors.empty()) fail("no channel error was measured");
    for (std::size_t i = 0; i < s.channel_errors.size(); ++i) {
      const bool last = i + 1 == s.channel_errors.size();
      if (!(s.channel_errors[i].second <= (last ? b[0] : b[1])))
        fail("max |v - v_exact| = " + std::to_string(s.channel_errors[i].second) +
             " v_max at t = " + std::to_string(s.channel_errors[i].first));
    }
  }
  if (checks.has("check-dam-break")) {
    const auto& b = checks.bounds("check-dam-break");  // front, density, energy rise
    const auto r = dam_break_errors(s);
    if (r.points == 0 || !(r.mean_error <= b[0])) fail("mean front error " + std::to_string(r.mean_error));
    if (!(largest_density_deviation(s) <= b[1]))
      fail("|rho/rho0 - 1| reached " + std::to_string(largest_density_deviation(s)));
    if (!(r.largest_rise <= b[2])) fail("the mechanical energy rose by " + std::to_string(r.largest_rise) + " |E0|");
  }
  return pass ? 0 : 1;
}

template<int D>
int run(const app::run_context& context) {
  fluid_run<D> s;
  sph::configure(s, context);
  s.problem = fluid_app::problem_parameters().read(context.parameters());
  s.fluid = fl::fluid_parameters().read(context.parameters());
  if (s.physics.adaptive_smoothing_length)
    throw runtime::parameter_error("fluid: adaptive_smoothing_length = true: the liquid keeps h = h_factor dx");
  if (s.physics.individual_time_steps())
    throw runtime::parameter_error(
      "fluid: time_steps = individual is not supported (the weakly compressible "
      "liquid's steps are all set by its sound speed c0, so one step for all loses "
      "nothing): use time_steps = global");
  // A checkpoint holds drho/dt and the walls' own velocity (fluid_fields.hh); initial data would not.
  if (!s.files.initial_data.empty())
    throw runtime::parameter_error("fluid: initial_data = '" + s.files.initial_data +
                                   "' is not supported (the walls' velocities and drho/dt are not in initial data; "
                                   "restart_file continues a fluid run)");
  if (s.problem.type == problem_type::dam_break && !(s.fluid.body_force[1] < 0))
    throw runtime::parameter_error("fluid: dam_break needs gravity along -y (body_force_y < 0)");
  s.layout = fluid_app::layout_of(s.program, s.problem, s.fluid);
  s.gauge_keys = fl::gauge_parameters().read(context.parameters());
  if (s.gauge_keys.file == "auto")
    s.gauge_keys.file = app::beside_output(s.files.output_file, s.program, ".gauges.csv");
  if (!s.gauge_keys.file.empty())
    app::check_distinct_file("gauge_file", s.gauge_keys.file,
                             {{"output_file", s.files.output_file},
                              {"checkpoint_file", s.files.checkpoint_file},
                              {"restart_file", s.files.restart_file},
                              {"statistics_file", s.statistics_keys.file}});
  if (s.problem.type == problem_type::poiseuille) {
    const double unit = s.problem.length * s.problem.length / s.fluid.kinematic_viscosity();
    s.check_times = {0.1 * unit, 0.2 * unit, s.run.end_time};
  } else if (s.problem.type == problem_type::couette) {
    s.check_times = {s.run.end_time};
  }
  {
    std::ostringstream eos;
    eos << "Tait (rho0 " << s.fluid.eos.reference_density << ", c0 " << s.fluid.eos.reference_sound_speed
        << ", exponent " << s.fluid.eos.exponent << ")";
    s.equation_of_state = eos.str();
  }
  s.description = {{"dx", s.layout.dx}};  // the particle spacing the keys imply (the keys: parameters)
  auto m = fl::make_fluid_control_model<fluid_run<D>>({set_domain<D>, create<D>});
  m.action("initialize", "measure", measure<D>).after("diagnostics");
  m.action("analyze", "measure", measure<D>).after("conserved_quantities");
  m.action("initialize", "gauges", open_gauges<D>).after("measure");
  m.action("analyze", "gauges", write_gauges<D>).after("measure");
  m.action("finalize", "report", report<D>);
  return context.execute(m, s, [&context](const fluid_run<D>& state) { return check(state, context.checks()); });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "fluid";
  definition.summary = "Weakly compressible SPH with solid walls: still tank, Poiseuille, Couette, dam break.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) {
    fluid_app::problem_parameters().declare(schema);
    fl::fluid_parameters().declare(schema);
    fl::gauge_parameters().declare(schema);
  };
  definition.physics_defaults.kernel = flecsph::physics::kernel_type::wendland_c2;
  definition.physics_defaults.adaptive_smoothing_length = false;
  definition.physics_defaults.courant = 0.25;
  definition.run_defaults.end_time = 1;
  definition.run_defaults.progress_every = 500;
  definition.run_defaults.diagnostics_every = 500;
  definition.file_defaults.output_file = "fluid.h5part";
  definition.file_defaults.output_every = 0.1;
  definition.file_defaults.checkpoint_file = "none";
  definition.checks = {
    {"check-still-tank", {"V", "P"}, "exit 1 unless max speed <= V sqrt(g H) and |P_bottom / rho0 g H - 1| <= P"},
    {"check-channel", {"STEADY", "TRANSIENT"}, "exit 1 unless max |v - v_exact| / v_max is within the bounds"},
    {"check-dam-break",
     {"FRONT", "RHO", "RISE"},
     "exit 1 unless the mean front error, max |rho/rho0 - 1| and the energy rise / |E0| are within them"}};
  definition.run = [](const app::run_context& context) {
    return context.parameters().get<int>("dimension") == 3 ? run<3>(context) : run<2>(context);
  };
  return sph::app_main(argc, argv, definition);
}
