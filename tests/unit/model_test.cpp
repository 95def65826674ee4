// Unit tests of the OBJ loader: de-duplication, normals, tangents on good and degenerate input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "common/core/check.hpp"
#include "common/model/model.hpp"
#include "common/model/obj_model.hpp"

namespace {

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / "vkbook-model-test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / name) << text;
    return dir / name;
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Every tangent frame is finite, unit length, orthogonal, and the bitangent is +-(n x t).
void expectOrthonormalFrames(const common::MeshData& mesh) {
    for (const common::Vertex& v : mesh.vertices) {
        ASSERT_TRUE(finite(v.normal) && finite(v.tangent) && finite(v.bitangent));
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(v.tangent), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(v.normal, v.tangent), 0.0f, 1e-5f);
        EXPECT_NEAR(std::abs(glm::dot(v.bitangent, glm::cross(v.normal, v.tangent))), 1.0f, 1e-5f);
    }
}

TEST(ObjLoader, DeduplicatesSharedCorners) {
    // A quad as two triangles: six corners, four distinct (position, normal, uv) triples.
    auto path = writeTemp("quad.obj",
                          "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                          "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n");
    common::ModelData model = common::loadObjModel(path);
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.meshes[0].vertices.size(), 4u);
    EXPECT_EQ(model.meshes[0].indices.size(), 6u);
    EXPECT_EQ(model.meshes[0].indices[0], model.meshes[0].indices[3]);  // corner 1/1/1 shared
}

TEST(ObjLoader, KeepsCornersThatDifferInNormalOrUv) {
    // A cube: 8 positions, 6 normals; each face's corners have their own normal -> 24 vertices.
    auto path =
        writeTemp("cube.obj",
                  "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                  "vn 0 0 -1\nvn 0 0 1\nvn -1 0 0\nvn 1 0 0\nvn 0 -1 0\nvn 0 1 0\n"
                  "f 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\nf 1//3 5//3 8//3 4//3\n"
                  "f 2//4 3//4 7//4 6//4\nf 1//5 2//5 6//5 5//5\nf 4//6 8//6 7//6 3//6\n");
    common::ModelData model = common::loadObjModel(path);
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.meshes[0].vertices.size(), 24u);
    EXPECT_EQ(model.meshes[0].indices.size(), 36u);  // quads triangulated
    EXPECT_EQ(model.boundsMin, glm::vec3(-1.0f));
    EXPECT_EQ(model.boundsMax, glm::vec3(1.0f));
    expectOrthonormalFrames(model.meshes[0]);
}

TEST(ObjLoader, ComputesNormalsWhenTheFileHasNone) {
    auto path = writeTemp("nonormals.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    common::ModelData model = common::loadObjModel(path);
    for (const common::Vertex& v : model.meshes[0].vertices) EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);
}

TEST(ObjLoader, ReadsPbrKeysAndDefaultsWhatIsMissing) {
    writeTemp("pbr.mtl", "newmtl stated\nKd 0.5 0.25 1\nd 0.75\nPr 0.3\nPm 1\nnewmtl bare\nKd 1 1 1\n");
    auto path = writeTemp(
        "pbr.obj",
        "mtllib pbr.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl stated\nf 1 2 3\nusemtl bare\nf 1 3 2\n");
    common::ModelData model = common::loadObjModel(path);
    ASSERT_GE(model.materials.size(), 2u);
    EXPECT_EQ(model.materials[0].diffuse, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_FLOAT_EQ(model.materials[0].roughness, 0.3f);
    EXPECT_FLOAT_EQ(model.materials[0].metallic, 1.0f);
    EXPECT_FLOAT_EQ(model.materials[1].roughness, 1.0f);  // no Pr: fully rough, as the book
    EXPECT_FLOAT_EQ(model.materials[1].metallic, 0.0f);
}

TEST(ObjLoader, RejectsBadInput) {
    EXPECT_THROW(common::loadObjModel(writeTemp("empty.obj", "")), common::InputError);
    EXPECT_THROW(common::loadObjModel(writeTemp("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")),
                 common::InputError);
    EXPECT_THROW(common::loadObjModel(writeTemp("nan.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n")),
                 common::InputError);
    EXPECT_THROW(common::loadObjModel(writeTemp("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n")),
                 common::InputError);
    EXPECT_THROW(common::loadObjModel("/no/such/file.obj"), common::InputError);
}

TEST(Tangents, FollowTheTextureOnAFlatQuad) {
    // uv u along +x, OBJ v along +y: tangent +x, bitangent +y (OpenGL normal-map convention).
    auto path = writeTemp("quad2.obj",
                          "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                          "f 1/1/1 2/2/1 3/3/1 4/4/1\n");
    common::ModelData model = common::loadObjModel(path);
    for (const common::Vertex& v : model.meshes[0].vertices) {
        EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);
        EXPECT_NEAR(v.bitangent.y, 1.0f, 1e-6f);
    }
}

TEST(Tangents, StayFiniteAndOrthogonalOnDegenerateInput) {
    common::MeshData mesh;
    auto vertex = [](glm::vec3 p, glm::vec3 n, glm::vec2 uv) { return common::Vertex{p, n, {}, {}, uv}; };
    // 0-2: zero-area triangle (all at one point); 3-5: collinear; 6-8: identical UVs;
    // 9-11: a normal along +x with UVs that put the tangent along +x (parallel to the normal).
    glm::vec3 up(0, 1, 0), x(1, 0, 0);
    mesh.vertices = {
        vertex({1, 1, 1}, up, {0, 0}),   vertex({1, 1, 1}, up, {1, 0}),   vertex({1, 1, 1}, up, {0, 1}),
        vertex({0, 0, 0}, up, {0, 0}),   vertex({1, 0, 0}, up, {1, 0}),   vertex({2, 0, 0}, up, {2, 0}),
        vertex({0, 0, 0}, up, {.5, .5}), vertex({1, 0, 0}, up, {.5, .5}), vertex({0, 0, 1}, up, {.5, .5}),
        vertex({0, 0, 0}, x, {0, 0}),    vertex({1, 0, 0}, x, {1, 0}),    vertex({0, 1, 0}, x, {0, 1})};
    mesh.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
    common::computeTangents(mesh);
    expectOrthonormalFrames(mesh);
}

TEST(Tangents, RandomMeshesGiveOrthonormalFrames) {
    std::mt19937 random(1234);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    common::MeshData mesh;
    for (int i = 0; i < 3000; ++i) {
        glm::vec3 n(unit(random), unit(random), unit(random));
        if (glm::length(n) < 1e-3f) n = glm::vec3(0, 0, 1);
        mesh.vertices.push_back(common::Vertex{{unit(random), unit(random), unit(random)},
                                               glm::normalize(n),
                                               {},
                                               {},
                                               {unit(random), unit(random)}});
        mesh.indices.push_back(uint32_t(i));
    }
    common::computeTangents(mesh);
    expectOrthonormalFrames(mesh);
}

}  // namespace
