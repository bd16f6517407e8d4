# The Python module `softglass` (python/): built when Debian's pybind11 is
# installed (scripts/install-deps.sh installs it), so that `make test` builds
# and tests it; -DSOFTGLASS_PYTHON=OFF leaves it out.
#
# The interpreter is Debian's /usr/bin/python3 unless -DPython_EXECUTABLE says
# otherwise: the module is tested with Debian's numpy, pytest and nbclient,
# which another python3 first on PATH (pyenv, conda) does not see.
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter of the softglass module")
endif()
find_package(Python 3 QUIET COMPONENTS Interpreter Development.Module)
if(Python_FOUND)
  find_package(pybind11 2.10 CONFIG QUIET)
endif()
set(python_default OFF)
# Under the sanitizers the module would need the sanitizer runtime preloaded
# into the interpreter: that build leaves it out.
if(pybind11_FOUND AND NOT SOFTGLASS_SANITIZE)
  set(python_default ON)
endif()
option(SOFTGLASS_PYTHON "Build the Python module softglass (python/)" ${python_default})
if(SOFTGLASS_PYTHON)
  if(NOT pybind11_FOUND)
    message(FATAL_ERROR "SOFTGLASS_PYTHON needs pybind11 (Debian: pybind11-dev python3-pybind11, "
                        "scripts/install-deps.sh) and Python's headers (python3-dev)")
  endif()
  # The module links the static libraries of common/, micro/, bridge/ and
  # macro/ into one shared object, so their code must be position
  # independent. -fno-semantic-interposition (softglass::options) keeps the
  # engines' code as fast as without: calls within a library are not routed
  # through the PLT as if another library could replace the callee.
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
endif()
