#!/usr/bin/env bash
# Fuzz every reader of untrusted input with libFuzzer (issue 18; README "Fuzzing").
#
#   tools/fuzz.sh [SECONDS] [TARGET...]
#
# Configures a clang build in build-fuzz/ (-DTRIBO_FUZZ=ON: ASan + UBSan + coverage), builds the
# fuzzers and runs each for SECONDS (default 60), one after another in one process each (one core, nice).
# Targets: surface bundle rig_config homogenise_config sweep_spec law_table drive_table ehl_config
# contact_config reynolds_config gap_model selftest_journal sweep_state (default: all).
# Each run starts from the committed corpus fuzz/corpus/<target>/ plus the inputs of earlier runs
# (build-fuzz/work/<target>/); findings are written to build-fuzz/artifacts/<target>/ and the
# script exits non-zero if any target found something. To keep a new interesting input:
#   build-fuzz/fuzz/fuzz_<target> -merge=1 fuzz/corpus/<target> build-fuzz/work/<target>
# (adds to the committed corpus only inputs that reach new coverage; keep it small).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(surface bundle rig_config homogenise_config sweep_spec law_table drive_table ehl_config contact_config reynolds_config gap_model selftest_journal sweep_state)

command -v clang++ >/dev/null || { echo "fuzz.sh: needs clang++ (Debian: apt-get install clang)" >&2; exit 2; }
export CCACHE_BASEDIR=$PWD
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" \
  -DTRIBO_FUZZ=ON -DTRIBO_BUILD_TESTS=OFF -DTRIBO_BUILD_BENCH=OFF -DTRIBO_BUILD_PYTHON=OFF >/dev/null
nice -n 10 cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]/#/fuzz_}"

status=0
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/work/$t" "build-fuzz/artifacts/$t"
  echo "== fuzz_$t for ${seconds} s"
  dict=()
  [ -f "fuzz/$t.dict" ] && dict=(-dict="fuzz/$t.dict")  # the loader's key names and TOML syntax
  # -max_len 4096: corpus files stay small; -malloc_limit_mb: a small input that asks for a
  # giant allocation is a finding; -timeout: one input taking more than 10 s is a hang.
  if ! nice -n 10 "build-fuzz/fuzz/fuzz_$t" -max_total_time="$seconds" -max_len=4096 \
      -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1 "${dict[@]}" \
      -artifact_prefix="build-fuzz/artifacts/$t/" "build-fuzz/work/$t" "fuzz/corpus/$t"; then
    echo "fuzz_$t: FOUND a crash, hang or leak — see build-fuzz/artifacts/$t/" >&2
    status=1
  fi
done
exit $status
