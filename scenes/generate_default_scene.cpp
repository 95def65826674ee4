// generate_default_scene DIR: writes the default scene of chapters 10-15 into DIR as plain files
// a reader could have made: OBJ + MTL models, PNG textures and scene.json; and the same scene as
// glTF 2.0 (scene-gltf.json naming courtyard.gltf, ...: the same geometry and materials, the
// roughness map packed into glTF's metal-rough image). Deterministic: the same bytes on every run
// (textures come from integer hashes, not a random generator).
//
// The scene shows what deferred shading and PBR are for: a courtyard (tiled floor and brick
// walls with albedo and normal maps, fluted marble columns), two rows of spheres sweeping
// roughness 0..1 (one row dielectric, one metal), an alpha-tested iron grille, and a small cube
// at the green point light. About 70,000 triangles, in the range of the usual deferred samples.
#include <stb_image_write.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/core/files.hpp"
#include "common/scene/scene.hpp"
#include "figures.hpp"
#include "gltf_writer.hpp"

namespace fs = std::filesystem;
using glm::vec2;
using glm::vec3;

namespace {

constexpr float kPi = 3.14159265358979f;

// ---- Textures ------------------------------------------------------------------------------

uint32_t hash(int32_t x, int32_t y, uint32_t seed) {
    uint32_t h = uint32_t(x) * 0x8da6b343u ^ uint32_t(y) * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    return h ^ (h >> 15);
}
float hash01(int32_t x, int32_t y, uint32_t seed) {
    return float(hash(x, y, seed) & 0xffffu) / 65535.0f;
}

// Smooth value noise on a lattice of `cell` pixels, wrapping every `period` cells so textures tile.
float valueNoise(float x, float y, float cell, int period, uint32_t seed) {
    float fx = x / cell, fy = y / cell;
    int ix = int(std::floor(fx)), iy = int(std::floor(fy));
    float tx = fx - float(ix), ty = fy - float(iy);
    tx = tx * tx * (3 - 2 * tx);
    ty = ty * ty * (3 - 2 * ty);
    auto at = [&](int cx, int cy) {
        return hash01(((cx % period) + period) % period, ((cy % period) + period) % period, seed);
    };
    float a = at(ix, iy), b = at(ix + 1, iy), c = at(ix, iy + 1), d = at(ix + 1, iy + 1);
    return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

float fractalNoise(float x, float y, int size, uint32_t seed) {
    float sum = 0, amplitude = 0.5f;
    for (int octave = 0, cells = 8; octave < 4; ++octave, cells *= 2, amplitude *= 0.5f)
        sum += amplitude * valueNoise(x, y, float(size) / float(cells), cells, seed + uint32_t(octave));
    return sum / 0.9375f;
}

struct Image {
    int size;
    int channels;
    std::vector<uint8_t> pixels;
    Image(int s, int c) : size(s), channels(c), pixels(size_t(s) * size_t(s) * size_t(c)) {}
    void set(int x, int y, vec3 rgb) {
        for (int c = 0; c < 3 && c < channels; ++c)
            pixels[(size_t(y) * size_t(size) + size_t(x)) * size_t(channels) + size_t(c)] =
                uint8_t(std::lround(glm::clamp(rgb[c], 0.0f, 1.0f) * 255.0f));
    }
};

void writePng(const fs::path& path, const Image& image) {
    if (!stbi_write_png(common::utf8(path).c_str(), image.size, image.size, image.channels,
                        image.pixels.data(), image.size * image.channels))
        throw std::runtime_error("cannot write " + common::utf8(path));
}

// A tangent-space normal map from a height field (OpenGL convention: green points up the image).
Image normalMap(int size, float strength, const std::function<float(int, int)>& height) {
    Image image(size, 3);
    auto h = [&](int x, int y) { return height((x + size) % size, (y + size) % size); };
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            float du = (h(x + 1, y) - h(x - 1, y)) * 0.5f;
            float dv = -(h(x, y + 1) - h(x, y - 1)) * 0.5f;  // rows run down, v runs up
            vec3 n = glm::normalize(vec3(-du * strength, -dv * strength, 1.0f));
            image.set(x, y, n * 0.5f + 0.5f);
        }
    return image;
}

// Distance in pixels from (x, y) to the nearest edge of its cell in a grid of cells w x h;
// rows may be offset by half a cell (running bond).
float edgeDistance(int x, int y, int w, int h, bool runningBond, int* cellX, int* cellY) {
    int row = y / h;
    int shifted = runningBond && (row % 2) ? x + w / 2 : x;
    int column = shifted / w;
    *cellX = column;
    *cellY = row;
    int lx = shifted % w, ly = y % h;
    return float(std::min(std::min(lx, w - 1 - lx), std::min(ly, h - 1 - ly)));
}

void writeTextures(const fs::path& dir) {
    constexpr int S = 512;
    // Floor: 4 x 4 sandstone tiles with dark grout.
    {
        Image albedo(S, 3);
        for (int y = 0; y < S; ++y)
            for (int x = 0; x < S; ++x) {
                int cx, cy;
                float d = edgeDistance(x, y, S / 4, S / 4, false, &cx, &cy);
                float n = fractalNoise(float(x), float(y), S, 11);
                vec3 tile =
                    vec3(0.60f, 0.52f, 0.42f) * (0.85f + 0.3f * hash01(cx, cy, 3)) * (0.85f + 0.3f * n);
                albedo.set(x, y, d < 4 ? vec3(0.22f, 0.20f, 0.18f) : tile);
            }
        writePng(dir / "floor_albedo.png", albedo);
        // Roughness: the grout rough, the tiles a little polished, unevenly. For OBJ, one channel
        // (map_Pr); for glTF, packed as its metal-rough image wants: G = roughness, B = metallic
        // (white: the material's metallic factor alone decides, as for OBJ without map_Pm).
        Image rough(S, 1), metalRough(S, 3);
        for (int y = 0; y < S; ++y)
            for (int x = 0; x < S; ++x) {
                int cx, cy;
                float d = edgeDistance(x, y, S / 4, S / 4, false, &cx, &cy);
                float r = d < 4 ? 1.0f : 0.55f + 0.35f * fractalNoise(float(x), float(y), S, 13);
                rough.pixels[size_t(y) * S + size_t(x)] = uint8_t(std::lround(r * 255.0f));
                metalRough.set(x, y,
                               vec3(1.0f, float(rough.pixels[size_t(y) * S + size_t(x)]) / 255.0f, 1.0f));
            }
        writePng(dir / "floor_rough.png", rough);
        writePng(dir / "floor_metal_rough.png", metalRough);
        writePng(dir / "floor_normal.png", normalMap(S, 3.0f, [](int x, int y) {
                     int cx, cy;
                     float d = edgeDistance(x, y, S / 4, S / 4, false, &cx, &cy);
                     return std::min(d, 10.0f) / 10.0f * 2.0f +
                            fractalNoise(float(x), float(y), S, 12) * 0.6f;
                 }));
    }
    // Walls: running-bond bricks, 8 courses of 4 bricks.
    {
        Image albedo(S, 3);
        for (int y = 0; y < S; ++y)
            for (int x = 0; x < S; ++x) {
                int cx, cy;
                float d = edgeDistance(x, y, S / 4, S / 8, true, &cx, &cy);
                float n = fractalNoise(float(x), float(y), S, 21);
                vec3 brick =
                    vec3(0.55f, 0.25f, 0.17f) * (0.8f + 0.4f * hash01(cx, cy, 5)) * (0.85f + 0.3f * n);
                albedo.set(x, y, d < 3 ? vec3(0.55f, 0.53f, 0.50f) : brick);
            }
        writePng(dir / "wall_albedo.png", albedo);
        writePng(dir / "wall_normal.png", normalMap(S, 2.5f, [](int x, int y) {
                     int cx, cy;
                     float d = edgeDistance(x, y, S / 4, S / 8, true, &cx, &cy);
                     return std::min(d, 6.0f) / 6.0f * 2.0f + fractalNoise(float(x), float(y), S, 22) * 0.8f;
                 }));
    }
    // Columns: veined marble, with 16 flutes around the circumference (u wraps once per 1/2 turn).
    {
        Image albedo(S, 3);
        for (int y = 0; y < S; ++y)
            for (int x = 0; x < S; ++x) {
                float warp = fractalNoise(float(x), float(y), S, 31) * 60.0f;
                float vein = std::pow(std::abs(std::sin((float(x) + float(y) * 0.5f + warp) * 0.04f)), 8.0f);
                albedo.set(x, y, vec3(0.86f, 0.84f, 0.80f) * (1.0f - 0.35f * vein));
            }
        writePng(dir / "column_albedo.png", albedo);
        writePng(dir / "column_normal.png", normalMap(S, 12.0f, [](int x, int) {
                     return std::cos(float(x) / float(S) * 2.0f * kPi * 8.0f) * 0.5f;
                 }));
    }
    // Grille: dark iron colour, and a diamond lattice in map_d (alpha 1 on the bars, 0 in the holes).
    {
        Image albedo(S, 3), alpha(S, 1);
        for (int y = 0; y < S; ++y)
            for (int x = 0; x < S; ++x) {
                float n = fractalNoise(float(x), float(y), S, 41);
                albedo.set(x, y, vec3(0.30f, 0.28f, 0.26f) * (0.7f + 0.6f * n));
                // 4 x 4 diamonds. The bars cover more than half of the area, so alpha averaged
                // into any mip level stays above the 0.5 cut-off and the grille does not
                // dissolve with distance (thin bars would).
                float u = float(x) / S * 4.0f, v = float(y) / S * 4.0f;
                float a = std::abs(std::fmod(u + v, 1.0f) - 0.5f);
                float b = std::abs(std::fmod(u - v + 4.0f, 1.0f) - 0.5f);
                bool bar = a > 0.33f || b > 0.33f;
                bool frame = x < 16 || y < 16 || x >= S - 16 || y >= S - 16;
                alpha.pixels[size_t(y) * S + size_t(x)] = (bar || frame) ? 255 : 0;
            }
        writePng(dir / "grille_albedo.png", albedo);
        writePng(dir / "grille_alpha.png", alpha);
        // glTF has no separate alpha map: the base colour texture carries it.
        Image albedoAlpha(S, 4);
        for (size_t i = 0; i < size_t(S) * S; ++i) {
            for (size_t c = 0; c < 3; ++c) albedoAlpha.pixels[i * 4 + c] = albedo.pixels[i * 3 + c];
            albedoAlpha.pixels[i * 4 + 3] = alpha.pixels[i];
        }
        writePng(dir / "grille_albedo_alpha.png", albedoAlpha);
    }
}

// ---- Geometry ------------------------------------------------------------------------------

// A glTF metallic-roughness material, as the MTL materials of this scene translate.
struct GltfMaterial {
    glm::vec4 color{1.0f};
    float roughness = 1.0f;
    float metallic = 0.0f;
    std::string baseColorImage, metalRoughImage, normalImage;  // files beside the model, or none
    bool mask = false;                                         // alphaMode MASK (cutoff 0.5)
};

struct Obj {
    std::vector<vec3> positions, normals;
    std::vector<vec2> uvs;
    struct Group {
        std::string material;
        std::vector<uint32_t> corners;  // one index per corner into positions/normals/uvs (kept parallel)
    };
    std::vector<Group> groups;

    void use(const std::string& material) { groups.push_back({material, {}}); }
    uint32_t vertex(vec3 p, vec3 n, vec2 uv) {
        positions.push_back(p);
        normals.push_back(n);
        uvs.push_back(uv);
        return uint32_t(positions.size());  // OBJ indices start at 1
    }
    void triangle(uint32_t a, uint32_t b, uint32_t c) {
        groups.back().corners.insert(groups.back().corners.end(), {a, b, c});
    }

    // A grid of cells x rows quads from `corner` along `u` and `v` (counter-clockwise seen from
    // u x v), with texture coordinates (|u|, |v|) / uvSize.
    void grid(vec3 corner, vec3 u, vec3 v, int cells, int rows, float uvSize) {
        vec3 n = glm::normalize(glm::cross(u, v));
        uint32_t first = uint32_t(positions.size()) + 1;
        for (int j = 0; j <= rows; ++j)
            for (int i = 0; i <= cells; ++i) {
                float s = float(i) / float(cells), t = float(j) / float(rows);
                vertex(corner + u * s + v * t, n, vec2(s * glm::length(u), t * glm::length(v)) / uvSize);
            }
        for (int j = 0; j < rows; ++j)
            for (int i = 0; i < cells; ++i) {
                uint32_t a = first + uint32_t(j * (cells + 1) + i), b = a + 1, c = a + uint32_t(cells + 1),
                         d = c + 1;
                triangle(a, b, d);
                triangle(a, d, c);
            }
    }

    // An axis-aligned box from its centre and half extents, outward faces.
    void box(vec3 center, vec3 half, float uvSize) {
        vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (int axis = 0; axis < 3; ++axis)
            for (float side : {-1.0f, 1.0f}) {
                vec3 n = axes[axis] * side;
                vec3 u = axes[(axis + 1) % 3] * half[(axis + 1) % 3] * 2.0f;
                vec3 v = axes[(axis + 2) % 3] * half[(axis + 2) % 3] * 2.0f;
                if (side < 0) std::swap(u, v);
                grid(center + n * half[axis] - u * 0.5f - v * 0.5f, u, v, 1, 1, uvSize);
            }
    }

    // A vertical cylinder side (no caps), texture u wrapping twice around.
    void cylinder(vec3 base, float radius, float height, int segments, int rings) {
        uint32_t first = uint32_t(positions.size()) + 1;
        for (int j = 0; j <= rings; ++j)
            for (int i = 0; i <= segments; ++i) {
                float angle = float(i) / float(segments) * 2.0f * kPi;
                vec3 n(std::sin(angle), 0.0f, std::cos(angle));
                float t = float(j) / float(rings);
                vertex(base + n * radius + vec3(0, height * t, 0), n,
                       vec2(float(i) / float(segments) * 2.0f, t * height / 2.0f));
            }
        for (int j = 0; j < rings; ++j)
            for (int i = 0; i < segments; ++i) {
                uint32_t a = first + uint32_t(j * (segments + 1) + i), b = a + 1,
                         c = a + uint32_t(segments + 1), d = c + 1;
                triangle(a, b, d);
                triangle(a, d, c);
            }
    }

    // A unit UV sphere: `segments` around, `rings` from pole to pole.
    void sphere(int segments, int rings) {
        uint32_t first = uint32_t(positions.size()) + 1;
        for (int j = 0; j <= rings; ++j)
            for (int i = 0; i <= segments; ++i) {
                float theta = float(j) / float(rings) * kPi, phi = float(i) / float(segments) * 2.0f * kPi;
                vec3 p(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
                vertex(p, p, vec2(float(i) / float(segments), 1.0f - float(j) / float(rings)));
            }
        for (int j = 0; j < rings; ++j)
            for (int i = 0; i < segments; ++i) {
                uint32_t a = first + uint32_t(j * (segments + 1) + i), b = a + 1,
                         c = a + uint32_t(segments + 1), d = c + 1;
                if (j != 0) triangle(a, c, b);  // no zero-area triangles at the poles
                if (j != rings - 1) triangle(b, c, d);
            }
    }

    size_t triangles() const {
        size_t n = 0;
        for (const Group& g : groups) n += g.corners.size() / 3;
        return n;
    }

    void write(const fs::path& path, const std::string& mtl) const {
        std::ofstream out(path);
        out << "# generated by generate_default_scene\nmtllib " << mtl << "\n";
        char line[128];
        for (vec3 p : positions)
            std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", p.x, p.y, p.z), out << line;
        for (vec3 n : normals)
            std::snprintf(line, sizeof line, "vn %.6f %.6f %.6f\n", n.x, n.y, n.z), out << line;
        for (vec2 t : uvs) std::snprintf(line, sizeof line, "vt %.6f %.6f\n", t.x, t.y), out << line;
        for (const Group& g : groups) {
            out << "usemtl " << g.material << "\n";
            for (size_t i = 0; i < g.corners.size(); i += 3) {
                out << "f";
                for (size_t k = 0; k < 3; ++k)
                    out << ' ' << g.corners[i + k] << '/' << g.corners[i + k] << '/' << g.corners[i + k];
                out << "\n";
            }
        }
        if (!out) throw std::runtime_error("cannot write " + common::utf8(path));
    }

    // The same model as glTF: one primitive per group, in the material `materials` names for
    // its group. glTF's texture v runs down the image (v = 1 - the OBJ's).
    void writeGltf(const fs::path& path, const std::map<std::string, GltfMaterial>& materials) const;
};

void Obj::writeGltf(const fs::path& path, const std::map<std::string, GltfMaterial>& materials) const {
    gltf::File file;
    std::map<std::string, int> materialIndex;
    auto texture = [&](const std::string& image) {
        return nlohmann::json{{"index", file.texture(file.image(image))}};
    };
    nlohmann::json primitives = nlohmann::json::array();
    for (const Group& g : groups) {
        if (!materialIndex.count(g.material)) {
            const GltfMaterial& m = materials.at(g.material);
            nlohmann::json pbr = {{"baseColorFactor", {m.color.r, m.color.g, m.color.b, m.color.a}},
                                  {"roughnessFactor", m.roughness},
                                  {"metallicFactor", m.metallic}};
            if (!m.baseColorImage.empty()) pbr["baseColorTexture"] = texture(m.baseColorImage);
            if (!m.metalRoughImage.empty()) pbr["metallicRoughnessTexture"] = texture(m.metalRoughImage);
            nlohmann::json json = {{"name", g.material}, {"pbrMetallicRoughness", pbr}};
            if (!m.normalImage.empty()) json["normalTexture"] = texture(m.normalImage);
            if (m.mask) json["alphaMode"] = "MASK";
            materialIndex[g.material] = file.material(json);
        }
        std::vector<vec3> p, n;
        std::vector<vec2> t;
        std::vector<uint32_t> indices;
        std::map<uint32_t, uint32_t> local;
        for (uint32_t corner : g.corners) {
            auto [it, added] = local.try_emplace(corner, uint32_t(p.size()));
            if (added) {
                p.push_back(positions[corner - 1]);
                n.push_back(normals[corner - 1]);
                t.push_back({uvs[corner - 1].x, 1.0f - uvs[corner - 1].y});
            }
            indices.push_back(it->second);
        }
        primitives.push_back({{"attributes",
                               {{"POSITION", file.positions(p)},
                                {"NORMAL", file.values(n, gltf::kFloat, "VEC3")},
                                {"TEXCOORD_0", file.values(t, gltf::kFloat, "VEC2")}}},
                              {"indices", file.values(indices, gltf::kUnsignedInt, "SCALAR")},
                              {"material", materialIndex[g.material]}});
    }
    file.node({{"mesh", file.mesh(primitives)}});
    file.scene({0});
    file.writeGltf(path);
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + common::utf8(path));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: generate_default_scene DIR\n");
        return 2;
    }
    try {
        fs::path dir = argv[1];
        fs::create_directories(dir);
        writeTextures(dir);

        // The courtyard: 30 x 30 floor, 6-unit walls facing inwards, two rows of five columns.
        Obj courtyard;
        courtyard.use("floor");
        courtyard.grid({-15, 0, 15}, {30, 0, 0}, {0, 0, -30}, 48, 48, 2.0f);
        courtyard.use("wall");
        courtyard.grid({-15, 0, -15}, {30, 0, 0}, {0, 6, 0}, 40, 8, 3.0f);  // north, facing +z
        courtyard.grid({15, 0, 15}, {-30, 0, 0}, {0, 6, 0}, 40, 8, 3.0f);   // south, facing -z
        courtyard.grid({-15, 0, 15}, {0, 0, -30}, {0, 6, 0}, 40, 8, 3.0f);  // west, facing +x
        courtyard.grid({15, 0, -15}, {0, 0, 30}, {0, 6, 0}, 40, 8, 3.0f);   // east, facing -x
        courtyard.use("column");
        for (float x : {-10.0f, 10.0f})
            for (float z : {-10.0f, -5.0f, 0.0f, 5.0f, 10.0f}) {
                // The shaft runs 0.1 into the base and the capital: where it only touched them,
                // the depths of shaft and box would tie along the contact and flicker.
                courtyard.cylinder({x, 0.3f, z}, 0.5f, 5.4f, 32, 12);
                courtyard.box({x, 0.2f, z}, {0.7f, 0.2f, 0.7f}, 1.4f);  // base
                courtyard.box({x, 5.8f, z}, {0.7f, 0.2f, 0.7f}, 1.4f);  // capital
            }
        courtyard.write(dir / "courtyard.obj", "courtyard.mtl");
        writeText(
            dir / "courtyard.mtl",
            "newmtl floor\nKd 1 1 1\nPr 1\nPm 0\nmap_Kd floor_albedo.png\nnorm floor_normal.png\n"
            "map_Pr floor_rough.png\n\n"
            "newmtl wall\nKd 1 1 1\nPr 0.9\nPm 0\nmap_Kd wall_albedo.png\nnorm wall_normal.png\n\n"
            "newmtl column\nKd 1 1 1\nPr 0.35\nPm 0\nmap_Kd column_albedo.png\nnorm column_normal.png\n");

        Obj sphere;
        sphere.use("sphere");
        sphere.sphere(64, 32);
        sphere.write(dir / "sphere.obj", "sphere.mtl");
        writeText(dir / "sphere.mtl", "newmtl sphere\nKd 0.8 0.8 0.8\nPr 0.5\nPm 0\n");

        // The grille: two back-to-back quads, alpha-tested through map_d.
        Obj grille;
        grille.use("iron");
        grille.grid({-2, 0, 0}, {4, 0, 0}, {0, 3, 0}, 1, 1, 4.0f);
        grille.grid({2, 0, -0.01f}, {-4, 0, 0}, {0, 3, 0}, 1, 1, 4.0f);
        grille.write(dir / "grille.obj", "grille.mtl");
        writeText(dir / "grille.mtl",
                  "newmtl iron\nKd 1 1 1\nPr 0.45\nPm 1\nmap_Kd grille_albedo.png\nmap_d grille_alpha.png\n");

        Obj cube;
        cube.use("marker");
        cube.box({0, 0, 0}, {1, 1, 1}, 2.0f);
        cube.write(dir / "cube.obj", "cube.mtl");
        writeText(dir / "cube.mtl", "newmtl marker\nKd 0 1 0\nPr 1\nPm 0\n");

        // The same four models as glTF, with the materials their MTL files give.
        courtyard.writeGltf(
            dir / "courtyard.gltf",
            {{"floor",
              {.roughness = 1.0f,
               .baseColorImage = "floor_albedo.png",
               .metalRoughImage = "floor_metal_rough.png",
               .normalImage = "floor_normal.png"}},
             {"wall",
              {.roughness = 0.9f, .baseColorImage = "wall_albedo.png", .normalImage = "wall_normal.png"}},
             {"column",
              {.roughness = 0.35f,
               .baseColorImage = "column_albedo.png",
               .normalImage = "column_normal.png"}}});
        sphere.writeGltf(dir / "sphere.gltf",
                         {{"sphere", {.color = {0.8f, 0.8f, 0.8f, 1.0f}, .roughness = 0.5f}}});
        grille.writeGltf(dir / "grille.gltf", {{"iron",
                                                {.roughness = 0.45f,
                                                 .metallic = 1.0f,
                                                 .baseColorImage = "grille_albedo_alpha.png",
                                                 .mask = true}}});
        cube.writeGltf(dir / "cube.gltf",
                       {{"marker", {.color = {0.0f, 1.0f, 0.0f, 1.0f}, .roughness = 1.0f}}});

        // The scene: the book's lights (white ambient 0.2, a directional light straight down, a
        // green point light marked by a small cube), spheres sweeping roughness along x, the back
        // row metal (gold), the front row dielectric (red).
        common::Scene scene;
        scene.models.push_back({.file = "courtyard.obj"});
        for (int row = 0; row < 2; ++row)
            for (int i = 0; i < 7; ++i) {
                bool metal = row == 0;
                common::ModelInstance s{.file = "sphere.obj"};
                s.transform.position = {-6.0f + 2.0f * float(i), 0.75f, metal ? -1.5f : 1.0f};
                s.transform.scale = glm::vec3(0.7f);
                s.materials["sphere"] = {.diffuse = metal ? glm::vec4(1.0f, 0.77f, 0.34f, 1.0f)
                                                          : glm::vec4(0.8f, 0.1f, 0.08f, 1.0f),
                                         .roughness = float(i) / 6.0f,
                                         .metallic = metal ? 1.0f : 0.0f};
                scene.models.push_back(s);
            }
        common::ModelInstance grilleModel{.file = "grille.obj"};
        grilleModel.transform.position = {0.0f, 0.1f, -6.0f};
        scene.models.push_back(grilleModel);
        glm::vec3 pointLight(0.0f, 2.2f, -0.25f);
        common::ModelInstance marker{.file = "cube.obj"};
        marker.transform.position = pointLight;
        marker.transform.scale = glm::vec3(0.1f);
        scene.models.push_back(marker);

        scene.camera = {.position = {0.0f, 3.2f, 12.5f},
                        .yaw = 0.0f,
                        .pitch = -10.0f,
                        .fov = 60.0f,
                        .near = 0.1f,
                        .far = 60.0f};
        scene.ambientColor = glm::vec3(1.0f);
        scene.ambientIntensity = 0.2f;
        scene.lights.push_back(
            {.type = common::Light::Type::Directional, .direction = {0.0f, -1.0f, 0.0f}, .intensity = 1.0f});
        scene.lights.push_back({.type = common::Light::Type::Point,
                                .position = pointLight,
                                .color = {0.0f, 1.0f, 0.0f},
                                .intensity = 6.0f,
                                .marker = int(scene.models.size()) - 1});  // the cube, added last
        writeText(dir / "scene.json", common::sceneToJson(scene));
        for (common::ModelInstance& model : scene.models) model.file.replace_extension(".gltf");
        writeText(dir / "scene-gltf.json", common::sceneToJson(scene));

        // chapter-17's scene: the same, with two skinned figures (scenes/figures.hpp) playing --
        // a walking biped of boxes in front of the spheres and a bending arm on the left.
        figures::walker().writeGltf(dir / "walker.gltf");
        figures::arm().writeGltf(dir / "arm.gltf");
        figures::twistingTube().writeGltf(dir / "tube.gltf");
        for (common::ModelInstance& model : scene.models) model.file.replace_extension(".obj");
        common::ModelInstance walkerModel{.file = "walker.gltf"};
        walkerModel.transform.position = {2.5f, 0.0f, 4.0f};
        walkerModel.transform.rotation = {0.0f, -30.0f, 0.0f};
        scene.models.push_back(walkerModel);
        common::ModelInstance armModel{.file = "arm.gltf"};
        armModel.transform.position = {-5.5f, 1.2f, 6.0f};
        scene.models.push_back(armModel);
        writeText(dir / "animated.json", common::sceneToJson(scene));

        // A walker that walks 30 m away from the camera in a second, out of the shadow cascade it starts in
        // (chapter-17's test of the shadow cache with a caster that changes cascades).
        figures::walker(30.0f).writeGltf(dir / "walk-away.gltf");
        scene.models.resize(scene.models.size() - 2);
        common::ModelInstance awayModel{.file = "walk-away.gltf"};
        awayModel.transform.position = {0.8f, 0.0f, 10.5f};
        scene.models.push_back(awayModel);
        writeText(dir / "walk-away.json", common::sceneToJson(scene));

        size_t triangles =
            courtyard.triangles() + 14 * sphere.triangles() + grille.triangles() + cube.triangles();
        std::printf("default scene: %zu triangles in %s\n", triangles, common::utf8(dir).c_str());
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "generate_default_scene: %s\n", error.what());
        return 1;
    }
}
