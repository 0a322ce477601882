// Named wall-clock timers (timers.hh): per-rank totals, the union of the timed intervals for the
// "unaccounted" row, and the summary over ranks.
#include "flecsi_lite/runtime/timers.hh"

#include "flecsi_lite/runtime/context.hh"

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <unordered_map>
#include <utility>

namespace flecsi_lite::timers {
namespace {
using clock = std::chrono::steady_clock;

struct accumulated {
  double seconds = 0;
  long calls = 0;
};
std::vector<std::string> order;
std::unordered_map<std::string, accumulated> table;
std::unordered_map<std::string, std::string> readable_names;  // raw name -> row name

clock::time_point started = clock::now();  // at program start (static initialization)
double seconds_since_start() { return std::chrono::duration<double>(clock::now() - started).count(); }

/// The union of the timed intervals [end - seconds, end]: its length, and the latest disjoint
/// intervals in order of their ends. A call ends after the calls nested in it, so a new interval
/// contains every kept one that starts after it, and can overlap only the one before those.
/// Only the latest `kept_intervals` are kept (a call that spans more is partly counted twice).
double covered = 0;
std::vector<std::pair<double, double>> intervals;
constexpr std::size_t kept_intervals = 1024;

void cover(double begin, double end) {
  while (!intervals.empty() && intervals.back().first >= begin) {
    covered -= intervals.back().second - intervals.back().first;
    intervals.pop_back();
  }
  if (!intervals.empty() && intervals.back().second > begin) {
    begin = intervals.back().first;
    covered -= intervals.back().second - intervals.back().first;
    intervals.pop_back();
  }
  intervals.emplace_back(begin, end);
  covered += end - begin;
  if (intervals.size() > 2 * kept_intervals)
    intervals.erase(intervals.begin(), intervals.begin() + static_cast<std::ptrdiff_t>(kept_intervals));
}

/// "a::b::c" minus the components "detail", "{anonymous}", "(anonymous namespace)".
std::vector<std::string> name_components(const std::string& name) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t end = name.find("::", begin);
    std::string part = name.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    if (!part.empty() && part != "detail" && part != "{anonymous}" && part != "(anonymous namespace)")
      parts.push_back(std::move(part));
    if (end == std::string::npos) return parts;
    begin = end + 2;
  }
}
}  // namespace

std::string readable_name(const std::string& name) {
  std::string plain;  // without template arguments
  int depth = 0;
  for (const char c : name) {
    if (c == '<')
      ++depth;
    else if (c == '>' && depth > 0)
      --depth;
    else if (depth == 0)
      plain += c;
  }
  if (plain.find(' ') != std::string::npos && plain.find("(anonymous namespace)") == std::string::npos)
    return plain;  // a phrase ("ntree::distribute keys"), not a C++ name
  const auto parts = name_components(plain);
  if (parts.empty()) return plain;
  return parts.size() == 1 ? parts.back() : parts[parts.size() - 2] + "::" + parts.back();
}

void add(const std::string& name, double seconds) {
  const double end = seconds_since_start();
  cover(end - seconds, end);
  auto known = readable_names.find(name);
  if (known == readable_names.end()) known = readable_names.emplace(name, readable_name(name)).first;
  auto [it, inserted] = table.try_emplace(known->second);
  if (inserted) order.push_back(known->second);
  it->second.seconds += seconds;
  it->second.calls += 1;
}

double wall_seconds() { return seconds_since_start(); }
double covered_seconds() { return covered; }

void clear() {
  order.clear();
  table.clear();
  intervals.clear();
  covered = 0;
  started = clock::now();
}

namespace {
/// min, sum and max of `mine` over the ranks, element by element.
void over_ranks(const std::vector<double>& mine, std::vector<double>& lo, std::vector<double>& sum,
                std::vector<double>& hi) {
  MPI_Comm comm = runtime::communicator();
  const int n = static_cast<int>(mine.size());
  lo.resize(mine.size());
  sum.resize(mine.size());
  hi.resize(mine.size());
  MPI_Allreduce(mine.data(), lo.data(), n, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(mine.data(), hi.data(), n, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(mine.data(), sum.data(), n, MPI_DOUBLE, MPI_SUM, comm);
}

summary_row row_of(std::string name, long calls, double lo, double sum, double hi) {
  return {std::move(name), calls, lo, sum / runtime::size(), hi};
}
}  // namespace

std::vector<summary_row> summarize() {
  // Rank 0's names define the rows; every rank reports its own time for each (0 if unused).
  MPI_Comm comm = runtime::communicator();
  std::string names;
  for (auto& n : order) names += n + '\n';
  int length = static_cast<int>(names.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, comm);
  names.resize(length);
  MPI_Bcast(names.data(), length, MPI_CHAR, 0, comm);

  std::vector<std::string> row_names;
  std::size_t begin = 0;
  for (std::size_t end; (end = names.find('\n', begin)) != std::string::npos; begin = end + 1)
    row_names.push_back(names.substr(begin, end - begin));
  std::vector<double> mine(row_names.size(), 0.0), lo, sum, hi;
  for (std::size_t i = 0; i < row_names.size(); ++i)
    if (auto it = table.find(row_names[i]); it != table.end()) mine[i] = it->second.seconds;
  over_ranks(mine, lo, sum, hi);
  std::vector<summary_row> rows;
  for (std::size_t i = 0; i < row_names.size(); ++i) {
    auto it = table.find(row_names[i]);
    rows.push_back(row_of(row_names[i], it == table.end() ? 0 : it->second.calls, lo[i], sum[i], hi[i]));
  }
  return rows;
}

void report(std::ostream& out) {
  const auto rows = summarize();
  const double wall = wall_seconds();
  std::vector<double> lo, sum, hi;
  over_ranks({wall, std::max(0.0, wall - covered_seconds())}, lo, sum, hi);
  if (runtime::rank() != 0 || rows.empty()) return;
  const std::vector<summary_row> totals = {row_of("total (wall time)", 1, lo[0], sum[0], hi[0]),
                                           row_of("unaccounted (no timer)", 1, lo[1], sum[1], hi[1])};
  std::size_t width = 5;
  for (auto& r : rows) width = std::max(width, r.name.size());
  for (auto& r : totals) width = std::max(width, r.name.size());
  out << "\nTimers (seconds over " << runtime::size() << " rank(s); nested timers are part of their callers')\n"
      << std::left << std::setw(int(width)) << "timer" << std::right << std::setw(10) << "calls" << std::setw(12)
      << "min" << std::setw(12) << "mean" << std::setw(12) << "max" << '\n';
  out << std::fixed << std::setprecision(4);
  const auto line = [&](const summary_row& r) {
    out << std::left << std::setw(int(width)) << r.name << std::right << std::setw(10) << r.calls << std::setw(12)
        << r.min << std::setw(12) << r.mean << std::setw(12) << r.max << '\n';
  };
  for (auto& r : rows) line(r);
  for (auto& r : totals) line(r);
  out << std::defaultfloat;
}

}  // namespace flecsi_lite::timers
