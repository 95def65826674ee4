// Arithmetic on numbers read from files (offsets, sizes, counts, indices) that cannot wrap.
//
// A file can say anything: an accessor's byteOffset of 2^64 - 8 plus a few elements wraps a
// 64-bit sum to a small number, and a bounds check on that sum passes. The loaders compute offsets,
// sizes and counts from file data with these functions, which say when the true result does not
// fit instead of returning a wrapped one, wherever an earlier check has not already bounded the
// operands far below 2^64 (a count of at most 2^25 times 3, say). Plain C++ (no compiler
// built-ins), so MSVC builds them as GCC and Clang do.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

namespace common {

inline constexpr uint64_t kNoFit = std::numeric_limits<uint64_t>::max();

// a + b, or nothing when it exceeds 2^64 - 1.
constexpr std::optional<uint64_t> checkedAdd(uint64_t a, uint64_t b) {
    if (b > kNoFit - a) return std::nullopt;
    return a + b;
}

// a * b, or nothing when it exceeds 2^64 - 1.
constexpr std::optional<uint64_t> checkedMul(uint64_t a, uint64_t b) {
    if (a != 0 && b > kNoFit / a) return std::nullopt;
    return a * b;
}

// a + b and a * b that stop at 2^64 - 1: for totals that are only compared with a limit far below
// it (a budget), where "more than the limit" is all that matters.
constexpr uint64_t saturatingAdd(uint64_t a, uint64_t b) {
    return checkedAdd(a, b).value_or(kNoFit);
}
constexpr uint64_t saturatingMul(uint64_t a, uint64_t b) {
    return checkedMul(a, b).value_or(kNoFit);
}

// Whether the bytes [offset, offset + size) lie within [0, n): offset + size <= n, decided
// without computing a sum that could wrap.
constexpr bool fitsIn(uint64_t offset, uint64_t size, uint64_t n) {
    return offset <= n && size <= n - offset;
}

// Where `count` elements of `element` bytes, `stride` bytes apart, starting at `offset`, end:
// offset + (count - 1) * stride + element; nothing when that does not fit in 64 bits. count >= 1.
constexpr std::optional<uint64_t> elementsEnd(uint64_t offset, uint64_t count, uint64_t stride,
                                              uint64_t element) {
    if (count == 0) return offset;
    std::optional<uint64_t> span = checkedMul(count - 1, stride);
    if (!span) return std::nullopt;
    std::optional<uint64_t> last = checkedAdd(offset, *span);
    if (!last) return std::nullopt;
    return checkedAdd(*last, element);
}

}  // namespace common
