// The data model: field definitions, references and accessors with privileges, the storage of a
// field, and what every topology instance shares (owned and ghost entities, the ghost plan).
#pragma once
#include "flecsi_lite/data/field.hh"
#include "flecsi_lite/data/field_storage.hh"
#include "flecsi_lite/data/privilege.hh"
#include "flecsi_lite/data/topology_base.hh"
