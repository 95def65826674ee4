// Unit tests of common/core/checked.hpp: the arithmetic the loaders do on numbers read from files, at
// the boundaries where a plain 64-bit sum or product would wrap.
#include <gtest/gtest.h>

#include "common/core/checked.hpp"

namespace {

constexpr uint64_t kMax = UINT64_MAX;

TEST(Checked, AddAtTheTop) {
    EXPECT_EQ(common::checkedAdd(kMax, 0), kMax);
    EXPECT_EQ(common::checkedAdd(kMax - 1, 1), kMax);
    EXPECT_FALSE(common::checkedAdd(kMax, 1));
    EXPECT_FALSE(common::checkedAdd(kMax / 2 + 1, kMax / 2 + 1));
    EXPECT_EQ(common::checkedAdd(kMax / 2, kMax / 2 + 1), kMax);
}

TEST(Checked, MultiplyAtTheTop) {
    EXPECT_EQ(common::checkedMul(0, kMax), 0u);
    EXPECT_EQ(common::checkedMul(kMax, 1), kMax);
    EXPECT_EQ(common::checkedMul(4294967295ull, 4294967297ull), kMax);  // (2^32 - 1)(2^32 + 1) = 2^64 - 1
    EXPECT_FALSE(common::checkedMul(4294967296ull, 4294967296ull));     // 2^64
    EXPECT_FALSE(common::checkedMul(3, kMax / 3 + 1));
    EXPECT_EQ(common::checkedMul(3, kMax / 3), kMax / 3 * 3);
}

TEST(Checked, SaturatingStopsAtTheTop) {
    EXPECT_EQ(common::saturatingAdd(kMax, 5), kMax);
    EXPECT_EQ(common::saturatingMul(1ull << 40, 1ull << 40), kMax);
    EXPECT_EQ(common::saturatingAdd(2, 3), 5u);
    EXPECT_EQ(common::saturatingMul(1ull << 31, 1ull << 32), 1ull << 63);
}

TEST(Checked, FitsInWithoutASum) {
    EXPECT_TRUE(common::fitsIn(0, 0, 0));
    EXPECT_TRUE(common::fitsIn(36, 0, 36));
    EXPECT_FALSE(common::fitsIn(37, 0, 36));
    EXPECT_TRUE(common::fitsIn(12, 24, 36));
    EXPECT_FALSE(common::fitsIn(12, 25, 36));
    // offset + size wraps to 35, which a plain sum would call inside a 36-byte buffer.
    EXPECT_FALSE(common::fitsIn(kMax - 10, 46, 36));
    EXPECT_FALSE(common::fitsIn(4, kMax, 36));
    EXPECT_TRUE(common::fitsIn(kMax, 0, kMax));
}

TEST(Checked, ElementsEnd) {
    EXPECT_EQ(common::elementsEnd(0, 3, 12, 12), 36u);
    EXPECT_EQ(common::elementsEnd(4, 3, 16, 12), 48u);  // a stride larger than the element
    EXPECT_EQ(common::elementsEnd(8, 0, 12, 12), 8u);
    EXPECT_EQ(common::elementsEnd(0, 1, kMax, 12), 12u);  // one element: the stride never counts
    // The wrap a hostile accessor asks for: 2^64 - 96 MiB plus 8,388,611 elements of 12 bytes is
    // 36 modulo 2^64.
    EXPECT_FALSE(common::elementsEnd(18446744073608888320ull, 8388611, 12, 12));
    EXPECT_FALSE(common::elementsEnd(0, kMax, 2, 1));
    EXPECT_FALSE(common::elementsEnd(kMax - 11, 1, 12, 12));
    EXPECT_EQ(common::elementsEnd(kMax - 12, 1, 12, 12), kMax);
}

}  // namespace
