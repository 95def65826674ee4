// Unit tests of the glTF loader (common/model/gltf_model.cpp): what the glTF 2.0 specification asks of
// it, checked as numbers on small files written here with scenes/gltf_writer.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "../../scenes/gltf_writer.hpp"
#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/model/gltf_accessors.hpp"
#include "common/model/gltf_document.hpp"
#include "common/model/gltf_model.hpp"
#include "common/model/load_model.hpp"
#include "common/model/model.hpp"

namespace {

namespace fs = std::filesystem;
using glm::vec2;
using glm::vec3;
using gltf::json;

fs::path tempDir() {
    fs::path dir = fs::temp_directory_path() / "vkbook-gltf-test";
    fs::create_directories(dir);
    return dir;
}

// One primitive with the given attributes and indices, in a file of its own, loaded.
struct Primitive {
    std::vector<vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    std::vector<vec3> normals{3, vec3(0, 0, 1)};
    std::vector<vec2> uvs;
    std::vector<uint32_t> indices;
    int mode = gltf::kTriangles;
};

common::ModelData load(gltf::File& file, const std::string& name) {
    fs::path path = tempDir() / name;
    file.writeGltf(path);
    return common::loadGltfModel(path);
}

int addPrimitive(gltf::File& file, const Primitive& p, int material = -1) {
    json attributes = {{"POSITION", file.positions(p.positions)}};
    if (!p.normals.empty()) attributes["NORMAL"] = file.values(p.normals, gltf::kFloat, "VEC3");
    if (!p.uvs.empty()) attributes["TEXCOORD_0"] = file.values(p.uvs, gltf::kFloat, "VEC2");
    json primitive = {{"attributes", attributes}, {"mode", p.mode}};
    if (!p.indices.empty()) primitive["indices"] = file.values(p.indices, gltf::kUnsignedInt, "SCALAR");
    if (material >= 0) primitive["material"] = material;
    return file.mesh(json::array({primitive}));
}

common::ModelData loadPrimitive(const Primitive& p, const std::string& name, json node = json::object()) {
    gltf::File file;
    node["mesh"] = addPrimitive(file, p);
    file.node(node);
    file.scene({0});
    return load(file, name);
}

// The triangles' corner positions, in index order.
std::vector<vec3> corners(const common::MeshData& mesh) {
    std::vector<vec3> out;
    for (uint32_t i : mesh.indices) out.push_back(mesh.vertices[i].position);
    return out;
}

void expectNear(vec3 a, vec3 b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// The geometric normal of each triangle agrees with its vertices' normals: it is wound
// counter-clockwise as seen from the side its normals face.
void expectFrontFacing(const common::MeshData& mesh) {
    for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
        const common::Vertex &a = mesh.vertices[mesh.indices[k]], &b = mesh.vertices[mesh.indices[k + 1]],
                             &c = mesh.vertices[mesh.indices[k + 2]];
        vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        EXPECT_GT(glm::dot(face, a.normal), 0.0f) << "triangle " << k / 3;
    }
}

TEST(GltfLoader, ComposesMatrixAndTrsNodes) {
    // 3.5.3: a parent with `matrix` (column-major: translation in elements 12..14) and a child
    // with T * R * S; the vertex (1, 0, 0) goes through S, R, T of the child, then the parent.
    gltf::File file;
    int mesh = addPrimitive(file, Primitive{});
    int child = file.node({{"mesh", mesh},
                           {"translation", {0, 2, 0}},
                           {"rotation", {0, 0, 0.70710678, 0.70710678}},  // 90 degrees about z
                           {"scale", {2, 2, 2}}});
    file.node({{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1}}, {"children", {child}}});
    file.scene({1});
    common::ModelData model = load(file, "hierarchy.gltf");
    ASSERT_EQ(model.meshes.size(), 1u);
    std::vector<vec3> p = corners(model.meshes[0]);
    expectNear(p[0], {10, 2, 0});  // (0,0,0): scaled and turned stays 0, then +(0,2,0), +(10,0,0)
    expectNear(p[1], {10, 4, 0});  // (1,0,0) -> (2,0,0) -> (0,2,0) -> (0,4,0) -> (10,4,0)
    expectNear(p[2], {8, 2, 0});   // (0,1,0) -> (0,2,0) -> (-2,0,0) -> (-2,2,0) -> (8,2,0)
    expectFrontFacing(model.meshes[0]);
    expectNear(model.boundsMin, {8, 2, 0});
    expectNear(model.boundsMax, {10, 4, 0});
}

TEST(GltfLoader, MirroredNodeReversesWinding) {
    // 3.7.4: a node whose transform mirrors (negative determinant) keeps its faces front-facing
    // only if the winding is reversed.
    common::ModelData model = loadPrimitive(Primitive{}, "mirrored.gltf", {{"scale", {-1, 1, 1}}});
    const common::MeshData& mesh = model.meshes[0];
    std::vector<vec3> p = corners(mesh);
    expectNear(p[0], {0, 0, 0});
    expectNear(p[1], {0, 1, 0});  // swapped with the mirrored (1, 0, 0)
    expectNear(p[2], {-1, 0, 0});
    expectNear(mesh.vertices[0].normal, {0, 0, 1});
    expectFrontFacing(mesh);
}

TEST(GltfLoader, SparseAccessorReplacesValues) {
    // 3.6.2.3: the base positions from a buffer view, vertex 1 replaced; and an accessor of zeros
    // with two values substituted (no buffer view at all).
    gltf::File file;
    Primitive p;
    int mesh = addPrimitive(file, p);
    std::vector<uint16_t> indices{1};
    std::vector<float> values{5, 0, 0};
    json& position = file.root["accessors"][0];
    position["sparse"] = {
        {"count", 1},
        {"indices", {{"bufferView", file.view(indices.data(), 2)}, {"componentType", gltf::kUnsignedShort}}},
        {"values", {{"bufferView", file.view(values.data(), 12)}}}};
    position["max"] = {5, 1, 0};
    file.node({{"mesh", mesh}});
    file.scene({0});
    std::vector<vec3> replaced = corners(load(file, "sparse.gltf").meshes[0]);
    expectNear(replaced[1], {5, 0, 0});
    expectNear(replaced[2], {0, 1, 0});

    gltf::File zeros;
    int zeroMesh = addPrimitive(zeros, p);
    std::vector<uint32_t> which{1, 2};
    std::vector<float> xyz{3, 0, 0, 0, 3, 0};
    zeros.root["accessors"][0] = {
        {"componentType", gltf::kFloat},
        {"count", 3},
        {"type", "VEC3"},
        {"min", {0, 0, 0}},
        {"max", {3, 3, 0}},
        {"sparse",
         {{"count", 2},
          {"indices", {{"bufferView", zeros.view(which.data(), 8)}, {"componentType", gltf::kUnsignedInt}}},
          {"values", {{"bufferView", zeros.view(xyz.data(), 24)}}}}}};
    zeros.node({{"mesh", zeroMesh}});
    zeros.scene({0});
    std::vector<vec3> fromZeros = corners(load(zeros, "sparse_zeros.gltf").meshes[0]);
    expectNear(fromZeros[0], {0, 0, 0});
    expectNear(fromZeros[1], {3, 0, 0});
    expectNear(fromZeros[2], {0, 3, 0});
}

TEST(GltfLoader, NormalizedIntegerTexCoords) {
    // 3.7.2.1 and 3.11: TEXCOORD_0 as normalized unsigned bytes and shorts, c / 255 and c / 65535.
    for (int type : {gltf::kUnsignedByte, gltf::kUnsignedShort}) {
        gltf::File file;
        int mesh = addPrimitive(file, Primitive{});
        if (type == gltf::kUnsignedByte) {
            // Vertex attributes start on 4-byte boundaries (3.6.2.4): 2 bytes of data, 2 of padding.
            std::vector<uint8_t> uv{0, 255, 0, 0, 128, 64, 0, 0, 255, 0, 0, 0};
            file.root["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
                file.accessor(file.view(uv.data(), uv.size(), 4), type, 3, "VEC2", true);
        } else {
            std::vector<uint16_t> uv{0, 65535, 32768, 16384, 65535, 0};
            file.root["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
                file.accessor(file.view(uv.data(), uv.size() * 2), type, 3, "VEC2", true);
        }
        file.node({{"mesh", mesh}});
        file.scene({0});
        common::ModelData model = load(file, "normalized.gltf");
        const common::MeshData& mesh0 = model.meshes[0];
        float max = type == gltf::kUnsignedByte ? 255.0f : 65535.0f;
        EXPECT_FLOAT_EQ(mesh0.vertices[0].uv.x, 0.0f);
        EXPECT_FLOAT_EQ(mesh0.vertices[0].uv.y, 1.0f);
        EXPECT_FLOAT_EQ(mesh0.vertices[1].uv.x, (type == gltf::kUnsignedByte ? 128.0f : 32768.0f) / max);
        EXPECT_FLOAT_EQ(mesh0.vertices[1].uv.y, (type == gltf::kUnsignedByte ? 64.0f : 16384.0f) / max);
        EXPECT_FLOAT_EQ(mesh0.vertices[2].uv.x, 1.0f);
    }
    // Not normalized: the specification allows no integer texture coordinates then.
    gltf::File file;
    int mesh = addPrimitive(file, Primitive{});
    std::vector<uint16_t> uv{0, 1, 1, 0, 1, 1};
    file.root["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
        file.accessor(file.view(uv.data(), 12), gltf::kUnsignedShort, 3, "VEC2", false);
    file.node({{"mesh", mesh}});
    file.scene({0});
    EXPECT_THROW(load(file, "unnormalized.gltf"), common::InputError);
}

TEST(GltfLoader, FansBecomeCounterClockwiseTriangles) {
    // 3.7.2.1: a fan of 5 vertices is 3 triangles about vertex 0, p_i = {v_i+1, v_i+2, v_0}.
    Primitive fan;
    fan.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}};
    fan.normals.assign(5, vec3(0, 0, 1));
    fan.mode = gltf::kTriangleFan;
    common::MeshData f = loadPrimitive(fan, "fan.gltf").meshes[0];
    ASSERT_EQ(f.indices.size(), 9u);
    std::vector<vec3> p = corners(f);
    expectNear(p[0], {1, 0, 0});  // p_0 = {v1, v2, v0}
    expectNear(p[1], {1, 1, 0});
    expectNear(p[2], {0, 0, 0});
    expectFrontFacing(f);
}

TEST(GltfLoader, StripWindingAlternates) {
    // v0 v1 v2 v3: triangles {v0, v1, v2} and {v1, v3, v2} (p_i = {v_i, v_i+(1+i%2), v_i+(2-i%2)}).
    Primitive strip;
    strip.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    strip.normals.assign(4, vec3(0, 0, 1));
    strip.mode = gltf::kTriangleStrip;
    common::MeshData s = loadPrimitive(strip, "strip4.gltf").meshes[0];
    std::vector<vec3> p = corners(s);
    ASSERT_EQ(p.size(), 6u);
    expectNear(p[3], {1, 0, 0});  // {v1, v3, v2}
    expectNear(p[4], {1, 1, 0});
    expectNear(p[5], {0, 1, 0});
    expectFrontFacing(s);
}

TEST(GltfLoader, FlatNormalsWhenNormalsAreMissing) {
    // 3.7.2.1: without NORMAL, flat normals; each triangle gets vertices of its own.
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    p.normals.clear();
    p.indices = {0, 1, 2, 0, 3, 1};
    common::MeshData mesh = loadPrimitive(p, "flat.gltf").meshes[0];
    ASSERT_EQ(mesh.vertices.size(), 6u);
    for (int k = 0; k < 3; ++k) expectNear(mesh.vertices[size_t(k)].normal, {0, 0, 1});
    for (int k = 3; k < 6; ++k) expectNear(mesh.vertices[size_t(k)].normal, {0, 1, 0});  // (0,0,1) x (1,0,0)
}

TEST(GltfLoader, TangentsComputedOrTakenWithTheirSign) {
    // Without TANGENT: computed, along +u, orthonormal. With TANGENT: taken, bitangent =
    // cross(normal, tangent.xyz) * w (3.7.2.1), w = -1 here.
    Primitive p;
    p.uvs = {{0, 1}, {1, 1}, {0, 0}};  // u along +x, v down the image along -y
    common::MeshData computed = loadPrimitive(p, "no_tangents.gltf").meshes[0];
    for (const common::Vertex& v : computed.vertices) {
        expectNear(v.tangent, {1, 0, 0});
        expectNear(v.bitangent, {0, 1, 0});  // up in the image
    }
    gltf::File file;
    int mesh = addPrimitive(file, p);
    std::vector<glm::vec4> tangents(3, glm::vec4(1, 0, 0, -1));
    file.root["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] =
        file.values(tangents, gltf::kFloat, "VEC4");
    file.node({{"mesh", mesh}});
    file.scene({0});
    common::ModelData model = load(file, "tangents.gltf");
    for (const common::Vertex& v : model.meshes[0].vertices) {
        expectNear(v.tangent, {1, 0, 0});
        expectNear(v.bitangent, {0, -1, 0});
    }
}

// A frame model.hpp promises: unit normal, tangent and bitangent, the tangent perpendicular to the
// normal.
void expectOrthonormal(const common::MeshData& mesh) {
    for (const common::Vertex& v : mesh.vertices) {
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
        EXPECT_NEAR(glm::length(v.tangent), 1.0f, 1e-4f);
        EXPECT_NEAR(glm::length(v.bitangent), 1.0f, 1e-4f);
        EXPECT_NEAR(glm::dot(v.normal, v.tangent), 0.0f, 1e-4f);
    }
}

TEST(GltfLoader, FileTangentsMadeOrthonormal) {
    // A file's tangent need not be perpendicular to its normal (tilted: made so, its side kept),
    // and may be unusable (zero, or along the normal: computed from the texture coordinates).
    Primitive p;
    p.uvs = {{0, 1}, {1, 1}, {0, 0}};
    for (glm::vec4 tangent : {glm::vec4(1, 0, 0.5f, -1), glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, 2, 1)}) {
        gltf::File file;
        int mesh = addPrimitive(file, p);
        std::vector<glm::vec4> tangents(3, tangent);
        file.root["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] =
            file.values(tangents, gltf::kFloat, "VEC4");
        file.node({{"mesh", mesh}});
        file.scene({0});
        common::ModelData model = load(file, "odd_tangents.gltf");
        expectOrthonormal(model.meshes[0]);
        for (const common::Vertex& v : model.meshes[0].vertices) {
            expectNear(v.tangent, {1, 0, 0});
            expectNear(v.bitangent, tangent.w < 0 ? vec3(0, -1, 0) : vec3(0, 1, 0));
        }
    }
}

TEST(GltfLoader, ExtremeScalesKeepUnitNormals) {
    // A node scaled by 1e-200 along x is valid JSON and glTF; a triangle in the yz plane keeps
    // finite positions, and its normal, through the inverse-transpose, grows to 1e200 (squared,
    // past what a double holds): it must still come out unit length.
    Primitive p;
    p.positions = {{0, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    p.normals.assign(3, vec3(1, 0, 0));
    p.uvs = {{0, 1}, {1, 1}, {0, 0}};
    common::ModelData model = loadPrimitive(p, "extreme_scale.gltf", {{"scale", {1e-200, 1, 1}}});
    expectOrthonormal(model.meshes[0]);
    for (const common::Vertex& v : model.meshes[0].vertices) expectNear(v.normal, {1, 0, 0});
}

TEST(GltfLoader, BufferAndImageMayShareAFile) {
    // An image file is left to the texture upload, but a file that is also a buffer is read.
    gltf::File file;
    int mesh = addPrimitive(
        file, Primitive{},
        file.material({{"pbrMetallicRoughness",
                        {{"baseColorTexture", {{"index", file.texture(file.image("shared.bin"))}}}}}}));
    file.node({{"mesh", mesh}});
    file.scene({0});
    fs::path path = tempDir() / "shared.gltf";
    file.writeGltf(path);
    // writeGltf names the buffer after the model: rename it to the image's name.
    std::vector<uint8_t> text = gltf::readBytes(path);
    json root = json::parse(text.begin(), text.end());
    fs::rename(tempDir() / root["buffers"][0]["uri"].get<std::string>(), tempDir() / "shared.bin");
    root["buffers"][0]["uri"] = "shared.bin";
    std::string out = root.dump();
    gltf::writeBytes(path, out.data(), out.size());
    common::ModelData model = common::loadGltfModel(path);
    EXPECT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.materials[0].diffuseTexture.image.file, tempDir() / "shared.bin");
}

TEST(GltfLoader, HugeAlphaCutoffStaysFinite) {
    gltf::File file;
    int mesh = addPrimitive(file, Primitive{}, file.material({{"alphaMode", "MASK"}, {"alphaCutoff", 1e39}}));
    file.node({{"mesh", mesh}});
    file.scene({0});
    common::ModelData model = load(file, "huge_cutoff.gltf");
    EXPECT_TRUE(std::isfinite(model.materials[0].alphaCutoff));
    EXPECT_GT(model.materials[0].alphaCutoff, 1.0f);  // still cuts every texel
}

TEST(GltfLoader, MaterialsAndSamplers) {
    gltf::File file;
    int sampler =
        file.add("samplers", {{"magFilter", 9728}, {"minFilter", 9729}, {"wrapS", 33071}, {"wrapT", 33648}});
    int image = file.image("base.png");
    int withSampler = file.texture(image, sampler), plain = file.texture(image);
    json pbr = {{"baseColorFactor", {0.5, 0.25, 1, 0.75}},
                {"metallicFactor", 0.3},
                {"roughnessFactor", 0.6},
                {"baseColorTexture", {{"index", withSampler}}},
                {"metallicRoughnessTexture", {{"index", plain}}}};
    int mask = file.material({{"name", "cut"},
                              {"pbrMetallicRoughness", pbr},
                              {"normalTexture", {{"index", plain}, {"scale", 0.5}}},
                              {"occlusionTexture", {{"index", plain}, {"strength", 0.25}}},
                              {"alphaMode", "MASK"},
                              {"alphaCutoff", 0.3},
                              {"doubleSided", true}});
    int blend = file.material({{"alphaMode", "BLEND"}});
    int opaque = file.material(json::object());
    std::vector<json> primitives;
    for (int m : {mask, blend, opaque}) {
        int mesh = addPrimitive(file, Primitive{}, m);
        primitives.push_back(file.root["meshes"][size_t(mesh)]["primitives"][0]);
    }
    file.root["meshes"] = json::array({{{"primitives", primitives}}});
    file.node({{"mesh", 0}});
    file.scene({0});
    common::ModelData model = load(file, "materials.gltf");
    ASSERT_EQ(model.materials.size(), 4u);  // three, and the default
    const common::MaterialData& m = model.materials[0];
    EXPECT_EQ(m.name, "cut");
    EXPECT_EQ(m.diffuse, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_FLOAT_EQ(m.metallic, 0.3f);
    EXPECT_FLOAT_EQ(m.roughness, 0.6f);
    EXPECT_EQ(m.diffuseTexture.image.file, tempDir() / "base.png");
    EXPECT_EQ(m.metalRoughTexture.image.file, tempDir() / "base.png");
    EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
    EXPECT_FLOAT_EQ(m.occlusionStrength, 0.25f);
    EXPECT_EQ(m.alphaMode, common::AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_TRUE(m.doubleSided);
    const common::SamplerDesc& s = m.diffuseTexture.sampler;
    EXPECT_EQ(s.magFilter, common::Filter::Nearest);
    EXPECT_EQ(s.minFilter, common::Filter::Linear);
    EXPECT_FALSE(s.mipmaps);  // LINEAR minification: level 0 only
    EXPECT_EQ(s.wrapU, common::Wrap::ClampToEdge);
    EXPECT_EQ(s.wrapV, common::Wrap::MirroredRepeat);
    EXPECT_EQ(m.metalRoughTexture.sampler, common::SamplerDesc{});     // no sampler: the default
    EXPECT_EQ(model.materials[1].alphaMode, common::AlphaMode::Mask);  // BLEND, drawn as a mask
    EXPECT_FLOAT_EQ(model.materials[1].alphaCutoff, 0.5f);
    EXPECT_EQ(model.materials[2].alphaMode, common::AlphaMode::Opaque);
    EXPECT_FLOAT_EQ(model.materials[2].metallic, 1.0f);  // 3.9.2: the factors default to 1
    EXPECT_FALSE(model.materials[2].doubleSided);
    ASSERT_EQ(model.meshes.size(), 3u);
    EXPECT_EQ(model.meshes[2].material, 2u);
}

TEST(GltfLoader, ThreeFormsLoadTheSame) {
    // .gltf + .bin, .gltf with data: URIs, .glb: the same vertices, indices and materials.
    gltf::File file;
    Primitive p;
    p.uvs = {{0, 0}, {1, 0}, {0, 1}};
    int mesh = addPrimitive(file, p);
    file.node({{"mesh", mesh}, {"translation", {1, 2, 3}}});
    file.scene({0});
    fs::path dir = tempDir();
    file.writeGltf(dir / "three.gltf");
    file.writeEmbedded(dir / "three_embedded.gltf", dir);
    file.writeGlb(dir / "three.glb", dir);
    common::ModelData a = common::loadModel(dir / "three.gltf"),
                      b = common::loadModel(dir / "three_embedded.gltf"),
                      c = common::loadModel(dir / "three.glb");
    for (const common::ModelData* other : {&b, &c}) {
        ASSERT_EQ(other->meshes.size(), 1u);
        EXPECT_EQ(other->meshes[0].indices, a.meshes[0].indices);
        ASSERT_EQ(other->meshes[0].vertices.size(), a.meshes[0].vertices.size());
        EXPECT_EQ(std::memcmp(other->meshes[0].vertices.data(), a.meshes[0].vertices.data(),
                              a.meshes[0].vertices.size() * sizeof(common::Vertex)),
                  0);
    }
}

TEST(GltfLoader, EmbeddedImagesAreKeptUndecoded) {
    // An image in a data: URI or a GLB buffer view reaches the texture upload as its bytes.
    gltf::File file;
    std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 1, 2, 3};
    gltf::writeBytes(tempDir() / "tiny.png", png.data(), png.size());
    json pbr = {{"baseColorTexture", {{"index", file.texture(file.image("tiny.png"))}}}};
    int mesh = addPrimitive(file, Primitive{}, file.material({{"pbrMetallicRoughness", pbr}}));
    file.node({{"mesh", mesh}});
    file.scene({0});
    file.writeGlb(tempDir() / "image.glb", tempDir());
    common::ModelData model = common::loadModel(tempDir() / "image.glb");
    const common::ImageSource& source = model.materials[0].diffuseTexture.image;
    ASSERT_TRUE(source.embedded);
    EXPECT_EQ(*source.embedded, png);
    EXPECT_EQ(source.name(), common::utf8(tempDir() / "image.glb") + " (image 0)");
}

TEST(GltfLoader, EachAccessorIsDecodedOnce) {
    // Two primitives and two nodes read the same POSITION accessor: the reader hands out the
    // values it decoded the first time (the same vector), so the work is once per accessor.
    gltf::File file;
    int mesh = addPrimitive(file, Primitive{});
    file.node({{"mesh", mesh}});
    file.node({{"mesh", mesh}, {"translation", {1, 0, 0}}});
    file.scene({0, 1});
    fs::path path = tempDir() / "decoded_once.gltf";
    file.writeGltf(path);
    common::GltfDocument document = common::readGltfDocument(path);
    common::GltfReader reader(document);
    const int position = document.model.meshes[0].primitives[0].attributes.at("POSITION");
    const std::vector<float>& first =
        reader.floats(position, "POSITION", {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT}, false);
    const std::vector<float>& second =
        reader.floats(position, "POSITION", {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT}, false);
    EXPECT_EQ(&first, &second);
    EXPECT_EQ(first.size(), 9u);
    // The model itself: both nodes baked from it.
    common::ModelData model = common::loadGltfModel(path);
    ASSERT_EQ(model.meshes.size(), 2u);
    expectNear(model.meshes[1].vertices[0].position, {1, 0, 0});
}

}  // namespace
