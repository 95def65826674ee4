// Warnings and one-line messages (report.hpp).
#include "common/core/report.hpp"

#include <cstdio>
#include <mutex>
#include <set>

namespace common {

namespace {

std::mutex gMutex;
std::set<std::string> gSaid;  // the warnings printed: at most kMaxWarnings
uint64_t gPrinted = 0;

// The length of the UTF-8 sequence that starts at `at` when it is a character that breaks a line
// or is a control (C1, U+2028, U+2029); 0 otherwise.
size_t breakingSequence(const std::string& text, size_t at) {
    auto byte = [&](size_t i) -> unsigned {
        return i < text.size() ? static_cast<unsigned char>(text[i]) : 0u;
    };
    unsigned c = byte(at);
    if (c < 0x20 || c == 0x7f) return 1;
    if (c == 0xc2 && byte(at + 1) >= 0x80 && byte(at + 1) <= 0x9f) return 2;  // C1
    if (c == 0xe2 && byte(at + 1) == 0x80 && (byte(at + 2) == 0xa8 || byte(at + 2) == 0xa9))
        return 3;  // LS, PS
    return 0;
}

}  // namespace

bool hasControlCharacter(const std::string& text) {
    for (size_t i = 0; i < text.size(); ++i) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 || c == 0x7f) return true;
        if (c == 0xc2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
            static_cast<unsigned char>(text[i + 1]) <= 0x9f)
            return true;
    }
    return false;
}

std::string oneLine(std::string message) {
    constexpr size_t kMaxLength = 1000;
    std::string out;
    out.reserve(std::min(message.size(), kMaxLength + 3));
    for (size_t i = 0; i < message.size();) {
        if (out.size() >= kMaxLength) {
            // Not in the middle of a character: drop continuation bytes already copied.
            while (!out.empty() && (static_cast<unsigned char>(out.back()) & 0xc0) == 0x80) out.pop_back();
            if (!out.empty() && static_cast<unsigned char>(out.back()) >= 0xc0) out.pop_back();
            return out + "...";
        }
        if (size_t n = breakingSequence(message, i); n != 0) {
            out += '?';
            i += n;
        } else {
            out += message[i++];
        }
    }
    return out;
}

void warn(const std::string& message) {
    std::string line = oneLine(message);
    std::lock_guard lock(gMutex);
    if (gPrinted < kMaxWarnings) {
        if (!gSaid.insert(line).second) return;
        std::fprintf(stderr, "warning: %s\n", line.c_str());
        ++gPrinted;
        if (gPrinted == kMaxWarnings)
            std::fprintf(stderr, "warning: %u warnings shown; further warnings are not shown\n",
                         kMaxWarnings);
        return;
    }
    // Past the cap nothing is kept: a set of every distinct line would grow with the input.
}

}  // namespace common
