// chapter-15-lab: the skinning study (--skinning-study FILE.csv) -- chapter-17's skinning, and what
// else could skin a figure, measured against a double-precision reference (docs/chapter-15-lab.md,
// "Skinning: speed against error"). Two generated figures: a tentacle of 16 joints whose vertices
// each have 8 influences, and the candy wrapper (a tube twisted 180 degrees by two joints). For each
// form, the GPU's skinned vertices are read back and compared with the same method done in double
// on the CPU with every influence the figure has, and the GPU time of skinning and drawing the
// figure in a scene pass and three cascade passes is measured with timestamps:
//   - chapter-17's way: a compute pass skins once, every pass draws the result; or the vertex
//     shader of every pass skins it again;
//   - linear blend skinning (chapter-17's) or dual-quaternion skinning;
//   - joint matrices in 32- or 16-bit floats;
//   - 8 influences or the heaviest 4 (renormalised).
// The study renders nothing to show: it prints a table and writes it as CSV, then exits.
#pragma once

#include "common/core/options.hpp"

// The study's command-line choices (--skinning-study, --skinning-study-size).
bool skinningStudyRequested(const common::Options& options);
// Runs the study (InputError for options it cannot be combined with); Failure when the GPU's
// chapter-17 form (compute, linear blend, fp32, all influences) is beyond its stated bound.
void runSkinningStudy(const common::Options& options);
