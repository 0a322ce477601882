# Fails, naming file and line, when a source under specialization/, apps/ or tutorial/ includes a
# framework header other than an umbrella (flecsi_lite/<layer>.hh or
# flecsi_lite/topology/<topology>.hh): applications see the framework's public face only.
# Usage: cmake -DROOT=<source dir> -P check_umbrella_includes.cmake
set(_bad "")
set(_checked 0)
foreach(_dir specialization apps tutorial)
  file(GLOB_RECURSE _files ${ROOT}/${_dir}/*.hh ${ROOT}/${_dir}/*.cc)
  foreach(_file IN LISTS _files)
    math(EXPR _checked "${_checked} + 1")
    file(STRINGS ${_file} _lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]flecsi_lite/")
    foreach(_line IN LISTS _lines)
      if(NOT _line MATCHES "[\"<]flecsi_lite/(topology/)?[a-z_]+\\.hh[\">]")
        file(RELATIVE_PATH _name ${ROOT} ${_file})
        string(APPEND _bad "  ${_name}: ${_line}\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(_checked EQUAL 0)
  message(FATAL_ERROR "no sources found under ${ROOT}/{specialization,apps,tutorial}")
endif()
if(_bad)
  message(FATAL_ERROR "framework internals included outside flecsi_lite/ (include the umbrella "
                      "header of the layer instead):\n${_bad}")
endif()
message(STATUS "${_checked} files include the framework through its umbrella headers only")
