#!/usr/bin/env bash
# Fuzzes every input loader with libFuzzer (clang from Debian packages) for a fixed time.
# Usage: bash scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]     (default 60 s, all targets)
#
# Builds into build-fuzz/ (library instrumented with ASan + UBSan + coverage), seeds each
# target's corpus from participants/, models/, studies/ and tests/data/, and runs the
# targets one after the other (one core; nice -n 10). The corpus grows in
# build-fuzz/corpus/<target>/ across runs. A crash, leak, hang (> 10 s per input) or an
# exception other than InputError stops that target; the input is saved as
# build-fuzz/artifacts/<target>-crash-*, and the script exits 1 after running the rest.
# Replay one input: build-fuzz/<target> build-fuzz/artifacts/<target>-crash-...
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
all_targets=(participant_fuzz knee_model_fuzz sweep_study_fuzz cylinder_study_fuzz diagnosis_study_fuzz csv_fuzz motion_file_fuzz osim_model_fuzz
             serve_request_fuzz)
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${all_targets[@]}")

# clang and its sanitizer/fuzzer runtimes (Debian 12: clang-14, libclang-rt-14-dev).
packages=(clang libclang-rt-dev build-essential cmake libeigen3-dev libyaml-cpp-dev libgtest-dev libgmock-dev)
bash scripts/install-packages.sh "${packages[@]}"

CC=clang CXX=clang++ bash scripts/configure.sh build-fuzz -DSWINGSIM_FUZZ=ON -DSWINGSIM_BUILD_BENCH=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
nice -n 10 cmake --build build-fuzz -j2 --target "${targets[@]}"

# Seeds: the real files each loader reads. CSV seeds are cut to 40 lines (small inputs
# mutate faster) and prefixed with the byte csv_fuzz uses to pick the spec.
seed() {  # seed TARGET FILE...
  local dir="build-fuzz/seeds/$1"; shift
  mkdir -p "$dir"
  for f in "$@"; do [ -f "$f" ] && cp "$f" "$dir/$(echo "$f" | tr '/' '_')"; done
}
rm -rf build-fuzz/seeds
seed participant_fuzz participants/*.yaml
seed knee_model_fuzz models/*.yaml
seed sweep_study_fuzz studies/burkett2004.yaml
seed cylinder_study_fuzz studies/mauch2014.yaml studies/mauch2014-bench.yaml
seed diagnosis_study_fuzz studies/diagnose-demo-cylinder.yaml studies/diagnose-demo-swing.yaml
mkdir -p build-fuzz/seeds/csv_fuzz
for f in studies/data/mauch2014/*.csv tests/data/*.csv; do
  [ -f "$f" ] || continue
  { printf '\000'; head -n 40 "$f"; } >"build-fuzz/seeds/csv_fuzz/bench_$(basename "$f")"
done
{ printf '\001'; head -n 40 studies/data/winter-natural-cadence.csv; } >build-fuzz/seeds/csv_fuzz/winter.csv
{ printf '\003'; cat studies/data/burkett2004-table4.csv; } >build-fuzz/seeds/csv_fuzz/burkett2004-table4.csv
printf '\002time_s,hip_flexion_deg,knee_flexion_deg,hip_moment_Nm\r\n0,-10,40,20\r\n0.01,-9,45,21\r\n' \
  >build-fuzz/seeds/csv_fuzz/kinematics.csv
# Motion files: the first byte picks the column map (motion_file_fuzz.cpp).
mkdir -p build-fuzz/seeds/motion_file_fuzz
for f in tests/data/*.sto tests/data/*.mot studies/data/*/*.sto; do
  [ -f "$f" ] || continue
  { printf '\101'; head -n 60 "$f"; } >"build-fuzz/seeds/motion_file_fuzz/$(basename "$f")"
done
printf '\101swing\nversion=1\nnRows=6\nnColumns=4\ninDegrees=yes\nendheader\ntime\thip_flexion_r\tknee_angle_r\thip_moment\n0\t-10\t40\t20\n0.01\t-8\t45\t21\n0.02\t-6\t50\t21\n0.03\t-4\t54\t20\n0.04\t-2\t57\t18\n0.05\t0\t59\t15\n' \
  >build-fuzz/seeds/motion_file_fuzz/inline.sto

# OpenSim models: the small leg the tests use (the shipped Gait2354 model is 235 kB, past
# -max_len); a dictionary of its element and attribute names.
seed osim_model_fuzz tests/data/*.osim

# Request bodies, the first byte the call (serve_request_fuzz.cpp: 0 describe, 1 simulate, 2 tune).
mkdir -p build-fuzz/seeds/serve_request_fuzz
printf '\000{"participant": "p1", "edits": {"segments.shank.mass_kg": "1.2"}, "knee": "passive-knee"}' \
  >build-fuzz/seeds/serve_request_fuzz/describe.json
printf '\001{"participant": "p2", "lowering_m": 0.03, "added_mass_kg": 0.5, "added_mass_position_m": 0.2}' \
  >build-fuzz/seeds/serve_request_fuzz/simulate.json
printf '\002{"participant": "p1", "knobs": [{"key": "lowering_m", "min": 0, "max": 0.1}], "targets": {"swing_time_s": 0.4}}' \
  >build-fuzz/seeds/serve_request_fuzz/tune.json
{ printf '\000{"participant_yaml": '; python3 -c 'import json,sys; print(json.dumps(open("participants/p1.yaml").read()))'; printf '}'; } \
  >build-fuzz/seeds/serve_request_fuzz/upload.json

# A dictionary per YAML target: every key its seeds use, so mutations stay near valid files.
dictionary() {  # dictionary TARGET -> path
  local dict="build-fuzz/seeds/$1.dict"
  if [ "$1" = serve_request_fuzz ]; then
    cat build-fuzz/seeds/"$1"/* | grep -aoE '"[A-Za-z_.]+"' | sort -u | sed 's/"/\\"/g; s/.*/"&"/' >"$dict"
  elif [ "$1" = osim_model_fuzz ]; then
    cat build-fuzz/seeds/"$1"/* | grep -oE '</?[A-Za-z_]+|[A-Za-z_]+="' | sort -u | sed 's/"/\\"/g; s/.*/"&"/' >"$dict"
  else
    cat build-fuzz/seeds/"$1"/* | grep -oE '[A-Za-z_]+:' | sort -u | sed 's/.*/"&"/' >"$dict"
  fi
  echo "$dict"
}

status=0
mkdir -p build-fuzz/artifacts
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t"
  dict_args=()
  [ "$t" != csv_fuzz ] && [ "$t" != motion_file_fuzz ] && dict_args=(-dict="$(dictionary "$t")")
  echo "== $t: ${seconds} s" >&2
  log="build-fuzz/$t.log"
  if ! nice -n 10 "build-fuzz/$t" "build-fuzz/corpus/$t" "build-fuzz/seeds/$t" "${dict_args[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
      -artifact_prefix="build-fuzz/artifacts/$t-" >"$log" 2>&1; then
    status=1
    echo "!! $t found a problem; see $log and build-fuzz/artifacts/" >&2
    grep -E "ERROR|SUMMARY|terminate|what\(\)" "$log" | head -5 >&2 || true
  fi
  grep -E "^stat::number_of_executed_units|^Done [0-9]+ runs" "$log" | sed "s/^/  $t: /" >&2 || true
done
exit $status
