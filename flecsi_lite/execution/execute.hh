// execute<task>(args...) and reduce<task, op>(args...): launch a task through the executor.
//
// The task's parameter types say how each argument is passed:
//   accessor<T, owned, ghost>  <- a field reference: privileges recorded, dependencies derived
//   tracked<X>::accessor<p>    <- a tracked<X>: its privilege recorded, dependencies derived
//   T (a value)                <- a future<T>: the task waits for the launch producing it
//   X& or const X&             <- an lvalue X of a shared_argument type (topologies and the
//                                 types that opt in, shared_argument.hh): by reference
//   const X&, X (a value)      <- anything else: copied when the task is launched, so later
//                                 changes by the caller do not reach the task
// A non-const X& of any other type does not compile (the task would write a private copy).
#pragma once

#include "flecsi_lite/data/field.hh"
#include "flecsi_lite/data/tracked.hh"
#include "flecsi_lite/execution/executor.hh"
#include "flecsi_lite/execution/future.hh"
#include "flecsi_lite/execution/reduction.hh"
#include "flecsi_lite/execution/shared_argument.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/runtime/timers.hh"

#include <string_view>
#include <tuple>
#include <utility>

namespace flecsi_lite {
namespace execution::detail {

template<class F>
struct function_traits;
template<class R, class... P>
struct function_traits<R (*)(P...)> {
  using result = R;
  using parameters = std::tuple<P...>;
};
template<class R, class... P>
struct function_traits<R (*)(P...) noexcept> : function_traits<R (*)(P...)> {};

/// The task's name as written in the program (for traces and timers).
template<auto F>
std::string task_name() {
  std::string_view s = __PRETTY_FUNCTION__;
  const auto begin = s.find("F = ");
  if (begin == std::string_view::npos) return std::string(s);
  s.remove_prefix(begin + 4);
  s = s.substr(0, s.find_first_of(";]"));
  if (s.size() && s.front() == '&') s.remove_prefix(1);
  std::string name(s);
  for (std::size_t at; (at = name.find("{anonymous}::")) != std::string::npos;) name.erase(at, 13);
  return name;
}

template<class T>
struct is_field_reference : std::false_type {};
template<class T, class Topo>
struct is_field_reference<field_reference<T, Topo>> : std::true_type {};
template<class T>
struct is_tracked : std::false_type {};
template<class T>
struct is_tracked<tracked<T>> : std::true_type {};
template<class T>
struct is_tracked_accessor : std::false_type {};
template<class T, privilege P>
struct is_tracked_accessor<tracked_accessor<T, P>> : std::true_type {};
template<class T>
struct is_accessor : std::false_type {};
template<class T, privilege O, privilege G>
struct is_accessor<accessor<T, O, G>> : std::true_type {};

struct collector {
  std::vector<field_access> accesses;
  std::vector<launch_ptr> after;
};

/// Holds one argument from launch to run time and converts it to the task's parameter.
template<class Param, class Arg, class = void>
struct binder {  // copy, at launch
  static_assert(!std::is_lvalue_reference_v<Param> || std::is_const_v<std::remove_reference_t<Param>>,
                "a task parameter X& (non-const reference) takes only shared_argument types "
                "(flecsi_lite/execution/shared_argument.hh): take the value or a const reference "
                "(both copied at launch), or pass the data as a field");
  static_assert(std::is_copy_constructible_v<std::decay_t<Arg>>,
                "task arguments are copied at launch; a type that cannot be copied must opt in "
                "through flecsi_lite::execution::shared_argument to travel by reference");
  std::decay_t<Arg> value;
  explicit binder(Arg&& a) : value(std::forward<Arg>(a)) {}
  void collect(collector&) const {}
  Param get() { return value; }
};

template<class Param, class Arg>
struct binder<Param, Arg,
              std::enable_if_t<std::is_lvalue_reference_v<Param> && shared_argument_v<Arg> &&
                               !is_field_reference<std::decay_t<Arg>>::value && !is_tracked<std::decay_t<Arg>>::value &&
                               !is_future<std::decay_t<Arg>>::value>> {  // by reference
  static_assert(std::is_lvalue_reference_v<Arg>, "a shared argument is passed as itself, not as a temporary");
  static_assert(std::is_const_v<std::remove_reference_t<Param>> || !std::is_const_v<std::remove_reference_t<Arg>>,
                "a task parameter X& needs a non-const argument");
  std::remove_reference_t<Arg>* pointer;
  explicit binder(Arg&& a) : pointer(&a) {}
  void collect(collector&) const {}
  Param get() { return *pointer; }
};

template<class Param, class Arg>
struct binder<Param, Arg, std::enable_if_t<is_field_reference<std::decay_t<Arg>>::value>> {
  using reference = std::decay_t<Arg>;
  using accessor_type = std::decay_t<Param>;
  static_assert(is_accessor<accessor_type>::value,
                "a field reference must be passed to an accessor<T, owned, ghost> parameter");
  static_assert(std::is_same_v<typename accessor_type::value_type, typename reference::value_type>,
                "the accessor's value type differs from the field's");
  reference ref;
  explicit binder(Arg&& a) : ref(a) {}
  void collect(collector& c) const {
    if (!ref.present()) return;  // an absent field: no dependency, no ghost copy, no storage
    c.accesses.push_back({ref.topology().instance_id(), &ref.topology(), ref.id(), &ref.storage(),
                          accessor_type::owned_privilege, accessor_type::ghost_privilege});
  }
  accessor_type get() {
    return ref.template make_accessor<accessor_type::owned_privilege, accessor_type::ghost_privilege>();
  }
};

template<class Param, class Arg>
struct binder<Param, Arg, std::enable_if_t<is_tracked<std::decay_t<Arg>>::value>> {
  using object = std::decay_t<Arg>;
  using accessor_type = std::decay_t<Param>;
  static_assert(is_tracked_accessor<accessor_type>::value,
                "a tracked object must be passed to a tracked<T>::accessor<privilege> parameter");
  static_assert(std::is_same_v<typename accessor_type::value_type, typename object::value_type>,
                "the accessor's value type differs from the tracked object's");
  static_assert(std::is_lvalue_reference_v<Arg>, "a tracked object is passed as itself, not as a temporary");
  static_assert(!writes(accessor_type::object_privilege) || !std::is_const_v<std::remove_reference_t<Arg>>,
                "a task that writes a tracked object needs it non-const");
  std::remove_reference_t<Arg>* pointer;
  explicit binder(Arg&& a) : pointer(&a) {}
  void collect(collector& c) const {
    c.accesses.push_back({pointer->instance_id(), nullptr, 0, nullptr, accessor_type::object_privilege, na});
  }
  accessor_type get() { return accessor_type(pointer->launch_value()); }
};

template<class Param, class Arg>
struct binder<Param, Arg,
              std::enable_if_t<is_future<std::decay_t<Arg>>::value && !is_future<std::decay_t<Param>>::value>> {
  std::decay_t<Arg> f;
  explicit binder(Arg&& a) : f(a) {}
  void collect(collector& c) const { c.after.push_back(f.launch()); }
  decltype(auto) get() { return f.value(); }
};

template<class Parameters, class... Args, std::size_t... I>
auto bind(std::index_sequence<I...>, Args&&... args) {
  using tuple = std::tuple<binder<std::tuple_element_t<I, Parameters>, Args>...>;
  return std::make_shared<tuple>(binder<std::tuple_element_t<I, Parameters>, Args>(std::forward<Args>(args))...);
}

template<auto F, class... Args>
auto prepare(Args&&... args) {
  using parameters = typename function_traits<decltype(F)>::parameters;
  static_assert(std::tuple_size_v<parameters> == sizeof...(Args), "wrong number of task arguments");
  auto binders = bind<parameters>(std::index_sequence_for<Args...>{}, std::forward<Args>(args)...);
  collector c;
  std::apply([&c](auto&... b) { (b.collect(c), ...); }, *binders);
  return std::make_pair(binders, std::move(c));
}

}  // namespace execution::detail

/// Launches task F; returns a future of its result.
template<auto F, class... Args>
auto execute(Args&&... args) {
  using namespace execution::detail;
  using result = typename function_traits<decltype(F)>::result;
  auto [binders, c] = prepare<F>(std::forward<Args>(args)...);
  auto& ex = execution::executor::instance();
  static const std::string name = task_name<F>();
  if constexpr (std::is_void_v<result>) {
    auto l = ex.record(name, execution::launch_kind::task, c.accesses, std::move(c.after),
                       [b = binders](execution::launch&) { std::apply([](auto&... a) { F(a.get()...); }, *b); });
    return future<void>(l);
  } else {
    auto value = std::make_shared<std::optional<result>>();
    auto l = ex.record(
      name, execution::launch_kind::task, c.accesses, std::move(c.after),
      [b = binders, value](execution::launch&) { *value = std::apply([](auto&... a) { return F(a.get()...); }, *b); });
    return future<result>(l, value);
  }
}

/// Launches task F on every rank and combines the results over ranks with Op (reduction::sum,
/// min, max, exact_sum); returns a future of the combined value, the same on every rank.
/// Two launches: the local task (holds the field privileges, so the fields are free once it
/// has run) and the collective (holds only the value).
template<auto F, class Op, class... Args>
auto reduce(Args&&... args) {
  using namespace execution::detail;
  using local = std::decay_t<typename function_traits<decltype(F)>::result>;
  using carrier = reduction::detail::carrier<Op, local>;
  using transported = typename carrier::transported;
  using result = typename carrier::result;
  static_assert(std::is_trivially_copyable_v<transported>, "reduced values are sent as bytes");
  auto [binders, c] = prepare<F>(std::forward<Args>(args)...);
  auto value = std::make_shared<std::optional<result>>();
  struct buffers {
    transported mine;
    std::vector<transported> all;
  };
  auto buffer = std::make_shared<buffers>();
  static const std::string name = task_name<F>();
  static const std::string collective_name = name + " (combine)";
  auto& ex = execution::executor::instance();
  auto part = ex.record(name, execution::launch_kind::task, c.accesses, std::move(c.after),
                        [b = binders, buffer](execution::launch&) {
                          buffer->mine = carrier::pack(std::apply([](auto&... a) { return F(a.get()...); }, *b));
                        });
  auto l = ex.record(
    collective_name, execution::launch_kind::reduction, {}, {part},
    [buffer](execution::launch& self) {
      buffer->all.resize(runtime::size());
      MPI_Request request;
      MPI_Iallgather(&buffer->mine, sizeof(transported), MPI_BYTE, buffer->all.data(), sizeof(transported), MPI_BYTE,
                     runtime::communicator(), &request);
      self.requests.push_back(request);
    },
    [buffer, value] {
      transported combined = buffer->all[0];
      for (std::size_t r = 1; r < buffer->all.size(); ++r) combined = Op::combine(combined, buffer->all[r]);
      *value = carrier::unpack(combined);
    });
  return future<result>(l, value);
}

/// Every rank's executor finishes all launches (fields may then be read directly).
inline void wait_all() { execution::executor::instance().wait_all(); }

/// A field's values after every pending launch is done: for inspection, I/O and tests. The
/// view may write the ghosts, so the field's next ghost copy sends every value.
template<class T, class Topo>
auto host_view(const field_reference<T, Topo>& ref) {
  auto& ex = execution::executor::instance();
  ex.wait_all();
  ex.forget_sent_values(ref.topology().instance_id(), ref.id());
  return typename data::field_storage<T>::view_type(ref.storage().view());
}

/// The same, read only: the ghosts keep what the last copy delivered, and the next copy sends
/// only the values that changed.
template<class T, class Topo>
auto host_read(const field_reference<T, Topo>& ref) {
  wait_all();
  return Kokkos::View<const T*, memory_space>(ref.storage().view());
}

}  // namespace flecsi_lite
