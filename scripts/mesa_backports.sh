#!/usr/bin/env bash
# Debian 12's newer lavapipe, for the tests that check every chapter's golden images on a second
# driver: Mesa 25 from bookworm-backports (Vulkan 1.4: descriptor indexing, ray tracing pipelines),
# fetched and unpacked into DIR, never installed -- the machine keeps its own Mesa 22.3, which the
# chapters use by default.
#
#   scripts/mesa_backports.sh DIR     prints DIR/lvp_icd.json: a Vulkan driver manifest whose library
#                                     path points into DIR (VK_DRIVER_FILES=DIR/lvp_icd.json)
#
# The packages come from the suite bookworm-backports of the archive this machine's apt already
# uses (its own deb entries, another suite; no host name is written down here), with apt's lists kept
# in DIR: the machine's package sources and state are not touched. What is fetched: the
# mesa-vulkan-drivers version below and the libdrm it needs (bookworm's is older). Nothing is done
# when DIR already holds them.
set -euo pipefail
dir=${1:?usage: scripts/mesa_backports.sh DIR}
mesa=25.0.7-2~bpo12+1
drm=2.4.123-1~bpo12+1
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
manifest=$dir/lvp_icd.json
if [ -f "$manifest" ] && [ "$(cat "$dir/version" 2> /dev/null)" = "$mesa" ]; then
    echo "$manifest"
    exit 0
fi
rm -rf "$dir/lists" "$dir/debs" "$dir/root"
mkdir -p "$dir/lists/partial" "$dir/debs" "$dir/root"
# This machine's deb entries for the Debian archive, their suite made bookworm-backports.
python3 - "$dir/backports.sources" << 'PY'
import glob, re, sys
entries = []
for path in glob.glob("/etc/apt/sources.list.d/*.sources"):
    for stanza in open(path).read().split("\n\n"):
        if re.search(r"^Types:(.*\s)?deb(\s|$)", stanza, re.M) and re.search(r"^Suites:(.*\s)?bookworm(\s|$)", stanza, re.M):
            entries.append(re.sub(r"^Suites:.*$", "Suites: bookworm-backports", stanza.strip(), flags=re.M))
try:
    for line in open("/etc/apt/sources.list"):
        m = re.match(r"^deb\s+(\[[^]]*\]\s+)?(\S+)\s+bookworm\s+(.*)$", line.strip())
        if m:
            entries.append(f"Types: deb\nURIs: {m.group(2)}\nSuites: bookworm-backports\nComponents: {m.group(3)}")
except FileNotFoundError:
    pass
if not entries:
    sys.exit("mesa_backports: this machine's apt has no bookworm entry to take the backports suite from")
open(sys.argv[1], "w").write("\n\n".join(entries) + "\n")
PY
apt=(-o "Dir::Etc::sourcelist=$dir/backports.sources" -o Dir::Etc::sourceparts=/nonexistent
     -o "Dir::State::Lists=$dir/lists" -o Debug::NoLocking=1 -qq)
apt-get "${apt[@]}" update > /dev/null
(cd "$dir/debs" && apt-get "${apt[@]}" download "mesa-vulkan-drivers=$mesa" "libdrm2=$drm" "libdrm-amdgpu1=$drm" \
    2> >(grep -v "unsandboxed" >&2))
for deb in "$dir"/debs/*.deb; do dpkg-deb -x "$deb" "$dir/root"; done
lib=$dir/root/usr/lib/x86_64-linux-gnu
[ -f "$lib/libvulkan_lvp.so" ] || { echo "mesa_backports: no libvulkan_lvp.so in the packages" >&2; exit 1; }
# The manifest names the library by its path: the loader finds it without LD_LIBRARY_PATH (which
# the runs still set, for the newer libdrm beside it).
sed "s|\"libvulkan_lvp.so\"|\"$lib/libvulkan_lvp.so\"|" "$dir/root/usr/share/vulkan/icd.d/lvp_icd.json" > "$manifest"
echo "$mesa" > "$dir/version"
echo "$manifest"
