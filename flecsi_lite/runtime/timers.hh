// Named wall-clock timers, accumulated per rank and summarized across ranks at the end of a run.
// Usage: { flecsi_lite::timers::scoped t("density"); ... }
#pragma once

#include <chrono>
#include <iosfwd>
#include <string>
#include <vector>

namespace flecsi_lite::timers {

/// Adds `seconds` (one call) to the timer `name`.
void add(const std::string& name, double seconds);

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
  long calls = 0;     // on rank 0
  double min = 0;     // over ranks, seconds
  double mean = 0;
  double max = 0;
};

/// Collective: per-timer min/mean/max over ranks, in order of first use on rank 0.
std::vector<summary_row> summarize();
/// Collective: writes the summary table on rank 0.
void report(std::ostream& out);
void clear();

} // namespace flecsi_lite::timers
