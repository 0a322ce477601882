# Checks the h5part_to_ascii tool on files that the 1-rank I/O test writes: default columns in
# splash's order, a chosen step and columns written to a file, clear errors, and a help without
# Kokkos options (the tool does not start Kokkos). tests/clients runs splash on its output.
# Usage: cmake -DTOOL=<h5part_to_ascii> -P check_h5part_to_ascii.cmake

function(run_tool)
  execute_process(COMMAND ${TOOL} ${ARGN} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
  set(rc "${rc}" PARENT_SCOPE)
endfunction()

function(require text pattern what)
  if(NOT "${text}" MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: expected to match '${pattern}', got:\n${text}")
  endif()
endfunction()

# Default columns: x y z vx vy vz m rho P u h id, in that order, then one row per particle.
run_tool(mpi_io_sph_columns_1ranks.h5part)
require("${rc}" "^0$" "default export exit code")
require("${out}" "^# 3\\.1250000000000000e-01  is the time of Step#0 \\(iteration 40\\)" "time line")
require("${out}" "\n#[ ]+x[ ]+y[ ]+z[ ]+vx[ ]+vy[ ]+vz[ ]+m[ ]+rho[ ]+P[ ]+u[ ]+h[ ]+id\n" "default labels")
string(REGEX MATCHALL "\n  [^#\n]+" rows "${out}")
list(LENGTH rows row_count)
require("${row_count}" "^4$" "one row per particle")

# A chosen step and columns, to a file that appears complete.
file(REMOVE step1.dat)
run_tool(--step 1 --columns x,id mpi_io_round_trip_1ranks.h5part --output step1.dat)
require("${rc}" "^0$" "export to a file")
file(READ step1.dat text)
require("${text}" "^# 2\\.6785714285714285e-01  is the time of Step#1" "time of step 1")
require("${text}" "\n#[ ]+x[ ]+id\n  1\\.0033333333333333e\\+02[ ]+1099511627777\n" "first row of step 1")
if(EXISTS step1.dat.partial)
  message(FATAL_ERROR "the partial output file was left behind")
endif()

# --output never replaces what is not a regular file: a folder, a symbolic link (its target stays
# as it was), a device; nor writes where the folder is missing. Refused before anything is written.
file(REMOVE_RECURSE export_folder.dat)
file(MAKE_DIRECTORY export_folder.dat)
run_tool(mpi_io_round_trip_1ranks.h5part --output export_folder.dat)
require("${rc}:${err}" "^1:h5part_to_ascii: --output 'export_folder.dat' exists and is a directory, not a regular file" "folder output")
file(WRITE export_target.dat "an earlier export\n")
file(REMOVE export_link.dat)
file(CREATE_LINK export_target.dat export_link.dat SYMBOLIC)
run_tool(mpi_io_round_trip_1ranks.h5part --output export_link.dat)
require("${rc}:${err}" "^1:.*--output 'export_link.dat' exists and is a symbolic link" "symbolic link output")
file(READ export_target.dat kept)
require("${kept}" "^an earlier export\n$" "the link's target is untouched")
if(NOT IS_SYMLINK export_link.dat OR EXISTS export_link.dat.partial)
  message(FATAL_ERROR "the symbolic link was replaced, or a partial file was written")
endif()
if(EXISTS /dev/full)
  run_tool(mpi_io_round_trip_1ranks.h5part --output /dev/full)
  require("${rc}:${err}" "^1:.*--output '/dev/full' exists and is a character device" "device output")
endif()
run_tool(mpi_io_round_trip_1ranks.h5part --output no_such_folder/out.dat)
require("${rc}:${err}" "^1:.*cannot write --output 'no_such_folder/out.dat': its folder 'no_such_folder' does not exist" "missing folder")

# Errors name what is missing; usage errors exit with 2.
run_tool(no_such_file.h5part)
require("${rc}:${err}" "^1:h5part_to_ascii: cannot open 'no_such_file.h5part': no such file" "missing file")
run_tool(--step 99 mpi_io_round_trip_1ranks.h5part)
require("${rc}:${err}" "^1:.*has no step 99 \\(it has steps 0 to 2\\)" "missing step")
run_tool(--columns x,ids mpi_io_round_trip_1ranks.h5part)
require("${rc}:${err}" "^1:.*has no dataset 'ids'; did you mean 'id'\\?" "missing column")
run_tool(mpi_io_errors_truncated_1ranks.h5part)
require("${rc}:${err}" "^1:.*is truncated or corrupted" "truncated file")
run_tool(--step abc mpi_io_round_trip_1ranks.h5part)
require("${rc}:${err}" "^2:.*--step takes a step index" "bad step")

# Help: the tool's own options only.
run_tool(--help)
require("${rc}:${out}" "^0:usage: h5part_to_ascii .*--columns" "help")
if("${out}" MATCHES "[Kk]okkos")
  message(FATAL_ERROR "the help of a tool that does not start Kokkos mentions Kokkos:\n${out}")
endif()
