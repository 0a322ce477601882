// Named wall-clock timers, accumulated per rank and summarized across ranks at the end of a run,
// with the run's wall time and the part of it no timer covered. Usage:
//   { flecsi_lite::timers::scoped t("density"); ... }
#pragma once

#include <chrono>
#include <iosfwd>
#include <string>
#include <vector>

namespace flecsi_lite::timers {

/// Adds `seconds` (one call) to the timer `name`; the call is taken to have ended now, so that
/// the time covered by any timer (nested ones counted once) is known. A C++ name is shortened
/// (readable_name): "flecsph::sph::compute_density<2>" is timed as "sph::compute_density".
void add(const std::string& name, double seconds);

/// `name` without template arguments, "detail" and anonymous namespaces, and with at most one
/// namespace: "a::b::detail::f<1, c<2>>" -> "b::f". Names with a space are kept as they are.
std::string readable_name(const std::string& name);

/// Times its own lifetime into the timer `name`.
class scoped {
 public:
  explicit scoped(std::string name) : name_(std::move(name)), start_(clock::now()) {}
  scoped(const scoped&) = delete;
  ~scoped() { add(name_, std::chrono::duration<double>(clock::now() - start_).count()); }

 private:
  using clock = std::chrono::steady_clock;
  std::string name_;
  clock::time_point start_;
};

struct summary_row {
  std::string name;
  long calls = 0;  // on rank 0
  double min = 0;  // over ranks, seconds
  double mean = 0;
  double max = 0;
};

/// Collective: per-timer min/mean/max over ranks, in order of first use on rank 0.
std::vector<summary_row> summarize();
/// This rank's wall seconds since the program started (or since clear()).
double wall_seconds();
/// This rank's wall seconds covered by at least one timer call since then: their union, so that
/// nested timers (a task inside a phase) count once.
double covered_seconds();
/// Collective: writes the summary table on rank 0: the timers, then "total" (wall time) and
/// "unaccounted" (wall time no timer covered) rows.
void report(std::ostream& out);
/// Forgets every timer and restarts the wall clock.
void clear();

}  // namespace flecsi_lite::timers
