#include "flecsi_lite/runtime/timers.hh"

#include "flecsi_lite/runtime/context.hh"

#include <iomanip>
#include <ostream>
#include <unordered_map>

namespace flecsi_lite::timers {
namespace {
struct accumulated {
  double seconds = 0;
  long calls = 0;
};
std::vector<std::string> order;
std::unordered_map<std::string, accumulated> table;
} // namespace

void add(const std::string& name, double seconds) {
  auto [it, inserted] = table.try_emplace(name);
  if (inserted) order.push_back(name);
  it->second.seconds += seconds;
  it->second.calls += 1;
}

void clear() {
  order.clear();
  table.clear();
}

std::vector<summary_row> summarize() {
  // Rank 0's names define the rows; every rank reports its own time for each (0 if unused).
  MPI_Comm comm = runtime::communicator();
  std::string names;
  for (auto& n : order) names += n + '\n';
  int length = static_cast<int>(names.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, comm);
  names.resize(length);
  MPI_Bcast(names.data(), length, MPI_CHAR, 0, comm);

  std::vector<summary_row> rows;
  std::size_t begin = 0;
  for (std::size_t end; (end = names.find('\n', begin)) != std::string::npos; begin = end + 1)
    rows.push_back({names.substr(begin, end - begin)});
  std::vector<double> mine(rows.size(), 0.0), lo(rows.size()), hi(rows.size()), sum(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (auto it = table.find(rows[i].name); it != table.end()) mine[i] = it->second.seconds;
  const int n = static_cast<int>(rows.size());
  MPI_Allreduce(mine.data(), lo.data(), n, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(mine.data(), hi.data(), n, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(mine.data(), sum.data(), n, MPI_DOUBLE, MPI_SUM, comm);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    auto it = table.find(rows[i].name);
    rows[i].calls = it == table.end() ? 0 : it->second.calls;
    rows[i].min = lo[i];
    rows[i].max = hi[i];
    rows[i].mean = sum[i] / runtime::size();
  }
  return rows;
}

void report(std::ostream& out) {
  const auto rows = summarize();
  if (runtime::rank() != 0 || rows.empty()) return;
  std::size_t width = 5;
  for (auto& r : rows) width = std::max(width, r.name.size());
  out << "\nTimers (seconds over " << runtime::size() << " rank(s))\n"
      << std::left << std::setw(int(width)) << "timer" << std::right << std::setw(10) << "calls"
      << std::setw(12) << "min" << std::setw(12) << "mean" << std::setw(12) << "max" << '\n';
  out << std::fixed << std::setprecision(4);
  for (auto& r : rows)
    out << std::left << std::setw(int(width)) << r.name << std::right << std::setw(10) << r.calls
        << std::setw(12) << r.min << std::setw(12) << r.mean << std::setw(12) << r.max << '\n';
  out << std::defaultfloat;
}

} // namespace flecsi_lite::timers
