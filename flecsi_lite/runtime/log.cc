#include "flecsi_lite/runtime/log.hh"

#include "flecsi_lite/runtime/context.hh"

#include <iostream>

namespace flecsi_lite::log {
namespace {
bool all_ranks = false;
severity threshold = severity::info;
}  // namespace

void set_all_ranks(bool all) { all_ranks = all; }
void set_threshold(severity s) { threshold = s; }

bool enabled(severity s) {
  if (s < threshold) return false;
  if (s >= severity::warn) return true;
  return all_ranks || runtime::rank() == 0;
}

message::~message() {
  if (!active_) return;
  std::ostringstream line;
  if (all_ranks || severity_ >= severity::warn) line << "[rank " << runtime::rank() << "] ";
  if (severity_ == severity::warn) line << "warning: ";
  if (severity_ == severity::error) line << "error: ";
  line << stream_.str() << '\n';
  auto& out = severity_ >= severity::warn ? std::cerr : std::cout;
  out << line.str() << std::flush;
}

}  // namespace flecsi_lite::log
