# Every dependency comes from Debian's packages; nothing is downloaded.
find_package(OpenMP REQUIRED)
find_package(MPI REQUIRED COMPONENTS CXX)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(fmt REQUIRED)
find_package(CLI11 REQUIRED)
find_package(Boost 1.74 REQUIRED)          # header-only parts: Boost.Math
find_package(GTest REQUIRED)
find_package(PkgConfig REQUIRED)

# HDF5: the serial flavour. deal.II pulls in the OpenMPI flavour as well, and its
# pkg-config alternative may point there; one file per run needs no MPI-IO.
pkg_check_modules(HDF5_SERIAL REQUIRED IMPORTED_TARGET hdf5-serial)
find_library(HDF5_SERIAL_CPP hdf5_cpp PATHS ${HDF5_SERIAL_LIBRARY_DIRS} NO_DEFAULT_PATH REQUIRED)
add_library(softglass_hdf5 INTERFACE)
add_library(softglass::hdf5 ALIAS softglass_hdf5)
target_link_libraries(softglass_hdf5 INTERFACE ${HDF5_SERIAL_CPP} PkgConfig::HDF5_SERIAL)

# deal.II 9.4: only for the command-line front ends (ParameterHandler) and macro/.
# Its include path carries the OpenMPI HDF5 headers, so it must never be combined
# with softglass::hdf5 in one translation unit (the HDF5 wrapper hides its headers).
find_package(deal.II 9.4 REQUIRED HINTS /usr/share/cmake/deal.II)
add_library(softglass_dealii INTERFACE)
add_library(softglass::dealii ALIAS softglass_dealii)
target_include_directories(softglass_dealii SYSTEM INTERFACE ${DEAL_II_INCLUDE_DIRS})
target_link_libraries(softglass_dealii INTERFACE ${DEAL_II_LIBRARIES_RELEASE})
