#!/usr/bin/env bash
# Writes the many-light tables and plots from bench/results/ (bench/light_scaling.sh calls it):
# docs/performance.md's "light-scaling" and "forward-deferred" sections, docs/accuracy.md's
# "light-cutoff" section, docs/images/light-scaling.svg, forward-deferred.svg and light-cutoff.svg.
# Needs gnuplot.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
results=$root/bench/results
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v gnuplot > /dev/null || { echo "light_report.sh: gnuplot is missing (apt-get install gnuplot-nox)" >&2; exit 2; }

# paste DOC SECTION FILE: replaces DOC between the section's markers with FILE.
paste_section() {
    local begin="<!-- $2:begin (written by bench/light_scaling.sh) -->" end="<!-- $2:end -->"
    grep -qF "$begin" "$1" || { echo "light_report.sh: $1 has no $2 markers" >&2; exit 1; }
    awk -v begin="$begin" -v end="$end" -v section="$3" '
        $0 == begin { print; while ((getline line < section) > 0) print line; skip = 1; next }
        $0 == end { skip = 0 }
        !skip { print }' "$1" > "$work/doc.md"
    cp "$work/doc.md" "$1"
}

# table TSV SIZE: one markdown table of the scaling results of one device and size.
table() {
    awk -F'\t' -v size="$2" '
        NR == 1 || $2 != size { next }
        { key = $3; n[key] = 1; v[key, $4, $5, "frame"] = $6; v[key, $4, $5, "cull"] = $7; v[key, $4, $5, "light"] = $8 }
        function ratio(a, b) { return (a == "" || b == "" || a == "-" || b == "-" || b == 0) ? "-" : sprintf("%.0fx", a / b) }
        function get(k, c, f, what) { x = v[k, c, f, what]; return x == "" ? "-" : x }
        END {
            print "| lights | loop: light pass, fragment / compute (ms) | tiled: culling (ms) | tiled: light pass, fragment / compute (ms) | tiled: whole frame, fragment / compute (ms) | light pass, loop / tiled (fragment, compute) |"
            print "|---:|---|---|---|---|---|"
            for (k = 16; k <= 65536; k *= 4) if (n[k])
                printf "| %d | %s / %s | %s | %s / %s | %s / %s | %s, %s |\n", k,
                    get(k, "none", "fragment", "light"), get(k, "none", "compute", "light"), get(k, "tiled", "fragment", "cull"),
                    get(k, "tiled", "fragment", "light"), get(k, "tiled", "compute", "light"),
                    get(k, "tiled", "fragment", "frame"), get(k, "tiled", "compute", "frame"),
                    ratio(v[k, "none", "fragment", "light"], v[k, "tiled", "fragment", "light"]),
                    ratio(v[k, "none", "compute", "light"], v[k, "tiled", "compute", "light"])
        }' "$1"
}

# targets TSV SIZE: the two targets, as one line.
targets() {
    awk -F'\t' -v size="$2" '
        NR == 1 || $2 != size { next }
        { v[$3, $4, $5, "frame"] = $6; v[$3, $4, $5, "light"] = $8 }
        function r(a, b) { return (a == "" || b == "" || a == "-" || b == "-") ? "-" : sprintf("%.2f", a / b) }
        END {
            printf "Whole frame with tiled culling at 65,536 lights over 64 lights: **%s** (fragment), **%s** (compute); target at most 2. ",
                r(v[65536, "tiled", "fragment", "frame"], v[64, "tiled", "fragment", "frame"]),
                r(v[65536, "tiled", "compute", "frame"], v[64, "tiled", "compute", "frame"])
            printf "Light pass at 4,096 lights, the loop over the tiled one: **%s** (fragment), **%s** (compute); target at least 50.\n",
                r(v[4096, "none", "fragment", "light"], v[4096, "tiled", "fragment", "light"]),
                r(v[4096, "none", "compute", "light"], v[4096, "tiled", "compute", "light"])
        }' "$1"
}

device() { awk -F'\t' -v size="$2" 'NR > 1 && $2 == size {print $1; exit}' "$1"; }

# plot_panels SVG SIZE YLABEL XTICS PLOT: one log-log panel per entry of plots ("FILE|TITLE"), each
# "plot 'FILE' PLOT" against the number of lights, side by side.
plot_panels() {
    local entry file title
    {
        echo "set terminal svg size $2 font 'sans,11' background '#ffffff'"
        echo "set output '$1'"
        echo "set multiplot layout 1,${#plots[@]}"
        echo "set logscale xy; set grid; set key top left font ',9'; set xlabel 'point lights'; set ylabel '$3'"
        echo "set xtics $4"
        for entry in "${plots[@]}"; do
            file=${entry%%|*} title=${entry#*|}
            echo "set title '$title' font ',10'"
            echo "plot '$file' $5"
        done
        echo "unset multiplot"
    } | gnuplot
}

section=$work/scaling.md
: > "$section"
plots=()
for tsv in "$results/light-scaling-lavapipe.tsv" "$results/light-scaling-gpu.tsv"; do
    [ -f "$tsv" ] || continue
    for size in $(awk -F'\t' 'NR > 1 && !seen[$2]++ {print $2}' "$tsv"); do
        {
            echo "**$(device "$tsv" "$size")**, ${size}, median GPU times (timestamp queries):"
            echo
            table "$tsv" "$size"
            echo
            targets "$tsv" "$size"
            echo
        } >> "$section"
        # Plot data: lights, loop fragment, loop compute, tiled frame fragment, tiled frame compute.
        name=$(echo "$(device "$tsv" "$size")-$size" | tr -c 'A-Za-z0-9\n' '-')
        awk -F'\t' -v size="$size" 'NR > 1 && $2 == size {
                k = $3; n[k] = 1; if ($4 == "none") l[k, $5] = $8; else f[k, $5] = $6 }
            END { for (k = 16; k <= 65536; k *= 4) if (n[k]) {
                printf "%d", k
                printf " %s %s %s %s\n", (l[k, "fragment"] == "" ? "NaN" : l[k, "fragment"]), (l[k, "compute"] == "" ? "NaN" : l[k, "compute"]),
                    f[k, "fragment"], f[k, "compute"] } }' "$tsv" > "$work/$name.dat"
        plots+=("$work/$name.dat|$(device "$tsv" "$size" | sed 's/ (.*//'), $size")
    done
done
if [ -f "$results/light-scaling-gpu-validation.txt" ]; then
    echo "Validation on the GPU: one 3-frame run of every configuration at 1920x1080 with \`--validation\`" \
         "(synchronization validation on): **$(cat "$results/light-scaling-gpu-validation.txt") messages**." >> "$section"
fi
paste_section "$root/docs/performance.md" light-scaling "$section"

# The scaling plot: one panel per device and size; light pass of the loop and whole frame with
# culling against the number of lights, log-log.
plot_panels "$root/docs/images/light-scaling.svg" 1100,380 "GPU ms (median)" "('16' 16, '256' 256, '4k' 4096, '64k' 65536)" \
    "using 1:2 with linespoints title 'loop: light pass (fragment)', '' using 1:3 with linespoints title 'loop: light pass (compute)', '' using 1:4 with linespoints title 'tiled: whole frame (fragment)', '' using 1:5 with linespoints title 'tiled: whole frame (compute)'"

# Forward against deferred: one table per device and size, and one plot (frame time against N).
forward_table() {
    awk -F'\t' -v size="$2" '
        NR == 1 || $2 != size { next }
        { k = $3; n[k] = 1; key = $4 "-" $5 "-" $6; frame[k, key] = $7; scene[k, key] = $8 }
        function consider(k, key, name) {
            if (frame[k, key] != "" && (bestName == "" || frame[k, key] + 0 < best + 0)) { best = frame[k, key]; bestName = name } }
        END {
            print "| lights | forward: frame (ms) | deferred, loop: frame, fragment / compute light pass (ms) | deferred, tiled culling: frame, fragment / compute (ms) | forward over the best deferred | fastest |"
            print "|---:|---|---|---|---|---|"
            for (k = 1; k <= 65536; k *= 2) if (n[k]) {
                best = ""; bestName = ""
                consider(k, "deferred-none-fragment", "deferred, loop, fragment")
                consider(k, "deferred-none-compute", "deferred, loop, compute")
                consider(k, "deferred-tiled-fragment", "deferred, tiled, fragment")
                consider(k, "deferred-tiled-compute", "deferred, tiled, compute")
                deferredBest = best
                consider(k, "forward-none-fragment", "**forward**")
                printf "| %d | %s | %s / %s | %s / %s | %.2f | %s |\n", k, frame[k, "forward-none-fragment"],
                    frame[k, "deferred-none-fragment"], frame[k, "deferred-none-compute"],
                    frame[k, "deferred-tiled-fragment"], frame[k, "deferred-tiled-compute"],
                    frame[k, "forward-none-fragment"] / deferredBest, bestName
            }
            printf "\nThe G-buffer pass (the scene pass of deferred shading) takes %s ms; the forward pass with 1 light %s ms.\n",
                scene[1, "deferred-none-fragment"], scene[1, "forward-none-fragment"]
        }' "$1"
}
section=$work/forward.md
: > "$section"
plots=()
for tsv in "$results/forward-deferred-lavapipe.tsv" "$results/forward-deferred-gpu.tsv"; do
    [ -f "$tsv" ] || continue
    for size in $(awk -F'\t' 'NR > 1 && !seen[$2]++ {print $2}' "$tsv"); do
        {
            echo "**$(device "$tsv" "$size")**, ${size}, median GPU times (timestamp queries):"
            echo
            forward_table "$tsv" "$size"
            echo
        } >> "$section"
        name=forward-$(echo "$(device "$tsv" "$size")-$size" | tr -c 'A-Za-z0-9\n' '-')
        awk -F'\t' -v size="$size" 'NR > 1 && $2 == size { k = $3; n[k] = 1; f[k, $4 "-" $5 "-" $6] = $7 }
            END { for (k = 1; k <= 65536; k *= 2) if (n[k])
                printf "%d %s %s %s %s %s\n", k, f[k, "forward-none-fragment"], f[k, "deferred-none-fragment"],
                    f[k, "deferred-none-compute"], f[k, "deferred-tiled-fragment"], f[k, "deferred-tiled-compute"] }' "$tsv" > "$work/$name.dat"
        plots+=("$work/$name.dat|$(device "$tsv" "$size" | sed 's/ (.*//'), $size")
    done
done
if [ -f "$results/forward-deferred-gpu-validation.txt" ]; then
    echo "Validation on the GPU: a 3-frame run of forward shading at 1920x1080 with \`--validation\` on the" \
         "default scene, lights-16 and lights-1024: **$(cat "$results/forward-deferred-gpu-validation.txt") messages**." >> "$section"
fi
if [ -s "$section" ]; then
    paste_section "$root/docs/performance.md" forward-deferred "$section"
    plot_panels "$root/docs/images/forward-deferred.svg" 1300,420 "GPU frame ms (median)" \
        "('1' 1, '4' 4, '16' 16, '64' 64, '256' 256, '1k' 1024); set xrange [0.8:1300]" \
        "using 1:2 with linespoints lw 2 title 'forward', '' using 1:3 with linespoints title 'deferred, loop (fragment)', '' using 1:4 with linespoints title 'deferred, loop (compute)', '' using 1:5 with linespoints title 'deferred, tiled (fragment)', '' using 1:6 with linespoints title 'deferred, tiled (compute)'"
fi

# The cutoff: table and the speed-against-error curve.
tsv=$results/light-cutoff-lavapipe.tsv
if [ -f "$tsv" ]; then
    awk -F'\t' 'NR == 1 { print "| --light-cutoff | frame (ms) | light pass (ms) | max abs error (/255) | RMSE (/255) |"; print "|---|---|---|---|---|"; next }
        { printf "| %s | %s | %s | %s | %s |\n", ($1 == "none" ? "none (the loop, unbounded)" : $1), $2, $3, $4, $5 }' "$tsv" > "$work/cutoff.md"
    paste_section "$root/docs/accuracy.md" light-cutoff "$work/cutoff.md"
    awk -F'\t' 'NR > 1 && $1 != "none" {print $2, $4, $1, $5}' "$tsv" > "$work/cutoff.dat"
    loop=$(awk -F'\t' '$1 == "none" {print $2}' "$tsv")
    gnuplot <<GNUPLOT
set terminal svg size 760,460 font "sans,11" background "#ffffff"
set output "$root/docs/images/light-cutoff.svg"
set title "Light reach: frame time against error (lights-1024 without ranges, lavapipe, 1280x720)" font ",10"
set xlabel "GPU frame time, median (ms): tiled culling with --light-cutoff E"
set ylabel "error on screen (/255), against the unbounded falloff"
set logscale xy
set xrange [100:20000]
set grid
set arrow from graph 0, first 1 to graph 1, first 1 nohead dashtype 2
set label "1/255" at graph 0.01, first 1.3
set arrow from first $loop, graph 0 to first $loop, graph 1 nohead dashtype 3
set label "the loop, unbounded" at first $loop, graph 0.97 right offset -0.5,0
set key bottom left
plot "$work/cutoff.dat" using 1:2 with linespoints pointtype 7 title "max abs", \
     "" using 1:4 with linespoints pointtype 5 title "RMSE", \
     "" using 1:2:(sprintf("%s", stringcolumn(3))) with labels offset 0,0.8 font ",8" notitle
GNUPLOT
    echo "light_report.sh: the unbounded loop's frame: $loop ms" >&2
fi
echo "light_report.sh: wrote docs/performance.md, docs/accuracy.md and their plots" >&2
