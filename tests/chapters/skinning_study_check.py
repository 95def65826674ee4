#!/usr/bin/env python3
"""Checks chapter-15-lab's skinning study table (--skinning-study FILE.csv) against what
docs/chapter-15-lab.md says of it. Exits 1 naming the first claim the table breaks."""
import csv
import math
import sys

rows = list(csv.DictReader(open(sys.argv[1], newline="")))


def row(figure, passname, method, joints, influences):
    for r in rows:
        if (r["figure"], r["pass"], r["method"], r["joints"], r["influences"]) == (
                figure, passname, method, joints, str(influences)):
            return r
    sys.exit(f"no row for {figure}, {passname}, {method}, {joints}, {influences}")


def value(r, column):
    v = float(r[column])
    if not math.isfinite(v):
        sys.exit(f"{column} of {r['figure']}, {r['pass']}, {r['method']}: not finite")
    return v


def claim(ok, text):
    if not ok:
        sys.exit("skinning study: " + text)


def name(r):
    return f"{r['figure']} ({r['pass']}, {r['method']}, {r['joints']}, {r['influences']})"


if len(rows) != 8:
    sys.exit(f"skinning study: {len(rows)} rows, not 8")
for r in rows:
    claim(value(r, "draw_ms") > 0, f"no draw time for {name(r)}")
    claim(r["pass"] == "vertex shader" or value(r, "skin_ms") > 0, f"no skinning time for {name(r)}")
    claim(value(r, "total_ms_min") <= value(r, "total_ms") <= value(r, "total_ms_max"),
          f"the median outside the runs' range for {name(r)}")
    claim(int(r["scene_samples"]) > 0, f"the scene pass drew nothing for {name(r)}")
    claim(value(r, "p99_error") <= value(r, "max_error"), f"p99 above the maximum for {name(r)}")
    # Every form against itself in double: fp32's rounding, except for fp16 joints (below).
    if r["joints"] == "fp32":
        claim(value(r, "max_error") <= 1e-5, f"{name(r)}: position error {r['max_error']} > 1e-5")
        claim(value(r, "max_normal_degrees") <= 0.01, f"{name(r)}: normal error {r['max_normal_degrees']} > 0.01")

# The vertex shader skins as the compute pass does, to the bit, and its timed passes drew the same
# fragments (they skin for themselves: the buffer they could read instead holds NaN).
for figure, n in (("tentacle", 8), ("candy wrapper", 4)):
    compute = row(figure, "compute", "linear blend", "fp32", n)
    vertex = row(figure, "vertex shader", "linear blend", "fp32", n)
    for column in ("max_error", "p99_error", "max_normal_degrees", "scene_samples"):
        claim(compute[column] == vertex[column], f"{figure}: the vertex shader's {column} differs from the compute pass's")

# 16-bit joints: measurably worse than 32-bit, yet within 2^-10 of the figure's size and 0.05 degrees.
full = row("tentacle", "compute", "linear blend", "fp32", 8)
half = row("tentacle", "compute", "linear blend", "fp16", 8)
claim(value(half, "max_error") > 10 * value(full, "max_error"), "fp16 joints no worse than fp32")
claim(value(half, "max_error") < 2 ** -10, f"fp16 joints' error {half['max_error']} >= 2^-10")
claim(value(half, "max_normal_degrees") < 0.05, f"fp16 joints' normal error {half['max_normal_degrees']} >= 0.05")
# The heaviest four of eight influences: right for four (above), but the missing weights move the skin.
four = row("tentacle", "compute", "linear blend", "fp32", 4)
claim(value(four, "max_error_every_influence") > 10 * value(full, "max_error_every_influence"),
      "4 of 8 influences as close to the 8-influence skin as 8")
for r in rows:
    if r["influences"] == "8" or r["figure"] == "candy wrapper":
        claim(r["max_error"] == r["max_error_every_influence"], f"{name(r)}: two references for one form")
# The candy wrapper: linear blending collapses its middle ring, dual quaternions keep it.
lbs = row("candy wrapper", "compute", "linear blend", "fp32", 4)
dqs = row("candy wrapper", "compute", "dual quaternion", "fp32", 4)
claim(value(lbs, "narrowest_ring") < 0.05, f"linear blend's narrowest ring {lbs['narrowest_ring']} >= 0.05")
claim(value(dqs, "narrowest_ring") > 0.95, f"dual quaternions' narrowest ring {dqs['narrowest_ring']} <= 0.95")
print("skinning study: every claim holds")
