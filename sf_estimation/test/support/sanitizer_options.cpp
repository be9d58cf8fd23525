// Linked into a unit test program compiled with the sanitizers (SF_ESTIMATION_SANITIZE_TESTS):
// the run-time options sanitizer_checks.py sets in the environment, as the programs' defaults,
// for runners that set none (catkin's gtest targets). The environment still overrides them.
extern "C" {
const char* __asan_default_options() {
  return "abort_on_error=1:detect_leaks=1:strict_string_checks=1";
}
const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }
}
