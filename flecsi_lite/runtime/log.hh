// Per-rank logging: rank 0 speaks by default, every rank with --log-all-ranks. Errors and
// warnings always print. Usage: flecsi_lite::log::info() << "step " << n;
#pragma once

#include <sstream>
#include <string>

namespace flecsi_lite::log {

enum class severity { debug, info, warn, error };

void set_all_ranks(bool all);
void set_threshold(severity s);
bool enabled(severity s);

/// One message, printed (prefixed by the rank when several ranks speak) when it goes out of scope.
class message {
 public:
  explicit message(severity s) : severity_(s), active_(enabled(s)) {}
  message(const message&) = delete;
  ~message();
  template<class T>
  message& operator<<(const T& value) {
    if (active_) stream_ << value;
    return *this;
  }

 private:
  severity severity_;
  bool active_;
  std::ostringstream stream_;
};

inline message debug() { return message(severity::debug); }
inline message info() { return message(severity::info); }
inline message warn() { return message(severity::warn); }
inline message error() { return message(severity::error); }

}  // namespace flecsi_lite::log
