#!/usr/bin/env python3
"""A parameter study that is not a lowering sweep: P1's swing time against the knee's damping
(the damping table's moments scaled) and the shank's mass (its inertia scaled with it), at
the standard knee-axis location. Swings run on a thread pool: swingsim releases the GIL.

Run from the repository root after building (docs/python.md):
    PYTHONPATH=build/python /usr/bin/python3 examples/python/parameter_study.py [OUT.png]
"""
import concurrent.futures
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

import swingsim  # noqa: E402

DAMPING_SCALES = [0.5, 0.75, 1.0, 1.5, 2.0]  # times the damping table's moments
SHANK_MASSES_KG = [0.6, 0.785, 1.0, 1.3]     # P1's own shank is 0.785 kg (Burkett 2004 Table 2)


def swing_time(participant, knee, damping_scale, shank_mass_kg):
    """P1's swing time, s, with the knee's damping scaled and the shank's mass set (its
    inertia about the COM scaled by the same factor: same shape, denser)."""
    p = participant.copy()
    shank = p.segments.shank
    factor = shank_mass_kg / shank.mass_kg
    shank.mass_kg = shank_mass_kg
    shank.inertia_kgm2 = shank.inertia_kgm2 * factor
    k = knee.copy()
    k.damping_table.moment_Nm = [m * damping_scale for m in knee.damping_table.moment_Nm]
    time = swingsim.simulate(p, knee=k).swing_time_s
    return float("nan") if time is None else time  # None: the swing did not end


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "docs/figures/python-parameter-study.png"
    participant = swingsim.load_participant("participants/p1.yaml")
    knee = swingsim.load_knee(participant.resolve(participant.knee_model))
    grid = [(d, m) for m in SHANK_MASSES_KG for d in DAMPING_SCALES]
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count()) as pool:
        times = list(pool.map(lambda dm: swing_time(participant, knee, *dm), grid))
    table = dict(zip(grid, times))

    print("swing time, s (P1, standard knee axis)")
    print("shank kg  " + "".join(f"  damping x{d:<5}" for d in DAMPING_SCALES))
    for m in SHANK_MASSES_KG:
        print(f"{m:8.3f}  " + "".join(f"  {table[(d, m)]:12.4f}" for d in DAMPING_SCALES))

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for m in SHANK_MASSES_KG:
        ax.plot(DAMPING_SCALES, [table[(d, m)] for d in DAMPING_SCALES], marker="o", label=f"shank {m:g} kg")
    ax.set_xlabel("knee damping scale (x damping-table-default moments)")
    ax.set_ylabel("swing time (s)")
    ax.set_title("P1: swing time against knee damping and shank mass")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"figure: {out}")


if __name__ == "__main__":
    main()
