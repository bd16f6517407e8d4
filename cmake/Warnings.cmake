# Project-wide compiler settings, applied through one interface target so that
# third-party code (deal.II, HDF5) keeps its own flags.
add_library(softglass_options INTERFACE)
add_library(softglass::options ALIAS softglass_options)
target_compile_options(softglass_options INTERFACE
  -Wall -Wextra -Wshadow -Wnon-virtual-dtor -Wpedantic
  $<$<CONFIG:Release>:-O3>)
if(SOFTGLASS_NATIVE)
  target_compile_options(softglass_options INTERFACE -march=native)
endif()
if(SOFTGLASS_SANITIZE)
  target_compile_options(softglass_options INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(softglass_options INTERFACE -fsanitize=address,undefined)
endif()
