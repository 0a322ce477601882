// Internals of the accessors (field.hh): the error of an access outside the regions a task's
// privileges allow, naming the field, the entity and the privileges.
#pragma once

#include "flecsi_lite/data/privilege.hh"

#include <cstddef>
#include <stdexcept>
#include <string>

namespace flecsi_lite::data::detail {

/// Thrown (out of line: the hot loops stay small) when a task touches entity `index` of field
/// `name` outside what accessor<owned, ghost> allows.
[[noreturn, gnu::cold, gnu::noinline]] inline void access_outside_privileges(const std::string* name, std::size_t index,
                                                                             std::size_t owned, std::size_t size,
                                                                             privilege owned_privilege,
                                                                             privilege ghost_privilege) {
  const std::string field = name ? "field '" + *name + "'" : "a field";
  const std::string where =
    index < owned ? "owned entity " + std::to_string(index) + " (owned privilege na)"
                  : "entity " + std::to_string(index) + " (the accessor spans " + std::to_string(size) + " entities)";
  throw std::out_of_range("flecsi_lite: " + field + ": a task with accessor<" + privilege_name(owned_privilege) + ", " +
                          privilege_name(ghost_privilege) + "> touched " + where + "; owned entities are [0, " +
                          std::to_string(owned) + ")");
}

}  // namespace flecsi_lite::data::detail
