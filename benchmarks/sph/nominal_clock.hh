// The clock the SPH benchmarks count cycles at.
#pragma once

#include <fstream>
#include <string>

namespace flecsph::benchmarks {

/// `given` when positive (--clock-ghz), else the first "cpu MHz" of /proc/cpuinfo (Linux: the
/// nominal clock on these VMs), else 1 GHz (the counts are then nanoseconds).
inline double nominal_clock_ghz(double given) {
  if (given > 0) return given;
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("cpu MHz", 0) == 0 && line.find(':') != std::string::npos)
      return std::stod(line.substr(line.find(':') + 1)) / 1000.0;
  return 1.0;
}

}  // namespace flecsph::benchmarks
