# Project-wide compiler settings, applied through one interface target so that
# third-party code (deal.II, HDF5) keeps its own flags.
add_library(softglass_options INTERFACE)
add_library(softglass::options ALIAS softglass_options)
target_compile_options(softglass_options INTERFACE
  -Wall -Wextra -Wshadow -Wnon-virtual-dtor -Wpedantic
  # Math functions never report through errno here, so sqrt can be inlined and
  # vectorised (no IEEE semantics change, unlike -ffast-math).
  -fno-math-errno
  # Nothing replaces a softglass function at load time: calls within a
  # library stay direct and inlinable when the code is position independent
  # (the Python module, cmake/Python.cmake).
  -fno-semantic-interposition
  $<$<CONFIG:Release>:-O3>)
if(SOFTGLASS_SANITIZE)
  target_compile_options(softglass_options INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(softglass_options INTERFACE -fsanitize=address,undefined)
endif()
