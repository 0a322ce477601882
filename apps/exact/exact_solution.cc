// Writes an exact solution as CSV for plots and validation: the Riemann problem (Sod by default;
// Toro ch. 4) on a line, or the Sedov-Taylor blast (Kamm & Timmes 2007) along a radius.
#include "specialization/analytic.hh"

#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

namespace {

using flecsi_lite::runtime::options;
using flecsi_lite::runtime::options_error;
namespace analytic = flecsph::analytic;

const std::set<std::string> sod_options = {"rho-left", "v-left", "p-left", "rho-right", "v-right",
                                           "p-right",  "x0",     "xmin",   "xmax",      "x-file"};
const std::set<std::string> sedov_options = {"dim", "energy", "rho0", "rmax", "shock"};

options command_line() {
  options parser(
    "Writes an exact solution as CSV (header line, then one row per point) to stdout or --output.\n"
    "  sod:   Riemann problem of an ideal gas, columns x,rho,v,P,u on [xmin, xmax] (both ends\n"
    "         included) at time t, for a discontinuity at x0 (Toro 2009, ch. 4); with --x-file\n"
    "         at the x values of FILE instead, written to the last digit (the apps' L1 errors).\n"
    "  sedov: Sedov-Taylor blast of energy E in gas of density rho0, columns r,rho,v,P,u at the\n"
    "         centres of `points` equal cells of [0, rmax] (the centre r = 0 has rho = 0 and\n"
    "         infinite u). In 1D E is the energy of the whole slab (both sides of x = 0). With\n"
    "         --shock one row t,R,rho,v,P: the shock radius R(t) and the post-shock state, to the\n"
    "         last digit (the shells of the app's comparison).");
  parser.flag("help", "print this help and exit")
    .positional("problem", "sod or sedov")
    .value("output", "FILE", "write the CSV to FILE instead of stdout")
    .value("t", "T", "time (default: 0.2 for sod, 0.05 for sedov)")
    .value("gamma", "G", "adiabatic index", "1.4")
    .value("points", "N", "number of points", "1000")
    .value("rho-left", "RHO", "sod: left density", "1")
    .value("v-left", "V", "sod: left velocity", "0")
    .value("p-left", "P", "sod: left pressure", "1")
    .value("rho-right", "RHO", "sod: right density", "0.125")
    .value("v-right", "V", "sod: right velocity", "0")
    .value("p-right", "P", "sod: right pressure", "0.1")
    .value("x0", "X", "sod: initial position of the discontinuity", "0")
    .value("xmin", "X", "sod: left end of the profile", "-0.5")
    .value("xmax", "X", "sod: right end of the profile", "0.5")
    .value("x-file", "FILE", "sod: evaluate at the x values in FILE (one number per line) instead of a grid")
    .value("dim", "D", "sedov: 1 (planar), 2 (cylindrical) or 3 (spherical)", "3")
    .value("energy", "E", "sedov: blast energy", "1")
    .value("rho0", "RHO", "sedov: ambient density", "1")
    .value("rmax", "R", "sedov: outer radius of the profile (default: 1.25 shock radius)")
    .flag("shock", "sedov: write the shock radius and the post-shock state instead of a profile");
  return parser;
}

/// Whether all of `text` is one finite number, stored in `value`.
bool parse_finite(const std::string& text, double& value) {
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size() && std::isfinite(value);
}

double number(const options& parser, const std::string& name) {
  const std::string text = parser.get(name);
  double value = 0.0;
  if (!parse_finite(text, value)) throw options_error("--" + name + " needs a finite number, not '" + text + "'");
  return value;
}

int integer(const options& parser, const std::string& name) {
  const std::string text = parser.get(name);
  std::size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size()) throw options_error("--" + name + " needs an integer, not '" + text + "'");
  return value;
}

void write_sod(const options& parser, std::ostream& out) {
  const double t = parser.has("t") ? number(parser, "t") : 0.2;
  const double gamma = number(parser, "gamma");
  const int points = integer(parser, "points");
  const double x0 = number(parser, "x0"), xmin = number(parser, "xmin");
  const double xmax = number(parser, "xmax");
  if (t < 0.0) throw options_error("--t must be >= 0");
  if (points < 2) throw options_error("--points must be at least 2");
  if (!(xmax > xmin)) throw options_error("--xmax must be larger than --xmin");
  const analytic::riemann_state left{number(parser, "rho-left"), number(parser, "v-left"), number(parser, "p-left")};
  const analytic::riemann_state right{number(parser, "rho-right"), number(parser, "v-right"),
                                      number(parser, "p-right")};
  const analytic::riemann_solution solution(left, right, gamma);

  out << "x,rho,v,P,u\n";
  const auto write = [&](double x) {
    // At t = 0 the initial data; the discontinuity itself belongs to the right state.
    const analytic::riemann_state q = t > 0.0 ? solution.at(x, t, x0) : (x < x0 ? left : right);
    out << x << ',' << q.rho << ',' << q.v << ',' << q.P << ',' << analytic::specific_internal_energy(q, gamma) << '\n';
  };
  if (parser.has("x-file")) {
    // The points of a caller that compares with particles (plot_sod.py's L1 errors): every value
    // read and written exactly, so the differences are those the app's own errors sum.
    std::ifstream file(parser.get("x-file"));
    if (!file) throw std::runtime_error("cannot open --x-file '" + parser.get("x-file") + "'");
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    for (std::string line; std::getline(file, line);) {
      if (line.empty()) continue;
      double x = 0;
      if (!parse_finite(line, x))
        throw options_error("--x-file '" + parser.get("x-file") + "': '" + line + "' is not a finite number");
      write(x);
    }
    return;
  }
  for (int i = 0; i < points; ++i) write(i + 1 == points ? xmax : xmin + (xmax - xmin) * i / (points - 1));
}

void write_sedov(const options& parser, std::ostream& out) {
  const double t = parser.has("t") ? number(parser, "t") : 0.05;
  const int points = integer(parser, "points");
  if (!(t > 0.0)) throw options_error("--t must be > 0 for sedov");
  if (points < 1) throw options_error("--points must be at least 1");
  const analytic::sedov_taylor blast(integer(parser, "dim"), number(parser, "gamma"), number(parser, "energy"),
                                     number(parser, "rho0"));
  if (parser.has("shock")) {
    const analytic::sedov_state q = blast.post_shock(t);
    out << "t,R,rho,v,P\n"
        << std::setprecision(std::numeric_limits<double>::max_digits10) << t << ',' << blast.shock_radius(t) << ','
        << q.rho << ',' << q.v << ',' << q.P << '\n';
    return;
  }
  const double rmax = parser.has("rmax") ? number(parser, "rmax") : 1.25 * blast.shock_radius(t);
  if (!(rmax > 0.0)) throw options_error("--rmax must be > 0");

  out << "r,rho,v,P,u\n";
  for (int i = 0; i < points; ++i) {
    const double r = rmax * (i + 0.5) / points;
    const analytic::sedov_state q = blast.at(r, t);
    out << r << ',' << q.rho << ',' << q.v << ',' << q.P << ',' << blast.specific_internal_energy(q) << '\n';
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string program = "exact_solution";
  options parser = command_line();
  try {
    parser.parse(argc, argv);
    if (parser.has("help")) {
      std::cout << parser.help(program);
      return 0;
    }
    const std::string problem = parser.get("problem");
    if (problem != "sod" && problem != "sedov")
      throw options_error("unknown problem '" + problem + "'; choose sod or sedov");
    const auto& foreign = problem == "sod" ? sedov_options : sod_options;
    for (const auto& name : foreign)
      if (parser.has(name)) throw options_error("option --" + name + " does not apply to " + problem);

    std::ofstream file;
    if (parser.has("output")) {
      file.open(parser.get("output"));
      if (!file) throw std::runtime_error("cannot open '" + parser.get("output") + "'");
    }
    std::ostream& out = parser.has("output") ? file : std::cout;
    out << std::setprecision(12);
    if (problem == "sod")
      write_sod(parser, out);
    else
      write_sedov(parser, out);
    out.flush();
    if (!out) throw std::runtime_error("writing the output failed");
  } catch (const options_error& error) {
    std::cerr << program << ": error: " << error.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& error) {  // rejected by the solvers
    std::cerr << program << ": error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << program << ": error: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
