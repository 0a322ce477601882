# Warnings and sanitizers for the project's own targets (not for fetched dependencies).
add_library(flecsph_warnings INTERFACE)
target_compile_options(flecsph_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wno-unknown-pragmas>)

if(FLECSPH_SANITIZE)
  string(REPLACE ";" "," _flecsph_sanitizers "${FLECSPH_SANITIZE}")
  target_compile_options(flecsph_warnings INTERFACE -fsanitize=${_flecsph_sanitizers} -fno-omit-frame-pointer)
  target_link_options(flecsph_warnings INTERFACE -fsanitize=${_flecsph_sanitizers})
endif()
