// Mip chains (common/vk/texture.cpp, makeMipChain): each level the 2x2 box filter of the one above,
// in linear light for sRGB and weighted by alpha, as stb_image_resize computes it.
#include <gtest/gtest.h>
#include <stb_image_resize.h>

#include <bit>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "common/vk/texture.hpp"

namespace {

common::Pixels noise(uint32_t width, uint32_t height, bool withAlpha) {
    std::mt19937 random(7);
    common::Pixels pixels{width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
    for (size_t i = 0; i < pixels.rgba.size(); ++i)
        pixels.rgba[i] = i % 4 == 3 && !withAlpha ? 255 : uint8_t(random() & 0xff);
    // Fully transparent blocks too: their colour must not turn black.
    if (withAlpha)
        for (uint32_t x = 0; x < 4; ++x) pixels.rgba[size_t(x) * 4 + 3] = 0;
    return pixels;
}

// The largest difference between level `level` of `chain` and stb_image_resize's box filter of
// the level above it.
int differenceFromStb(const common::MipChain& chain, uint32_t level, bool srgb) {
    const VkBufferImageCopy& above = chain.regions[level - 1];
    const VkBufferImageCopy& here = chain.regions[level];
    int w = int(above.imageExtent.width), h = int(above.imageExtent.height);
    int nw = int(here.imageExtent.width), nh = int(here.imageExtent.height);
    std::vector<uint8_t> expected(size_t(nw) * size_t(nh) * 4);
    stbir_resize_uint8_generic(chain.bytes.data() + above.bufferOffset, w, h, 0, expected.data(), nw, nh, 0,
                               4, 3, 0, STBIR_EDGE_WRAP, STBIR_FILTER_BOX,
                               srgb ? STBIR_COLORSPACE_SRGB : STBIR_COLORSPACE_LINEAR, nullptr);
    int worst = 0;
    for (size_t i = 0; i < expected.size(); ++i) {
        // stb leaves a fully transparent texel's colour black; ours keeps the plain mean.
        size_t texel = i / 4 * 4;
        if (i % 4 != 3 && expected[texel + 3] == 0) continue;
        worst = std::max(worst, std::abs(int(chain.bytes[here.bufferOffset + i]) - int(expected[i])));
    }
    return worst;
}

}  // namespace

TEST(MipChain, EveryLevelIsTheBoxFilterOfTheOneAbove) {
    for (VkFormat format : {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R8G8B8A8_UNORM}) {
        bool srgb = format == VK_FORMAT_R8G8B8A8_SRGB;
        // 256x64 halves evenly down to 4x1; 96x40 meets odd sides (3, 5) on the way.
        for (auto [w, h] : {std::pair{256u, 64u}, std::pair{96u, 40u}}) {
            common::MipChain chain =
                common::makeMipChain(noise(w, h, true), format, true, common::MipAlpha::Coverage);
            ASSERT_EQ(chain.regions.size(), size_t(std::bit_width(std::max(w, h))));
            for (uint32_t level = 1; level < chain.regions.size(); ++level)
                EXPECT_LE(differenceFromStb(chain, level, srgb), 1)
                    << (srgb ? "sRGB " : "UNORM ") << w << "x" << h << " level " << level;
        }
    }
}

TEST(MipChain, TransparentTexelsKeepTheirColour) {
    // A 2x2 block of red texels with alpha 0: the mean is red, not black.
    common::Pixels pixels{2, 2, std::vector<uint8_t>(16, 0)};
    for (size_t i = 0; i < 16; i += 4) pixels.rgba[i] = 200;
    common::MipChain chain =
        common::makeMipChain(pixels, VK_FORMAT_R8G8B8A8_SRGB, true, common::MipAlpha::Coverage);
    ASSERT_EQ(chain.regions.size(), 2u);
    const uint8_t* texel = chain.bytes.data() + chain.regions[1].bufferOffset;
    EXPECT_EQ(texel[0], 200);
    EXPECT_EQ(texel[3], 0);
}

TEST(MipChain, DataTexturesAverageEveryChannelOnItsOwn) {
    // A normal or metal-rough map's alpha means nothing: half its texels with alpha 0 must count
    // as much as the others, in the even path (2x2) and in stb's (3x2, an odd side).
    for (auto [w, h] : {std::pair{2u, 2u}, std::pair{3u, 2u}}) {
        common::Pixels pixels{w, h, std::vector<uint8_t>(size_t(w) * h * 4, 0)};
        for (size_t i = 0; i < size_t(w) * h; ++i) {
            bool even = i % 2 == 0;
            pixels.rgba[i * 4 + 0] = even ? 200 : 0;
            pixels.rgba[i * 4 + 1] = 128;
            pixels.rgba[i * 4 + 2] = 255;
            pixels.rgba[i * 4 + 3] = even ? 0 : 255;
        }
        common::MipChain data =
            common::makeMipChain(pixels, VK_FORMAT_R8G8B8A8_UNORM, true, common::MipAlpha::Independent);
        common::MipChain colour =
            common::makeMipChain(pixels, VK_FORMAT_R8G8B8A8_UNORM, true, common::MipAlpha::Coverage);
        ASSERT_GE(data.regions.size(), 2u);
        // The level-1 texel's red: its block's mean with every texel counted, and (coverage) with
        // only the opaque ones, whose red is 0.
        const uint8_t* plain = data.bytes.data() + data.regions[1].bufferOffset;
        const uint8_t* weighted = colour.bytes.data() + colour.regions[1].bufferOffset;
        EXPECT_NEAR(plain[0], 100, 1) << w << "x" << h;
        EXPECT_EQ(plain[1], 128) << w << "x" << h;
        EXPECT_EQ(plain[2], 255) << w << "x" << h;
        EXPECT_LT(weighted[0], 30) << w << "x" << h;
    }
}

TEST(MipChain, ChainOf1024x1024) {
    // Not a timed assertion: the times are printed for docs/performance.md, ours beside
    // stb_image_resize's for the same chain (what makeMipChain used for every level before).
    common::Pixels pixels = noise(1024, 1024, true);
    auto start = std::chrono::steady_clock::now();
    common::MipChain chain =
        common::makeMipChain(pixels, VK_FORMAT_R8G8B8A8_SRGB, true, common::MipAlpha::Coverage);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    start = std::chrono::steady_clock::now();
    std::vector<uint8_t> above = pixels.rgba, below;
    for (int size = 1024; size > 1; size /= 2) {
        below.resize(size_t(size / 2) * size_t(size / 2) * 4);
        stbir_resize_uint8_generic(above.data(), size, size, 0, below.data(), size / 2, size / 2, 0, 4, 3, 0,
                                   STBIR_EDGE_WRAP, STBIR_FILTER_BOX, STBIR_COLORSPACE_SRGB, nullptr);
        above.swap(below);
    }
    double stbMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "mip chain of a 1024x1024 sRGB texture with alpha: %zu levels in %.1f ms (stb_image_resize: %.1f "
        "ms)\n",
        chain.regions.size(), ms, stbMs);
    EXPECT_EQ(chain.regions.size(), 11u);
    EXPECT_EQ(chain.bytes.size(), size_t(4) * 1398101);  // 4 bytes * (1024^2 + 512^2 + ... + 1) texels
}

// The device-memory budget counts each texture with every mip level, from its header's size.
TEST(MipChainBytes, EveryLevelDownToOneTexel) {
    EXPECT_EQ(common::mipChainBytes({1, 1}), 4u);
    EXPECT_EQ(common::mipChainBytes({2, 2}), 4u * (4 + 1));
    EXPECT_EQ(common::mipChainBytes({4, 1}), 4u * (4 + 2 + 1));
    EXPECT_EQ(common::mipChainBytes({16384, 1}), 4u * 32767);
    uint64_t levels = 0;
    for (uint64_t side = 16384; side >= 1; side /= 2) levels += side * side * 4;
    EXPECT_EQ(common::mipChainBytes({16384, 16384}), levels);  // 1.33 GiB: no 32-bit arithmetic
    EXPECT_EQ(common::mipChainBytes({4294967295u, 4294967295u}) > (uint64_t{1} << 63), true);
}
