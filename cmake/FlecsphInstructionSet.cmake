# The instruction set of the code, and so the lanes of the pair loops' packs
# (specialization/numerics/simd.hh).
#
# Default: this machine's own, as SWIFT's configure does (-march=native: 4 doubles per pack with
# AVX2, 8 with AVX-512; the binaries then run on such machines only). -DFLECSPH_NATIVE_ARCH=OFF
# builds the portable binary for packaging (the compiler's default: 2 doubles on x86-64).
# Contraction into fused multiply-adds stays off either way (-ffp-contract=off in the root
# CMakeLists.txt): the results are bitwise the same on every instruction set and lane count
# (docs/performance.md; unit.sph.simd_pairs).
#
# ccache: -march=native on the command line would let a cache shared by machines with different
# CPUs hand one machine's objects to another (ccache issue #824: it hashes the command line, not
# what "native" means). So GCC's meaning of -march=native on this machine (the -march, -mtune,
# -m<feature> and --param flags its driver passes to cc1plus) is written out on the command line
# instead: the same code, and a cache key that names the instruction set.

# Build folders configured before native became the default hold FLECSPH_NATIVE_ARCH=OFF in their
# cache without anyone having chosen it: they move to the new default once (the version marker
# below says the choice was made under it); an explicit -DFLECSPH_NATIVE_ARCH=OFF is kept after that.
if(DEFINED CACHE{FLECSPH_NATIVE_ARCH} AND NOT DEFINED CACHE{FLECSPH_INSTRUCTION_SET_DEFAULTS})
  message(STATUS "FLECSPH_NATIVE_ARCH: this build folder predates the native default; now ON "
                 "(configure again with -DFLECSPH_NATIVE_ARCH=OFF for the portable build)")
  set(FLECSPH_NATIVE_ARCH ON CACHE BOOL "Compile for this machine's instruction set (-march=native)" FORCE)
endif()
set(FLECSPH_INSTRUCTION_SET_DEFAULTS 2 CACHE INTERNAL "version 2: FLECSPH_NATIVE_ARCH defaults to ON")

option(FLECSPH_NATIVE_ARCH "Compile for this machine's instruction set (-march=native)" ON)

# The flags GCC's driver derives from -march=native on this machine, in `result` (empty when they
# cannot be read: the caller then passes -march=native itself).
function(flecsph_expand_native_arch result)
  set(${result} "" PARENT_SCOPE)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    return()
  endif()
  # "-###" quoted: an unquoted # starts a CMake comment.
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -march=native "-###" -x c++ -E - INPUT_FILE /dev/null
                  OUTPUT_QUIET ERROR_VARIABLE driver_lines RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    return()
  endif()
  string(REGEX MATCH "[^\n]*cc1plus[^\n]*" compiler_line "${driver_lines}")
  separate_arguments(arguments UNIX_COMMAND "${compiler_line}")
  set(flags "")
  set(after_param OFF)
  foreach(argument IN LISTS arguments)
    if(after_param)
      # One token, --param=name=value: CMake removes repeated compile options, which would break
      # the pair "--param" "name=value".
      list(APPEND flags "--param=${argument}")
      set(after_param OFF)
    elseif(argument STREQUAL "--param")
      set(after_param ON)
    elseif(argument MATCHES "^-m(arch|tune)=" OR argument MATCHES "^-m[a-z0-9.-]+$")
      list(APPEND flags "${argument}")
    endif()
  endforeach()
  list(FILTER flags INCLUDE REGEX ".")
  list(FIND flags "-march=native" unresolved)
  if(NOT flags MATCHES "-march=" OR unresolved GREATER -1)
    return()
  endif()
  set(${result} "${flags}" PARENT_SCOPE)
endfunction()

if(FLECSPH_NATIVE_ARCH)
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag(-march=native FLECSPH_COMPILER_ACCEPTS_MARCH_NATIVE)
  if(NOT FLECSPH_COMPILER_ACCEPTS_MARCH_NATIVE)
    message(WARNING "FLECSPH_NATIVE_ARCH: ${CMAKE_CXX_COMPILER} does not accept -march=native; "
                    "building for its default instruction set")
  else()
    flecsph_expand_native_arch(FLECSPH_NATIVE_FLAGS)
    if(NOT FLECSPH_NATIVE_FLAGS)
      set(FLECSPH_NATIVE_FLAGS -march=native)
    endif()
    list(GET FLECSPH_NATIVE_FLAGS 0 _flecsph_arch_named)
    message(STATUS "FLECSPH_NATIVE_ARCH: ${_flecsph_arch_named} (${CMAKE_CXX_COMPILER_ID}; "
                   "-DFLECSPH_NATIVE_ARCH=OFF for the portable build)")
    add_compile_options(${FLECSPH_NATIVE_FLAGS})
  endif()
endif()
