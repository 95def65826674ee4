// common::specializationMismatch (common/shaders/shader_interface.cpp): the constants a pipeline sets,
// checked against those its shader declares -- on chapter-15's scene fragment shader as built
// (constant_id 0 ALPHA_TEST bool, 1 MATERIAL_FEATURES uint, 2 FEATURES_AT_RUN_TIME bool).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "common/shaders/shader_interface.hpp"

namespace {

std::vector<uint32_t> sceneFragment() {
    std::ifstream file(VKBOOK_BUILD_SHADERS "/chapter-15/scene.frag.spv", std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    std::vector<uint32_t> words(bytes.size() / 4);
    std::copy(bytes.begin(), bytes.begin() + std::ptrdiff_t(words.size() * 4),
              reinterpret_cast<char*>(words.data()));
    return words;
}

std::string check(std::vector<VkSpecializationMapEntry> entries) {
    uint32_t data[4] = {};
    VkSpecializationInfo info{uint32_t(entries.size()), entries.data(), sizeof(data), data};
    return common::specializationMismatch(sceneFragment(), info);
}

}  // namespace

TEST(Specialization, ConstantsTheShaderDeclaresPass) {
#if !defined(VKBOOK_RUNTIME_SHADERS)
    GTEST_SKIP() << "built without SPIRV-Cross: nothing is checked";
#endif
    ASSERT_FALSE(sceneFragment().empty());
    EXPECT_EQ(check({{0, 0, 4}, {1, 4, 4}, {2, 8, 4}}), "");
}

TEST(Specialization, AnUndeclaredIdIsNamed) {
#if !defined(VKBOOK_RUNTIME_SHADERS)
    GTEST_SKIP() << "built without SPIRV-Cross: nothing is checked";
#endif
    EXPECT_EQ(check({{0, 0, 4}, {5, 4, 4}}),
              "the pipeline sets specialization constant 5, which the shader does not declare");
}

TEST(Specialization, AValueOfAnotherSizeIsNamed) {
#if !defined(VKBOOK_RUNTIME_SHADERS)
    GTEST_SKIP() << "built without SPIRV-Cross: nothing is checked";
#endif
    EXPECT_EQ(check({{1, 0, 8}}),
              "the pipeline sets specialization constant 1 with 8 bytes; the shader's is 4");
    EXPECT_EQ(check({{0, 0, 1}}),
              "the pipeline sets specialization constant 0 with 1 bytes; the shader's is 4");
}
