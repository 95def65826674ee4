#!/usr/bin/env bash
# Runs a chapter with the object-names layer (names_layer/names_layer.cpp) and checks its report:
# every object the run created (images, buffers, memory, views, samplers, pipelines and layouts,
# shader modules, render passes, framebuffers, descriptor set layouts, pools and sets, command
# pools and buffers, semaphores, fences, query pools, swapchains) has a non-empty name, every label begun was ended, and each expected pass label is there.
#   names_check.sh REPORT LABEL[,LABEL...] CHAPTER [options...]
set -u
report=$1 labels=$2
shift 2
rm -f "$report"
VKBOOK_NAMES_REPORT=$report "$@" > /dev/null || { echo "names_check: the chapter failed ($?)"; exit 1; }
[ -s "$report" ] || { echo "names_check: no report in $report (was the layer loaded?)"; exit 1; }
status=0
if grep -q '^unnamed ' "$report"; then
    echo "names_check: objects without a name:"
    grep '^unnamed ' "$report" | sort | uniq -c | sort -rn | head -20
    status=1
fi
if grep -q '^unbalanced ' "$report"; then
    echo "names_check: $(grep '^unbalanced ' "$report")"
    status=1
fi
IFS=, read -ra expected <<< "$labels"
for label in "${expected[@]}"; do
    grep -qx "label $label" "$report" || { echo "names_check: no pass labelled '$label'"; status=1; }
done
for type in image buffer memory image-view sampler pipeline pipeline-layout shader-module descriptor-set-layout \
    descriptor-set command-pool command-buffer semaphore fence; do
    echo "$type: $(grep -c "^named $type " "$report") named"
done
echo "labels: $(grep '^label ' "$report" | cut -d' ' -f2- | paste -sd, -)"
exit $status
