#!/usr/bin/env bash
# Builds the libFuzzer programs (clang, ASan + UBSan) in build-fuzz/ and runs each target for
# SECONDS (default 60), FUZZ_JOBS at a time (default 2), on a copy of its committed seed corpus.
#   [FUZZ_JOBS=N] fuzz/run_fuzzers.sh [SECONDS] [TARGET...]
# Needs clang and libclang-rt-14-dev (apt-get install clang libclang-rt-14-dev). Inputs that
# crash, hang (10 s), leak or exceed 2 GB land in build-fuzz/artifacts/<target>/; fix the
# defect, then copy the input to fuzz/regressions/<target>/ so that fuzz_replay.<target>
# replays it. Each run's last status line (executions, coverage) is in build-fuzz/logs/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(read_MEDIT read_MSH read_VTU frame_field closed_surface vvm_mesh_arguments)
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ -DVVM_BUILD_FUZZERS=ON \
      -DBUILD_TESTING=OFF -DVVM_BUILD_EXAMPLES=OFF -DVVM_BUILD_BENCHMARKS=OFF -DVVM_BUILD_TOOLS=OFF > /dev/null
cmake --build build-fuzz -j2 --target "${targets[@]/#/fuzz_}"
mkdir -p build-fuzz/logs
# UBSan halts on its first report, except those documented in test/sanitizers/ubsan.supp
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$PWD/test/sanitizers/ubsan.supp"
run() {
  local t=$1
  mkdir -p "build-fuzz/corpus/$t" "build-fuzz/artifacts/$t"
  cp -n fuzz/corpus/"$t"/* "build-fuzz/corpus/$t/" 2>/dev/null || true
  build-fuzz/fuzz/fuzz_"$t" "build-fuzz/corpus/$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$t/" \
    > "build-fuzz/logs/$t.log" 2>&1 || echo "fuzz_$t: FINDING (see build-fuzz/logs/$t.log)"
  echo "fuzz_$t: $(grep -E '^#[0-9]+' "build-fuzz/logs/$t.log" | tail -1)"
}
running=0
for t in "${targets[@]}"; do
  run "$t" &
  running=$((running + 1))
  if [ $running -ge "${FUZZ_JOBS:-2}" ]; then wait -n; running=$((running - 1)); fi
done
wait
