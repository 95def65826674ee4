// sponza_standin DIR: a stand-in for the book's Sponza (the model its chapters 10-15 render, which
// this repository does not carry), of the same size and kind, for startup, memory and frame-time
// measurements (bench/startup.sh): one node scaled 0.008; one mesh of 103 primitives with
// POSITION, TEXCOORD_0, NORMAL and TANGENT and 16-bit indices, 266,976 triangles (Sponza: about
// 262,000); 25 materials (three MASK, three doubleSided, two without textures); 68 images of
// 1024x1024 (65 JPEG, 3 PNG with alpha) and one 4x4 PNG; one sampler (linear, mipmapped,
// repeat). Written as DIR/Sponza.gltf + Sponza.bin and as DIR/sponza.obj + sponza.mtl over the
// same images (the OBJ naming the packed metal-rough image twice, as map_Pr and map_Pm).
// Deterministic.
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../scenes/gltf_writer.hpp"

namespace {

namespace fs = std::filesystem;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using gltf::json;

uint32_t hash(uint32_t x, uint32_t y, uint32_t seed) {
    uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    return h ^ (h >> 15);
}

// Texture-like content (smooth blotches, fine grain, a few edges): JPEG sizes and decode times
// like a photographed texture's, not like a flat colour's.
std::vector<uint8_t> image(int size, int channels, uint32_t seed, int kind) {
    std::vector<uint8_t> pixels(size_t(size) * size * channels);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            float blotch = float(hash(uint32_t(x / 64), uint32_t(y / 64), seed) & 255) / 255.0f;
            float grain = float(hash(uint32_t(x), uint32_t(y), seed + 1) & 63) / 255.0f;
            bool edge = (x % 128) < 3 || (y % 96) < 3;
            for (int c = 0; c < channels; ++c) {
                float v;
                if (kind == 1)
                    v = c == 2 ? 0.95f : 0.5f + (grain - 0.12f) * (c == 0 ? 1.0f : 0.7f);  // normal map
                else if (kind == 2)
                    v = c == 1 ? 0.4f + 0.5f * blotch : c == 2 ? (blotch > 0.8f ? 1.0f : 0.0f) : 1.0f;
                else
                    v = (0.25f + 0.5f * blotch + grain) * (0.7f + 0.1f * float(c)) * (edge ? 0.4f : 1.0f);
                if (c == 3) v = ((x / 32 + y / 32) % 3) ? 1.0f : 0.0f;  // cut-out holes
                pixels[(size_t(y) * size + size_t(x)) * channels + size_t(c)] =
                    uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
            }
        }
    return pixels;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: sponza_standin DIR\n");
        return 2;
    }
    fs::path dir = argv[1];
    fs::create_directories(dir);
    constexpr int kSize = 1024, kMaterials = 25, kTextured = 23, kPrimitives = 103, kGrid = 36;

    // 69 images: 23 textured materials x (base colour, normal, metal-rough) but one normal map;
    // the base colour of the three MASK materials is a PNG with alpha; and one 4x4 PNG.
    std::vector<std::string> base, normal, metalRough;
    for (int m = 0; m < kTextured; ++m) {
        bool mask = m < 3;
        base.push_back("base_" + std::to_string(m) + (mask ? ".png" : ".jpg"));
        normal.push_back("normal_" + std::to_string(m) + ".jpg");
        metalRough.push_back("metal_rough_" + std::to_string(m) + ".jpg");
        std::vector<uint8_t> b = image(kSize, mask ? 4 : 3, uint32_t(3 * m), 0);
        if (mask)
            stbi_write_png((dir / base.back()).string().c_str(), kSize, kSize, 4, b.data(), kSize * 4);
        else
            stbi_write_jpg((dir / base.back()).string().c_str(), kSize, kSize, 3, b.data(), 90);
        std::vector<uint8_t> n = image(kSize, 3, uint32_t(3 * m + 1), 1),
                             r = image(kSize, 3, uint32_t(3 * m + 2), 2);
        if (m == kTextured - 1)
            normal.back().clear();  // one material without a normal map: 68 + 1 images
        else
            stbi_write_jpg((dir / normal.back()).string().c_str(), kSize, kSize, 3, n.data(), 90);
        stbi_write_jpg((dir / metalRough.back()).string().c_str(), kSize, kSize, 3, r.data(), 90);
    }
    std::vector<uint8_t> tiny = image(4, 3, 999, 0);
    stbi_write_png((dir / "tiny.png").string().c_str(), 4, 4, 3, tiny.data(), 12);

    gltf::File file;
    int sampler =
        file.add("samplers", {{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}});
    auto texture = [&](const std::string& name) {
        return json{{"index", file.texture(file.image(name), sampler)}};
    };
    std::string mtl;
    for (int m = 0; m < kMaterials; ++m) {
        json pbr = {{"baseColorFactor", {0.588, 0.588, 0.588, 1.0}},
                    {"metallicFactor", 1.0},
                    {"roughnessFactor", 1.0}};
        json material = {{"name", "material_" + std::to_string(m)}};
        mtl += "newmtl material_" + std::to_string(m) + "\nKd 0.588 0.588 0.588\nPr 1\nPm 1\n";
        if (m < kTextured) {
            pbr["baseColorTexture"] = texture(base[size_t(m)]);
            pbr["metallicRoughnessTexture"] = texture(metalRough[size_t(m)]);
            mtl += "map_Kd " + base[size_t(m)] + "\nmap_Pr " + metalRough[size_t(m)] + "\nmap_Pm " +
                   metalRough[size_t(m)] + "\n";
            if (!normal[size_t(m)].empty()) {
                material["normalTexture"] = texture(normal[size_t(m)]);
                mtl += "norm " + normal[size_t(m)] + "\n";
            }
        } else if (m == kTextured) {
            pbr["baseColorTexture"] = texture("tiny.png");
            mtl += "map_Kd tiny.png\n";
        }
        if (m < 3) material["alphaMode"] = "MASK";
        if (m >= 3 && m < 6) material["doubleSided"] = true;
        material["pbrMetallicRoughness"] = pbr;
        file.material(material);
        mtl += "\n";
    }

    // 103 panels of 36 x 36 quads (2,592 triangles each): a floor, four walls of two storeys and
    // hanging drapes, inside x -15..14, y -1..11.5, z -9.5..9 after the node's scale of 0.008.
    json primitives = json::array();
    std::ofstream obj(dir / "sponza.obj");
    obj << "mtllib sponza.mtl\n";
    size_t objVertices = 0;
    for (int p = 0; p < kPrimitives; ++p) {
        vec3 corner, u, v;
        int row = p % 10, band = p / 10;
        if (band < 2) {  // floor: 20 panels, facing up (u x v is the front face's normal)
            corner = {-15.0f + 2.9f * float(row), -1.0f, -9.5f + 9.25f * float(band + 1)};
            u = {2.9f, 0, 0}, v = {0, 0, -9.25f};
        } else if (band < 6) {  // long walls: 40 panels
            bool north = band % 2 == 0;
            float y = band < 4 ? -1.0f : 5.25f;
            corner = {-15.0f + 2.9f * float(row), y, north ? -9.5f : 9.0f};
            u = {north ? 2.9f : 2.9f, 0, 0}, v = {0, 6.25f, 0};
            if (!north) corner.x += 2.9f, u = -u;
        } else if (band < 8) {  // end walls: 20 panels
            bool west = band == 6;
            corner = {west ? -15.0f : 14.0f, -1.0f + 1.25f * float(row), west ? 9.0f : -9.5f};
            u = {0, 0, west ? -18.5f : 18.5f}, v = {0, 1.25f, 0};
        } else {  // drapes and columns: 23 panels
            corner = {-12.0f + 1.1f * float(p - 80), 0.0f, -2.0f + 0.2f * float(p % 3)};
            u = {0.9f, 0, 0.3f}, v = {0, 9.0f, 0};
        }
        vec3 n = glm::normalize(glm::cross(u, v));
        std::vector<vec3> positions, normals;
        std::vector<vec4> tangents;
        std::vector<vec2> uvs;
        std::vector<uint16_t> indices;
        for (int j = 0; j <= kGrid; ++j)
            for (int i = 0; i <= kGrid; ++i) {
                float s = float(i) / kGrid, t = float(j) / kGrid;
                // A little relief, so the panels are not flat planes for the rasterizer.
                float bump = 0.05f * std::sin(float(i) * 0.7f) * std::cos(float(j) * 0.5f);
                positions.push_back((corner + u * s + v * t + n * bump) / 0.008f);
                normals.push_back(n);
                tangents.push_back(vec4(glm::normalize(u), 1.0f));
                uvs.push_back({s * 4.0f, (1.0f - t) * 4.0f});
            }
        for (int j = 0; j < kGrid; ++j)
            for (int i = 0; i < kGrid; ++i) {
                uint16_t a = uint16_t(j * (kGrid + 1) + i), b = uint16_t(a + 1), c = uint16_t(a + kGrid + 1),
                         d = uint16_t(c + 1);
                indices.insert(indices.end(), {a, b, d, a, d, c});
            }
        int material = p % kMaterials;
        primitives.push_back({{"attributes",
                               {{"POSITION", file.positions(positions)},
                                {"NORMAL", file.values(normals, gltf::kFloat, "VEC3")},
                                {"TANGENT", file.values(tangents, gltf::kFloat, "VEC4")},
                                {"TEXCOORD_0", file.values(uvs, gltf::kFloat, "VEC2")}}},
                              {"indices", file.values(indices, gltf::kUnsignedShort, "SCALAR")},
                              {"material", material}});
        // The OBJ form: positions already scaled; v flipped (OBJ's v runs up).
        obj << "usemtl material_" << material << "\n";
        char line[128];
        for (size_t k = 0; k < positions.size(); ++k) {
            vec3 q = positions[k] * 0.008f;
            std::snprintf(line, sizeof line, "v %.5f %.5f %.5f\nvn %.4f %.4f %.4f\nvt %.5f %.5f\n", q.x, q.y,
                          q.z, normals[k].x, normals[k].y, normals[k].z, uvs[k].x, 1.0f - uvs[k].y);
            obj << line;
        }
        for (size_t k = 0; k < indices.size(); k += 3) {
            obj << "f";
            for (size_t c = 0; c < 3; ++c) {
                size_t index = objVertices + indices[k + c] + 1;
                obj << ' ' << index << '/' << index << '/' << index;
            }
            obj << "\n";
        }
        objVertices += positions.size();
    }
    file.node({{"mesh", file.mesh(primitives)}, {"scale", {0.008, 0.008, 0.008}}});
    file.scene({0});
    file.writeGltf(dir / "Sponza.gltf");
    std::ofstream(dir / "sponza.mtl") << mtl;
    std::printf("sponza stand-in: %d primitives, %d triangles, %d materials, %d images in %s\n", kPrimitives,
                kPrimitives * kGrid * kGrid * 2, kMaterials, 3 * kTextured, dir.string().c_str());
    return obj ? 0 : 1;
}
