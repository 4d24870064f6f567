# Sourced by scripts/sanitize.sh and scripts/fuzz.sh: the sanitizer runtime options of every run.
# halt_on_error: the first report ends the process with a failure (a test that goes on after memory
# corruption proves nothing). detect_leaks: LeakSanitizer at exit, with the suppressions of lsan.supp,
# which name only system libraries whose leaks are not ours (today: Mesa's OSMesa).
# verify_asan_link_order=0: ApitraceCliTest runs bench under `apitrace trace`, which LD_PRELOADs its GL
# wrapper ahead of everything; ASan would refuse to start because its runtime is not first. The wrapper
# intercepts GL and EGL calls, not malloc, so ASan's interceptors still see every allocation.
sanitizers_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:print_stacktrace=1:strict_init_order=1:verify_asan_link_order=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:report_error_type=1"
export LSAN_OPTIONS="suppressions=$sanitizers_dir/lsan.supp:print_suppressions=0"
