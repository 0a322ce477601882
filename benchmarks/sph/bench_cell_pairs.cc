// Prototype measurement for issue 14, item 3 (interactions by cell pairs without lists, SWIFT's
// route; Schaller et al. 2016, PASC, sec. 3) against this project's route (neighbour lists whose
// entries are gathered lane by lane), on the same particles with the same kernel code: a density
// pass (rho_a = sum_b m_b W(r_ab, h_a) and d rho_a / d h_a for every particle, as one Newton
// iteration of compute_density does) and a force pass (dv/dt, du/dt and the signal velocity of
// compute_forces: pressure, grad-h terms and viscosity, no conductivity).
//
// - lists: the pair rows of the SPH step (neighbourhood, packed entries with shift codes, in
//   ascending index order), gathered once per target into |r_ab| and m_b (detail::gather_pairs),
//   then summed (detail::density_sums); forces by detail::force_sums: the code of the SPH step.
// - cells: the particles sorted into a grid of cells of side >= support / S (x fastest, by x
//   within a cell), as SoA arrays; a target's candidates are the (2S+1)^2 rows of 2S+1 cells
//   around its cell, each row contiguous in memory (split where it wraps), loaded pack by pack
//   with no gather, whole or cut to reach along x; lanes outside the support are masked. No
//   list is built or kept. The force pass repeats force_sums' pair arithmetic (the same physics
//   functions, in the same order) with loads in place of gathers.
//
// The lists' own search is not timed here (bench_sedov reports it: sph::search_neighbours); the
// grid's sort is. Uniform h (a lattice, optionally jittered): the Sedov benchmark's
// particles before the blast reaches them. Not a test: the comparison prints both sums' largest
// relative difference, which must stay at rounding level (the sums' order differs).
#include "nominal_clock.hh"

#include "specialization/physics/kernels/cubic_spline.hh"
#include "specialization/physics/viscosity.hh"
#include "specialization/sph/step/density.hh"
#include "specialization/sph/step/forces.hh"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace {
namespace sph = flecsph::sph;
namespace physics = flecsph::physics;
namespace simd = physics::simd;
namespace tree = flecsi_lite::topology::ntree;
using Kernel = physics::cubic_spline<3>;
using pack = sph::detail::density_pack;  // the density's packs, as compute_density's
using force_pack = simd::pack;           // the forces', as compute_forces'
constexpr std::size_t W = std::max(simd::lanes<pack>, simd::lanes<force_pack>);  ///< the arrays' padding

struct options {
  int per_side = 50;
  double eta = 1.42;
  double jitter = 0.0;  ///< displacement of each lattice point, uniform in +-jitter/2 spacings per axis
  int repeats = 5;
  int split = 1;  ///< cells of side >= support / split: (2 split + 1)^3 cells around a target
  double clock_ghz = 0;
};

[[noreturn]] void usage(const std::string& why) {
  std::cerr << "bench_cell_pairs: " << why
            << "\nusage: bench_cell_pairs [--per-side N] [--eta E] [--jitter F] [--split S] [--repeats R] "
               "[--clock-ghz G]\n";
  std::exit(2);
}

options parse(int argc, char** argv) {
  options o;
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    if (i + 1 >= argc) usage("missing value after " + key);
    const std::string value = argv[++i];
    try {
      if (key == "--per-side")
        o.per_side = std::stoi(value);
      else if (key == "--eta")
        o.eta = std::stod(value);
      else if (key == "--jitter")
        o.jitter = std::stod(value);
      else if (key == "--split")
        o.split = std::stoi(value);
      else if (key == "--repeats")
        o.repeats = std::stoi(value);
      else if (key == "--clock-ghz")
        o.clock_ghz = std::stod(value);
      else
        usage("unknown option " + key);
    } catch (const std::logic_error&) {
      usage("bad value '" + value + "' for " + key);
    }
  }
  if (o.per_side < 4 || o.eta <= 0 || o.jitter < 0 || o.jitter >= 1 || o.split < 1 || o.repeats < 1)
    usage("need --per-side >= 4, --eta > 0, 0 <= --jitter < 1, --split >= 1, --repeats >= 1");
  return o;
}

/// The particles in cell order (x fastest), as SoA arrays padded with W far-away entries.
struct cell_grid {
  int cells = 0;                   ///< per side; the box is [0, 1)^3, periodic
  std::vector<std::size_t> start;  ///< first particle of each cell, and the total at the end
  std::vector<double> x, y, z, m;

  std::size_t cell_of(int cx, int cy, int cz) const {
    return std::size_t(cx) + std::size_t(cells) * (std::size_t(cy) + std::size_t(cells) * std::size_t(cz));
  }
  int coordinate(double position) const { return std::min(cells - 1, int(position * cells)); }
};

/// Counting sort of the particles into cells.
cell_grid sort_into_cells(const std::vector<sph::vector<3>>& p, double mass, int cells) {
  cell_grid g;
  g.cells = cells;
  const std::size_t n = p.size(), count = std::size_t(cells) * cells * cells;
  std::vector<std::size_t> cell(n);
  g.start.assign(count + 1, 0);
  for (std::size_t a = 0; a < n; ++a) {
    cell[a] = g.cell_of(g.coordinate(p[a][0]), g.coordinate(p[a][1]), g.coordinate(p[a][2]));
    ++g.start[cell[a] + 1];
  }
  for (std::size_t c = 0; c < count; ++c) g.start[c + 1] += g.start[c];
  std::vector<std::size_t> next(g.start.begin(), g.start.end() - 1);
  constexpr double far = 1e30;  // padding: outside every support
  g.x.assign(n + W, far);
  g.y.assign(n + W, far);
  g.z.assign(n + W, far);
  g.m.assign(n + W, 0.0);
  std::vector<std::size_t> order(n);
  for (std::size_t a = 0; a < n; ++a) order[next[cell[a]]++] = a;
  // Within a cell by x: a row of cells is then sorted by x, and cell_rows<true> can cut it.
  for (std::size_t c = 0; c < count; ++c)
    std::sort(order.begin() + std::ptrdiff_t(g.start[c]), order.begin() + std::ptrdiff_t(g.start[c + 1]),
              [&](std::size_t a, std::size_t b) { return p[a][0] < p[b][0]; });
  for (std::size_t slot = 0; slot < n; ++slot) {
    const std::size_t a = order[slot];
    g.x[slot] = p[a][0];
    g.y[slot] = p[a][1];
    g.z[slot] = p[a][2];
    g.m[slot] = mass;
  }
  return g;
}

/// A run of consecutive particles of the grid seen under one periodic shift.
struct candidate_range {
  std::size_t begin, end;
  double shift[3];
};

/// The rows of cells around cell (cx, cy, cz): (2S+1)^2 rows of 2S+1 cells, split where they wrap.
template<class Visit>
void for_each_row(const cell_grid& g, int cx, int cy, int cz, int S, Visit&& visit) {
  const int C = g.cells;
  const auto wrap = [C](int c, double& shift) {
    shift = c < 0 ? -1.0 : c >= C ? 1.0 : 0.0;
    return (c + C) % C;
  };
  for (int dz = -S; dz <= S; ++dz)
    for (int dy = -S; dy <= S; ++dy) {
      candidate_range r{};
      const int wz = wrap(cz + dz, r.shift[2]), wy = wrap(cy + dy, r.shift[1]);
      const int lo = cx - S, hi = cx + S;
      if (lo < 0) {  // cells C + lo .. C - 1 under shift -1 along x, then 0 .. hi
        r.shift[0] = -1;
        r.begin = g.start[g.cell_of(C + lo, wy, wz)], r.end = g.start[g.cell_of(C - 1, wy, wz) + 1];
        visit(r);
        r.shift[0] = 0;
        r.begin = g.start[g.cell_of(0, wy, wz)], r.end = g.start[g.cell_of(hi, wy, wz) + 1];
      } else if (hi >= C) {  // cells lo .. C - 1, then 0 .. hi - C under shift +1
        r.shift[0] = 0;
        r.begin = g.start[g.cell_of(lo, wy, wz)], r.end = g.start[g.cell_of(C - 1, wy, wz) + 1];
        visit(r);
        r.shift[0] = 1;
        r.begin = g.start[g.cell_of(0, wy, wz)], r.end = g.start[g.cell_of(hi - C, wy, wz) + 1];
      } else {
        r.shift[0] = 0;
        r.begin = g.start[g.cell_of(lo, wy, wz)], r.end = g.start[g.cell_of(hi, wy, wz) + 1];
      }
      visit(r);
    }
}

/// The rows of a cell's targets. Whole: every candidate of the (2S+1)^2 rows. Cut (Cut = true):
/// each row cut to the particles within `reach` of the target along x, as SWIFT's sorted cell
/// pairs keep only the particles whose projection on the pair's axis is within reach; a row is
/// sorted by x and a cell's targets come in ascending x, so the cut's ends only move forward.
template<bool Cut>
class cell_rows {
 public:
  cell_rows(const cell_grid& g, int S, double reach) : g_(g), S_(S), reach_(reach) {}

  void start(int cx, int cy, int cz) {
    rows_.clear();
    for_each_row(g_, cx, cy, cz, S_, [&](const candidate_range& r) { rows_.push_back(r); });
    cut_ = rows_;
    for (auto& c : cut_) c.end = c.begin;
  }

  /// visit(a) for every particle a of the grid, cell by cell (x fastest), after start() of its
  /// cell: visit() then gives a's rows.
  template<class Visit>
  void for_each_target(Visit&& visit) {
    const int C = g_.cells;
    for (int cz = 0; cz < C; ++cz)
      for (int cy = 0; cy < C; ++cy)
        for (int cx = 0; cx < C; ++cx) {
          start(cx, cy, cz);
          const std::size_t cell = g_.cell_of(cx, cy, cz);
          for (std::size_t a = g_.start[cell]; a < g_.start[cell + 1]; ++a) visit(a);
        }
  }

  /// visit(range) for each row of target a (a particle of the started cell; ascending a).
  template<class Visit>
  void visit(std::size_t a, Visit&& visit) {
    if constexpr (!Cut) {
      for (const auto& r : rows_) visit(r);
    } else {
      const double* x = g_.x.data();
      for (std::size_t i = 0; i < rows_.size(); ++i) {
        candidate_range& c = cut_[i];
        const std::size_t end = rows_[i].end;
        const double centre = x[a] - c.shift[0];
        while (c.begin < end && x[c.begin] < centre - reach_) ++c.begin;
        c.end = std::max(c.end, c.begin);
        while (c.end < end && x[c.end] <= centre + reach_) ++c.end;
        visit(c);
      }
    }
  }

 private:
  const cell_grid& g_;
  int S_;
  double reach_;
  std::vector<candidate_range> rows_, cut_;
};

/// The cell route: rho and d rho / d h of every particle (grid order) from contiguous packs; with
/// Cut, each row cut to the particles within reach along x first.
template<bool Cut>
void density_by_cells(const cell_grid& g, double h, int S, std::vector<double>& rho, std::vector<double>& drho_dh) {
  const sph::kernel_at<Kernel> kernel(h);
  const double reach = physics::kernel_support * h, reach2 = reach * reach;
  const pack lane = simd::generate<pack>([](std::size_t i) { return double(i); }), zero = 0.0;
  cell_rows<Cut> rows(g, S, reach);
  rows.for_each_target([&](std::size_t a) {
    simd::striped_sum<pack> sum, derivative;
    rows.visit(a, [&](const candidate_range& r) {
      // r_ab = x_a - (x_b + shift) = (x_a - shift) - x_b
      const double xa = g.x[a] - r.shift[0], ya = g.y[a] - r.shift[1], za = g.z[a] - r.shift[2];
      for (std::size_t j = r.begin; j < r.end; j += simd::lanes<pack>) {
        const pack dx = xa - simd::load<pack>(&g.x[j]), dy = ya - simd::load<pack>(&g.y[j]),
                   dz = za - simd::load<pack>(&g.z[j]);
        const pack r2 = dx * dx + dy * dy + dz * dz;
        const auto inside = (r2 < reach2) && (lane < double(r.end - j));
        if (!simd::any_lane(inside)) {
          sum.skip();
          derivative.skip();
          continue;
        }
        pack w, dw_dh;
        kernel.value_and_h_derivative(simd::square_root(r2), w, dw_dh);
        const pack m = simd::load<pack>(&g.m[j]);
        sum.add(simd::select(inside, m * w, zero));
        derivative.add(simd::select(inside, m * dw_dh, zero));
      }
    });
    rho[a] = sum.total();
    drho_dh[a] = derivative.total();
  });
}

/// Candidates of the cell rows (the particles the cell route loads) over all targets.
template<bool Cut>
double candidate_count(const cell_grid& g, int S, double reach) {
  double candidates = 0;
  cell_rows<Cut> rows(g, S, reach);
  rows.for_each_target(
    [&](std::size_t a) { rows.visit(a, [&](const candidate_range& r) { candidates += double(r.end - r.begin); }); });
  return candidates;
}

/// The lists of the cell route's pairs (every b with |r_ab| < support h, itself included), in
/// ascending index per row with packed shift codes: the neighbourhood the SPH step would hold.
sph::neighbourhood<3> lists_of(const cell_grid& g, double h, int S) {
  sph::neighbourhood<3> n;
  const double reach = physics::kernel_support * h, reach2 = reach * reach;
  for (int code = 0; code < tree::shift_code_count<3>; ++code)
    for (int k = 0, c = code; k < 3; ++k, c /= 3) n.shift_table[code][k] = double(c % 3 - 1);
  n.lists.offsets.assign(g.x.size() - W + 1, 0);
  std::vector<std::uint32_t> row;
  cell_rows<false> rows(g, S, reach);
  rows.for_each_target([&](std::size_t a) {
    row.clear();
    rows.visit(a, [&](const candidate_range& r) {
      const int digits[3] = {int(r.shift[0]) + 1, int(r.shift[1]) + 1, int(r.shift[2]) + 1};
      const auto code = tree::shift_code(digits[0] + 3 * digits[1] + 9 * digits[2]);
      for (std::size_t b = r.begin; b < r.end; ++b) {
        const double dx = (g.x[a] - g.x[b]) - r.shift[0], dy = (g.y[a] - g.y[b]) - r.shift[1],
                     dz = (g.z[a] - g.z[b]) - r.shift[2];
        if (dx * dx + dy * dy + dz * dz < reach2) row.push_back(tree::packed_entry(std::uint32_t(b), code));
      }
    });
    std::sort(row.begin(), row.end(),
              [](std::uint32_t p, std::uint32_t q) { return tree::packed_neighbour(p) < tree::packed_neighbour(q); });
    n.lists.neighbours.insert(n.lists.neighbours.end(), row.begin(), row.end());
    n.lists.offsets[a + 1] = n.lists.neighbours.size();
  });
  return n;
}

/// The list route: gather |r_ab| and m_b of each row, then sum (compute_density's own functions).
void density_by_lists(const sph::neighbourhood<3>& n, const std::vector<sph::vector<3>>& x,
                      const std::vector<double>& m, double h, int iterations, std::vector<double>& rho,
                      std::vector<double>& drho_dh) {
  const sph::neighbour_walk<3> walk(n);
  sph::detail::gathered_pairs pairs;
  for (std::size_t a = 0; a < n.size(); ++a) {
    sph::detail::gather_pairs<3>(walk.row(a), a, x.data(), m.data(), pairs);
    for (int i = 0; i < iterations; ++i) sph::detail::density_sums<Kernel>(pairs, h, rho[a], drho_dh[a]);
  }
}

/// The fields the force pass reads besides positions and masses, in grid order, padded with W
/// entries (never inside a pair): SoA arrays for the cells, arrays of vectors for the lists.
struct force_inputs {
  std::vector<double> vx, vy, vz, h, inverse_h, rho, P, cs, pressure_term, u;
  std::vector<sph::vector<3>> v;
};

/// Values of a gas at rest but for random velocities (half the pairs approach: the viscosity
/// runs), u = 1, gamma 5/3, Omega = 1, rho from the density pass.
force_inputs gas_state(const std::vector<double>& rho, double h, std::size_t n) {
  force_inputs f;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> speed(-0.1, 0.1);
  const double gamma = 5.0 / 3.0;
  for (auto* field : {&f.vx, &f.vy, &f.vz, &f.rho, &f.P, &f.cs, &f.pressure_term, &f.u}) field->assign(n + W, 0.0);
  f.h.assign(n + W, h);
  f.inverse_h.assign(n + W, 1.0 / h);
  f.v.resize(n);
  for (std::size_t a = 0; a < n; ++a) {
    f.v[a] = {speed(random), speed(random), speed(random)};
    f.vx[a] = f.v[a][0], f.vy[a] = f.v[a][1], f.vz[a] = f.v[a][2];
    f.rho[a] = rho[a];
    f.u[a] = 1.0;
    f.P[a] = (gamma - 1) * rho[a] * f.u[a];
    f.cs[a] = std::sqrt(gamma * f.P[a] / rho[a]);
    f.pressure_term[a] = f.P[a] / (rho[a] * rho[a]);
  }
  return f;
}

struct force_results {
  std::vector<double> ax, ay, az, du, signal;
  explicit force_results(std::size_t n) : ax(n), ay(n), az(n), du(n), signal(n) {}
};

/// The cell route of the force pass: force_sums' arithmetic on contiguous packs of the cell rows
/// (with Cut, cut to reach along x; reach: the support of the largest h).
template<bool Cut>
void forces_by_cells(const cell_grid& g, const force_inputs& f, int S, const physics::viscosity_parameters& viscosity,
                     double reach, force_results& out) {
  using T = force_pack;
  const double support2 = physics::kernel_support * physics::kernel_support;
  const T lane = simd::generate<T>([](std::size_t i) { return double(i); }), zero = 0.0;
  cell_rows<Cut> rows(g, S, reach);
  rows.for_each_target([&](std::size_t a) {
    const double h_a = f.h[a], rho_a = f.rho[a], c_a = f.cs[a], term_a = f.pressure_term[a];
    const double v_a[3] = {f.vx[a], f.vy[a], f.vz[a]};
    const sph::kernel_at<Kernel, T> kernel_a(T(h_a), T(f.inverse_h[a]));
    const physics::basic_viscosity_particle<T> particle_a{rho_a, c_a, h_a, 1.0};
    simd::striped_sum<T> sum_v[3], sum_u;
    T largest = c_a;
    rows.visit(a, [&](const candidate_range& range) {
      const double x_a[3] = {g.x[a] - range.shift[0], g.y[a] - range.shift[1], g.z[a] - range.shift[2]};
      const double* x[3] = {g.x.data(), g.y.data(), g.z.data()};
      const double* v[3] = {f.vx.data(), f.vy.data(), f.vz.data()};
      for (std::size_t j = range.begin; j < range.end; j += simd::lanes<T>) {
        T r[3], r2 = 0.0, r_dot_v = 0.0;
        for (int k = 0; k < 3; ++k) {
          r[k] = x_a[k] - simd::load<T>(x[k] + j);
          r2 += r[k] * r[k];
        }
        const T h_b = simd::load<T>(&f.h[j]), h_max = simd::maximum(T(h_a), h_b);
        const auto pair = (lane < double(range.end - j)) && !(r2 >= support2 * h_max * h_max) && (r2 != 0.0);
        if (!simd::any_lane(pair)) {
          for (auto& s : sum_v) s.skip();
          sum_u.skip();
          continue;
        }
        const T distance = simd::square_root(r2), inverse_r = 1.0 / distance;
        const T F_a = kernel_a.gradient_factor(distance, inverse_r);
        const sph::kernel_at<Kernel, T> kernel_b(h_b, simd::load<T>(&f.inverse_h[j]));
        const T F_b = kernel_b.gradient_factor(distance, inverse_r);
        const T F_ab = 0.5 * (F_a + F_b);
        for (int k = 0; k < 3; ++k) r_dot_v += r[k] * (v_a[k] - simd::load<T>(v[k] + j));
        const T c_b = simd::load<T>(&f.cs[j]), rho_b = simd::load<T>(&f.rho[j]);
        const T Pi = simd::select(
          r_dot_v < 0.0,
          physics::approaching_pair_viscosity<T>(viscosity, r_dot_v, r2, particle_a, {rho_b, c_b, h_b, T(1.0)}), zero);
        const T bracket = (term_a * F_a + simd::load<T>(&f.pressure_term[j]) * F_b) + Pi * F_ab;
        const T m_b = simd::load<T>(&g.m[j]);
        for (int k = 0; k < 3; ++k) sum_v[k].subtract(simd::select(pair, m_b * bracket * r[k], zero));
        sum_u.add(simd::select(pair, m_b * (term_a * F_a + 0.5 * Pi * F_ab) * r_dot_v, zero));
        const T signal = physics::signal_velocity_from_inverse<T>(c_a, c_b, r_dot_v, inverse_r);
        largest = simd::maximum(largest, simd::select(pair, signal, zero));
      }
    });
    out.ax[a] = sum_v[0].total(), out.ay[a] = sum_v[1].total(), out.az[a] = sum_v[2].total();
    out.du[a] = sum_u.total();
    out.signal[a] = simd::largest_lane(largest);
  });
}

/// The list route of the force pass: compute_forces' own sums.
void forces_by_lists(const sph::neighbourhood<3>& n, const std::vector<sph::vector<3>>& x, const std::vector<double>& m,
                     const force_inputs& f, const physics::viscosity_parameters& viscosity, force_results& out) {
  const sph::neighbour_walk<3> walk(n);
  sph::detail::force_fields<3> in{x.data(),     f.v.data(), m.data(),    f.h.data(),
                                  f.rho.data(), f.P.data(), f.cs.data(), f.pressure_term.data(),
                                  f.u.data(),   nullptr};
  in.inverse_h = f.inverse_h.data();
  for (std::size_t a = 0; a < n.size(); ++a) {
    sph::vector<3> dv;
    sph::detail::force_sums<Kernel, false, false, false, 3>(walk, a, in, viscosity, 0.0, dv, out.du[a], out.signal[a]);
    out.ax[a] = dv[0], out.ay[a] = dv[1], out.az[a] = dv[2];
  }
}

/// Largest |p - q| over the particles, relative to the largest |q|.
double relative_difference(const std::vector<double>& p, const std::vector<double>& q) {
  double difference = 0, scale = 0;
  for (std::size_t a = 0; a < q.size(); ++a) {
    difference = std::max(difference, std::fabs(p[a] - q[a]));
    scale = std::max(scale, std::fabs(q[a]));
  }
  return scale > 0 ? difference / scale : difference;
}

template<class F>
double fastest_of(int repeats, F&& f) {
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}
}  // namespace

int main(int argc, char** argv) {
  const options o = parse(argc, argv);
  const double ghz = flecsph::benchmarks::nominal_clock_ghz(o.clock_ghz);
  const int N = o.per_side;
  const std::size_t n = std::size_t(N) * N * N;
  const double spacing = 1.0 / N, h = o.eta * spacing, mass = 1.0 / double(n);
  const double support = physics::kernel_support * h;
  const int cells = int(std::floor(o.split / support));
  if (cells < 2 * o.split + 1) usage("too few particles per side for cells of side support / split");

  std::mt19937_64 random(20261205);
  std::uniform_real_distribution<double> offset(-0.5 * o.jitter, 0.5 * o.jitter);
  std::vector<sph::vector<3>> lattice(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t c[3] = {i % N, i / N % N, i / (std::size_t(N) * N)};
    for (int k = 0; k < 3; ++k) {
      const double p = (double(c[k]) + 0.5 + offset(random)) * spacing;
      lattice[i][k] = p - std::floor(p);
    }
  }

  cell_grid grid;
  const double sort_s = fastest_of(o.repeats, [&] { grid = sort_into_cells(lattice, mass, cells); });
  std::vector<sph::vector<3>> x(n);  // the grid's order, for the lists
  for (std::size_t a = 0; a < n; ++a) x[a] = {grid.x[a], grid.y[a], grid.z[a]};
  const std::vector<double> m(grid.m.begin(), grid.m.begin() + std::ptrdiff_t(n));
  const sph::neighbourhood<3> lists = lists_of(grid, h, o.split);

  std::vector<double> rho_c(n), drho_c(n), rho_l(n), drho_l(n);
  const double candidates = candidate_count<false>(grid, o.split, support),
               cut_candidates = candidate_count<true>(grid, o.split, support);
  const double cells_s = fastest_of(o.repeats, [&] { density_by_cells<false>(grid, h, o.split, rho_c, drho_c); });
  const double cut_s = fastest_of(o.repeats, [&] { density_by_cells<true>(grid, h, o.split, rho_c, drho_c); });
  const double lists_1_s = fastest_of(o.repeats, [&] { density_by_lists(lists, x, m, h, 1, rho_l, drho_l); });
  const double lists_2_s = fastest_of(o.repeats, [&] { density_by_lists(lists, x, m, h, 2, rho_l, drho_l); });

  const force_inputs gas = gas_state(rho_l, h, n);
  const physics::viscosity_parameters viscosity{};
  force_results forces_c(n), forces_l(n);
  const double forces_cells_s =
    fastest_of(o.repeats, [&] { forces_by_cells<false>(grid, gas, o.split, viscosity, support, forces_c); });
  const double forces_cut_s =
    fastest_of(o.repeats, [&] { forces_by_cells<true>(grid, gas, o.split, viscosity, support, forces_c); });
  const double forces_lists_s = fastest_of(o.repeats, [&] { forces_by_lists(lists, x, m, gas, viscosity, forces_l); });

  const double worst =
    std::max({relative_difference(rho_c, rho_l), relative_difference(drho_c, drho_l),
              relative_difference(forces_c.ax, forces_l.ax), relative_difference(forces_c.ay, forces_l.ay),
              relative_difference(forces_c.az, forces_l.az), relative_difference(forces_c.du, forces_l.du),
              relative_difference(forces_c.signal, forces_l.signal)});

  const double hits = double(lists.lists.total());
  const auto cycles = [&](double seconds) { return seconds * ghz * 1e9 / hits; };
  std::cout << std::fixed << "bench_cell_pairs: " << N << "^3 particles, eta " << std::setprecision(2) << o.eta
            << ", jitter " << o.jitter << std::setprecision(1) << ", " << simd::lanes<pack> << " / "
            << simd::lanes<force_pack> << " lanes (density / forces), cells of side >= support/" << o.split << " ("
            << cells << "^3, " << double(n) / (double(cells) * cells * cells) << " particles each)\n"
            << "  pairs within the support per particle " << hits / double(n) << "; candidates of the cell rows "
            << candidates / double(n) << " (" << std::setprecision(2) << candidates / hits
            << " per pair), cut to reach along x " << std::setprecision(1) << cut_candidates / double(n) << " ("
            << std::setprecision(2) << cut_candidates / hits << " per pair)\n"
            << std::setprecision(1) << "  cycles per pair at " << std::setprecision(2) << ghz << " GHz (fastest of "
            << o.repeats << "):\n"
            << std::setprecision(1) << "    density, lists: gather and one sum   " << cycles(lists_1_s) << "\n"
            << "    density, lists: a further Newton sum " << cycles(lists_2_s - lists_1_s) << "\n"
            << "    density, cells: one pass             " << cycles(cells_s) << "\n"
            << "    density, cells cut to reach          " << cycles(cut_s) << "\n"
            << "    forces, lists                        " << cycles(forces_lists_s) << "\n"
            << "    forces, cells                        " << cycles(forces_cells_s) << "\n"
            << "    forces, cells cut to reach           " << cycles(forces_cut_s) << "\n"
            << "    cells: sort into cells per step      " << cycles(sort_s) << "\n"
            << std::scientific << std::setprecision(2)
            << "  largest difference between the routes (rho, d rho / d h, dv/dt, du/dt, signal velocity; relative to "
               "each one's largest value) "
            << worst << "\n";
  return worst < 1e-10 ? 0 : 1;
}
