#!/usr/bin/env bash
# Measures the G-buffer layouts of chapter-15-lab (chapter-15's passes) -- bytes per pixel, frame
# time, error against the fp64 reference -- on the default scene and the hard scenes, runs the numeric tests of the shading
# math, and writes the results into docs/accuracy.md (between its "results" markers) with a plot
# of frame time against error in docs/images/accuracy.svg.
#
#   bench/accuracy.sh [BUILD_DIR]      (default: build; configure and build it first)
#
# Needs gnuplot (Debian: gnuplot-nox) for the plot. Takes a few minutes on two cores.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
chapter=$build/bin/chapter-15-lab
reference=$build/tests/bin/reference_render
numeric=$build/tests/bin/pbr_numeric_test
spirv=$build/bin/shaders/tests/pbr_numeric.comp.spv
command -v gnuplot >/dev/null || { echo "accuracy.sh: gnuplot is missing (apt-get install gnuplot-nox)" >&2; exit 2; }
size=(--width 1280 --height 720)

scenes=(default far-from-origin grazing-light light-touching-surface mirror-sphere intense-light)
scene_file() { [ "$1" = default ] && echo "$build/bin/scenes/default/scene.json" || echo "$build/tests/data/scenes/$1.json"; }

device=""
rows=""
plot_data=""
for scene in "${scenes[@]}"; do
    file=$(scene_file "$scene")
    declare -A ms bpp
    for layout in reference book compact; do
        "$chapter" --headless --device llvmpipe "${size[@]}" --scene "$file" --gbuffer "$layout" \
            --check-output --dump "$out/$scene-$layout" > "$out/run.txt"
        grep -q "0 NaN, 0 infinite, 0 negative" "$out/run.txt" || { cat "$out/run.txt"; exit 1; }
        "$chapter" --headless --device llvmpipe "${size[@]}" --scene "$file" --gbuffer "$layout" \
            --benchmark --warmup 5 --frames 30 > "$out/bench.txt"
        ms[$layout]=$(awk '/^GPU frame/ {print $3}' "$out/bench.txt")
        bpp[$layout]=$(awk '/^gbuffer_bytes_per_pixel/ {print $2}' "$out/bench.txt")
        device=$(awk '/^device/ {$1=""; print substr($0,2)}' "$out/bench.txt")
        driver=$(awk '/^driver/ {$1=""; print substr($0,2)}' "$out/bench.txt")
    done
    "$reference" "$file" "$out/$scene-reference" --compare reference="$out/$scene-reference/light.pfm" \
        --compare book="$out/$scene-book/light.pfm" --compare compact="$out/$scene-compact/light.pfm" > "$out/ref.txt"
    for layout in reference book compact; do
        read -r maxabs rmse psnr other < <(awk -v l="$layout" '$1 == l {sub("/255", "", $4); sub("/255", "", $6);
            match($0, /; [0-9]+ pixels see/); print $4, $6, $8, substr($0, RSTART + 2, RLENGTH - 12)}' "$out/ref.txt")
        rows+="| $scene | $layout | ${bpp[$layout]} | ${ms[$layout]} | $maxabs | $rmse | $psnr | $other |"$'\n'
        plot_data+="$layout ${ms[$layout]} $maxabs $scene"$'\n'
    done
    unset ms bpp
done

# The plot: one point per scene and layout; error on a log scale (the reference's own error is
# the fp32 arithmetic, around 1e-4/255).
printf '%s' "$plot_data" > "$out/points.txt"
gnuplot <<GNUPLOT
set terminal svg size 760,460 font "sans,11" background "#ffffff"
set output "$root/docs/images/accuracy.svg"
set title "chapter-15-lab G-buffer layouts: lavapipe frame time against error (1280x720)"
set xlabel "GPU frame time, median (ms)"
set ylabel "worst-pixel error against the fp64 reference (1/255, log)"
set logscale y
set format y "%g"
set key top right
set grid
plot "$out/points.txt" using (stringcolumn(1) eq "reference" ? \$2 : 1/0):(\$3 > 0 ? \$3 : 1e-4) title "reference (68 B/px)" with points pt 7 ps 1.2, \
     "" using (stringcolumn(1) eq "book" ? \$2 : 1/0):3 title "book (36 B/px)" with points pt 5 ps 1.2, \
     "" using (stringcolumn(1) eq "compact" ? \$2 : 1/0):3 title "compact (16 B/px)" with points pt 9 ps 1.4
GNUPLOT

# The numeric tests and the measured effect of each deviation from the book's formulas.
numeric_random=$("$numeric" "$spirv" --check random --device llvmpipe | sed -n '/^output/,/^light used/p')
numeric_hard=$("$numeric" "$spirv" --check hard --device llvmpipe | sed -n '/^hard case/,/^camera at/p')
deviations=$("$numeric" --deviations)

results=$(cat <<MARKDOWN
Measured on **$device** ($driver), $(date -u +%Y-%m-%d), by \`bench/accuracy.sh\`.

### G-buffer layouts: bytes, frame time and error

Frame time: median GPU frame time over 30 frames after 5 warm-up frames (\`--benchmark\`), 1280x720,
on a 2-core machine shared with other jobs (compare within one run). Error: the GPU's final image against the
fp64 reference shading of the \`reference\` layout's fp32 G-buffer, on displayed values (clamped,
sRGB-encoded, not quantised), per channel in 1/255: the worst pixel, the RMSE, and PSNR, over the
pixels where the layout shows the same surface as the reference (the others are counted in the
last column: see "Visibility is not shading" above).

| scene | layout | B/px | GPU frame (ms) | max abs error (1/255) | RMSE (1/255) | PSNR (dB) | pixels showing another surface |
|---|---|---|---|---|---|---|---|
${rows}
![frame time against error](images/accuracy.svg)

### The shading math on the GPU against fp64 (\`numeric.pbr-random\`, \`numeric.pbr-hard\`)

\`\`\`
$numeric_random
\`\`\`

\`\`\`
$numeric_hard
\`\`\`

### Each deviation from the book's formulas, and its measured effect (fp64)

\`\`\`
$deviations
\`\`\`
MARKDOWN
)

doc=$root/docs/accuracy.md
begin='<!-- results:begin (written by bench/accuracy.sh) -->'
end='<!-- results:end -->'
grep -qF "$begin" "$doc" || { echo "accuracy.sh: $doc has no results markers" >&2; exit 1; }
awk -v begin="$begin" -v end="$end" -v results="$results" '
    $0 == begin { print; print results; skip = 1; next }
    $0 == end { skip = 0 }
    !skip { print }' "$doc" > "$out/doc.md"
cp "$out/doc.md" "$doc"
echo "accuracy.sh: wrote $doc and docs/images/accuracy.svg"
