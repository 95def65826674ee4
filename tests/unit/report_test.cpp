// common/core/report.hpp's one-line messages and common/core/files.hpp's temporaries.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/core/files.hpp"
#include "common/core/report.hpp"

namespace {

TEST(Report, OneLineReplacesEveryLineBreakingCharacter) {
    // ASCII controls, DEL, NEL (U+0085) and the other C1 controls, the line and paragraph
    // separators (U+2028, U+2029): each one '?', whatever its length in UTF-8.
    EXPECT_EQ(common::oneLine("a\nb\rc\td\x7f"), "a?b?c?d?");
    EXPECT_EQ(common::oneLine("a\xc2\x85"
                              "b\xc2\x9f"
                              "c"),
              "a?b?c");
    EXPECT_EQ(common::oneLine("a\xe2\x80\xa8"
                              "b\xe2\x80\xa9"
                              "c"),
              "a?b?c");
    // Other characters pass unchanged: an accented letter, U+2027 (beside the separators), NBSP.
    EXPECT_EQ(common::oneLine("caf\xc3\xa9 \xe2\x80\xa7 \xc2\xa0"), "caf\xc3\xa9 \xe2\x80\xa7 \xc2\xa0");
}

TEST(Report, OneLineCutsLongMessagesOnACharacterBoundary) {
    std::string euros;
    for (int i = 0; i < 600; ++i) euros += "\xe2\x82\xac";  // 3 bytes each
    std::string line = common::oneLine(euros);
    ASSERT_TRUE(line.ends_with("..."));
    std::string kept = line.substr(0, line.size() - 3);
    EXPECT_LE(kept.size(), 1000u);
    EXPECT_EQ(kept.size() % 3, 0u) << "a character was cut in the middle";
}

TEST(Report, HasControlCharacter) {
    EXPECT_TRUE(common::hasControlCharacter(std::string("a\0b", 3)));
    EXPECT_TRUE(common::hasControlCharacter("a\nb"));
    EXPECT_TRUE(common::hasControlCharacter("a\xc2\x85"));
    EXPECT_FALSE(common::hasControlCharacter("textures/caf\xc3\xa9.png"));
}

TEST(Temporaries, RegisteredOnesAreRemovedAndForgottenOnesKept) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / "vkbook-report-test";
    fs::create_directories(dir);
    fs::path kept = dir / "kept.bin", written = dir / "written.bin";
    {
        common::RegisteredTemporary first(kept);
        std::ofstream(first.path) << "done";
        fs::rename(first.path, kept);
    }  // forgotten: renamed into place
    common::RegisteredTemporary second(written);
    std::ofstream(second.path) << "half";
    common::removeRegisteredTemporaries();  // what a run cut short does
    EXPECT_FALSE(fs::exists(second.path));
    EXPECT_TRUE(fs::exists(kept));
    fs::remove_all(dir);
}

TEST(Temporaries, StaleOnesOfProcessesThatRunNoMoreAreRemoved) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / "vkbook-stale-test";
    fs::create_directories(dir);
    fs::path file = dir / "cache.bin";
    fs::path stale = dir / "cache.bin.tmp2147483646";  // no process has this number
    fs::path mine = common::temporarySibling(file);    // this process: running
    fs::path other = dir / "other.bin.tmp2147483646";  // another file's
    for (const fs::path& p : {stale, mine, other}) std::ofstream(p) << "x";
    common::removeStaleTemporaries(file);
#if defined(_WIN32)
    EXPECT_TRUE(fs::exists(stale));
#else
    EXPECT_FALSE(fs::exists(stale));
#endif
    EXPECT_TRUE(fs::exists(mine));
    EXPECT_TRUE(fs::exists(other));
    fs::remove_all(dir);
}

}  // namespace
