# Finds MPI, parallel HDF5, Eigen and Kokkos (installed, upstream release, or the offline source
# that scripts/install_deps.sh unpacks; see ../shared/KOKKOS.md in the team docs).
find_package(MPI REQUIRED COMPONENTS C CXX)

set(HDF5_PREFER_PARALLEL ON)
find_package(HDF5 REQUIRED COMPONENTS C)
if(NOT HDF5_IS_PARALLEL)
  message(FATAL_ERROR "HDF5 at ${HDF5_INCLUDE_DIRS} is serial; FleCSPH-lite needs parallel HDF5 "
                      "(Debian: libhdf5-openmpi-dev; run scripts/install_deps.sh)")
endif()

find_package(Eigen3 3.3 REQUIRED NO_MODULE)

# An installed Kokkos first (Kokkos_ROOT or CMAKE_PREFIX_PATH); else the offline Kokkos 3.4.01
# source that scripts/install_deps.sh puts in .deps/; else CMake downloads the upstream release.
# (FetchContent skips find_package whenever a source dir is given, hence the explicit search.)
find_package(Kokkos 3.4 CONFIG QUIET)
if(NOT Kokkos_FOUND)
  include(FetchContent)
  set(FLECSPH_OFFLINE_KOKKOS ${PROJECT_SOURCE_DIR}/.deps/pykokkos-base-0.0.7/external/kokkos)
  if(NOT FETCHCONTENT_SOURCE_DIR_KOKKOS AND EXISTS ${FLECSPH_OFFLINE_KOKKOS}/CMakeLists.txt)
    set(FETCHCONTENT_SOURCE_DIR_KOKKOS ${FLECSPH_OFFLINE_KOKKOS} CACHE PATH "Kokkos source tree")
  endif()
  if(NOT DEFINED Kokkos_ENABLE_OPENMP)
    set(Kokkos_ENABLE_OPENMP ON CACHE BOOL "Kokkos OpenMP backend")
  endif()
  set(Kokkos_ENABLE_SERIAL ON CACHE BOOL "Kokkos Serial backend")
  FetchContent_Declare(Kokkos
    URL https://github.com/kokkos/kokkos/releases/download/4.4.01/kokkos-4.4.01.tar.gz)
  FetchContent_MakeAvailable(Kokkos)
else()
  message(STATUS "Kokkos ${Kokkos_VERSION}: installed at ${Kokkos_DIR}")
endif()
if(NOT TARGET Kokkos::kokkos)
  message(FATAL_ERROR "Kokkos was found but provides no Kokkos::kokkos target")
endif()
