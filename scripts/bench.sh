#!/usr/bin/env bash
# Benchmarks (docs/speed.md): build swingsim_bench (Release, build-perf/), run every benchmark
# with repetitions, write the JSON to out/bench/bench.json and print medians and the ratios
# the README reports (Simbody swing / reference swing, sweep on 1 core / all cores).
#
#   bash scripts/bench.sh [REPETITIONS]      (default 10; extra benchmark flags via BENCH_ARGS)
#
# Ratios come from one run, so machine load cancels; absolute medians depend on the machine
# and its load, which the summary prints.
set -euo pipefail
cd "$(dirname "$0")/.."
reps="${1:-10}"
build=build-perf
bash scripts/configure.sh "$build" -DCMAKE_BUILD_TYPE=Release
make -C "$build" -j2 swingsim_bench >/dev/null
mkdir -p out/bench
json=out/bench/bench.json
# Random interleaving: the repetitions of all benchmarks run in a shuffled order, so a drift of
# the machine's speed (up to 1.6x from minute to minute here) falls on all of them alike and the
# ratios below compare like with like.
"$build"/swingsim_bench --benchmark_repetitions="$reps" --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true \
  --benchmark_out="$json" --benchmark_out_format=json ${BENCH_ARGS:-} >/dev/null
python3 - "$json" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
ctx = d["context"]
med = {b["run_name"]: b for b in d["benchmarks"] if b.get("aggregate_name") == "median"}
def ms(name):
    b = med[name]
    t = b["real_time"]
    return {"ns": t * 1e-6, "us": t * 1e-3, "ms": t, "s": t * 1e3}[b["time_unit"]]
print(f"machine: {ctx['num_cpus']} x {ctx['mhz_per_cpu']} MHz, load average {', '.join(f'{x:.2f}' for x in ctx.get('load_avg', []))}, {ctx['date']}")
print("| benchmark | median (ms, wall) | counters |")
print("|---|---|---|")
skip = {"name", "run_name", "run_type", "repetitions", "threads", "aggregate_name", "aggregate_unit", "real_time",
        "cpu_time", "time_unit", "iterations", "family_index", "per_family_instance_index", "repetition_index"}
for name, b in med.items():
    counters = ", ".join(f"{k}={b[k]:.6g}" for k in b if k not in skip)
    print(f"| {name} | {ms(name):.3f} | {counters} |")
swing = float("nan")
# Each block prints when the benchmarks it needs ran (BENCH_ARGS may filter some out).
def name_of(prefix):
    return next(k for k in med if k.startswith(prefix))
def section(block):
    try:
        block()
    except (StopIteration, KeyError):
        pass
def block_0():
    global swing
    swing = ms(name_of("BM_SwingSimbody/variant:0"))
    plain = ms(name_of("BM_SwingSimbody/variant:1"))
    rkm = ms(name_of("BM_SwingSimbody/variant:2"))
    rk3 = ms(name_of("BM_SwingSimbody/variant:3"))
    print(f"\nSimbody swing: plain path (RKM 1e-4, Simbody event handlers) / default (Dormand-Prince 1e-5): {plain / swing:.2f}x; "
          f"fast path on Simbody's RKM 1e-4 / default: {rkm / swing:.2f}x; on Simbody's RK3 1e-3 / default: {rk3 / swing:.2f}x")
    realize = ms("BM_RealizeLeg")
    n = med[name_of("BM_SwingSimbody/variant:0")]["realizations"]
    print(f"one realization of the leg: {realize * 1e3:.2f} us; default swing: {n:.0f} realizations = {n * realize:.2f} ms "
          f"= {100 * n * realize / swing:.0f} % of the swing's {swing:.2f} ms")
    ref = ms(name_of("BM_SwingReference/tol_exp:0"))
    ref6 = ms(name_of("BM_SwingReference/tol_exp:6"))
    print(f"Simbody swing / reference swing (same accuracy number): {swing / ref:.0f}x; / reference at 1e-6 (converged): {swing / ref6:.0f}x")
section(block_0)
def block_1():
    allc = name_of("BM_SweepBurkett/jobs:0")
    one = name_of("BM_SweepBurkett/jobs:1")
    print(f"sweep (84 swings) on 1 core / all cores: {ms(one) / ms(allc):.2f}x")
section(block_1)
def block_2():
    fit0 = ms(name_of("BM_FitMauch/fit_switches:0"))
    fit1 = ms(name_of("BM_FitMauch/fit_switches:1"))
    print(f"fitting both Mauch models on three files: {fit0:.1f} ms at fixed switches, {fit1:.1f} ms with the switch "
          f"constants fitted ({fit1 / fit0:.0f}x)")
section(block_2)
def block_3():
    dgc = ms(name_of("BM_DiagnoseCylinder"))
    dgs = ms(name_of("BM_DiagnoseSwing"))
    print(f"one cylinder diagnosis: {dgc / 1e3:.2f} s; one swing diagnosis (three trials): {dgs / 1e3:.2f} s; "
          f"swing diagnosis / Simbody swing: {dgs / swing:.0f}x")
section(block_3)
def block_4():
    # The Monte Carlo (sweep --uncertainty 1000 on the four Burkett participants is
    # 84,000 swings), measured on fewer samples and extrapolated by swings.
    mc = {j: name_of(f"BM_UncertaintyBurkett/jobs:{j}") for j in (1, 2)}
    mc_swings = med[mc[1]]["swings"]
    print(f"Monte Carlo, 84,000 swings (sweep --uncertainty 1000, Burkett study), EXTRAPOLATED from "
          f"{mc_swings:.0f} swings (20 samples) measured in this run: "
          f"1 thread {ms(mc[1]) / 1e3 * 84000 / mc_swings:.0f} s (measured {ms(mc[1]) / 1e3:.2f} s), "
          f"2 threads {ms(mc[2]) / 1e3 * 84000 / mc_swings:.0f} s (measured {ms(mc[2]) / 1e3:.2f} s); "
          f"{mc_swings / (ms(mc[2]) / 1e3):.0f} swings/s on 2 threads; 1 / 2 threads {ms(mc[1]) / ms(mc[2]):.2f}x")
section(block_4)
def block_5():
    lib = ms(name_of("BM_SwingAddedDamper/expression:0"))
    expr = ms(name_of("BM_SwingAddedDamper/expression:1"))
    print(f"P1 swing with an added 0.3 N m s/rad damper: as a user's expression / as the library's record: {expr / lib:.3f}x")
section(block_5)
print(f"json: {sys.argv[1]}")
EOF
