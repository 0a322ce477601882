# Test helpers: unit tests (one executable per source file) and MPI tests run at several rank
# counts through mpiexec, with the flags Open MPI needs for oversubscription and for root.
find_package(Catch2 2 REQUIRED)

# Open MPI refuses to oversubscribe cores or to run as root unless told; CI machines need both.
execute_process(COMMAND ${MPIEXEC_EXECUTABLE} --version OUTPUT_VARIABLE _flecsph_mpiexec_version
                ERROR_QUIET)
set(FLECSPH_MPIEXEC_FLAGS "")
if(_flecsph_mpiexec_version MATCHES "Open MPI|OpenRTE")
  list(APPEND FLECSPH_MPIEXEC_FLAGS --oversubscribe)
  execute_process(COMMAND id -u OUTPUT_VARIABLE _flecsph_uid OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(_flecsph_uid STREQUAL "0")
    list(APPEND FLECSPH_MPIEXEC_FLAGS --allow-run-as-root)
  endif()
endif()

# The same flags as one string, for tests run through a shell.
string(REPLACE ";" " " FLECSPH_MPIEXEC_FLAGS_STRING "${FLECSPH_MPIEXEC_FLAGS}")

# With Open MPI 4 every test's mpiexec runs its job with a session directory of its own
# (tests/support/mpiexec_own_session.sh.in says why): MPIEXEC_EXECUTABLE, from here on, is that
# wrapper (the cache keeps the real one).
if(_flecsph_mpiexec_version MATCHES "(Open MPI|OpenRTE)\\) 4\\.")
  set(FLECSPH_REAL_MPIEXEC ${MPIEXEC_EXECUTABLE})
  configure_file(${PROJECT_SOURCE_DIR}/tests/support/mpiexec_own_session.sh.in ${PROJECT_BINARY_DIR}/tests/mpiexec
                 FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ
                                  WORLD_EXECUTE @ONLY)
  set(MPIEXEC_EXECUTABLE ${PROJECT_BINARY_DIR}/tests/mpiexec)
endif()

# Quiet, reproducible test environment: no thread binding warnings from Kokkos, no
# shared-memory single-copy errors from Open MPI inside containers.
# CTest runs two tests at once on CI's two cores and unit tests run two threads: OpenMP threads
# that wait sleep instead of spinning, so an oversubscribed test does not take the core from the
# other (docs/performance.md measured spinning threads 4x slower on shared cores).
set(FLECSPH_TEST_ENVIRONMENT
  OMP_PROC_BIND=false
  OMP_WAIT_POLICY=passive
  OMPI_MCA_btl_vader_single_copy_mechanism=none
  OMPI_MCA_rmaps_base_oversubscribe=1)
# Open MPI 4's start-up probes network transports (tcp, openib, ofi) and the UCX layer: a
# singleton (an app run without mpiexec, as the fuzz and file tests run hundreds) spent 0.33 s
# before main here, 0.12 s on shared memory (vader) and ob1 alone, the transports used on one node
# anyway. Not isolated singletons (ess_singleton_isolated, 0.04 s): they all share one session
# directory, which each removes as it ends, and concurrent ones then fail in MPI_Init or in
# MPI_File_open (validation.rayleigh_taylor.rank_invariance failed so; docs/performance.md,
# "Stop 46"). The fuzz scripts keep them, each run with a TMPDIR of its own.
# When a rank exits non-zero (every bad-input test), mpiexec stops the others with SIGTERM and
# waits odls_base_sigkill_timeout (1 s) twice before it returns: 2.1 s of each such test's 2.2 s,
# 116 tests; the suite took 845 slot-seconds with the wait, 400 without (stop 46). The wait buys
# nothing: no rank of ours handles SIGTERM, so the signal ends it at once.
if(_flecsph_mpiexec_version MATCHES "(Open MPI|OpenRTE)\\) 4\\.")
  list(APPEND FLECSPH_TEST_ENVIRONMENT OMPI_MCA_btl=self,vader OMPI_MCA_pml=ob1 OMPI_MCA_odls_base_sigkill_timeout=0)
endif()

add_library(flecsph_test_main OBJECT ${PROJECT_SOURCE_DIR}/tests/support/test_main.cc)
target_link_libraries(flecsph_test_main PUBLIC flecsi_lite::flecsi_lite Catch2::Catch2)

# The external headers every test parses (Catch2 1.4 s, Kokkos 1.9 s of a test's compile time),
# precompiled once and reused by the unit and MPI tests (flecsph_reuse_test_headers). Only
# libraries' headers: a project header here would give every test its static registrations.
# (test_main.cc defines CATCH_CONFIG_RUNNER before Catch2, so the header is made apart from it.)
set(FLECSPH_EXTERNAL_HEADERS <Kokkos_Core.hpp> <mpi.h> <Eigen/Dense> <algorithm> <cmath> <cstdint> <functional>
    <iostream> <map> <memory> <random> <sstream> <string> <vector>)
file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/flecsph_test_headers.cc CONTENT "// The precompiled test headers' target.\n")
add_library(flecsph_test_headers OBJECT ${PROJECT_BINARY_DIR}/flecsph_test_headers.cc)
target_link_libraries(flecsph_test_headers PRIVATE flecsph_test_main flecsph_warnings)
target_precompile_headers(flecsph_test_headers PRIVATE <catch2/catch.hpp> ${FLECSPH_EXTERNAL_HEADERS})
function(flecsph_reuse_test_headers target)
  target_precompile_headers(${target} REUSE_FROM flecsph_test_headers)
endfunction()

# flecsph_add_unit_test(<source> [LIBRARIES libs...]): test named unit.<dir>.<file>, one thread
# count of 2.
function(flecsph_add_unit_test source)
  cmake_parse_arguments(T "" "" "LIBRARIES" ${ARGN})
  get_filename_component(_stem ${source} NAME_WE)
  get_filename_component(_dir ${source} ABSOLUTE)
  get_filename_component(_dir ${_dir} DIRECTORY)
  get_filename_component(_dir ${_dir} NAME)
  set(_name unit_${_dir}_${_stem})
  add_executable(${_name} ${source})
  target_link_libraries(${_name} PRIVATE flecsph_test_main flecsph_warnings ${T_LIBRARIES})
  flecsph_reuse_test_headers(${_name})
  add_test(NAME unit.${_dir}.${_stem} COMMAND ${_name})
  set_tests_properties(unit.${_dir}.${_stem} PROPERTIES
    ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT};OMP_NUM_THREADS=2" TIMEOUT 600)
endfunction()

# flecsph_add_mpi_test(<name> SOURCES src... RANKS n... [LIBRARIES libs...] [ARGS args...]):
# one executable, one CTest test mpi.<name>.<n> per rank count, one OpenMP thread per rank.
function(flecsph_add_mpi_test name)
  cmake_parse_arguments(T "" "" "SOURCES;RANKS;LIBRARIES;ARGS" ${ARGN})
  if(NOT T_RANKS)
    set(T_RANKS 1 2 4)
  endif()
  add_executable(mpi_${name} ${T_SOURCES})
  target_link_libraries(mpi_${name} PRIVATE flecsph_test_main flecsph_warnings ${T_LIBRARIES})
  flecsph_reuse_test_headers(mpi_${name})
  foreach(_n IN LISTS T_RANKS)
    add_test(NAME mpi.${name}.${_n}
      COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${_n} ${FLECSPH_MPIEXEC_FLAGS}
              ${MPIEXEC_PREFLAGS} $<TARGET_FILE:mpi_${name}> ${MPIEXEC_POSTFLAGS} ${T_ARGS})
    set_tests_properties(mpi.${name}.${_n} PROPERTIES PROCESSORS ${_n}
      ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT};OMP_NUM_THREADS=1" TIMEOUT 900)
  endforeach()
endfunction()

# The command line prefix of an MPI run (the rank count follows) and the options that quieten an
# SPH app in tests.
set(FLECSPH_MPIEXEC_RUN ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG})
set(FLECSPH_QUIET_APP --set progress_every=0 --set diagnostics_every=0 --no-timers)

# flecsph_add_restart_test(<name> APP <target> PARAMETERS <file> CHECKPOINT_EVERY <n> [ARGS ...]):
# a run on 2 ranks with checkpoints every CHECKPOINT_EVERY steps (app.<name>.restart.write), the
# same run restarted on 1 rank from its last checkpoint (.continue), and a bitwise comparison of
# their final steps (.compare, with compare_h5part from tests/validation).
function(flecsph_add_restart_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "APP;PARAMETERS;CHECKPOINT_EVERY" "ARGS")
  set(_run ${FLECSPH_MPIEXEC_RUN})
  set(_common $<TARGET_FILE:${arg_APP}> ${arg_PARAMETERS} ${arg_ARGS} ${FLECSPH_QUIET_APP}
              --set checkpoint_file=${name}_checkpoint.h5part --set checkpoint_every=${arg_CHECKPOINT_EVERY})
  add_test(NAME app.${name}.restart.write
    COMMAND ${_run} 2 ${FLECSPH_MPIEXEC_FLAGS} ${_common} --set output_file=${name}_full.h5part)
  add_test(NAME app.${name}.restart.continue
    COMMAND ${_run} 1 ${FLECSPH_MPIEXEC_FLAGS} ${_common} --set output_file=${name}_restarted.h5part
            --set restart_file=${name}_checkpoint.h5part)
  add_test(NAME app.${name}.restart.compare COMMAND compare_h5part ${name}_full.h5part ${name}_restarted.h5part)
  set_tests_properties(app.${name}.restart.write PROPERTIES FIXTURES_SETUP ${name}_written PROCESSORS 2)
  set_tests_properties(app.${name}.restart.continue PROPERTIES FIXTURES_REQUIRED ${name}_written
    FIXTURES_SETUP ${name}_restarted PASS_REGULAR_EXPRESSION "restarting at step [1-9]")
  set_tests_properties(app.${name}.restart.compare PROPERTIES FIXTURES_REQUIRED "${name}_written;${name}_restarted")
  set_tests_properties(app.${name}.restart.write app.${name}.restart.continue app.${name}.restart.compare
    PROPERTIES WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} TIMEOUT 300
    ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT};OMP_NUM_THREADS=1")
endfunction()

# flecsph_add_bad_input_test(<name> APP <target> STATUS <code> [RANKS <n>] [FIXTURES ...]
#                            [MESSAGES <regex>...] [ARGS ...]):
# app.bad_input.<name> runs tests/apps/expect_failure.sh: the app with ARGS on RANKS ranks (1 by
# default) must exit with STATUS, print every MESSAGES regex, and leave keep_<name>.h5part, an
# earlier run's output, unchanged. Needs the fixture bad_input_files (tests/apps) and FIXTURES.
function(flecsph_add_bad_input_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "APP;RANKS;STATUS;FIXTURES" "MESSAGES;ARGS")
  if(NOT arg_RANKS)
    set(arg_RANKS 1)
  endif()
  add_test(NAME app.bad_input.${name}
    COMMAND sh ${PROJECT_SOURCE_DIR}/tests/apps/expect_failure.sh ${arg_STATUS} keep_${name}.h5part ${arg_MESSAGES} --
            ${FLECSPH_MPIEXEC_RUN} ${arg_RANKS} ${FLECSPH_MPIEXEC_FLAGS} $<TARGET_FILE:${arg_APP}> ${arg_ARGS}
            --set output_file=keep_${name}.h5part --no-timers
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(app.bad_input.${name} PROPERTIES PROCESSORS ${arg_RANKS} TIMEOUT 120
    FIXTURES_REQUIRED "bad_input_files;${arg_FIXTURES}" ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT};OMP_NUM_THREADS=1")
endfunction()

# Validation records (tests/validation/record_result.py): a recorded test runs its command through
# the recorder, which passes the output and exit status through and writes the figures the run
# printed (validation_problems.json says which) to FLECSPH_VALIDATION_RECORDS; validation.report
# (tests/validation) writes the report from them after every test of the fixture validation_records.
set(FLECSPH_VALIDATION_RECORDS ${PROJECT_BINARY_DIR}/validation/records)

# flecsph_record_prefix(<var> <problem> <run>): the words that run a command through the recorder
# as run <run> of problem <problem> at the size ci.
function(flecsph_record_prefix var problem run)
  set(${var} /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/validation/record_result.py
      --records ${FLECSPH_VALIDATION_RECORDS} --size ci --problem ${problem} --run ${run} -- PARENT_SCOPE)
endfunction()

# flecsph_report_input(<test>...): the tests record figures or make plots for the report (fixture
# validation_records). Call it after the tests' last set_tests_properties, which would replace it.
function(flecsph_report_input)
  foreach(_test IN LISTS ARGN)
    set_property(TEST ${_test} APPEND PROPERTY FIXTURES_SETUP validation_records)
  endforeach()
endfunction()

# flecsph_add_validation(<name> APP <target> PARAMETERS <file> [RANKS <n1> <n2>] [RECORD <problem>]
#                        [ARGS <arg>...]):
# validation.<name>.<n> runs the app with the parameter file and ARGS (its checks included) on n
# ranks, one thread each, writing <name>_<n>.h5part; validation.<name>.rank_invariance compares
# the last steps of the two runs bit by bit. RANKS: two rank counts, 1 and 2 by default. RECORD:
# the run on the second rank count records its figures as run <name> of <problem> (one record:
# the two runs are bitwise equal).
function(flecsph_add_validation name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "APP;PARAMETERS;RECORD" "RANKS;ARGS")
  if(NOT arg_RANKS)
    set(arg_RANKS 1 2)
  endif()
  list(LENGTH arg_RANKS _count)
  if(NOT _count EQUAL 2)
    message(FATAL_ERROR "flecsph_add_validation(${name}): RANKS takes two rank counts, not '${arg_RANKS}'")
  endif()
  set(_outputs)
  set(_fixtures)
  list(GET arg_RANKS 1 _recorded)
  foreach(_n IN LISTS arg_RANKS)
    set(_prefix)
    if(arg_RECORD AND _n EQUAL _recorded)
      flecsph_record_prefix(_prefix ${arg_RECORD} ${name})
    endif()
    add_test(NAME validation.${name}.${_n}
      COMMAND ${_prefix} ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${_n} ${FLECSPH_MPIEXEC_FLAGS}
              $<TARGET_FILE:${arg_APP}> ${arg_PARAMETERS} ${arg_ARGS} --set output_file=${name}_${_n}.h5part
              --set progress_every=0 --set diagnostics_every=0 --no-timers
      WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set_tests_properties(validation.${name}.${_n} PROPERTIES PROCESSORS ${_n} TIMEOUT 600
      FIXTURES_SETUP ${name}_${_n} ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT};OMP_NUM_THREADS=1")
    if(_prefix)
      flecsph_report_input(validation.${name}.${_n})
    endif()
    list(APPEND _outputs ${name}_${_n}.h5part)
    list(APPEND _fixtures ${name}_${_n})
  endforeach()
  add_test(NAME validation.${name}.rank_invariance COMMAND compare_h5part ${_outputs}
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(validation.${name}.rank_invariance PROPERTIES FIXTURES_REQUIRED "${_fixtures}"
    ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT}")
endfunction()

# flecsph_client_run(<name> <app> <parameter file> [args...]): clients.<name>.write runs the app
# (apps/<app>/<parameter file>) on 2 ranks, writing <name>.h5part; fixture clients_<name>.
function(flecsph_client_run name app parameter_file)
  add_test(NAME clients.${name}.write
    COMMAND ${FLECSPH_MPIEXEC_RUN} 2 ${FLECSPH_MPIEXEC_FLAGS} $<TARGET_FILE:${app}>
            ${PROJECT_SOURCE_DIR}/apps/${app}/${parameter_file} --set output_file=${name}.h5part ${ARGN}
            ${FLECSPH_QUIET_APP}
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(clients.${name}.write PROPERTIES FIXTURES_SETUP clients_${name} PROCESSORS 2
    TIMEOUT 300 ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT};OMP_NUM_THREADS=1")
endfunction()

# flecsph_client_test(<name> <fixture> COMMAND ... [PROPERTIES ...]): a client reading the
# fixture's file.
function(flecsph_client_test name fixture)
  cmake_parse_arguments(T "" "" "COMMAND;PROPERTIES" ${ARGN})
  add_test(NAME clients.${name} COMMAND ${T_COMMAND} WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(clients.${name} PROPERTIES FIXTURES_REQUIRED clients_${fixture} TIMEOUT 300
    ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT}" ${T_PROPERTIES})
endfunction()

# flecsph_add_tutorial(<chapter> TARGET <target> [RANKS n] [ARGS args...]): test
# tutorial.<chapter> runs the chapter's program on n ranks (1 by default), one thread each, in
# its own folder; the program checks its own result.
function(flecsph_add_tutorial chapter)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "TARGET;RANKS" "ARGS")
  if(NOT arg_RANKS)
    set(arg_RANKS 1)
  endif()
  set(_directory ${CMAKE_CURRENT_BINARY_DIR}/${chapter})
  file(MAKE_DIRECTORY ${_directory})
  add_test(NAME tutorial.${chapter}
    COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${arg_RANKS} ${FLECSPH_MPIEXEC_FLAGS}
            $<TARGET_FILE:${arg_TARGET}> ${arg_ARGS} --no-timers
    WORKING_DIRECTORY ${_directory})
  set_tests_properties(tutorial.${chapter} PROPERTIES PROCESSORS ${arg_RANKS} TIMEOUT 300
    ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT};OMP_NUM_THREADS=1")
endfunction()

# flecsph_add_fuzz_test(<name> SCRIPT <python file> [ARGS ...]): fuzz.<name> runs the seeded,
# bounded fuzz driver (tests/fuzz) with /usr/bin/python3 on 1 rank, the apps started as MPI
# singletons (an mpiexec per case doubled the test's time); label "fuzz" (ctest -L fuzz runs them
# all, ctest -LE fuzz leaves them out).
function(flecsph_add_fuzz_test name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "SCRIPT" "ARGS")
  add_test(NAME fuzz.${name}
    COMMAND /usr/bin/python3 ${arg_SCRIPT} ${arg_ARGS}
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(fuzz.${name} PROPERTIES LABELS fuzz PROCESSORS 2 TIMEOUT 900
    ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT};OMP_NUM_THREADS=1")
endfunction()
