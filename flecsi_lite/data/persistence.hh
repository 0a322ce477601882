// What a field's definition says about its life outside memory: under which dataset names it is
// written, whether to every OUTPUT step and to RESTART checkpoints, and how it is read as INITIAL
// data with which validity rule. The I/O (data/field_io.hh) walks the registered fields by it.
//
// Vocabulary. A field's COMPONENTS are its values per entity: 1 for a scalar, N for a
// std::array<S, N> (e.g. a D-vector). Each component is one DATASET of a file, named here (e.g.
// "vx" "vy" "vz"); a PADDED field also writes zeros under its names beyond its components, so a
// 1-D velocity is vx vy vz as 3-D readers expect. The ROLES:
//   output    written to every output step;
//   restart   written to every checkpoint and read back (every component required) at a restart;
//   initial   read from initial data: required, or optional (absent: zero, or for an id field
//             the entity's index in the step); the RULE checks every value read (also at restart).
// A field that exists in files ONLY WITH a FEATURE of the run (a name the specialization gives,
// e.g. "gravity") keeps its roles only in runs that have it (without it: none).
// A field's UNITS are the powers of the base units (mass, length, time) of its values; a field
// IN SNAPSHOTS is written to the SWIFT/GADGET-layout snapshots (io/snapshot_writer.hh) under
// SWIFT's dataset name with a description, whatever its roles in H5Part files (the last
// accelerations are checkpoint data in H5Part, but a snapshot holds them), and may be read from
// SWIFT-format initial conditions under the name SWIFT reads (its hydro_io.h reads "Density" and
// writes "Densities"). A snapshot quantity of MOVING PARTICLES ONLY is absent for particles held
// fixed in place (walls).
//
//   static inline const definition<double> density{
//     "rho", persist::output().restart().initial_optional(persist::at_least(0, "densities"))};
#pragma once

#include <cmath>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace flecsi_lite::data {

/// What every value read for a field must satisfy, and the words that say it in an error message
/// ("densities must be >= 0"). An empty rule accepts everything.
struct value_rule {
  std::string expectation;
  std::function<bool(double)> holds;

  explicit operator bool() const { return static_cast<bool>(holds); }
};

/// Finite values: "<what> must be finite".
inline value_rule must_be_finite(const std::string& what) {
  return {what + " must be finite", [](double value) { return std::isfinite(value); }};
}
/// Finite values > 0: "<what> must be positive".
inline value_rule must_be_positive(const std::string& what) {
  return {what + " must be positive", [](double value) { return value > 0 && std::isfinite(value); }};
}
/// Finite values >= bound: "<what> must be >= <bound>".
inline value_rule at_least(double bound, const std::string& what) {
  std::ostringstream expectation;
  expectation << what << " must be >= " << bound;
  return {expectation.str(), [bound](double value) { return value >= bound && std::isfinite(value); }};
}
/// Values equal to one of `allowed`; `expectation` says what they mean ("0 for fluid or 1 for wall").
inline value_rule one_of(std::initializer_list<double> allowed, const std::string& expectation) {
  return {expectation, [values = std::vector<double>(allowed)](double value) {
            for (double v : values)
              if (value == v) return true;
            return false;
          }};
}

/// Powers of the base units (mass, length, time) of a quantity: a velocity is {0, 1, -1}, a
/// density in D dimensions {1, -D, 0}; all zero for a pure number.
struct unit_exponents {
  float mass = 0, length = 0, time = 0;
};

/// A field in SWIFT's layout (Schaller et al. 2024; SWIFT's hydro/*/hydro_io.h): the snapshot
/// dataset it is written to and SWIFT's "Description" of it, the initial-conditions dataset it
/// is read from ("" when none), and whether particles held fixed have it.
struct swift_naming {
  std::string snapshot_dataset;  ///< "" when the field is in no snapshot
  std::string description;
  std::string initial_conditions_dataset;
  bool moving_particles_only = false;
};

/// The roles of a field in files, combinable: role::output | role::restart.
enum class role : unsigned { none = 0, output = 1, restart = 2, initial = 4 };
constexpr role operator|(role a, role b) { return role(unsigned(a) | unsigned(b)); }
constexpr bool any_of(role roles, role wanted) { return (unsigned(roles) & unsigned(wanted)) != 0; }

/// How a field is read as initial data (when it has role::initial).
enum class initial_reading {
  required,       // the datasets must be present
  optional,       // absent datasets read as zero
  optional_index  // absent: the entity's index in the step (ids)
};

/// A field's persistence, built by chaining: persist::as("vx", "vy", "vz").padded().output().
class persistence {
 public:
  persistence() = default;

  /// The dataset name of each component (default: the field's name for a scalar, name_0, name_1,
  /// ... for the components of an array).
  template<class... Names>
  persistence as(Names&&... names) const {
    persistence p = *this;
    p.datasets_ = {std::string(std::forward<Names>(names))...};
    return p;
  }
  /// Also writes zeros under the dataset names beyond the field's components.
  persistence padded() const {
    return with([](persistence& p) { p.padded_ = true; });
  }
  persistence output() const {
    return with([](persistence& p) { p.roles_ = p.roles_ | role::output; });
  }
  persistence restart() const {
    return with([](persistence& p) { p.roles_ = p.roles_ | role::restart; });
  }
  persistence initial_required(value_rule rule = {}) const {
    return initial(initial_reading::required, std::move(rule));
  }
  persistence initial_optional(value_rule rule = {}) const {
    return initial(initial_reading::optional, std::move(rule));
  }
  /// In files only for runs that have `feature` (the specialization names its features, e.g.
  /// "gravity"); in other runs the field has no role.
  persistence only_with(std::string feature) const {
    return with([&feature](persistence& p) { p.feature_ = std::move(feature); });
  }
  /// Optional initial data that defaults to the entity's index in the step (for ids).
  persistence initial_optional_index() const { return initial(initial_reading::optional_index, {}); }
  /// The units of the field's values (default: a pure number).
  persistence units(float mass, float length, float time) const {
    return with([=](persistence& p) { p.units_ = {mass, length, time}; });
  }
  /// Written to every snapshot as SWIFT's dataset `dataset`, with SWIFT's "Description".
  persistence in_snapshots(std::string dataset, std::string description) const {
    return with([&](persistence& p) {
      p.swift_.snapshot_dataset = std::move(dataset);
      p.swift_.description = std::move(description);
    });
  }
  /// Read from SWIFT-format initial conditions under `dataset` (when it has role initial).
  persistence in_swift_initial_conditions(std::string dataset) const {
    return with([&dataset](persistence& p) { p.swift_.initial_conditions_dataset = std::move(dataset); });
  }
  /// In snapshots for moving particles only: particles held fixed (walls) have no such dataset.
  persistence moving_particles_only() const {
    return with([](persistence& p) { p.swift_.moving_particles_only = true; });
  }

  role roles() const { return roles_; }
  bool has(role wanted) const { return any_of(roles_, wanted); }
  bool is_padded() const { return padded_; }
  initial_reading reading() const { return reading_; }
  const value_rule& rule() const { return rule_; }
  /// The feature the field's roles depend on ("" when none).
  const std::string& feature() const { return feature_; }
  const unit_exponents& units() const { return units_; }
  const swift_naming& swift() const { return swift_; }

  /// The dataset names of a field called `field_name` with `components` components: as given,
  /// or the defaults.
  std::vector<std::string> dataset_names(const std::string& field_name, int components) const {
    if (!datasets_.empty()) return datasets_;
    if (components == 1) return {field_name};
    std::vector<std::string> names;
    for (int k = 0; k < components; ++k) names.push_back(field_name + "_" + std::to_string(k));
    return names;
  }

 private:
  template<class Change>
  persistence with(Change change) const {
    persistence p = *this;
    change(p);
    return p;
  }
  persistence initial(initial_reading how, value_rule rule) const {
    persistence p = *this;
    p.roles_ = p.roles_ | role::initial;
    p.reading_ = how;
    p.rule_ = std::move(rule);
    return p;
  }

  std::vector<std::string> datasets_;
  bool padded_ = false;
  role roles_ = role::none;
  initial_reading reading_ = initial_reading::optional;
  value_rule rule_;
  std::string feature_;
  unit_exponents units_;
  swift_naming swift_;
};

}  // namespace flecsi_lite::data

namespace flecsi_lite::persist {
/// Entry points of the chain: persist::output().restart(), persist::as("m").output(), ...
template<class... Names>
data::persistence as(Names&&... names) {
  return data::persistence().as(std::forward<Names>(names)...);
}
inline data::persistence output() { return data::persistence().output(); }
inline data::persistence restart() { return data::persistence().restart(); }
inline data::persistence initial_required(data::value_rule rule = {}) {
  return data::persistence().initial_required(std::move(rule));
}
inline data::persistence initial_optional(data::value_rule rule = {}) {
  return data::persistence().initial_optional(std::move(rule));
}
using data::at_least;
using data::must_be_finite;
using data::must_be_positive;
using data::one_of;
}  // namespace flecsi_lite::persist
