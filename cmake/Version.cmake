# Writes the version header with the current source revision. Run at every build
# (common/CMakeLists.txt) so that result files name the revision they came from;
# configure_file rewrites the header only when the revision changed.
execute_process(COMMAND git describe --always --dirty --tags
                WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE SOFTGLASS_GIT_REVISION OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(NOT SOFTGLASS_GIT_REVISION)
  set(SOFTGLASS_GIT_REVISION "unknown")
endif()
configure_file(${SOURCE_DIR}/common/version.h.in ${OUTPUT} @ONLY)
