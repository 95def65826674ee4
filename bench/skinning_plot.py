#!/usr/bin/env python3
"""Plots chapter-15-lab's skinning study (--skinning-study FILE.csv) as SVG: a row per form of
skinning the tentacle, sorted by its largest position error against the tentacle skinned in double
with all its 8 influences (relative to its size, written
beside its name), and on each row a dot per table for the GPU time of skinning and drawing it in
four passes, relative to chapter-17's form (compute once, linear blend, fp32 joints, 8 influences)
in the same table: the median run as a dot, the fastest to the slowest run as a line.

  bench/skinning_plot.py OUT.svg LABEL=FILE.csv [LABEL=FILE.csv ...]

Needs nothing beyond Python's standard library."""
import csv
import sys

COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"]
W, LEFT, RIGHT, TOP, ROW, BOTTOM = 820, 300, 30, 20, 34, 90


def short(r):
    if r["pass"] == "vertex shader":
        return "skinned in every pass's vertex shader"
    if r["method"] == "dual quaternion":
        return "dual quaternions"
    if r["joints"] == "fp16":
        return "fp16 joint matrices"
    if r["influences"] == "4":
        return "the heaviest 4 of 8 influences"
    return "chapter-17: compute once, LBS, fp32, 8"


def main():
    out, series = sys.argv[1], []
    for arg in sys.argv[2:]:
        label, path = arg.split("=", 1)
        rows = [r for r in csv.DictReader(open(path, newline="")) if r["figure"] == "tentacle"]
        base = float(rows[0]["total_ms"])  # the first row: chapter-17's form
        series.append((label, {short(r): (float(r["total_ms"]) / base, float(r["max_error_every_influence"]),
                                          float(r["total_ms_min"]) / base, float(r["total_ms_max"]) / base)
                               for r in rows}))
    forms = sorted(series[0][1], key=lambda f: max(s[f][1] for _, s in series))
    xmax = 2.5
    height = TOP + ROW * len(forms) + BOTTOM
    px = lambda x: LEFT + (W - LEFT - RIGHT) * x / xmax
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{height}" font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{height}" fill="white"/>']
    bottom = TOP + ROW * len(forms)
    step = 0.5 if xmax <= 4 else 1.0
    x = 0.0
    while x <= xmax + 1e-9:
        svg.append(f'<line x1="{px(x):.1f}" y1="{TOP}" x2="{px(x):.1f}" y2="{bottom}" stroke="{"#999" if x == 1 else "#e4e4e4"}"/>')
        svg.append(f'<text x="{px(x):.1f}" y="{bottom + 16}" text-anchor="middle">{x:g}</text>')
        x += step
    for i, form in enumerate(forms):
        y = TOP + ROW * i + ROW / 2
        error = max(s[form][1] for _, s in series)
        svg.append(f'<line x1="{LEFT}" y1="{y}" x2="{W - RIGHT}" y2="{y}" stroke="#f0f0f0"/>')
        svg.append(f'<text x="{LEFT - 10}" y="{y - 2}" text-anchor="end">{form}</text>')
        svg.append(f'<text x="{LEFT - 10}" y="{y + 12}" text-anchor="end" fill="#555">error {error:.1e}</text>')
        for k, (_, s) in enumerate(series):
            ratio, _, fastest, slowest = s[form]
            cy = y + 4 * (k - 1)
            svg.append(f'<line x1="{px(fastest):.1f}" y1="{cy}" x2="{px(min(slowest, xmax)):.1f}" y2="{cy}" '
                       f'stroke="{COLORS[k]}" stroke-opacity="0.5" stroke-width="2"/>')
            svg.append(f'<circle cx="{px(ratio):.1f}" cy="{cy}" r="5" fill="{COLORS[k]}" fill-opacity="0.85"/>')
    svg.append(f'<rect x="{LEFT}" y="{TOP}" width="{W - LEFT - RIGHT}" height="{bottom - TOP}" fill="none" stroke="black"/>')
    svg.append(f'<text x="{(LEFT + W - RIGHT) / 2}" y="{bottom + 34}" text-anchor="middle">GPU time of skinning + scene pass + 3 cascades, relative to chapter-17\'s form</text>')
    for k, (label, _) in enumerate(series):
        lx = 40 + 260 * k
        svg.append(f'<circle cx="{lx}" cy="{bottom + 60}" r="5" fill="{COLORS[k]}"/>')
        svg.append(f'<text x="{lx + 10}" y="{bottom + 64}">{label}</text>')
    svg.append("</svg>")
    open(out, "w").write("\n".join(svg) + "\n")


main()
