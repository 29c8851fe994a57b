#!/usr/bin/env python3
"""Cut the two swings of Winter's natural-cadence walking (studies/data/winter-natural-cadence.csv,
Winter 2009 Appendix Tables A.4 and A.5) into swing kinematics CSVs for studies/winter-swing.yaml:

  swing1.csv  frames 1-28  (toe-off right at 0.000 s to heel contact right at 0.386 s)
  swing2.csv  frames 70-97 (toe-off right at 0.987 s to heel contact right at 1.373 s)

Time is rebased to 0 at toe-off. Angles are copied as published (degrees, flexion positive).
knee_moment_Nm is Winter's knee moment (Table A.5, the moment of force acting on the thigh at
the knee, counter-clockwise positive with the subject progressing left to right, +x): on the
thigh a counter-clockwise moment is the reaction of a clockwise one on the shank, and a
clockwise moment on the shank swings it backwards, i.e. flexes the knee. So Winter's value is
the knee moment with swingsim's sign (+ = flexion), copied unchanged; e.g. late swing +15 N m
is the hamstrings braking the knee's extension. No hip moment column: the swing is driven by
the measured thigh. Nothing is smoothed or resampled.

  python3 scripts/winter-swing-data.py
"""
import csv
import os

here = os.path.dirname(os.path.abspath(__file__))
source = os.path.join(here, "..", "studies", "data", "winter-natural-cadence.csv")
out_dir = os.path.join(here, "..", "studies", "data", "winter-swing")
rows = list(csv.DictReader(open(source)))
for name, first, last in (("swing1", 1, 28), ("swing2", 70, 97)):
    cut = [r for r in rows if first <= int(r["frame"]) <= last]
    assert cut[0]["event"] == "TOR" and cut[-1]["event"] == "HCR", name
    t0 = float(cut[0]["time_s"])
    with open(os.path.join(out_dir, name + ".csv"), "w", newline="") as f:
        f.write("time_s,hip_flexion_deg,knee_flexion_deg,knee_moment_Nm\n")
        for r in cut:
            f.write("%.3f,%s,%s,%s\n" % (float(r["time_s"]) - t0, r["hip_deg"], r["knee_deg"], r["knee_moment_Nm"]))
    print(name, len(cut), "rows")
