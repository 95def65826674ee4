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


if len(rows) != 8:
    sys.exit(f"skinning study: {len(rows)} rows, not 8")
for r in rows:
    claim(value(r, "draw_ms") > 0, f"no draw time for {r}")
    claim(r["pass"] == "vertex shader" or value(r, "skin_ms") > 0, f"no skinning time for {r}")

# chapter-17's form, and the vertex shader's, within chapter-17's bound of the reference.
compute = row("tentacle", "compute", "linear blend", "fp32", 8)
vertex = row("tentacle", "vertex shader", "linear blend", "fp32", 8)
for r in (compute, vertex):
    claim(value(r, "max_error") <= 1e-5, f"{r['pass']}'s position error {r['max_error']} > 1e-5")
    claim(value(r, "max_normal_degrees") <= 0.01, f"{r['pass']}'s normal error > 0.01 degrees")
    claim(value(r, "p99_error") <= value(r, "max_error"), "p99 above the maximum")
# 16-bit joints: measurably worse than 32-bit, yet within 2^-10 of the figure's size.
half = row("tentacle", "compute", "linear blend", "fp16", 8)
claim(value(half, "max_error") > 10 * value(compute, "max_error"), "fp16 joints no worse than fp32")
claim(value(half, "max_error") < 2 ** -10, f"fp16 joints' error {half['max_error']} >= 2^-10")
# The heaviest four of eight influences: the missing weights move the skin.
four = row("tentacle", "compute", "linear blend", "fp32", 4)
claim(value(four, "max_error") > 10 * value(compute, "max_error"), "4 of 8 influences as exact as 8")
# Dual quaternions in float against dual quaternions in double.
for figure, n in (("tentacle", 8), ("candy wrapper", 4)):
    dq = row(figure, "compute", "dual quaternion", "fp32", n)
    claim(value(dq, "max_error") <= 1e-5, f"{figure}'s dual quaternion error {dq['max_error']} > 1e-5")
# The candy wrapper: linear blending collapses its middle ring, dual quaternions keep it.
lbs = row("candy wrapper", "compute", "linear blend", "fp32", 4)
dqs = row("candy wrapper", "compute", "dual quaternion", "fp32", 4)
claim(value(lbs, "narrowest_ring") < 0.05, f"linear blend's narrowest ring {lbs['narrowest_ring']} >= 0.05")
claim(value(dqs, "narrowest_ring") > 0.95, f"dual quaternions' narrowest ring {dqs['narrowest_ring']} <= 0.95")
print("skinning study: every claim holds")
