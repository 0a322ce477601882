// Futures of launches: get() runs the executor until the launch (and, for a reduction, its
// collective) is done, and rethrows the launch's exception when it failed (or the cancellation,
// naming the failed launch, when a launch it depended on failed). A future can be passed to a task whose parameter is the value type:
// the task then depends on the launch that produces it.
#pragma once

#include "flecsi_lite/execution/executor.hh"

#include <optional>

namespace flecsi_lite {

template<class T>
class future {
 public:
  using value_type = T;
  future() = default;
  future(execution::launch_ptr l, std::shared_ptr<std::optional<T>> value)
      : launch_(std::move(l)), value_(std::move(value)) {}

  bool ready() const { return !launch_ || launch_->finished(); }
  /// False for a default-constructed future (no launch will give it a value).
  bool valid() const { return value_ != nullptr; }
  void wait() const {
    if (launch_) execution::executor::instance().wait(*launch_);
  }
  const T& get() const {
    wait();
    return **value_;
  }
  const execution::launch_ptr& launch() const { return launch_; }
  /// The value of a launch known to be done (what tasks receive for a future argument).
  const T& value() const { return **value_; }

 private:
  execution::launch_ptr launch_;
  std::shared_ptr<std::optional<T>> value_;
};

template<>
class future<void> {
 public:
  using value_type = void;
  future() = default;
  explicit future(execution::launch_ptr l) : launch_(std::move(l)) {}
  bool ready() const { return !launch_ || launch_->finished(); }
  void wait() const {
    if (launch_) execution::executor::instance().wait(*launch_);
  }
  void get() const { wait(); }
  const execution::launch_ptr& launch() const { return launch_; }

 private:
  execution::launch_ptr launch_;
};

template<class T>
struct is_future : std::false_type {};
template<class T>
struct is_future<future<T>> : std::true_type {};

}  // namespace flecsi_lite
