// The data model: field definitions, references and accessors with privileges.
#pragma once
#include "flecsi_lite/data/field.hh"
#include "flecsi_lite/data/privilege.hh"
