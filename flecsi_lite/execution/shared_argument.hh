// Which task arguments travel by reference. execute<task>(args...) copies every argument when
// the task is launched (a const X& parameter gets a reference to that copy), so a task never
// sees a change the caller makes after the launch. A type opts out of the copy through
// shared_argument: its objects are passed by reference (X& or const X& parameters), and the
// caller promises to keep them alive and unchanged until the launches that use them have run.
//
//   template<> struct flecsi_lite::execution::shared_argument<my_lists> : std::true_type {};
#pragma once

#include "flecsi_lite/data/topology_base.hh"

#include <type_traits>

namespace flecsi_lite::execution {

/// True for types tasks take by reference. Topologies are: their layout changes wait for every
/// pending launch, and their values reach tasks through fields.
template<class T>
struct shared_argument : std::is_base_of<data::topology_base, T> {};

template<class T>
inline constexpr bool shared_argument_v = shared_argument<std::remove_cv_t<std::remove_reference_t<T>>>::value;

}  // namespace flecsi_lite::execution
