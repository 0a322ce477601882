// Sedov-Taylor point blast in a uniform, cold medium (planar, cylindrical, spherical): the
// analytic similarity solution of Sedov (1959) in the form of Kamm & Timmes (2007, LA-UR-07-2849).
#pragma once

namespace flecsph::analytic {

/// Density, radial velocity and pressure at one radius.
struct sedov_state {
  double rho;
  double v;
  double P;
};

/// The similarity functions at lambda = r/R: velocity, density and pressure relative to their
/// values just behind the shock, v/v2 = f, rho/rho2 = g, P/P2 = h (Kamm & Timmes eqs. 38-41).
struct sedov_similarity {
  double f;
  double g;
  double h;
};

/// The blast of energy E released at r = 0, t = 0 into gas of density rho0 and zero pressure,
/// in `dimension` D = 1 (planar: E per unit area of the whole slab, both sides), D = 2
/// (cylindrical: E per unit length) or D = 3 (spherical). The shock is at
///   R(t) = xi0 (E t^2 / rho0)^(1/(D+2)),   E = alpha rho0 R^(D+2) / t^2,   xi0 = alpha^(-1/(D+2)).
/// Valid for gamma > 1 (gamma < 7 when D = 3; beyond, the solution has a vacuum core, the
/// "vacuum" family of Kamm & Timmes, which is not implemented). gamma = 2 is the removable
/// singularity omega = omega3 of Kamm & Timmes and uses their special forms.
class sedov_taylor {
 public:
  sedov_taylor(int dimension, double gamma, double energy, double rho0);

  int dimension() const { return dimension_; }
  double gamma() const { return gamma_; }
  double energy() const { return energy_; }
  double rho0() const { return rho0_; }
  double alpha() const { return alpha_; }
  double xi0() const { return xi0_; }

  double shock_radius(double t) const;
  /// dR/dt = 2 R / ((D+2) t).
  double shock_velocity(double t) const;
  /// State just behind the strong shock: rho0 (gamma+1)/(gamma-1), 2 U/(gamma+1),
  /// 2 rho0 U^2/(gamma+1) with U = dR/dt.
  sedov_state post_shock(double t) const;
  /// State at radius r >= 0 and time t > 0: the similarity profile inside the shock, the
  /// undisturbed gas (rho0, 0, 0) outside. At r = 0 the density is 0 and the pressure finite.
  sedov_state at(double r, double t) const;
  /// f, g, h at lambda = r/R in [0, 1].
  sedov_similarity similarity(double lambda) const;

  /// Specific internal energy P / ((gamma-1) rho); +infinity at the centre, where rho = 0.
  double specific_internal_energy(const sedov_state& state) const;

 private:
  struct point {  // the parametric solution at one value of the parameter s in (0, 1]
    double lambda;
    double dlambda_ds;
    sedov_similarity values;
  };
  point evaluate(double s) const;
  double parameter_of(double lambda) const;  // s with lambda(s) = lambda

  int dimension_;
  double gamma_, energy_, rho0_;
  bool omega3_singular_;
  // constants of Kamm & Timmes eqs. 33-37 and exponents eqs. 42-47 (omega = 0)
  double a_, b_, c_, d_, e_;
  double alpha0_, alpha1_, alpha2_, alpha3_, alpha4_, alpha5_;
  double v0_, v2_;  // V at the centre and behind the shock
  double alpha_, xi0_;
};

}  // namespace flecsph::analytic
