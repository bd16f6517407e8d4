// Sanitize builds only: every test suite gives LeakSanitizer its options
// itself (tests/CMakeLists.txt passes them in). ctest's ENVIRONMENT covers the
// tests and the tools they start, but not CMake's run of a suite at build
// time to list its tests — and a suite whose main() starts MPI then fails on
// Open MPI's own leaks before a test has run.
extern "C" const char* __lsan_default_options() {
  return SOFTGLASS_LSAN_OPTIONS;
}
