// The PFM images (Portable Float Map, little-endian) that chapter-15-lab --dump writes, read back
// for the accuracy tools: reference_render (shading) and shadow_reference (shadows).
#pragma once

#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/core/check.hpp"

namespace accuracy {

using glm::dvec3;

struct Pfm {
    int width = 0, height = 0, channels = 0;
    std::vector<float> values;  // top row first, `channels` per pixel
    dvec3 at(size_t pixel) const {
        const float* v = &values[pixel * size_t(channels)];
        return channels == 3 ? dvec3(v[0], v[1], v[2]) : dvec3(v[0]);
    }
};

// InputError naming the file when it is not a little-endian PFM of at most 16384 x 16384 pixels
// (what a chapter renders) or is cut short -- found before anything is allocated for its pixels.
inline Pfm readPfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    double scale = 0;
    Pfm pfm;
    in >> magic >> pfm.width >> pfm.height >> scale;
    in.get();
    if (!in || (magic != "PF" && magic != "Pf") || !std::isfinite(scale) || scale >= 0 || pfm.width <= 0 ||
        pfm.height <= 0 || pfm.width > 16384 || pfm.height > 16384)
        throw common::InputError(path + ": not a little-endian PFM file");
    pfm.channels = magic == "PF" ? 3 : 1;
    size_t rowFloats = size_t(pfm.width) * size_t(pfm.channels);
    std::streamoff start = in.tellg();
    in.seekg(0, std::ios::end);
    std::streamoff available = in.tellg() - start;
    in.seekg(start);
    if (available < 0 || uint64_t(available) < uint64_t(rowFloats) * uint64_t(pfm.height) * 4u)
        throw common::InputError(path + ": truncated");
    pfm.values.resize(rowFloats * size_t(pfm.height));
    for (int y = pfm.height - 1; y >= 0; --y)  // stored bottom row first
        in.read(reinterpret_cast<char*>(&pfm.values[size_t(y) * rowFloats]), std::streamsize(rowFloats * 4));
    if (!in) throw common::InputError(path + ": truncated");
    return pfm;
}

}  // namespace accuracy
