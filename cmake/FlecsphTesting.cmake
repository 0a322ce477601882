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

# Quiet, reproducible test environment: no thread binding warnings from Kokkos, no
# shared-memory single-copy errors from Open MPI inside containers.
set(FLECSPH_TEST_ENVIRONMENT
  OMP_PROC_BIND=false
  OMPI_MCA_btl_vader_single_copy_mechanism=none
  OMPI_MCA_rmaps_base_oversubscribe=1)

add_library(flecsph_test_main OBJECT ${PROJECT_SOURCE_DIR}/tests/support/test_main.cc)
target_link_libraries(flecsph_test_main PUBLIC flecsi_lite::flecsi_lite Catch2::Catch2)

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
  foreach(_n IN LISTS T_RANKS)
    add_test(NAME mpi.${name}.${_n}
      COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${_n} ${FLECSPH_MPIEXEC_FLAGS}
              ${MPIEXEC_PREFLAGS} $<TARGET_FILE:mpi_${name}> ${MPIEXEC_POSTFLAGS} ${T_ARGS})
    set_tests_properties(mpi.${name}.${_n} PROPERTIES PROCESSORS ${_n}
      ENVIRONMENT "${FLECSPH_TEST_ENVIRONMENT};OMP_NUM_THREADS=1" TIMEOUT 900)
  endforeach()
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
