// Unit tests of the loaders on hostile input (tests/reliability/hostile.cmake has the whole-program ones):
// concave polygons triangulated correctly, byte order marks, binary data, the scene limits.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/core/check.hpp"
#include "common/model/model.hpp"
#include "common/model/obj_model.hpp"
#include "common/scene/scene.hpp"

namespace {

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / "vkbook-hostile-test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / name, std::ios::binary) << text;
    return dir / name;
}

// Sum of the triangles' areas, and whether every triangle faces along `normal`: a correct
// triangulation of a flat polygon covers exactly its area, with no triangle flipped.
struct Coverage {
    size_t triangles = 0;
    double area = 0.0;
    bool allFacing = true;
};

Coverage coverage(const common::ModelData& model, glm::dvec3 normal) {
    Coverage c;
    for (const common::MeshData& mesh : model.meshes)
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            glm::dvec3 a(mesh.vertices[mesh.indices[i]].position),
                b(mesh.vertices[mesh.indices[i + 1]].position),
                cc(mesh.vertices[mesh.indices[i + 2]].position);
            glm::dvec3 n = glm::cross(b - a, cc - a);
            c.area += glm::length(n) / 2.0;
            c.allFacing = c.allFacing && glm::dot(n, normal) > 0.0;
            ++c.triangles;
        }
    return c;
}

// A dart: the corner at (1,1) is reflex. tinyobjloader splits a quad along its shorter diagonal,
// here (0,0)-(0,2), outside the dart: triangles of total area 11 instead of 9, one of them flipped.
TEST(HostileObj, ConcaveQuadIsTriangulatedInside) {
    auto path = writeTemp("dart.obj", "v 0 0 0\nv 10 1 0\nv 0 2 0\nv 1 1 0\nf 1 2 3 4\n");
    Coverage c = coverage(common::loadObjModel(path), {0, 0, 1});
    EXPECT_EQ(c.triangles, 2u);
    EXPECT_NEAR(c.area, 9.0, 1e-6);
    EXPECT_TRUE(c.allFacing);
}

// A ten-pointed star (area 1.1755705), moved around: tinyobjloader's ear test depends on where the
// polygon lies (at (5,5) it leaves out two triangles, at (100,-50) it overlaps and flips them).
TEST(HostileObj, ConcaveStarIsTriangulatedWhereverItLies) {
    for (glm::dvec2 offset : {glm::dvec2(0, 0), glm::dvec2(5, 5), glm::dvec2(100, -50), glm::dvec2(-5, 3)}) {
        std::string obj;
        for (int i = 0; i < 10; ++i) {
            double r = i % 2 == 0 ? 1.0 : 0.4, angle = i * 3.14159265358979 / 5.0;
            obj += "v " + std::to_string(offset.x + r * std::cos(angle)) + " " +
                   std::to_string(offset.y + r * std::sin(angle)) + " 0\n";
        }
        obj += "f 1 2 3 4 5 6 7 8 9 10\n";
        Coverage c = coverage(common::loadObjModel(writeTemp("star.obj", obj)), {0, 0, 1});
        EXPECT_EQ(c.triangles, 8u) << "at " << offset.x << ", " << offset.y;
        EXPECT_NEAR(c.area, 1.1755705, 1e-4) << "at " << offset.x << ", " << offset.y;
        EXPECT_TRUE(c.allFacing) << "at " << offset.x << ", " << offset.y;
    }
}

// The L-shaped hexagon of the hostile tests, standing in the YZ plane with the opposite winding:
// the triangles keep the polygon's winding (-X), so back-face culling sees what the file says.
TEST(HostileObj, ConcavePolygonKeepsItsWindingInAnyPlane) {
    auto path =
        writeTemp("l-shape.obj", "v 0 0 0\nv 0 0 2\nv 0 1 2\nv 0 1 1\nv 0 2 1\nv 0 2 0\nf 1 2 3 4 5 6\n");
    Coverage c = coverage(common::loadObjModel(path), {-1, 0, 0});
    EXPECT_EQ(c.triangles, 4u);
    EXPECT_NEAR(c.area, 3.0, 1e-6);
    EXPECT_TRUE(c.allFacing);
}

// A byte order mark before "newmtl": tinyobjloader alone would lose that line, and the material.
TEST(HostileObj, ByteOrderMarksAreSkipped) {
    writeTemp("bom.mtl", "\xef\xbb\xbfnewmtl red\nKd 1 0 0\n");
    auto path =
        writeTemp("bom.obj", "\xef\xbb\xbfv 0 0 0\nv 1 0 0\nv 0 1 0\nmtllib bom.mtl\nusemtl red\nf 1 2 3\n");
    common::ModelData model = common::loadObjModel(path);
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.materials[model.meshes[0].material].name, "red");
    EXPECT_EQ(model.materials[model.meshes[0].material].diffuse, glm::vec4(1, 0, 0, 1));
}

TEST(HostileObj, BinaryAndUtf16AreRefused) {
    EXPECT_THROW(common::loadObjModel(writeTemp("nul.obj", std::string("v 0 0 0\nv 1 0\0 0\n", 17))),
                 common::InputError);
    EXPECT_THROW(common::loadObjModel(writeTemp("utf16.obj", std::string("\xff\xfev\0 \0", 6))),
                 common::InputError);
}

std::string sceneWithLights(size_t lights) {
    std::string json = R"({"models": [{"file": "a.obj"}], "lights": [)";
    for (size_t i = 0; i < lights; ++i)
        json += std::string(i ? "," : "") + R"({"type": "point", "position": [0, 1, 0]})";
    return json + "]}";
}

TEST(HostileScene, LightCountUpToTheLimit) {
    EXPECT_EQ(common::parseScene(sceneWithLights(0), "s.json", ".").lights.size(), 0u);
    EXPECT_EQ(common::parseScene(sceneWithLights(common::kMaxSceneLights), "s.json", ".").lights.size(),
              common::kMaxSceneLights);
    try {
        common::parseScene(sceneWithLights(common::kMaxSceneLights + 1), "s.json", ".");
        FAIL() << "no error";
    } catch (const common::InputError& error) {
        EXPECT_STREQ(error.what(), "s.json: lights: 100001 lights, at most 100000");
    }
}

}  // namespace

// `mtllib` splits its names as tinyobjloader does: a backslash keeps a space in a name. The MTL
// behind such a name is the one checked and the one read (its Kd arrives; its bad number is caught).
TEST(HostileObj, MtllibNameWithEscapedSpace) {
    writeTemp("escaped space.mtl", "newmtl m\nKd 0.25 0.5 0.75\n");
    auto path = writeTemp("escaped_space.obj",
                          "mtllib escaped\\ space.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    common::ModelData model = common::loadObjModel(path);
    ASSERT_FALSE(model.materials.empty());
    EXPECT_FLOAT_EQ(model.materials[0].diffuse.g, 0.5f);

    writeTemp("escaped bad.mtl", "newmtl m\nKd 0.25 nope 0.75\n");
    auto bad = writeTemp("escaped_bad.obj",
                         "mtllib escaped\\ bad.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    try {
        common::loadObjModel(bad);
        FAIL() << "a bad number in an MTL named with an escaped space was not caught";
    } catch (const common::InputError& error) {
        EXPECT_NE(std::string(error.what()).find("escaped bad.mtl:2: 'Kd' has 'nope'"), std::string::npos)
            << error.what();
    }
}

namespace {

// `faces` faces of 255 corners on one vertex (each "f" line 513 bytes, 253 triangles, 759
// indices): flat, so they triangulate in linear time.
common::ModelData loadFlatPolygons(size_t faces, const std::string& name) {
    std::string polygon = "f";
    for (int k = 0; k < 255; ++k) polygon += " 1";
    polygon += "\n";
    std::string text = "v 0 0 0\n";
    text.reserve(text.size() + faces * polygon.size());
    for (size_t k = 0; k < faces; ++k) text += polygon;
    return common::loadObjModel(writeTemp(name, text));
}

}  // namespace

TEST(HostileObj, IndexBudgetCheckedAsFacesAreRead) {
    // common/model/model.hpp: at most 2^25 indices. 44,208 faces of 759 indices are 33,553,872, within
    // it; one face more is 33,554,631, refused at that face.
    static_assert(44208 * 759 <= common::kMaxModelIndices && 44209 * 759 > common::kMaxModelIndices);
    try {
        loadFlatPolygons(44209, "over_index_budget.obj");
        FAIL() << "a model over the index budget loaded";
    } catch (const common::InputError& error) {
        EXPECT_NE(std::string(error.what())
                      .find("over_index_budget.obj: the model has more than 33554432 indices "
                            "(at face 44209); at most that many are loaded"),
                  std::string::npos)
            << error.what();
    }
    common::ModelData model = loadFlatPolygons(44208, "at_index_budget.obj");
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.meshes[0].indices.size(), 44208u * 759);
}
