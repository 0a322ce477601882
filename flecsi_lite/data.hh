// The data model: field definitions, references and accessors with privileges, the storage of a
// field, what every topology instance shares (owned and ghost entities, the ghost plan), tracked
// objects (data other than fields that tasks share), and the persistence of fields (output, restart, initial data) with the I/O that walks them.
#pragma once
#include "flecsi_lite/data/field.hh"
#include "flecsi_lite/data/field_registry.hh"
#include "flecsi_lite/data/field_storage.hh"
#include "flecsi_lite/data/ghost_plan_builder.hh"
#include "flecsi_lite/data/persistence.hh"
#include "flecsi_lite/data/privilege.hh"
#include "flecsi_lite/data/topology_base.hh"
#include "flecsi_lite/data/tracked.hh"
