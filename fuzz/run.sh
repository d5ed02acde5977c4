#!/usr/bin/env bash
# Builds and runs the libFuzzer programs of fuzz/ (docs/fuzzing.md).
#
#   fuzz/run.sh --smoke [TARGET...]             every seed once, then a fixed number of
#                                               mutations from a fixed seed (a few s each)
#   fuzz/run.sh --campaign [MINUTES] [TARGET...]  MINUTES (default 10) of mutation each
#   fuzz/run.sh --build                         build only
#
# TARGET is a program's name without _fuzz (api_routes, kider_archive, ...); all by default.
# The build is build-fuzz/, or $CLEARSKY_FUZZ_BUILD_DIR (clang with ASan + UBSan + libFuzzer,
# ccache when present; deploy/test.sh shares it with its sanitizer run of the unit tests). What the fuzzer learns goes to BUILD/fuzz-work/TARGET (the committed
# seeds in fuzz/corpus/ are only read), crashes to BUILD/fuzz-artifacts/, logs to
# BUILD/fuzz-logs/. Exits non-zero when a program finds anything; the summary lists
# executions, coverage (cov, ft) and findings per program.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

mode=${1:-}
shift || true
seconds=10
case "$mode" in
  --smoke) ;;
  --campaign)
    minutes=10
    if [[ "${1:-}" =~ ^[0-9]+$ ]]; then
      minutes=$1
      shift
    fi
    seconds=$((minutes * 60))
    ;;
  --build) ;;
  *)
    sed -n '2,13p' "$0" >&2
    exit 2
    ;;
esac

all_targets=(api_routes kider_archive iso8601_time cron_schedule coordinates table_cache sample_blob)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")

# clang, its sanitizer and fuzzer runtimes (libclang-rt-14-dev) and ccache come with the
# project's dependencies.
deploy/install-deps.sh

build=${CLEARSKY_FUZZ_BUILD_DIR:-build-fuzz}
launcher=()
command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# ccache shares the objects between clones and build folders: paths relative to the root, and
# the folder not hashed for the debug information.
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
# -O1 with line tables: quick to build, fast enough to fuzz, readable reports. The unit tests
# of this tree are configured too (built only when asked: deploy/test.sh runs them).
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCMAKE_CXX_COMPILER=clang++ -DCLEARSKY_FUZZ=ON -DCLEARSKY_PCH=OFF \
  -DCLEARSKY_BUILD_BENCHMARKS=OFF -DCLEARSKY_BUILD_ACCURACY_TESTS=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/%/_fuzz}"
[ "$mode" = "--build" ] && exit 0

# The longest input each program is given: an HTTP request with a small body; an archive as
# large as the seed archives; short texts; a few small tables.
max_len() {
  case "$1" in
    api_routes) echo 8192 ;;
    kider_archive) echo 65536 ;;
    table_cache) echo 32768 ;;
    sample_blob) echo 4096 ;;
    *) echo 256 ;;
  esac
}

# The smoke run's mutations per program: a fixed count from a fixed seed, so that the run does
# not depend on the machine's speed or load (a timed run explores further on a fast machine and
# may find there what a slow one did not), about 5 s each on the 2-core machine.
smoke_runs() {
  case "$1" in
    api_routes) echo 8000 ;;
    kider_archive) echo 15000 ;;
    iso8601_time | cron_schedule | sample_blob) echo 100000 ;;
    *) echo 25000 ;;
  esac
}

# One program: its log, and its summary line and exit status next to the log.
run_target() {
  local target=$1 work="$build/fuzz-work/$1" log="$build/fuzz-logs/$1.log" status=0
  mkdir -p "$work"
  local options=(-max_len="$(max_len "$target")" -timeout=10
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/fuzz-artifacts/$target-")
  if [ "$mode" = "--smoke" ]; then
    # A guard of 120 s only stops a smoke run on a machine far slower than ours.
    options+=(-seed=1 -runs="$(smoke_runs "$target")" -max_total_time=120)
  else
    options+=(-max_total_time="$seconds")
  fi
  [ -f "fuzz/dictionaries/$target.dict" ] && options+=(-dict="fuzz/dictionaries/$target.dict")
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/fuzz/${target}_fuzz" "${options[@]}" "$work" "fuzz/corpus/$target" >"$log" 2>&1 ||
    status=$?
  local runs last cov ft result
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  last=$(grep -aE '^#[0-9]+' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  if [ "$status" -eq 0 ]; then
    result="no finding"
  else
    result="FINDING (exit $status): $(grep -a -m1 -E 'ERROR:|FUZZ INVARIANT|runtime error' "$log" || echo see log)"
  fi
  printf '%-14s %10s runs  cov %-6s ft %-6s %s\n' "$target" "${runs:-?}" "${cov:-?}" "${ft:-?}" \
    "$result" >"$log.summary"
  echo "$status" >"$log.status"
}

# The smoke run uses every core (the programs are single-threaded); a campaign runs one
# program at a time unless CLEARSKY_FUZZ_JOBS says otherwise.
parallel=${CLEARSKY_FUZZ_JOBS:-1}
[ "$mode" = "--smoke" ] && parallel=${CLEARSKY_FUZZ_JOBS:-$(nproc)}
mkdir -p "$build/fuzz-work" "$build/fuzz-artifacts" "$build/fuzz-logs"
for target in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do wait -n || true; done
  if [ "$mode" = "--smoke" ]; then
    echo "fuzz: $target, seeds then $(smoke_runs "$target") mutations (log $build/fuzz-logs/$target.log)"
  else
    echo "fuzz: $target for ${seconds} s (log $build/fuzz-logs/$target.log)"
  fi
  run_target "$target" &
done
wait
failed=0
if [ "$mode" = "--smoke" ]; then
  echo "fuzz summary (smoke: seeds and fixed mutations, seed 1, root $root):"
else
  echo "fuzz summary (${seconds} s each, root $root):"
fi
for target in "${targets[@]}"; do
  log="$build/fuzz-logs/$target.log"
  printf '  %s' "$(cat "$log.summary")"
  echo
  if [ "$(cat "$log.status")" != 0 ]; then
    failed=1
    echo "---- $log (end)" >&2
    tail -40 "$log" >&2
  fi
done
exit "$failed"
