#!/usr/bin/env bash
# chapter-15-lab's shadow study: the GPU time of each way of drawing and filtering chapter-16's
# cascade shadows, against its error -- the visibility it gives each pixel against a reference
# found by rays (tests/accuracy/shadow_reference.cpp). docs/chapter-15-lab.md, "Shadows: speed
# against error".
#
#   bench/shadow_study.sh [BUILD_DIR] OUT_DIR [--device NAME] [--size W H] [--rounds N] [--only NAMES]
#   bench/shadow_study.sh --report OUT_DIR [PLOT.svg]
#
# The first form measures, into OUT_DIR: the study's scenes (the default courtyard with its sun
# 40 and 10 degrees above the horizon: scene-sun40.json, scene-sun10.json), each configuration's
# visibility at 640x360 (chapter-15-lab --gbuffer reference --view visibility --dump) and the
# reference's verdict on it (errors-sun40.json, errors-sun10.json: shadow_reference, when BUILD_DIR
# has it), and the GPU times (timings.tsv: --benchmark --warmup 10 --frames 40 at 1280x720 unless
# --size, on the 40-degree scene, the configurations taken in turn for N rounds, default 3). The
# second form prints the markdown table (medians of the rounds) and, with gnuplot, plots the time
# of the shadow and light passes against the fraction of pixels wrong.
#
# The configurations: the book's variance map with 3 cascades of 2048 drawn by its geometry shader
# (chapter-16's defaults), and from there one thing changed at a time -- 1, 2 or 4 cascades; maps
# of 512, 1024 or 4096; depth comparison with PCF over 2x2, 3x3 or 5x5 texels, and PCF 2x2 on
# maps of 4096 (about the variance map's time at 2048: error at equal time); the cascades drawn
# with multiview or a pass each; the variance map's moments in half floats; the depth alone at one
# texel, compared in the shader (chapter-16's read without the bound) -- and no shadows at all, for
# the time. --only "NAME;NAME": those configurations alone (none and vsm 3x2048 always: the
# baseline the errors are counted against, and the time without shadows).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

configs=(
    "none|--shadows none"
    "vsm 3x2048|--shadows vsm"
    "1 cascade|--shadows vsm --cascades 1"
    "2 cascades|--shadows vsm --cascades 2"
    "4 cascades|--shadows vsm --cascades 4"
    "size 512|--shadows vsm --shadow-map-size 512"
    "size 1024|--shadows vsm --shadow-map-size 1024"
    "size 4096|--shadows vsm --shadow-map-size 4096"
    "pcf 2x2|--shadows pcf2"
    "pcf 3x3|--shadows pcf3"
    "pcf 5x5|--shadows pcf5"
    "pcf 2x2, 4096|--shadows pcf2 --shadow-map-size 4096"
    "vsm fp16|--shadows vsm16"
    "depth 1 texel|--shadows depth"
    "multiview|--shadows vsm --shadow-layers multiview"
    "pass per cascade|--shadows vsm --shadow-layers passes"
)
slug() { tr ' ' '_' <<< "$1"; }

if [ "${1:-}" = --report ]; then
    out=$(cd "$2" && pwd)
    plot=${3:-}
    python3 - "$out" "$plot" <<'EOF'
import json, os, statistics, subprocess, sys
out, plot = sys.argv[1], sys.argv[2]
rows = {}
order = []
device = ""
for line in open(os.path.join(out, "timings.tsv")):
    name, frame, shadow, light, dev = line.rstrip("\n").split("\t")
    device = dev
    if name not in rows:
        rows[name] = []
        order.append(name)
    rows[name].append((float(frame), float(shadow or 0), float(light)))
errors = {}
for scene in ("sun40", "sun10"):
    path = os.path.join(out, "errors-%s.json" % scene)
    if os.path.exists(path):
        errors[scene] = json.load(open(path))["compared"]
def med(values, i):
    return statistics.median(v[i] for v in values)
print("Device: %s. GPU medians in ms over %d rounds; errors in %% of the pixels facing the sun." %
      (device, len(rows[order[0]])))
print()
print("| configuration | shadow pass ms | light pass ms | frame ms | wrong, sun 40 deg | at outlines | acne | leaks | bleeding | MAE | wrong, sun 10 deg | acne | leaks |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
points = []
for name in order:
    v = rows[name]
    cells = ["%s" % name, "%.2f" % med(v, 1) if med(v, 1) else "", "%.2f" % med(v, 2), "%.2f" % med(v, 0)]
    e40 = errors.get("sun40", {}).get(name.replace(" ", "_"))
    e10 = errors.get("sun10", {}).get(name.replace(" ", "_"))
    if e40:
        cells += ["%.3f" % (100 * e40["wrong"]), "%.3f" % (100 * e40["edge"]), "%.3f" % (100 * e40["false_shadow"]),
                  "%.3f" % (100 * e40["false_light"]), "%.4f" % e40["bleeding"], "%.4f" % e40["mae"]]
        points.append((med(v, 1) + med(v, 2), 100 * e40["wrong"], name))
    else:
        cells += [""] * 6
    if e10:
        cells += ["%.3f" % (100 * e10["wrong"]), "%.3f" % (100 * e10["false_shadow"]), "%.3f" % (100 * e10["false_light"])]
    else:
        cells += [""] * 3
    print("| " + " | ".join(cells) + " |")
if plot and points:
    data = os.path.join(out, "plot.dat")
    # Labels of points that would overlap (the same error, nearly the same time: the ways of
    # drawing the layers) stacked one under the other.
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    dx, dy = (max(xs) - min(xs)) or 1.0, (max(ys) - min(ys)) or 1.0
    placed = []
    with open(data, "w") as f:
        for x, y, name in points:
            ly = y
            while any(abs(x - px) < 0.12 * dx and abs(ly - py) < 0.04 * dy for px, py in placed):
                ly -= 0.05 * dy
            placed.append((x, ly))
            f.write('%f %f %f "%s"\n' % (x, y, ly, name))
    script = """set terminal svg size 720,420 font 'sans,11'
set output '%s'
set title 'Shadows: GPU time against error (%s)'
set xlabel 'shadow pass + light pass, ms'
set ylabel 'pixels wrong, %% (sun 40 degrees)'
set grid
set key off
set offsets graph 0.02, graph 0.2, graph 0.08, graph 0.05
set yrange [0:*]
plot '%s' using 1:2 with points pointtype 7 pointsize 0.8 linecolor rgb '#1f5fa8', \
     '' using 1:3:4 with labels offset 0.8,0.6 left font ',9'
""" % (plot, device, data)
    subprocess.run(["gnuplot"], input=script.encode(), check=True)
EOF
    exit 0
fi

build=$root/build
device=()
size=(--width 1280 --height 720)
rounds=3
out=
only=
while [ $# -gt 0 ]; do
    case $1 in
        --device) device=(--device "$2"); shift ;;
        --size) size=(--width "$2" --height "$3"); shift 2 ;;
        --rounds) rounds=$2; shift ;;
        --only)
            [ $# -ge 2 ] && [ -n "$2" ] || { echo "shadow_study.sh: --only needs names, separated by ;" >&2; exit 2; }
            only=$2; shift ;;
        *) if [ -z "$out" ] && [ -d "$1/bin" ]; then build=$(cd "$1" && pwd); else out=$1; fi ;;
    esac
    shift
done
[ -n "$out" ] || { echo "shadow_study.sh: name an OUT_DIR" >&2; exit 2; }
if [ -n "$only" ]; then
    IFS=';' read -r -a wanted <<< "$only"
    for name in "${wanted[@]}"; do
        known=0
        for entry in "${configs[@]}"; do [ "${entry%%|*}" = "$name" ] && known=1; done
        [ $known = 1 ] || { echo "shadow_study.sh: --only: no configuration named '$name'" >&2; exit 2; }
    done
    kept=()
    for entry in "${configs[@]}"; do
        name=${entry%%|*}
        keep=0
        [ "$name" = none ] || [ "$name" = "vsm 3x2048" ] && keep=1
        for w in "${wanted[@]}"; do [ "$w" = "$name" ] && keep=1; done
        [ $keep = 1 ] && kept+=("$entry")
    done
    configs=("${kept[@]}")
fi
lab=$build/bin/chapter-15-lab
[ -x "$lab" ] || { echo "shadow_study.sh: build $build first: no $lab" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)

# The study's scenes: the default courtyard, its sun turned to 40 and 10 degrees above the horizon
# (toward -x, -z), its models' paths made absolute.
# (awk, not python: the GPU machine has no python.)
scenes=$build/bin/scenes/default
for scene in sun40 sun10; do
    awk -v degrees="${scene#sun}" -v dir="$scenes" '
        BEGIN { e = degrees * atan2(0, -1) / 180 }
        skipping { if ($0 ~ /\]/) skipping = 0; next }
        /"direction": \[/ && !done {
            printf "      \"direction\": [%.6f, %.6f, %.6f],\n", cos(e) * 0.7071, -sin(e), cos(e) * 0.7071
            skipping = 1; done = 1; next
        }
        { sub(/"file": "/, "\"file\": \"" dir "/"); print }' "$scenes/scene.json" > "$out/scene-$scene.json"
done

# Each configuration's visibility, and the reference's verdict.
reference=$build/tests/bin/shadow_reference
for scene in sun40 sun10; do
    compares=()
    for entry in "${configs[@]}"; do
        name=${entry%%|*}
        read -r -a args <<< "${entry#*|}"
        [ "$name" = none ] && continue
        dir=$out/dumps-$scene/$(slug "$name")
        "$lab" "${args[@]}" --headless "${device[@]}" --width 640 --height 360 --gbuffer reference \
            --scene "$out/scene-$scene.json" --view visibility --dump "$dir" > /dev/null
        compares+=(--compare "$(slug "$name")=$dir/light.pfm")
    done
    if [ -x "$reference" ]; then
        pictures=()  # the pictures of the errors, for the configurations measured
        for picture in vsm_3x2048=vsm pcf_5x5=pcf5 size_512=512 vsm_fp16=vsm16 depth_1_texel=depth; do
            case " ${compares[*]} " in
                *" ${picture%%=*}="*) pictures+=(--errors "${picture%%=*}=$out/errors-$scene-${picture#*=}.png") ;;
            esac
        done
        "$reference" "$out/scene-$scene.json" "$out/dumps-$scene/vsm_3x2048" "${compares[@]}" \
            --json "$out/errors-$scene.json" "${pictures[@]}"
    else
        echo "shadow_study.sh: no $reference (Embree missing): errors not measured" >&2
    fi
done

# The GPU times, each configuration in turn, round after round.
: > "$out/timings.tsv"
for ((round = 1; round <= rounds; ++round)); do
    for entry in "${configs[@]}"; do
        name=${entry%%|*}
        read -r -a args <<< "${entry#*|}"
        report=$("$lab" "${args[@]}" --headless "${device[@]}" "${size[@]}" --scene "$out/scene-sun40.json" \
            --benchmark --warmup 10 --frames 40)
        gpu() { awk -v pass="$1" '$1 == "GPU" && $2 == pass {print $3; exit}' <<< "$report"; }
        name_of_device=$(awk '$1 == "device" {$1 = ""; sub(/^ +/, ""); print; exit}' <<< "$report")
        printf '%s\t%s\t%s\t%s\t%s\n' "$name" "$(gpu frame)" "$(gpu shadow)" "$(gpu light)" "$name_of_device" \
            >> "$out/timings.tsv"
        echo "round $round: $name: frame $(gpu frame) shadow $(gpu shadow) light $(gpu light)" >&2
    done
done
