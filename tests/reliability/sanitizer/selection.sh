# The sanitizer stage's selection (sourced by scripts/setup.sh and scripts/coverage.sh): the
# tests of the Release suite that `scripts/setup.sh test` does NOT run again in the sanitizer
# build, as a ctest regular expression. scripts/coverage.sh measures what the selection covers
# against the whole suite (docs/reliability.md, "Sanitizers").
#
# Left out because the sanitizers would distort what they measure: the window-life tests and the
# live-reload leak tests (resident memory, which AddressSanitizer's shadow memory and quarantine
# inflate), the peak memory of the largest admitted models, chapter-16.reload-walk (two minutes of
# walking and reloading; chapter-16's reloads run there in live-reload.chapter-16.*).
# Left out because they run no code of ours built with the sanitizers: the builds of a chapter on
# its own (chapter-20's ThreadSanitizer build among them, and its runs, tsan.*: a sanitizer of its
# own, which cannot be combined with AddressSanitizer), formatting, the docs checks, the fuzzers (built with sanitizers of their own), and the
# GPU package's list (it maps the Release binaries' libraries; these would add the sanitizers').
# Left out because the Release suite's run already covers every line they run, and they repeat it
# at length (scripts/coverage.sh shows the selection covers as much):
#   - chapter-16's always-redrawn references (every cascade drawn every frame, the same code each
#     frame) and the comparisons of the cache's images with them;
#   - the live-reload runs in a window (the same reload as headless, in a windowed frame loop the
#     window tests run) and the 50 reloads of the object-names run;
#   - the lab's light culling at 65,536 lights (the code of its 4,096-light runs, more of it);
#   - of chapter-16's moving casters (120 frames each), the runs that only serve as references:
#     the whole-cascade redraw (chapter-16.walk-changed runs that form) and the still light.
sanitize_skip='window-life|^extremes\.memory-|standalone|^tsan\.|^format$|^docs\.|^fuzz\.|^live-reload\..*\.leak$|^scripts\.'
sanitize_skip+='|^chapter-16\.reload-walk$|^chapter-16\..*-(always|same-image)$|^live-reload\..*\.window-|^live-reload\.chapter-15\.names$'
sanitize_skip+='|^chapter-15-lab\.cull-.*65536|^chapter-16\.moving-caster-(changed|still|visibility-.*|shadow-moved)$'
