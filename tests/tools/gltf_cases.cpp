// gltf_cases DIR: writes the glTF files of tests/reliability/gltf.cmake into DIR. Good ones, each made to
// show one rule of the glTF 2.0 specification in a picture (cases/ and the scenes naming them), the same
// model as .gltf + .bin, as one .gltf with data: URIs and as .glb (same/), and hostile ones (hostile/), each
// breaking one rule a loader must not trust, and a stand-in for a clone of the book's repository (book/) for
// --book-scene. Deterministic: the same bytes on every run.
#include <stb_image_write.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "../../scenes/figures.hpp"
#include "../../scenes/gltf_writer.hpp"

namespace {

namespace fs = std::filesystem;
using glm::vec2;
using glm::vec3;
using gltf::json;

// A quad of 2 x 2 in the xy plane, facing +z, counter-clockwise, texture (0, 0) at its top left.
struct Quad {
    std::vector<vec3> positions{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    std::vector<vec3> normals{4, vec3(0, 0, 1)};
    std::vector<vec2> uvs{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    std::vector<uint16_t> indices{0, 1, 2, 0, 2, 3};
};

json quadPrimitive(gltf::File& file, int material, bool withNormals = true) {
    Quad q;
    json attributes = {{"POSITION", file.positions(q.positions)},
                       {"TEXCOORD_0", file.values(q.uvs, gltf::kFloat, "VEC2")}};
    if (withNormals) attributes["NORMAL"] = file.values(q.normals, gltf::kFloat, "VEC3");
    json p = {{"attributes", attributes},
              {"indices", file.values(q.indices, gltf::kUnsignedShort, "SCALAR")}};
    if (material >= 0) p["material"] = material;
    return p;
}

json color(float r, float g, float b, float a = 1.0f) {
    return {{"baseColorFactor", {r, g, b, a}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}};
}

void writePng(const fs::path& path, int w, int h, int channels, const std::vector<uint8_t>& pixels) {
    if (!stbi_write_png(path.string().c_str(), w, h, channels, pixels.data(), w * channels))
        throw std::runtime_error("cannot write " + path.string());
}

std::string readBytesText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

// A one-quad model in a material.
void quadModel(const fs::path& path, json material, bool withNormals = true) {
    gltf::File file;
    int m = file.material(std::move(material));
    file.node({{"mesh", file.mesh(json::array({quadPrimitive(file, m, withNormals)}))}});
    file.scene({0});
    file.writeGltf(path);
}

// ---- Cases drawn in the cases scenes --------------------------------------------------------

void writeCases(const fs::path& dir) {
    fs::create_directories(dir);
    // A texture whose alpha rises from 0 at the left to 1 at the right, white; and an occlusion
    // map, black on its left half, white on its right.
    std::vector<uint8_t> ramp(64 * 8 * 4), occlusion(64 * 8 * 3);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 64; ++x) {
            uint8_t* p = &ramp[size_t(y * 64 + x) * 4];
            p[0] = p[1] = p[2] = 255;
            p[3] = uint8_t(std::lround((x + 0.5) / 64.0 * 255.0));
            uint8_t* o = &occlusion[size_t(y * 64 + x) * 3];
            o[0] = o[1] = o[2] = x < 32 ? 0 : 255;
        }
    writePng(dir / "alpha_ramp.png", 64, 8, 4, ramp);
    writePng(dir / "occlusion_halves.png", 64, 8, 3, occlusion);

    // doubleSided (3.9.5): both models are seen from behind in the scene; only this one shows.
    quadModel(dir / "double_sided.gltf",
              {{"pbrMetallicRoughness", color(0.9f, 0.2f, 0.1f)}, {"doubleSided", true}});
    quadModel(dir / "single_sided.gltf", {{"pbrMetallicRoughness", color(0.9f, 0.2f, 0.1f)}});
    // MASK (3.9.4) at two cutoffs: the quad is cut where the ramp's alpha is below the cutoff,
    // so 75% of it remains at 0.25 and 25% at 0.75 (nearest filtering: no blur at the edge).
    for (float cutoff : {0.25f, 0.75f}) {
        gltf::File file;
        json pbr = color(0.2f, 0.5f, 0.9f);
        int sampler = file.add(
            "samplers", {{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}});
        pbr["baseColorTexture"] = {{"index", file.texture(file.image("alpha_ramp.png"), sampler)}};
        int m =
            file.material({{"pbrMetallicRoughness", pbr}, {"alphaMode", "MASK"}, {"alphaCutoff", cutoff}});
        file.node({{"mesh", file.mesh(json::array({quadPrimitive(file, m)}))}});
        file.scene({0});
        file.writeGltf(dir / (cutoff < 0.5f ? "mask_25.gltf" : "mask_75.gltf"));
    }
    // A mirrored node (3.7.4): an L whose parent node has scale (-1, 1, 1). Single-sided, so it
    // shows only if the loader turns its winding around; it must appear as a mirrored L.
    {
        gltf::File file;
        std::vector<vec3> p{{-1, -1, 0},       {1, -1, 0},    {1, -0.5f, 0},
                            {-0.5f, -0.5f, 0}, {-0.5f, 1, 0}, {-1, 1, 0}};
        std::vector<uint16_t> i{0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5};
        std::vector<vec3> n(p.size(), vec3(0, 0, 1));
        int m = file.material({{"pbrMetallicRoughness", color(0.9f, 0.8f, 0.2f)}});
        json prim = {{"attributes",
                      {{"POSITION", file.positions(p)}, {"NORMAL", file.values(n, gltf::kFloat, "VEC3")}}},
                     {"indices", file.values(i, gltf::kUnsignedShort, "SCALAR")},
                     {"material", m}};
        int child = file.node({{"mesh", file.mesh(json::array({prim}))}});
        file.node({{"scale", {-1, 1, 1}}, {"children", {child}}});
        file.scene({1});
        file.writeGltf(dir / "mirrored.gltf");
    }
    // An occlusion map (3.9.3): darkens the left half under ambient light, nothing under the sun.
    {
        gltf::File file;
        json material = {{"pbrMetallicRoughness", color(0.8f, 0.8f, 0.8f)}};
        material["occlusionTexture"] = {{"index", file.texture(file.image("occlusion_halves.png"))},
                                        {"strength", 1.0}};
        int m = file.material(material);
        file.node({{"mesh", file.mesh(json::array({quadPrimitive(file, m)}))}});
        file.scene({0});
        file.writeGltf(dir / "occlusion.gltf");
    }

    // The scenes: the five models in a row, seen from the front (+z), the two sided ones turned
    // around; lit by ambient light only, and by a sun from the camera's side only.
    auto scene = [&](const char* name, float ambient, bool sun) {
        json models = json::array();
        const char* files[] = {"double_sided.gltf", "single_sided.gltf", "mask_25.gltf",
                               "mask_75.gltf",      "mirrored.gltf",     "occlusion.gltf"};
        for (int k = 0; k < 6; ++k) {
            json model = {{"file", files[k]}, {"position", {-6.25 + 2.5 * k, 0, 0}}};
            if (k < 2) model["rotation"] = {0, 180, 0};
            models.push_back(model);
        }
        json lights = json::array();
        if (sun) lights.push_back({{"type", "directional"}, {"direction", {0, 0, -1}}, {"intensity", 1.0}});
        json root = {{"models", models},
                     {"camera", {{"position", {0, 0, 4.5}}, {"fov", 60}, {"near", 0.5}, {"far", 50}}},
                     {"ambient", {{"color", {1, 1, 1}}, {"intensity", ambient}}},
                     {"lights", lights}};
        writeText(dir / name, root.dump(2));
    };
    scene("ambient.json", 1.0f, false);
    scene("sun.json", 0.0f, true);
}

// ---- The same model three ways --------------------------------------------------------------

void writeSame(const fs::path& dir) {
    fs::create_directories(dir);
    std::vector<uint8_t> checker(16 * 16 * 3);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c)
                checker[size_t(y * 16 + x) * 3 + size_t(c)] =
                    ((x / 4 + y / 4) % 2) ? 230 : uint8_t(40 + 60 * c);
    writePng(dir / "checker.png", 16, 16, 3, checker);
    gltf::File file;
    json pbr = color(1, 1, 1);
    pbr["baseColorTexture"] = {{"index", file.texture(file.image("checker.png"))}};
    int m = file.material({{"pbrMetallicRoughness", pbr}, {"doubleSided", true}});
    int quad = file.mesh(json::array({quadPrimitive(file, m)}));
    int a = file.node({{"mesh", quad}, {"translation", {-1.2, 0, 0}}});
    // A child, small, placed relative to its parent: drawn as a root (at its own translation) it
    // would stand elsewhere.
    int child = file.node({{"mesh", quad}, {"translation", {0, 0.9, 0.2}}, {"scale", {0.3, 0.3, 0.3}}});
    int b = file.node({{"mesh", quad},
                       {"translation", {1.2, 0, 0}},
                       {"rotation", {0, 0.3826834, 0, 0.9238795}},
                       {"children", {child}}});
    file.scene({a, b});
    file.writeGltf(dir / "model.gltf");
    file.writeEmbedded(dir / "model_embedded.gltf", dir);
    file.writeGlb(dir / "model.glb", dir);
    // No scene at all (3.5.1 leaves it optional): every root node is drawn, the same two quads.
    file.root.erase("scene");
    file.root.erase("scenes");
    file.writeGltf(dir / "model_no_scene.gltf");
}

// ---- Every material feature ------------------------------------------------------------------

// Eleven quads in a grid of three columns, one material each, between them every feature a scene
// pipeline is specialised for -- base-colour texture, normal map (scale 1 and not), metal-rough
// texture, occlusion map, alpha mask, double-sided -- alone and all at once, and each pairing of
// the alpha test with the culling; two materials of one class (plain colours), so the scene has 10
// material classes; and one material no primitive uses. Lit by a sun and two point lights.
void writeFeatures(const fs::path& dir) {
    fs::create_directories(dir);
    std::vector<uint8_t> checker(16 * 16 * 4), bumps(16 * 16 * 3), metalRough(16 * 16 * 3),
        occlusion(16 * 16 * 3);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            size_t i = size_t(y * 16 + x);
            bool odd = (x / 4 + y / 4) % 2 != 0;
            uint8_t* c = &checker[i * 4];
            c[0] = odd ? 230 : 60, c[1] = odd ? 200 : 120, c[2] = odd ? 90 : 220;
            c[3] = uint8_t(std::lround((x + 0.5) / 16.0 * 255.0));  // alpha rises left to right
            // Normals tilted +x on the left half, -x on the right, in tangent space.
            uint8_t* n = &bumps[i * 3];
            n[0] = x < 8 ? 200 : 56, n[1] = 128, n[2] = 230;
            uint8_t* m = &metalRough[i * 3];
            m[0] = 0, m[1] = uint8_t(40 + 12 * y), m[2] = odd ? 255 : 0;  // G roughness, B metallic
            uint8_t* o = &occlusion[i * 3];
            o[0] = o[1] = o[2] = uint8_t(64 + 12 * x);
        }
    writePng(dir / "checker_alpha.png", 16, 16, 4, checker);
    writePng(dir / "bumps.png", 16, 16, 3, bumps);
    writePng(dir / "metal_rough.png", 16, 16, 3, metalRough);
    writePng(dir / "occlusion.png", 16, 16, 3, occlusion);

    gltf::File file;
    int checkerTexture = file.texture(file.image("checker_alpha.png"));
    int bumpsTexture = file.texture(file.image("bumps.png"));
    int metalRoughTexture = file.texture(file.image("metal_rough.png"));
    int occlusionTexture = file.texture(file.image("occlusion.png"));
    auto withBase = [&](json pbr) {
        pbr["baseColorTexture"] = {{"index", checkerTexture}};
        return pbr;
    };
    auto withMetalRough = [&](json pbr) {
        pbr["metallicFactor"] = 1.0;
        pbr["metallicRoughnessTexture"] = {{"index", metalRoughTexture}};
        return pbr;
    };
    std::vector<json> materials{
        {{"pbrMetallicRoughness", color(0.8f, 0.3f, 0.2f)}},  // none of the extras
        {{"pbrMetallicRoughness", withBase(color(1, 1, 1))}},
        {{"pbrMetallicRoughness", withBase(color(1, 1, 1))}, {"normalTexture", {{"index", bumpsTexture}}}},
        {{"pbrMetallicRoughness", color(0.7f, 0.7f, 0.7f)},
         {"normalTexture", {{"index", bumpsTexture}, {"scale", 0.5}}}},
        {{"pbrMetallicRoughness", withMetalRough(color(0.9f, 0.8f, 0.5f))}},
        {{"pbrMetallicRoughness", color(0.6f, 0.8f, 0.6f)},
         {"occlusionTexture", {{"index", occlusionTexture}, {"strength", 0.7}}}},
        {{"pbrMetallicRoughness", withBase(color(0.5f, 0.9f, 0.9f))},
         {"alphaMode", "MASK"},
         {"alphaCutoff", 0.4},
         {"doubleSided", true}},
        {{"pbrMetallicRoughness", withMetalRough(withBase(color(1, 1, 1)))},
         {"normalTexture", {{"index", bumpsTexture}, {"scale", 2.0}}},
         {"occlusionTexture", {{"index", occlusionTexture}, {"strength", 0.5}}},
         {"alphaMode", "MASK"},
         {"alphaCutoff", 0.3},
         {"doubleSided", true}},
        {{"pbrMetallicRoughness", color(0.2f, 0.4f, 0.9f)}},  // the first one's class again
        // Double-sided but opaque, and a cut-out that is single-sided: the other two pairings of
        // the alpha test and the culling.
        {{"pbrMetallicRoughness", color(0.9f, 0.6f, 0.3f)},
         {"normalTexture", {{"index", bumpsTexture}}},
         {"doubleSided", true}},
        {{"pbrMetallicRoughness", withBase(color(0.9f, 0.5f, 0.9f))},
         {"alphaMode", "MASK"},
         {"alphaCutoff", 0.6}},
    };
    json roots = json::array();
    for (size_t k = 0; k < materials.size(); ++k) {
        int m = file.material(materials[k]);
        float x = -2.5f + 2.5f * float(k % 3), y = 2.5f - 2.5f * float(k / 3);
        // The double-sided ones turned half away, so their back faces show too.
        json node = {{"mesh", file.mesh(json::array({quadPrimitive(file, m)}))}, {"translation", {x, y, 0}}};
        if (k == 6 || k == 7 || k == 9)
            node["rotation"] = {0, 0.9238795, 0, 0.3826834};  // 135 degrees about y
        roots.push_back(file.node(node));
    }
    // A material no primitive uses, of a class of its own: it must make no pipeline.
    file.material({{"pbrMetallicRoughness", color(0.5f, 0.5f, 0.5f)},
                   {"occlusionTexture", {{"index", occlusionTexture}}},
                   {"doubleSided", true}});
    file.scene(roots);
    file.writeGltf(dir / "features.gltf");

    json lights = json::array(
        {{{"type", "point"}, {"position", {-2, 1, 2}}, {"color", {1, 0.9, 0.8}}, {"intensity", 6.0}},
         {{"type", "directional"}, {"direction", {-0.3, -0.4, -1}}, {"intensity", 1.5}},
         {{"type", "point"}, {"position", {2.5, -1.5, 1.5}}, {"intensity", 4.0}, {"range", 6.0}}});
    json root = {{"models", json::array({{{"file", "features.gltf"}}})},
                 {"camera", {{"position", {0, -1.25, 11.5}}, {"fov", 60}, {"near", 0.5}, {"far", 50}}},
                 {"ambient", {{"color", {1, 1, 1}}, {"intensity", 0.2}}},
                 {"lights", lights}};
    writeText(dir / "features.json", root.dump(2));
}

// ---- Shadows: a box over a plane ------------------------------------------------------------

// An axis-aligned box of faces with outward normals, counter-clockwise seen from outside.
json boxPrimitive(gltf::File& file, int material, vec3 lo, vec3 hi) {
    std::vector<vec3> p, n;
    std::vector<uint16_t> i;
    auto face = [&](vec3 corner, vec3 u, vec3 v) {  // u x v is the outward normal
        uint16_t k = uint16_t(p.size());
        vec3 normal = glm::normalize(glm::cross(u, v));
        for (vec3 q : {corner, corner + u, corner + u + v, corner + v}) {
            p.push_back(q);
            n.push_back(normal);
        }
        i.insert(i.end(), {k, uint16_t(k + 1), uint16_t(k + 2), k, uint16_t(k + 2), uint16_t(k + 3)});
    };
    vec3 d = hi - lo;
    face(lo, {0, d.y, 0}, {d.x, 0, 0});                  // -z
    face({lo.x, lo.y, hi.z}, {d.x, 0, 0}, {0, d.y, 0});  // +z
    face(lo, {0, 0, d.z}, {0, d.y, 0});                  // -x
    face({hi.x, lo.y, lo.z}, {0, d.y, 0}, {0, 0, d.z});  // +x
    face(lo, {d.x, 0, 0}, {0, 0, d.z});                  // -y
    face({lo.x, hi.y, lo.z}, {0, 0, d.z}, {d.x, 0, 0});  // +y
    return {
        {"attributes", {{"POSITION", file.positions(p)}, {"NORMAL", file.values(n, gltf::kFloat, "VEC3")}}},
        {"indices", file.values(i, gltf::kUnsignedShort, "SCALAR")},
        {"material", material}};
}

// A plane of 12 x 12 at y = 0 and a box from (-0.5, 1, -0.5) to (0.5, 2, 0.5) above it, white,
// seen from straight above; a sun travelling along (1, -1, 0.5), no ambient light. Each point of
// the box at height h lands h further along x and h / 2 along z: the shadow on the plane is the
// box's square swept from (0.5..1.5, 0..1) at h = 1 to (1.5..2.5, 0.5..1.5) at h = 2, black, and
// symmetric in neither x nor z; the rest of the plane is lit.
void writeShadows(const fs::path& dir) {
    fs::create_directories(dir);
    gltf::File file;
    int white = file.material({{"pbrMetallicRoughness", color(0.8f, 0.8f, 0.8f)}});
    int plane = file.mesh(json::array({boxPrimitive(file, white, {-6, -0.1f, -6}, {6, 0, 6})}));
    int box = file.mesh(json::array({boxPrimitive(file, white, {-0.5f, 1, -0.5f}, {0.5f, 2, 0.5f})}));
    file.scene({file.node({{"mesh", plane}}), file.node({{"mesh", box}})});
    file.writeGltf(dir / "box_on_plane.gltf");
    // A scene of `model` seen from 10 above (unless `cameraChanges` say otherwise), with `lights`
    // and `ambient` white light.
    auto sceneFile = [&](const char* name, const char* model, json lights, json cameraChanges = {},
                         double ambient = 0.0) {
        json camera = {
            {"position", {0, 10, 0}}, {"yaw", -90}, {"pitch", -89}, {"fov", 60}, {"near", 0.5}, {"far", 50}};
        if (cameraChanges.is_object()) camera.update(cameraChanges);
        json root = {{"models", json::array({{{"file", model}}})},
                     {"camera", camera},
                     {"ambient", {{"color", {1, 1, 1}}, {"intensity", ambient}}},
                     {"lights", lights}};
        writeText(dir / name, root.dump(2));
    };
    auto sun = [](json direction) {
        return json{{"type", "directional"}, {"direction", direction}, {"intensity", 2.0}};
    };
    auto scene = [&](const char* name, json direction, json more = json::array(), json cameraChanges = {}) {
        json lights = json::array({sun(direction)});
        for (json& light : more) lights.push_back(light);
        sceneFile(name, "box_on_plane.gltf", lights, cameraChanges);
    };
    // A point light under the box, over the middle of the sun's shadow: the sun's shadow must not
    // darken it (the book multiplies all the lights by the sun's visibility).
    scene("box_on_plane_point.json", {1, -1, 0.5},
          json::array(
              {{{"type", "point"}, {"position", {1.5, 0.5, 0.75}}, {"intensity", 1.0}, {"range", 3.0}}}));
    scene("box_on_plane.json", {1, -1, 0.5});
    // A cut-out: a 2 x 2 quad 1.5 over the plane, facing up, whose texture's half at z < 0 is
    // transparent (alpha 0, rows 0-3 of an 8 x 8 image: v < 0.5) and the half at z > 0 opaque,
    // under a sun along (1, -1, 0): the opaque half's shadow falls at x 0.5..2.5, z 0..1, beside the
    // quad; the transparent half casts none (z -1..0 of the same strip stays lit).
    {
        gltf::File cut;
        std::vector<uint8_t> halves(8 * 8 * 4, 255);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 8; ++x) halves[size_t((y * 8 + x) * 4 + 3)] = 0;
        writePng(dir / "alpha_halves.png", 8, 8, 4, halves);
        int sampler = cut.add("samplers",
                              {{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}});
        json pbr = color(0.8f, 0.8f, 0.8f);
        pbr["baseColorTexture"] = {{"index", cut.texture(cut.image("alpha_halves.png"), sampler)}};
        int masked =
            cut.material({{"pbrMetallicRoughness", pbr}, {"alphaMode", "MASK"}, {"alphaCutoff", 0.5}});
        int floor = cut.material({{"pbrMetallicRoughness", color(0.8f, 0.8f, 0.8f)}});
        std::vector<vec3> p{{-1, 1.5f, -1}, {-1, 1.5f, 1}, {1, 1.5f, 1}, {1, 1.5f, -1}}, n(4, vec3(0, 1, 0));
        std::vector<glm::vec2> uv{{0, 0}, {0, 1}, {1, 1}, {1, 0}};  // u along x, v along z
        std::vector<uint16_t> i{0, 1, 2, 0, 2, 3};
        json quad = {{"attributes",
                      {{"POSITION", cut.positions(p)},
                       {"NORMAL", cut.values(n, gltf::kFloat, "VEC3")},
                       {"TEXCOORD_0", cut.values(uv, gltf::kFloat, "VEC2")}}},
                     {"indices", cut.values(i, gltf::kUnsignedShort, "SCALAR")},
                     {"material", masked}};
        int ground = cut.mesh(json::array({boxPrimitive(cut, floor, {-6, -0.1f, -6}, {6, 0, 6})}));
        cut.scene({cut.node({{"mesh", ground}}), cut.node({{"mesh", cut.mesh(json::array({quad}))}})});
        cut.writeGltf(dir / "cutout_over_plane.gltf");
        sceneFile("cutout_over_plane.json", "cutout_over_plane.gltf", json::array({sun({1, -1, 0})}));
    }
    // The same seen through extreme splits (near 0.01, far 1000: a scene much smaller than the
    // view), and from under the box looking straight up.
    scene("box_on_plane_far.json", {1, -1, 0.5}, json::array(), {{"near", 0.01}, {"far", 1000}});
    // A slab high over the camera (y 20) covering x -6..-2.5, under a sun straight down: far
    // toward the light from every cascade's box, its shadow is there only if casters beyond the
    // box are kept (depth clamping, or boxes reaching toward the light where a device lacks it).
    {
        gltf::File high;
        int grey = high.material({{"pbrMetallicRoughness", color(0.8f, 0.8f, 0.8f)}});
        int ground = high.mesh(json::array({boxPrimitive(high, grey, {-6, -0.1f, -6}, {6, 0, 6})}));
        int slab = high.mesh(json::array({boxPrimitive(high, grey, {-6, 20, -6}, {-2.5f, 20.1f, 6})}));
        high.scene({high.node({{"mesh", ground}}), high.node({{"mesh", slab}})});
        high.writeGltf(dir / "slab_overhead.gltf");
        sceneFile("slab_overhead.json", "slab_overhead.gltf", json::array({sun({0, -1, 0})}));
    }
    // Peter-panning: a box standing on the plane (y 0..1) under a sun one degree above the horizon,
    // along +x: its shadow must start at its foot, not a gap away (an offset that lifts the
    // receiver toward the light too far would light the plane just behind the box).
    {
        gltf::File standing;
        int grey = standing.material({{"pbrMetallicRoughness", color(0.8f, 0.8f, 0.8f)}});
        int ground = standing.mesh(json::array({boxPrimitive(standing, grey, {-6, -0.1f, -6}, {6, 0, 6})}));
        int block =
            standing.mesh(json::array({boxPrimitive(standing, grey, {-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f})}));
        standing.scene({standing.node({{"mesh", ground}}), standing.node({{"mesh", block}})});
        standing.writeGltf(dir / "box_standing.gltf");
        sceneFile("box_standing_grazing.json", "box_standing.gltf",
                  json::array({sun({std::cos(glm::radians(1.0)), -std::sin(glm::radians(1.0)), 0})}));
    }
    // No sun: a point light over the box alone.
    sceneFile("no_sun.json", "box_on_plane.gltf",
              json::array({{{"type", "point"}, {"position", {2, 3, 1}}, {"intensity", 4.0}}}), {}, 0.1);
    // Looking along the plane (1 over it, 10 degrees down, far 20): which cascade each distance takes.
    scene("cascade_rows.json", {0, -1, 0}, json::array(),
          {{"position", {0, 1, 5.5}}, {"yaw", 0}, {"pitch", -10}, {"far", 20}});
    scene("camera_up.json", {1, -1, 0.5}, json::array(), {{"position", {0.8, 0.5, 0}}, {"pitch", 89}});
    // The hard directions: straight down (the book's default), 5e-4 radians off it (far enough
    // that |dot(light, y)| is not 1 in float, where the book keeps y as its up vector), and
    // grazing, one degree above the horizon.
    scene("sun_down.json", {0, -1, 0});
    scene("sun_down_5e-4.json", {std::sin(5e-4), -std::cos(5e-4), 0});
    scene("sun_grazing.json", {std::cos(glm::radians(1.0)), -std::sin(glm::radians(1.0)), 0});
}

// ---- A degenerate tangent frame --------------------------------------------------------------

// A normal-mapped quad whose normals and tangents are all zero (an exporter's bug, or vectors
// interpolated to nothing), under a normal map whose texel decodes to almost nothing and with
// normalTexture.scale 0: every normalisation in the scene shader meets a zero vector, and its
// fallback must keep NaN out of the image.
void writeDegenerate(const fs::path& dir) {
    fs::create_directories(dir);
    writePng(dir / "flat_normal.png", 1, 1, 4, {128, 128, 128, 255});
    gltf::File file;
    json normalTexture = {{"index", file.texture(file.image("flat_normal.png"))}, {"scale", 0.0}};
    int m = file.material({{"pbrMetallicRoughness", color(0.8f, 0.8f, 0.8f)},
                           {"normalTexture", normalTexture},
                           {"doubleSided", true}});
    Quad q;
    std::vector<vec3> zeros(4, vec3(0));
    std::vector<glm::vec4> zeroTangents(4, glm::vec4(0, 0, 0, 1));
    json attributes = {{"POSITION", file.positions(q.positions)},
                       {"TEXCOORD_0", file.values(q.uvs, gltf::kFloat, "VEC2")},
                       {"NORMAL", file.values(zeros, gltf::kFloat, "VEC3")},
                       {"TANGENT", file.values(zeroTangents, gltf::kFloat, "VEC4")}};
    json primitive = {{"attributes", attributes},
                      {"indices", file.values(q.indices, gltf::kUnsignedShort, "SCALAR")},
                      {"material", m}};
    file.node({{"mesh", file.mesh(json::array({primitive}))}});
    file.scene({0});
    file.writeGltf(dir / "zero_frame.gltf");
}

// ---- Hostile files --------------------------------------------------------------------------

// A valid triangle model's JSON and buffer, for the hostile cases to break.
struct Triangle {
    gltf::File file;
    Triangle() {
        std::vector<vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        std::vector<uint16_t> i{0, 1, 2};
        json prim = {{"attributes", {{"POSITION", file.positions(p)}}},
                     {"indices", file.values(i, gltf::kUnsignedShort, "SCALAR")}};
        file.node({{"mesh", file.mesh(json::array({prim}))}});
        file.scene({0});
    }
};

void writeHostile(const fs::path& dir) {
    fs::create_directories(dir / "inner");
    auto make = [&](const std::string& name, const std::function<void(gltf::File&)>& edit) {
        Triangle t;
        edit(t.file);
        t.file.writeGltf(dir / name);
    };
    writeText(dir / "syntax.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [}");
    writeText(dir / "version1.gltf", "{\"asset\": {\"version\": \"1.0\"}}");
    make("index_past_vertices.gltf", [](gltf::File& f) {
        std::vector<uint16_t> bad{0, 1, 7};
        f.root["meshes"][0]["primitives"][0]["indices"] = f.values(bad, gltf::kUnsignedShort, "SCALAR");
    });
    make("accessor_past_view.gltf", [](gltf::File& f) { f.root["accessors"][0]["count"] = 4; });
    make("view_past_buffer.gltf", [](gltf::File& f) { f.root["bufferViews"][0]["byteLength"] = 4000; });
    make("stride_lies.gltf", [](gltf::File& f) { f.root["bufferViews"][0]["byteStride"] = 8; });
    make("stride_odd.gltf", [](gltf::File& f) { f.root["bufferViews"][0]["byteStride"] = 6; });
    make("cycle.gltf", [](gltf::File& f) {
        f.root["nodes"].push_back({{"children", {2}}});
        f.root["nodes"].push_back({{"children", {1}}});
    });
    make("two_parents.gltf", [](gltf::File& f) {
        f.root["nodes"].push_back({{"children", {0}}});
        f.root["nodes"].push_back({{"children", {0}}});
        f.root["scenes"][0]["nodes"] = {1, 2};
    });
    make("deep.gltf", [](gltf::File& f) {
        for (int k = 1; k <= 2000; ++k) f.root["nodes"].push_back({{"children", {k - 1}}});
        f.root["scenes"][0]["nodes"] = {2000};
    });
    make("missing_bin.gltf", [](gltf::File&) {});
    fs::remove(dir / "missing_bin.bin");
    make("nan_position.gltf", [](gltf::File& f) {
        std::vector<float> p{0, 0, 0, 1, 0, 0, 0, NAN, 0};
        f.root["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = f.values(p, gltf::kFloat, "VEC3");
    });
    make("huge_count.gltf", [](gltf::File& f) {
        // Zeros and one sparse value: nothing in the buffer bounds the count.
        std::vector<uint32_t> index{0};
        std::vector<float> value{1, 2, 3};
        int indices = f.view(index.data(), 4), values = f.view(value.data(), 12);
        f.root["accessors"][0] = {
            {"componentType", gltf::kFloat},
            {"count", 2000000000},
            {"type", "VEC3"},
            {"sparse",
             {{"count", 1},
              {"indices", {{"bufferView", indices}, {"componentType", gltf::kUnsignedInt}}},
              {"values", {{"bufferView", values}}}}}};
    });
    // Edits of what File::writeGltf wrote (its buffers are set there).
    auto edit = [&](const std::string& name, const std::function<void(json&)>& change) {
        make(name, [](gltf::File&) {});
        std::ifstream in(dir / name);
        json root = json::parse(in);
        change(root);
        writeText(dir / name, root.dump());
    };
    // Offsets near 2^64: a sum that wraps would pass a bounds check (the byteOffset below plus
    // 8,388,611 elements of 12 bytes is 36 modulo 2^64) and read 96 MiB before the buffer.
    static constexpr uint64_t kNearTop = 18446744073608888320ull;  // 2^64 - 96 MiB
    make("offset_wrap.gltf", [](gltf::File& f) {
        f.root["accessors"][0]["byteOffset"] = kNearTop;
        f.root["accessors"][0]["count"] = 8388611;
    });
    make("view_offset_wrap.gltf", [](gltf::File& f) { f.root["bufferViews"][0]["byteOffset"] = kNearTop; });
    make("index_offset_wrap.gltf", [](gltf::File& f) { f.root["accessors"][1]["byteOffset"] = kNearTop; });
    // The largest stride with the largest count: 8 GiB of a 36-byte view.
    make("stride_count.gltf", [](gltf::File& f) {
        f.root["bufferViews"][0]["byteStride"] = 252;
        f.root["accessors"][0]["count"] = 33554432;
    });
    // Sparse parts whose offsets wrap.
    auto sparseAt = [](gltf::File& f, uint64_t indicesOffset, uint64_t valuesOffset) {
        std::vector<uint32_t> index{1};
        std::vector<float> value{2, 0, 0};
        int indices = f.view(index.data(), 4), values = f.view(value.data(), 12);
        f.root["accessors"][0]["sparse"] = {
            {"count", 1},
            {"indices",
             {{"bufferView", indices}, {"byteOffset", indicesOffset}, {"componentType", gltf::kUnsignedInt}}},
            {"values", {{"bufferView", values}, {"byteOffset", valuesOffset}}}};
    };
    make("sparse_indices_wrap.gltf", [&](gltf::File& f) { sparseAt(f, kNearTop, 0); });
    make("sparse_values_wrap.gltf", [&](gltf::File& f) { sparseAt(f, 0, 18446744073709551612ull); });
    // An index beyond 32 bits: tinygltf would read 4294967296 as 0, a node that exists.
    make("index_beyond_32_bits.gltf", [](gltf::File& f) {
        f.root["nodes"].push_back({{"children", {4294967296ull}}});
        f.root["scenes"][0]["nodes"] = {1};
    });
    // Node chains at the depth limit (1,024 levels: loads) and one level past it.
    for (int levels : {1024, 1025})
        make("chain_" + std::to_string(levels) + ".gltf", [&](gltf::File& f) {
            for (int k = 1; k < levels; ++k) f.root["nodes"].push_back({{"children", {k - 1}}});
            f.root["scenes"][0]["nodes"] = {levels - 1};
        });
    // Numbers beyond 32 bits where glTF allows them: application data, an extension's own fields
    // (not read as numbers) and an accessor's bounds (read as doubles): loaded.
    make("big_numbers_in_extras.gltf", [](gltf::File& f) {
        f.root["nodes"][0]["extras"] = {{"id", 1099511627776ull}};
        f.root["extensions"] = {{"EXT_example", {{"size", 18446744073709551615ull}}}};
        f.root["extensionsUsed"] = {"EXT_example"};
        f.root["accessors"][1]["min"] = {0};  // an accessor's bounds are read as doubles
        f.root["accessors"][1]["max"] = {4294967295ull};
        f.root["nodes"][0]["translation"] = {3000000000ull, 0, 0};  // so is a translation
    });
    // An extension's name with a line break: its warning is still one line.
    make("newline_extension.gltf", [](gltf::File& f) { f.root["extensionsUsed"] = {"EXT_a\nb"}; });
    // The index budget: 1,000 triangles over 3 vertices with normals (3,000 bytes of indices)
    // under 11,200 nodes: 33,600,000 indices after baking, 33,600 vertices.
    make("index_budget.gltf", [](gltf::File& f) {
        std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, n(3, glm::vec3(0, 0, 1));
        std::vector<uint8_t> corners;
        for (int k = 0; k < 1000; ++k) corners.insert(corners.end(), {0, 1, 2});
        json prim = {
            {"attributes", {{"POSITION", f.positions(p)}, {"NORMAL", f.values(n, gltf::kFloat, "VEC3")}}},
            {"indices", f.values(corners, gltf::kUnsignedByte, "SCALAR")}};
        int mesh = f.mesh(json::array({prim}));
        json roots = json::array();
        for (int k = 0; k < 11200; ++k) roots.push_back(f.node({{"mesh", mesh}}));
        f.root["scenes"][0]["nodes"] = roots;
    });
    // The values budget: POSITION, NORMAL, TANGENT and TEXCOORD_0 of 2^25 sparse zeros each,
    // drawn by 3 indices: 12 x 2^25 values to decode, 2^25 + 3 corner slots, for one triangle.
    make("values_budget.gltf", [](gltf::File& f) {
        std::vector<uint32_t> index{1};
        std::vector<float> value{0, 0, 1, 1};
        int indices = f.view(index.data(), 4), values = f.view(value.data(), 16);
        auto zeros = [&](const char* type) {
            return f.add("accessors",
                         {{"componentType", gltf::kFloat},
                          {"count", 33554432},
                          {"type", type},
                          {"sparse",
                           {{"count", 1},
                            {"indices", {{"bufferView", indices}, {"componentType", gltf::kUnsignedInt}}},
                            {"values", {{"bufferView", values}}}}}});
        };
        json& primitive = f.root["meshes"][0]["primitives"][0];
        primitive["attributes"] = {{"POSITION", zeros("VEC3")},
                                   {"NORMAL", zeros("VEC3")},
                                   {"TANGENT", zeros("VEC4")},
                                   {"TEXCOORD_0", zeros("VEC2")}};
    });
    // Nodes times primitives: 10,000 nodes share a mesh of 11 primitives, 110,000 draws (past the
    // 100,000 a model may make), refused before any is visited.
    make("primitive_product.gltf", [](gltf::File& f) {
        json prim = f.root["meshes"][0]["primitives"][0];
        json primitives = json::array();
        for (int k = 0; k < 11; ++k) primitives.push_back(prim);
        f.root["meshes"][0]["primitives"] = primitives;
        json roots = json::array();
        for (int k = 0; k < 10000; ++k) roots.push_back(f.node({{"mesh", 0}}));
        f.root["scenes"][0]["nodes"] = roots;
    });
    // A Radiance HDR image inside the model (stb_image's HDR reader loops forever on a truncated
    // run, CVE-2021-42715): refused by its magic bytes before any decoder runs.
    make("hdr_image.gltf", [](gltf::File& f) {
        const std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n\x02\x02\x00\x08";
        json pbr = {
            {"baseColorTexture",
             {{"index", f.texture(f.image("data:image/png;base64," +
                                          gltf::base64(std::vector<uint8_t>(hdr.begin(), hdr.end()))))}}}};
        f.root["meshes"][0]["primitives"][0]["material"] = f.material({{"pbrMetallicRoughness", pbr}});
    });
    // Index fields that tinygltf would read as absent: a fraction, a negative index.
    make("mode_fraction.gltf", [](gltf::File& f) { f.root["meshes"][0]["primitives"][0]["mode"] = 1.0; });
    make("negative_mesh.gltf", [](gltf::File& f) { f.root["nodes"][0]["mesh"] = -5; });
    // A scene that lists its root twice (its subtree would be walked, and drawn, twice).
    make("root_twice.gltf", [](gltf::File& f) { f.root["scenes"][0]["nodes"] = {0, 0}; });
    // A scale whose vertices are finite floats but whose extent is not.
    make("huge_scale.gltf", [](gltf::File& f) { f.root["nodes"][0]["scale"] = {3e38, 3e38, 3e38}; });
    // "data:" that is not a data: URI tinygltf decodes is a path to it: refused as one.
    make("data_folder_uri.gltf", [](gltf::File& f) { f.image("data:/../outside.png"); });
    // Legal: a WebP image (EXT_texture_webp, used but not required) with the PNG fallback the
    // extension asks for as the texture's source; the WebP image is never decoded.
    writePng(dir / "fallback.png", 1, 1, 4, {255, 255, 255, 255});
    make("webp_fallback.gltf", [](gltf::File& f) {
        int png = f.image("fallback.png");
        int webp = f.image("data:image/webp;base64,UklGRgAAAABXRUJQ");
        f.root["extensionsUsed"] = {"EXT_texture_webp"};
        int texture =
            f.add("textures", {{"source", png}, {"extensions", {{"EXT_texture_webp", {{"source", webp}}}}}});
        json pbr = {{"baseColorTexture", {{"index", texture}}}};
        f.root["meshes"][0]["primitives"][0]["material"] = f.material({{"pbrMetallicRoughness", pbr}});
    });
    // A missing image whose name holds a line break: its warning stays one line.
    make("missing_newline.gltf", [](gltf::File& f) {
        json pbr = {{"baseColorTexture", {{"index", f.texture(f.image("missing%0Aline.png"))}}}};
        f.root["meshes"][0]["primitives"][0]["material"] = f.material({{"pbrMetallicRoughness", pbr}});
    });
    // The same under a key with a line break: the message shows it as '?', on one line.
    make("newline_key.gltf",
         [](gltf::File& f) { f.root["meshes"][0]["primitives"][0]["attributes"]["a\nb"] = 4294967296ull; });
    // Work from a small file: 10,000 nodes share one mesh whose POSITION is 2^25 zeros and one
    // sparse value (no buffer view), drawn without indices: 2^25 vertices per node.
    auto sharedSparse = [](gltf::File& f, int nodes, bool fewIndices, uint64_t count = 33554432) {
        std::vector<uint32_t> index{1};
        std::vector<float> value{1, 0, 0};
        int indices = f.view(index.data(), 4), values = f.view(value.data(), 12);
        int positions = f.add(
            "accessors", {{"componentType", gltf::kFloat},
                          {"count", count},
                          {"type", "VEC3"},
                          {"sparse",
                           {{"count", 1},
                            {"indices", {{"bufferView", indices}, {"componentType", gltf::kUnsignedInt}}},
                            {"values", {{"bufferView", values}}}}}});
        std::vector<uint32_t> corners{0, 1, 2};
        json prim = {{"attributes", {{"POSITION", positions}}}};
        if (fewIndices) prim["indices"] = f.values(corners, gltf::kUnsignedInt, "SCALAR");
        int mesh = f.mesh(json::array({prim}));
        json roots = json::array();
        for (int k = 0; k < nodes; ++k) roots.push_back(f.node({{"mesh", mesh}, {"translation", {0, 0, k}}}));
        f.root["scenes"][0]["nodes"] = roots;
    };
    make("shared_sparse.gltf", [&](gltf::File& f) { sharedSparse(f, 10000, false); });
    // The same accessor (of 2^24 vertices) under 1,000 nodes, drawn by 3 indices: legal and within
    // the budget, it is decoded once (not 1,000 times) and draws 1,000 triangles.
    make("shared_sparse_indexed.gltf", [&](gltf::File& f) { sharedSparse(f, 1000, true, 16777216); });
    // A strip of 2^25 vertices (zeros and one sparse value: no bytes) without normals: flat
    // shading would bake 3 vertices for each of its 2^25 - 2 triangles, 100 M vertices.
    auto sparsePositions = [](gltf::File& f, uint64_t count, int mode) {
        std::vector<uint32_t> index{1};
        std::vector<float> value{1, 0, 0};
        int indices = f.view(index.data(), 4), values = f.view(value.data(), 12);
        json& primitive = f.root["meshes"][0]["primitives"][0];
        primitive["attributes"]["POSITION"] = f.add(
            "accessors", {{"componentType", gltf::kFloat},
                          {"count", count},
                          {"type", "VEC3"},
                          {"sparse",
                           {{"count", 1},
                            {"indices", {{"bufferView", indices}, {"componentType", gltf::kUnsignedInt}}},
                            {"values", {{"bufferView", values}}}}}});
        primitive.erase("indices");
        primitive["mode"] = mode;
    };
    make("strip_flat.gltf", [&](gltf::File& f) { sparsePositions(f, 33554432, gltf::kTriangleStrip); });
    // One triangle more than the vertex budget: 5,592,406 flat triangles bake 16,777,218 vertices.
    make("budget_plus_one.gltf", [&](gltf::File& f) { sparsePositions(f, 3 * 2796203, gltf::kTriangles); });
    // One triangle less: the largest flat-shaded model the budget admits (its peak memory is
    // tests/reliability/extremes.cmake's).
    make("budget_inside.gltf", [&](gltf::File& f) { sparsePositions(f, 3 * 2796202, gltf::kTriangles); });
    // Accessor counts at the limit and one past it (an accessor no mesh uses is checked too).
    for (uint64_t count : {33554432ull, 33554433ull})
        make("count_" + std::to_string(count) + ".gltf", [&](gltf::File& f) {
            f.add("accessors", {{"componentType", gltf::kFloat}, {"count", count}, {"type", "SCALAR"}});
        });
    // 300,000 nested arrays in an extras field, 600 KB: tinygltf's recursive copy of the JSON
    // would overflow the stack.
    make("deep_extras.gltf", [](gltf::File&) {});
    {
        std::ifstream in(dir / "deep_extras.gltf");
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        text.insert(text.rfind('}'), ",\"extras\":" + std::string(300000, '[') + std::string(300000, ']'));
        writeText(dir / "deep_extras.gltf", text);
    }
    // Brackets inside strings are not nesting: a name of 100,000 '[' loads.
    make("brackets_in_string.gltf",
         [](gltf::File& f) { f.root["nodes"][0]["name"] = std::string(100000, '['); });
    // data: URIs whose bytes disagree with the buffer's byteLength (both ways).
    for (auto [name, length] :
         {std::pair{"data_uri_short.gltf", 2147483647ull}, std::pair{"data_uri_long.gltf", 4ull}})
        edit(name, [&](json& root) {
            root["buffers"][0]["uri"] = "data:application/octet-stream;base64,AAAAAAAAgD8AAAAAAAAAAAAAAAA=";
            root["buffers"][0]["byteLength"] = length;
        });
    edit("huge_buffer.gltf", [](json& root) { root["buffers"][0]["byteLength"] = 1000000000000000000ull; });
    make("absolute_uri.gltf", [](gltf::File& f) { f.image("/etc/passwd"); });
    make("scheme_uri.gltf", [](gltf::File& f) { f.image("https://example.com/texture.png"); });
    make("climbing_uri.gltf", [](gltf::File& f) { f.image("textures/../../secret.png"); });
    make("draco.gltf", [](gltf::File& f) {
        f.root["extensionsUsed"] = {"KHR_draco_mesh_compression"};
        f.root["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    });
    make("meshopt.gltf", [](gltf::File& f) { f.root["extensionsRequired"] = {"EXT_meshopt_compression"}; });
    make("lines_only.gltf",
         [](gltf::File& f) { f.root["meshes"][0]["primitives"][0]["mode"] = gltf::kLines; });
    make("blend.gltf", [](gltf::File& f) {
        f.root["meshes"][0]["primitives"][0]["material"] = f.material({{"alphaMode", "BLEND"}});
    });
    // What is not drawn: one warning each.
    make("emissive.gltf", [](gltf::File& f) {
        f.root["meshes"][0]["primitives"][0]["material"] = f.material({{"emissiveFactor", {1, 0.5, 0}}});
    });
    make("vertex_colors.gltf", [](gltf::File& f) {
        std::vector<glm::vec4> colors(3, glm::vec4(1, 0, 0, 1));
        f.root["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
            f.values(colors, gltf::kFloat, "VEC4");
    });
    make("skin.gltf", [](gltf::File& f) {
        f.root["skins"] = json::array({{{"joints", {0}}}});
        f.root["nodes"][0]["skin"] = 0;
    });
    make("morph_targets.gltf", [](gltf::File& f) {
        std::vector<vec3> offsets(3, vec3(0, 0, 0.5f));
        f.root["meshes"][0]["primitives"][0]["targets"] = json::array({{{"POSITION", f.positions(offsets)}}});
        f.root["meshes"][0]["weights"] = {1.0};
    });
    make("camera.gltf", [](gltf::File& f) {
        f.root["cameras"] =
            json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}}});
    });
    make("animation.gltf", [](gltf::File& f) {
        std::vector<float> times{0.0f, 1.0f};
        std::vector<vec3> moves{vec3(0), vec3(1, 0, 0)};
        int input = f.values(times, gltf::kFloat, "SCALAR");
        f.root["accessors"][input]["min"] = {0.0};
        f.root["accessors"][input]["max"] = {1.0};
        int output = f.values(moves, gltf::kFloat, "VEC3");
        f.root["animations"] = json::array(
            {{{"channels",
               json::array({{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}})},
              {"samplers", json::array({{{"input", input}, {"output", output}}})}}});
    });
    writePng(dir / "white.png", 1, 1, 4, {255, 255, 255, 255});
    make("second_uv_set.gltf", [](gltf::File& f) {
        std::vector<glm::vec2> uv(3, glm::vec2(0.5f));
        f.root["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = f.values(uv, gltf::kFloat, "VEC2");
        f.root["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = f.values(uv, gltf::kFloat, "VEC2");
        json info = {{"index", f.texture(f.image("white.png"))}, {"texCoord", 1}};
        f.root["meshes"][0]["primitives"][0]["material"] =
            f.material({{"pbrMetallicRoughness", {{"baseColorTexture", info}}}});
    });
    make("texture_transform.gltf", [](gltf::File& f) {
        f.root["extensionsUsed"] = {"KHR_texture_transform"};
        json info = {{"index", f.texture(f.image("white.png"))},
                     {"extensions", {{"KHR_texture_transform", {{"scale", {2, 2}}}}}}};
        f.root["meshes"][0]["primitives"][0]["material"] =
            f.material({{"pbrMetallicRoughness", {{"baseColorTexture", info}}}});
    });
    make("missing_image.gltf", [](gltf::File& f) {
        json pbr = {{"baseColorTexture", {{"index", f.texture(f.image("no_such_image.png"))}}}};
        f.root["meshes"][0]["primitives"][0]["material"] = f.material({{"pbrMetallicRoughness", pbr}});
    });
    // A URI with the shell's syntax: read as a file name, never expanded (tinygltf's own file
    // callbacks ran it through wordexp before tinygltf 2.6).
    edit("shell_uri.gltf",
         [](json& root) { root["buffers"][0]["uri"] = "$(touch shell_was_run)`touch shell_was_run`.bin"; });
    // GLB: one whose header claims more bytes than the file has (cut short), and one whose JSON
    // chunk claims more than there is.
    Triangle t;
    t.file.writeGlb(dir / "good.glb", dir);
    std::vector<uint8_t> glb = gltf::readBytes(dir / "good.glb");
    gltf::writeBytes(dir / "truncated.glb", glb.data(), glb.size() - 8);
    std::vector<uint8_t> lying = glb;
    lying[12] = 0xff, lying[13] = 0xff, lying[14] = 0x00;
    gltf::writeBytes(dir / "lying_chunk.glb", lying.data(), lying.size());
    // A BIN chunk that claims 4 GiB, and a GLB whose JSON nests 300,000 deep.
    std::vector<uint8_t> bin = glb;
    uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, glb.data() + 12, 4);
    std::memset(bin.data() + 20 + jsonLength, 0xff, 4);
    gltf::writeBytes(dir / "lying_bin_chunk.glb", bin.data(), bin.size());
    std::string nested = "{\"asset\":{\"version\":\"2.0\"},\"extras\":" + std::string(300000, '[') +
                         std::string(300000, ']') + "}";
    std::vector<uint8_t> deep(20 + nested.size());
    auto put32 = [&](size_t at, uint32_t v) { std::memcpy(deep.data() + at, &v, 4); };
    std::memcpy(deep.data(), "glTF", 4);
    put32(4, 2);
    put32(8, uint32_t(deep.size()));
    put32(12, uint32_t(nested.size()));
    std::memcpy(deep.data() + 16, "JSON", 4);
    std::memcpy(deep.data() + 20, nested.data(), nested.size());
    gltf::writeBytes(dir / "deep.glb", deep.data(), deep.size());
    fs::remove(dir / "good.glb");
}

// ---- A stand-in for the book's clone (--book-scene) -----------------------------------------

// The book's converted model format (common/model/book_model.hpp): 14 big-endian floats a vertex,
// big-endian 32-bit indices, a JSON of byte ranges and one of materials.
struct BookMesh {
    std::vector<float> vertices;  // 14 a vertex
    std::vector<uint32_t> indices;
    std::string material;
};

void bookQuad(BookMesh& mesh, vec3 corner, vec3 u, vec3 v, glm::vec2 uvScale) {
    vec3 n = glm::normalize(glm::cross(u, v)), t = glm::normalize(u), b = glm::normalize(v);
    uint32_t first = uint32_t(mesh.vertices.size() / 14);
    const glm::vec2 corners[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (glm::vec2 c : corners) {
        vec3 p = corner + u * c.x + v * c.y;
        for (float f :
             {p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y, t.z, b.x, b.y, b.z, c.x * uvScale.x, c.y * uvScale.y})
            mesh.vertices.push_back(f);
    }
    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
}

// The stand-in for the book's chapter-16 tree, in its units (the book scales it by 0.005): a trunk
// 100 x 1000 x 100 and a flat crown 800 x 800 at height 900 whose leaf texture is a checker of
// opaque and transparent squares (the shadow it casts is that checker).
std::pair<BookMesh, BookMesh> bookTreeMeshes() {
    BookMesh trunk{.material = "tree-mat-1"}, crown{.material = "tree-mat-2"};
    const float h = 50, top = 1000;
    bookQuad(trunk, {-h, 0, h}, {2 * h, 0, 0}, {0, top, 0}, {1, 1});       // +z face
    bookQuad(trunk, {h, 0, -h}, {-2 * h, 0, 0}, {0, top, 0}, {1, 1});      // -z
    bookQuad(trunk, {h, 0, h}, {0, 0, -2 * h}, {0, top, 0}, {1, 1});       // +x
    bookQuad(trunk, {-h, 0, -h}, {0, 0, 2 * h}, {0, top, 0}, {1, 1});      // -x
    bookQuad(crown, {-400, 900, 400}, {800, 0, 0}, {0, 0, -800}, {1, 1});  // facing up
    return {trunk, crown};
}

// DIR/trunk.png and leaf.png: the tree's textures, 8 x 8 texels.
void writeBookTreeTextures(const fs::path& dir) {
    std::vector<uint8_t> bark(8 * 8 * 3), leaf(8 * 8 * 4);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            uint8_t* b = &bark[size_t(y * 8 + x) * 3];
            b[0] = 110, b[1] = 80, b[2] = 50;
            uint8_t* l = &leaf[size_t(y * 8 + x) * 4];
            l[0] = 60, l[1] = 150, l[2] = 50;
            l[3] = ((x / 2 + y / 2) % 2) ? 255 : 0;  // 2 x 2 texel squares, every other one transparent
        }
    writePng(dir / "trunk.png", 8, 8, 3, bark);
    writePng(dir / "leaf.png", 8, 8, 4, leaf);
}

// DIR/tree.json, tree.vtx, tree.idx, tree_mat.json and the textures: the tree in the book's
// converted format, as its chapter-16 Main.java loads it.
void writeBookTree(const fs::path& dir) {
    fs::create_directories(dir);
    auto [trunk, crown] = bookTreeMeshes();
    std::vector<uint8_t> vtx, idx;
    auto put = [](std::vector<uint8_t>& out, uint32_t bits) {
        for (int shift : {24, 16, 8, 0}) out.push_back(uint8_t(bits >> shift));
    };
    json meshes = json::array();
    for (const BookMesh* mesh : {&trunk, &crown}) {
        size_t vtxStart = vtx.size(), idxStart = idx.size();
        for (float f : mesh->vertices) {
            uint32_t bits;
            std::memcpy(&bits, &f, sizeof(bits));
            put(vtx, bits);
        }
        for (uint32_t i : mesh->indices) put(idx, i);
        meshes.push_back({{"id", mesh->material == "tree-mat-1" ? "trunk_0" : "leaf_1"},
                          {"material_id", mesh->material},
                          {"offset_vtx", vtxStart},
                          {"vtx_size", vtx.size() - vtxStart},
                          {"offset_idx", idxStart},
                          {"idx_size", idx.size() - idxStart}});
    }
    writeText(dir / "tree.vtx", std::string(vtx.begin(), vtx.end()));
    writeText(dir / "tree.idx", std::string(idx.begin(), idx.end()));
    writeText(dir / "tree.json", json({{"id", "tree"},
                                       {"meshes", meshes},
                                       {"vtx_path", "resources/models/tree/tree.vtx"},
                                       {"idx_path", "resources/models/tree/tree.idx"}})
                                     .dump(2));
    auto material = [](const char* id, const char* texture) {
        return json{{"id", id},
                    {"texture_path", texture},
                    {"normal_map_path", ""},
                    {"metal_rough_map", ""},
                    {"diffuse_color", {{"x", 1.0}, {"y", 1.0}, {"z", 1.0}, {"w", 1.0}}},
                    {"roughness_factor", 1.0},
                    {"metallic_factor", 0.0}};
    };
    writeText(dir / "tree_mat.json",
              json::array({material("tree-mat-1", "resources\\models\\tree\\trunk.png"),
                           material("tree-mat-2", "resources\\models\\tree\\leaf.png")})
                  .dump(2));
    writeBookTreeTextures(dir);
}

// DIR/tree.obj, tree.mtl and the textures: the same tree as the OBJ the book's clone keeps beside
// its converted files (booksamples/chapter-16/resources/models/tree/tree.obj), for a clone whose
// converted files are missing.
void writeBookTreeObj(const fs::path& dir) {
    fs::create_directories(dir);
    auto [trunk, crown] = bookTreeMeshes();
    std::string obj = "mtllib tree.mtl\n";
    uint32_t base = 1;
    for (const BookMesh* mesh : {&trunk, &crown}) {
        size_t count = mesh->vertices.size() / 14;
        for (size_t k = 0; k < count; ++k) {
            const float* v = &mesh->vertices[k * 14];
            obj +=
                "v " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
            obj +=
                "vn " + std::to_string(v[3]) + " " + std::to_string(v[4]) + " " + std::to_string(v[5]) + "\n";
            // The converted format keeps v top-down (its generator wrote 1 - v); OBJ counts it up.
            obj += "vt " + std::to_string(v[12]) + " " + std::to_string(1.0f - v[13]) + "\n";
        }
        obj += std::string("usemtl ") + (mesh == &trunk ? "trunk" : "leaf") + "\n";
        for (size_t i = 0; i + 2 < mesh->indices.size(); i += 3) {
            obj += "f";
            for (int c = 0; c < 3; ++c) {
                std::string n = std::to_string(base + mesh->indices[i + size_t(c)]);
                obj += " " + n + "/" + n + "/" + n;
            }
            obj += "\n";
        }
        base += uint32_t(count);
    }
    writeText(dir / "tree.obj", obj);
    writeText(dir / "tree.mtl",
              "newmtl trunk\nKd 1 1 1\nmap_Kd trunk.png\n\nnewmtl leaf\nKd 1 1 1\nmap_Kd leaf.png\n");
    writeBookTreeTextures(dir);
}

// DIR/booksamples/chapter-15/resources/models/sponza/Sponza.gltf, where the book keeps Sponza: a
// floor and four walls of Sponza's extent (x -15..14, y -1..11.5, z -9.5..9), under one node
// scaled 0.008 like the real file's, each face its own grey, so that the book's camera (at
// (0, 5, 0), looking along +x and down) and lights show in one picture.
// tree: the chapter-16 tree in the converted format, as OBJ only, or none.
enum class BookTree { Converted, Obj, None };
// The book's converted format with its chapter-17 animation (a stand-in for its Bob), written by the
// rules of the book's ModelGenerator rather than by its field names' reading: a bending arm as
// figures.hpp makes it, in 14-float big-endian vertices, textured, with the (0, 0, 0, 1) diffuse
// colour the generator writes beside a texture; "frame_millis" the clip's length in seconds
// (Assimp's duration over its ticks a second: 24 key frames at 24 a second span 23/24 s); a prop
// no bone touches (weights 0, 0, 0, 0, as the generator writes them); and the arm's vertex ranges
// named again by a third mesh with weights of its own (every vertex on the elbow's bone: the arm
// swung whole about the elbow), in a second texture. "anim_meshes": 4 weights and bone ids a
// vertex; "animations": joint matrices by JOML's m00..m33 fields. `edit` breaks it for the
// hostile cases; `scale` sizes it.
void writeBookModel(const fs::path& dir, const std::string& name, const std::vector<float>& vertices,
                    const std::vector<uint32_t>& indices, json meshes, json materials);
json bookMaterial(const std::string& id, const std::string& texture);

void writeBookFigure(const fs::path& dir, const std::string& name,
                     const std::function<void(json&)>& edit = nullptr, float scale = 1.0f) {
    figures::SkinnedMesh arm, prop;
    arm.tube(0.0f, 2.0f, 0.15f, 16, 12,
             [](float x, glm::u16vec4& j, glm::vec4& w) { figures::blend(x, 0.8f, 1.2f, 0, 1, j, w); });
    prop.box({0.0f, -0.45f, 0.0f}, {0.15f, 0.15f, 0.15f}, 0);
    std::vector<float> vertices;
    std::vector<uint32_t> indices = arm.indices;
    auto putVertices = [&](const figures::SkinnedMesh& mesh) {
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            vec3 n = mesh.normals[v],
                 t = glm::normalize(glm::cross(std::abs(n.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0), n)),
                 b = glm::cross(n, t);
            for (vec3 x : {mesh.positions[v] * scale, n, t, b})
                vertices.insert(vertices.end(), {x.x, x.y, x.z});
            vec2 uv = v < mesh.uvs.size() ? mesh.uvs[v] : vec2(0.5f);
            vertices.insert(vertices.end(), {uv.x, uv.y});
        }
    };
    putVertices(arm);
    putVertices(prop);
    indices.insert(indices.end(), prop.indices.begin(), prop.indices.end());
    json armWeights = json::array(), armIds = json::array(), swungWeights = json::array(),
         swungIds = json::array(), propWeights = json::array(), propIds = json::array();
    for (size_t v = 0; v < arm.positions.size(); ++v)
        for (int k = 0; k < 4; ++k) {
            armWeights.push_back(arm.weights[v][k]);
            armIds.push_back(arm.joints[v][k]);
            swungWeights.push_back(k == 0 ? 1.0 : 0.0);
            swungIds.push_back(k == 0 ? 1 : 0);
        }
    for (size_t v = 0; v < prop.positions.size(); ++v)
        for (int k = 0; k < 4; ++k) {
            propWeights.push_back(0.0);  // no bone: the generator's weights for such a vertex
            propIds.push_back(0);
        }
    auto matrix = [](const glm::mat4& m) {
        json out = {{"properties", 0}};
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                const char key[4] = {'m', char('0' + c), char('0' + r), '\0'};
                out[key] = m[c][r];
            }
        return out;
    };
    json frames = json::array();
    for (int f = 0; f < 24; ++f) {
        float degrees = 90.0f * std::sin(6.2831853f * float(f) / 24.0f);
        glm::mat4 elbow = glm::translate(glm::mat4(1), vec3(scale, 0, 0)) *
                          glm::mat4_cast(figures::axisAngle({0, 0, 1}, degrees)) *
                          glm::translate(glm::mat4(1), vec3(-scale, 0, 0));
        frames.push_back({{"joint_matrices", {matrix(glm::mat4(1)), matrix(elbow)}}});
    }
    const size_t armVertexBytes = arm.positions.size() * 14 * 4, armIndexBytes = arm.indices.size() * 4;
    json meshes = json::array({{{"id", "arm"},
                                {"material_id", "skin"},
                                {"offset_vtx", 0},
                                {"vtx_size", armVertexBytes},
                                {"offset_idx", 0},
                                {"idx_size", armIndexBytes}},
                               {{"id", "prop"},
                                {"material_id", "prop"},
                                {"offset_vtx", armVertexBytes},
                                {"vtx_size", prop.positions.size() * 14 * 4},
                                {"offset_idx", armIndexBytes},
                                {"idx_size", prop.indices.size() * 4}},
                               {{"id", "arm swung"},
                                {"material_id", "skin2"},
                                {"offset_vtx", 0},
                                {"vtx_size", armVertexBytes},
                                {"offset_idx", 0},
                                {"idx_size", armIndexBytes}}});
    // The generator's materials: a textured one has the diffuse colour (0, 0, 0, 1).
    json skin = bookMaterial("skin", "arm.png"), skin2 = bookMaterial("skin2", "arm2.png"),
         propMaterial = bookMaterial("prop", "");
    for (json* m : {&skin, &skin2}) (*m)["diffuse_color"] = {{"x", 0.0}, {"y", 0.0}, {"z", 0.0}, {"w", 1.0}};
    propMaterial["diffuse_color"] = {{"x", 0.9}, {"y", 0.8}, {"z", 0.2}, {"w", 1.0}};
    writeBookModel(dir, name, vertices, indices, meshes, json::array({skin, propMaterial, skin2}));
    // Stripes along the arm (u runs along it): orange and white; blue and white.
    std::vector<uint8_t> stripes(8 * 8 * 3), stripes2(8 * 8 * 3);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            bool light = (x / 2) % 2 == 0;
            uint8_t* a = &stripes[size_t(y * 8 + x) * 3];
            uint8_t* b = &stripes2[size_t(y * 8 + x) * 3];
            a[0] = light ? 240 : 230, a[1] = light ? 240 : 120, a[2] = light ? 240 : 30;
            b[0] = light ? 240 : 40, b[1] = light ? 240 : 90, b[2] = light ? 240 : 220;
        }
    writePng(dir / "arm.png", 8, 8, 3, stripes);
    writePng(dir / "arm2.png", 8, 8, 3, stripes2);
    json root = json::parse(readBytesText(dir / (name + ".json")));
    root["anim_meshes"] = json::array({{{"weights", armWeights}, {"bone_ids", armIds}},
                                       {{"weights", propWeights}, {"bone_ids", propIds}},
                                       {{"weights", swungWeights}, {"bone_ids", swungIds}}});
    root["animations"] = json::array({{{"name", "bend"}, {"frame_millis", 23.0 / 24.0}, {"frames", frames}}});
    if (edit) edit(root);
    writeText(dir / (name + ".json"), root.dump());
}

void writeBookClone(const fs::path& dir, BookTree tree = BookTree::Converted) {
    fs::path models = dir / "booksamples" / "chapter-15" / "resources" / "models" / "sponza";
    fs::create_directories(models);
    gltf::File file;
    json primitives = json::array();
    // corner, u, v: the face spans corner + s u + t v; u x v is its front (inward) normal.
    struct Face {
        vec3 corner, u, v;
        float grey;
    };
    const Face faces[] = {
        {{-15, -1, 9}, {29, 0, 0}, {0, 0, -18.5f}, 0.8f},       // floor, up
        {{14, -1, -9.5f}, {0, 0, 18.5f}, {0, 12.5f, 0}, 0.6f},  // wall at +x, facing -x
        {{-15, -1, -9.5f}, {29, 0, 0}, {0, 12.5f, 0}, 0.5f},    // wall at -z, facing +z
        {{14, -1, 9}, {-29, 0, 0}, {0, 12.5f, 0}, 0.4f},        // wall at +z, facing -z
        {{-15, -1, 9}, {0, 0, -18.5f}, {0, 12.5f, 0}, 0.7f},    // wall at -x, facing +x
    };
    for (const Face& f : faces) {
        vec3 n = glm::normalize(glm::cross(f.u, f.v));
        // A grid of 8 x 8 quads, so that the point light's falloff is sampled across the face.
        std::vector<vec3> p, normals;
        std::vector<uint16_t> i;
        const int grid = 8;
        for (int b = 0; b <= grid; ++b)
            for (int a = 0; a <= grid; ++a) {
                p.push_back((f.corner + f.u * (float(a) / grid) + f.v * (float(b) / grid)) / 0.008f);
                normals.push_back(n);
            }
        for (int b = 0; b < grid; ++b)
            for (int a = 0; a < grid; ++a) {
                uint16_t k = uint16_t(b * (grid + 1) + a);
                i.insert(i.end(), {k, uint16_t(k + 1), uint16_t(k + grid + 2), k, uint16_t(k + grid + 2),
                                   uint16_t(k + grid + 1)});
            }
        int m = file.material({{"pbrMetallicRoughness", color(f.grey, f.grey, f.grey)}});
        primitives.push_back(
            {{"attributes",
              {{"POSITION", file.positions(p)}, {"NORMAL", file.values(normals, gltf::kFloat, "VEC3")}}},
             {"indices", file.values(i, gltf::kUnsignedShort, "SCALAR")},
             {"material", m}});
    }
    file.node({{"mesh", file.mesh(primitives)}, {"scale", {0.008, 0.008, 0.008}}});
    file.scene({0});
    file.writeGltf(models / "Sponza.gltf");
    fs::path treeDir = dir / "booksamples" / "chapter-16" / "resources" / "models" / "tree";
    if (tree == BookTree::Converted) writeBookTree(treeDir);
    if (tree == BookTree::Obj) writeBookTreeObj(treeDir);
    // chapter-17's Bob: a stand-in in his place (the book's converted boblamp.json).
    // Bob is about 60 units tall, drawn at 0.04: the stand-in's arm 80 long. (Not in the clone
    // that holds chapter 15's sample alone.)
    if (tree != BookTree::None)
        writeBookFigure(dir / "booksamples" / "chapter-17" / "resources" / "models" / "bob", "boblamp",
                        nullptr, 40.0f);
}

// The book's converted format broken one rule at a time (DIR/NAME/tree.json, with the stand-in
// tree's other files): each must be refused in one line naming the file and the rule.
void writeBookModelHostile(const fs::path& dir) {
    auto variant = [&](const char* name, const std::function<void(json&, json&)>& change) {
        fs::path out = dir / name;
        writeBookTree(out);
        json model = json::parse(std::ifstream(out / "tree.json"));
        json materials = json::parse(std::ifstream(out / "tree_mat.json"));
        change(model, materials);
        writeText(out / "tree.json", model.dump(2));
        writeText(out / "tree_mat.json", materials.dump(2));
    };
    variant("vertices_past_end", [](json& m, json&) { m["meshes"][1]["vtx_size"] = 56 * 1000; });
    variant("offset_wraps", [](json& m, json&) { m["meshes"][0]["offset_vtx"] = UINT64_MAX - 10; });
    variant("partial_vertex", [](json& m, json&) { m["meshes"][0]["vtx_size"] = 55; });
    variant("partial_triangle", [](json& m, json&) { m["meshes"][0]["idx_size"] = 8; });
    variant("unknown_material", [](json& m, json&) { m["meshes"][0]["material_id"] = "no-such-material"; });
    variant("size_not_a_number", [](json& m, json&) { m["meshes"][0]["vtx_size"] = "many"; });
    variant("no_meshes", [](json& m, json&) { m["meshes"] = json::array(); });
    variant("color_out_of_range", [](json&, json& mat) { mat[0]["diffuse_color"]["x"] = 1e30; });
    variant("materials_not_a_list", [](json&, json& mat) { mat = json::object(); });
    variant("material_id_twice", [](json&, json& mat) { mat[1]["id"] = "tree-mat-1"; });
    variant("texture_names_no_file",
            [](json&, json& mat) { mat[0]["texture_path"] = "resources\\models\\.."; });
    variant("too_many_meshes", [](json& m, json&) {
        json one = m["meshes"][0];
        m["meshes"] = json::array();
        for (int i = 0; i < 20001; ++i) m["meshes"].push_back(one);
    });
    // Accepted: backslashes in the binaries' paths (a model converted on Windows), and a mesh
    // without a material id (the default material).
    variant("windows_paths", [](json& m, json&) {
        m["vtx_path"] = "resources\\models\\tree\\tree.vtx";
        m["idx_path"] = "resources\\models\\tree\\tree.idx";
        m["meshes"][1]["material_id"] = "";
    });
    {  // a NaN among the vertices
        fs::path out = dir / "vertex_nan";
        writeBookTree(out);
        std::ifstream in(out / "tree.vtx", std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        in.close();
        const char nan[4] = {'\x7f', '\xc0', 0, 0};  // big-endian quiet NaN
        bytes.replace(56 * 2 + 4, 4, nan, 4);        // vertex 2's y
        writeText(out / "tree.vtx", bytes);
    }
    // A small file asking for much work: 20,000 meshes each naming the same 900 vertices (50 KB of
    // them) make 18 million vertices, more than the 2^24 our limit allows -- refused before any is
    // decoded.
    {
        fs::path out = dir / "ranges_repeated";
        writeBookTree(out);
        writeText(out / "tree.vtx", std::string(900 * 56, '\0'));
        writeText(out / "tree.idx", std::string(12, '\0'));
        json meshes = json::array();
        for (int i = 0; i < 20000; ++i)
            meshes.push_back({{"material_id", "tree-mat-1"},
                              {"offset_vtx", 0},
                              {"vtx_size", 900 * 56},
                              {"offset_idx", 0},
                              {"idx_size", 12}});
        writeText(out / "tree.json",
                  json({{"meshes", meshes}, {"vtx_path", "tree.vtx"}, {"idx_path", "tree.idx"}}).dump());
    }
    variant("index_past_vertices", [](json& m, json&) {
        m["meshes"][0]["vtx_size"] = 56 * 4;  // the trunk's first face only: its indices reach 15
    });
    // The .idx file named by the JSON is not there.
    fs::path missing = dir / "missing_idx";
    writeBookTree(missing);
    fs::remove(missing / "tree.idx");
}

// ---- Work, numbers and mirrors at the extremes (tests/reliability/extremes.cmake) -------------------------

// Writes a model in the book's converted format: NAME.json naming `meshes` (ranges of NAME.vtx
// and NAME.idx), NAME_mat.json with `materials`.
void writeBookModel(const fs::path& dir, const std::string& name, const std::vector<float>& vertices,
                    const std::vector<uint32_t>& indices, json meshes, json materials) {
    fs::create_directories(dir);
    std::string vtx, idx;
    auto put = [](std::string& out, uint32_t bits) {
        for (int shift : {24, 16, 8, 0}) out.push_back(char(uint8_t(bits >> shift)));
    };
    for (float f : vertices) {
        uint32_t bits;
        std::memcpy(&bits, &f, sizeof(bits));
        put(vtx, bits);
    }
    for (uint32_t i : indices) put(idx, i);
    writeText(dir / (name + ".vtx"), vtx);
    writeText(dir / (name + ".idx"), idx);
    writeText(dir / (name + ".json"),
              json({{"meshes", meshes}, {"vtx_path", name + ".vtx"}, {"idx_path", name + ".idx"}}).dump());
    writeText(dir / (name + "_mat.json"), materials.dump());
}

json bookMaterial(const std::string& id, const std::string& texture = "") {
    return json{{"id", id},
                {"texture_path", texture},
                {"normal_map_path", ""},
                {"metal_rough_map", ""},
                {"diffuse_color", {{"x", 0.8}, {"y", 0.8}, {"z", 0.8}, {"w", 1.0}}},
                {"roughness_factor", 1.0},
                {"metallic_factor", 0.0}};
}

// `count` squares of side 2 x `half`, facing up, at heights 0, 1 mm, 2 mm, ...: each covers the
// view and every shadow cascade, so a frame rasterises `count` layers of fragments in every pass.
BookMesh stackedQuads(int count, float half) {
    BookMesh mesh;
    for (int i = 0; i < count; ++i)
        bookQuad(mesh, {-half, 0.001f * float(i), half}, {2 * half, 0, 0}, {0, 0, -2 * half}, {1, 1});
    return mesh;
}

void writeStackedGltf(const fs::path& path, int count, float half, int nodes) {
    BookMesh quads = stackedQuads(count, half);
    gltf::File file;
    std::vector<vec3> p, n;
    for (size_t v = 0; v < quads.vertices.size(); v += 14) {
        p.push_back({quads.vertices[v], quads.vertices[v + 1], quads.vertices[v + 2]});
        n.push_back({quads.vertices[v + 3], quads.vertices[v + 4], quads.vertices[v + 5]});
    }
    int grey = file.material({{"pbrMetallicRoughness", color(0.8f, 0.8f, 0.8f)}});
    int mesh = file.mesh(json::array(
        {{{"attributes", {{"POSITION", file.positions(p)}, {"NORMAL", file.values(n, gltf::kFloat, "VEC3")}}},
          {"indices", file.values(quads.indices, gltf::kUnsignedInt, "SCALAR")},
          {"material", grey}}}));
    std::vector<int> roots;
    for (int i = 0; i < nodes; ++i) roots.push_back(file.node({{"mesh", mesh}}));
    file.scene(roots);
    file.writeGltf(path);
}

// The same in the book's format: one range of `count` quads named by `names` meshes.
void writeStackedBook(const fs::path& dir, const std::string& name, int count, float half, int names) {
    BookMesh quads = stackedQuads(count, half);
    json meshes = json::array();
    for (int i = 0; i < names; ++i)
        meshes.push_back({{"material_id", "grey"},
                          {"offset_vtx", 0},
                          {"vtx_size", quads.vertices.size() * 4},
                          {"offset_idx", 0},
                          {"idx_size", quads.indices.size() * 4}});
    writeBookModel(dir, name, quads.vertices, quads.indices, meshes, json::array({bookMaterial("grey")}));
}

// An asymmetric solid on a floor (an L of two boxes of different colours at +x, a slab at -z), and
// scenes that show it plain and mirrored in x: by a scene file's scale, by a glTF node's, and the
// book's format by a scene file's. Camera and sun lie in the plane x = 0, so the mirrored scene's
// picture is the plain one's mirror image.
void writeMirrors(const fs::path& dir) {
    fs::create_directories(dir);
    auto build = [](gltf::File& file) {
        int floorGrey = file.material({{"pbrMetallicRoughness", color(0.7f, 0.7f, 0.7f)}});
        int red = file.material({{"pbrMetallicRoughness", color(0.8f, 0.15f, 0.1f)}});
        int blue = file.material({{"pbrMetallicRoughness", color(0.1f, 0.2f, 0.8f)}});
        json primitives = json::array({boxPrimitive(file, floorGrey, {-6, -0.1f, -6}, {6, 0, 6}),
                                       boxPrimitive(file, red, {0.5f, 0, -1}, {2.5f, 0.8f, 0}),
                                       boxPrimitive(file, blue, {1.7f, 0.8f, -1}, {2.5f, 2.4f, 0}),
                                       boxPrimitive(file, red, {-3, 0, -3}, {-0.5f, 1.2f, -2.6f})});
        return file.mesh(primitives);
    };
    {
        gltf::File plain;
        int mesh = build(plain);
        plain.scene({plain.node({{"mesh", mesh}})});
        plain.writeGltf(dir / "lblock.gltf");
    }
    {
        gltf::File mirrored;
        int mesh = build(mirrored);
        int child = mirrored.node({{"mesh", mesh}});
        mirrored.scene({mirrored.node({{"children", {child}}, {"scale", {-1, 1, 1}}})});
        mirrored.writeGltf(dir / "lblock_mirrored_node.gltf");
    }
    auto sceneFile = [&](const char* name, json models) {
        json root = {
            {"models", models},
            {"camera",
             {{"position", {0, 5, 7}}, {"yaw", 0}, {"pitch", -35}, {"fov", 60}, {"near", 0.1}, {"far", 40}}},
            {"ambient", {{"color", {1, 1, 1}}, {"intensity", 0.15}}},
            {"lights",
             json::array({{{"type", "directional"}, {"direction", {0, -1, -0.6}}, {"intensity", 2.0}}})}};
        writeText(dir / name, root.dump(2));
    };
    sceneFile("mirror_plain.json", json::array({{{"file", "lblock.gltf"}}}));
    sceneFile("mirror_scene.json", json::array({{{"file", "lblock.gltf"}, {"scale", {-1, 1, 1}}}}));
    sceneFile("mirror_node.json", json::array({{{"file", "lblock_mirrored_node.gltf"}}}));
    // Mirrored twice (x and z, determinant positive) is a half turn: drawn as it is, no winding
    // turned (the same picture as a rotation of 180 degrees about y).
    sceneFile("mirror_twice.json", json::array({{{"file", "lblock.gltf"}, {"scale", {-1, 1, -1}}}}));
    sceneFile("mirror_turned.json", json::array({{{"file", "lblock.gltf"}, {"rotation", {0, 180, 0}}}}));
    // The book's format: an open box (its four sides only, like the book's tree trunk) standing at
    // +x on a floor, seen from outside: with the winding wrong, the near sides are culled and the
    // far sides' insides show.
    BookMesh box{.material = "grey"};
    const float h = 0.6f;
    vec3 c(1.5f, 0, -1);
    bookQuad(box, c + vec3(-h, 0, h), {2 * h, 0, 0}, {0, 1.5f, 0}, {1, 1});   // +z face
    bookQuad(box, c + vec3(h, 0, -h), {-2 * h, 0, 0}, {0, 1.5f, 0}, {1, 1});  // -z
    bookQuad(box, c + vec3(h, 0, h), {0, 0, -2 * h}, {0, 1.5f, 0}, {1, 1});   // +x
    bookQuad(box, c + vec3(-h, 0, -h), {0, 0, 2 * h}, {0, 1.5f, 0}, {1, 1});  // -x
    bookQuad(box, c + vec3(-h, 0.4f, h), {h, 0, 0}, {0, 0, -2 * h}, {1, 1});  // a ledge inside, facing up
    json boxMeshes = json::array({{{"material_id", "grey"},
                                   {"offset_vtx", 0},
                                   {"vtx_size", box.vertices.size() * 4},
                                   {"offset_idx", 0},
                                   {"idx_size", box.indices.size() * 4}}});
    writeBookModel(dir, "openbox", box.vertices, box.indices, boxMeshes, json::array({bookMaterial("grey")}));
    sceneFile("mirror_book_plain.json", json::array({{{"file", "openbox.json"}}}));
    sceneFile("mirror_book_scene.json", json::array({{{"file", "openbox.json"}, {"scale", {-1, 1, 1}}}}));
}

void writeExtremes(const fs::path& dir) {
    fs::create_directories(dir);
    // Overdraw: 2,000 quads of 40 x 40 m stacked 1 mm apart (4,000 triangles, one mesh); the
    // same drawn by 20 nodes; quads of 2 km; 200 (drawn: within the bound at the defaults).
    writeStackedGltf(dir / "stacked_2000.gltf", 2000, 20.0f, 1);
    writeStackedGltf(dir / "stacked_2000_x20.gltf", 2000, 20.0f, 20);
    writeStackedGltf(dir / "stacked_2000_2km.gltf", 2000, 1000.0f, 1);
    writeStackedGltf(dir / "stacked_200.gltf", 200, 20.0f, 1);
    // 450: within the bound, and more than a second a frame on lavapipe (the stop tests' long frame).
    writeStackedGltf(dir / "stacked_450.gltf", 450, 20.0f, 1);
    // The book's format: one range of 2,000 quads named by 20 meshes, and by one.
    writeStackedBook(dir / "book", "stacked_x20", 2000, 20.0f, 20);
    writeStackedBook(dir / "book", "stacked_200", 200, 20.0f, 1);
    // The book's clone whose tree is 2,000 stacked quads named 20 times (its units: the book
    // scales the tree by 0.005).
    writeBookClone(dir / "clone");
    writeStackedBook(dir / "clone" / "booksamples" / "chapter-16" / "resources" / "models" / "tree", "tree",
                     2000, 2000.0f, 20);
    // Memory: one range of 4,096 vertices (229 KB) named by 2,048 meshes (2^23 vertices named,
    // decoded once), and 2,048 ranges sliding by one vertex over 6,143 (2^23 vertices, all
    // distinct: the largest the vertex budget admits, from a 344 KB file).
    {
        std::vector<float> vertices;
        for (int v = 0; v < 6143; ++v)
            for (float f : {float(v % 64) * 0.01f, 0.0f, float(v / 64) * 0.01f, 0.0f, 1.0f, 0.0f, 1.0f, 0.0f,
                            0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f})
                vertices.push_back(f);
        std::vector<uint32_t> indices{0, 64, 1};
        json shared = json::array(), sliding = json::array();
        for (int i = 0; i < 2048; ++i) {
            json mesh = {{"material_id", "grey"},
                         {"offset_vtx", 0},
                         {"vtx_size", 4096 * 56},
                         {"offset_idx", 0},
                         {"idx_size", 12}};
            shared.push_back(mesh);
            mesh["offset_vtx"] = i * 56;
            sliding.push_back(mesh);
        }
        writeBookModel(dir / "memory", "shared_range", vertices, indices, shared,
                       json::array({bookMaterial("grey")}));
        writeBookModel(dir / "memory", "sliding_ranges", vertices, indices, sliding,
                       json::array({bookMaterial("grey")}));
    }
    // Warnings: 5,000 materials no mesh uses, naming 15,000 textures that do not exist.
    {
        BookMesh quad{.material = "used"};
        bookQuad(quad, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, {1, 1});
        json materials = json::array({bookMaterial("used")});
        for (int i = 0; i < 5000; ++i) {
            json m = bookMaterial("unused" + std::to_string(i), "missing_" + std::to_string(i) + ".png");
            m["normal_map_path"] = "missing_normal_" + std::to_string(i) + ".png";
            m["metal_rough_map"] = "missing_rough_" + std::to_string(i) + ".png";
            materials.push_back(m);
        }
        json meshes = json::array({{{"material_id", "used"},
                                    {"offset_vtx", 0},
                                    {"vtx_size", quad.vertices.size() * 4},
                                    {"offset_idx", 0},
                                    {"idx_size", quad.indices.size() * 4}}});
        writeBookModel(dir / "warnings", "many_missing", quad.vertices, quad.indices, meshes, materials);
    }
    // Paths with control characters: a NUL in the book format's binary path ("m.vtx\0.other" would
    // be read as m.vtx), a line break in a texture's; NEL (U+0085) in a scene file's model path.
    {
        BookMesh quad{.material = "grey"};
        bookQuad(quad, {-1, 0, 1}, {2, 0, 0}, {0, 0, -2}, {1, 1});
        json meshes = json::array({{{"material_id", "grey"},
                                    {"offset_vtx", 0},
                                    {"vtx_size", quad.vertices.size() * 4},
                                    {"offset_idx", 0},
                                    {"idx_size", quad.indices.size() * 4}}});
        writeBookModel(dir / "paths", "nul", quad.vertices, quad.indices, meshes,
                       json::array({bookMaterial("grey")}));
        json model = json::parse(std::ifstream(dir / "paths" / "nul.json"));
        model["vtx_path"] = std::string("nul.vtx\0.other", 14);
        writeText(dir / "paths" / "nul.json", model.dump());
        writeBookModel(dir / "paths", "newline_texture", quad.vertices, quad.indices, meshes,
                       json::array({bookMaterial("grey", "leaf\npng.png")}));
        writeText(dir / "paths" / "nel_scene.json",
                  json({{"models", json::array({{{"file", "model\xc2\x85.gltf"}}})}}).dump());
    }
    // Numbers at the edge of float: suns whose length no float holds, a model whose bounds
    // overflow once placed, a far plane 1e6 times the near one, the 16-bit G-buffer's limit.
    {
        auto sceneWith = [&](const char* name, json sunDirection, json model, json camera = json::object()) {
            json cam = {{"position", {0, 10, 0}},
                        {"yaw", -90},
                        {"pitch", -89},
                        {"fov", 60},
                        {"near", 0.5},
                        {"far", 50}};
            cam.update(camera);
            writeText(dir / "numbers" / name, json({{"models", json::array({model})},
                                                    {"camera", cam},
                                                    {"ambient", {{"color", {1, 1, 1}}, {"intensity", 0.0}}},
                                                    {"lights", json::array({{{"type", "directional"},
                                                                             {"direction", sunDirection},
                                                                             {"intensity", 2.0}}})}})
                                                  .dump(2));
        };
        fs::create_directories(dir / "numbers");
        fs::copy_file(dir / ".." / "shadows" / "box_on_plane.gltf", dir / "numbers" / "box_on_plane.gltf",
                      fs::copy_options::overwrite_existing);
        fs::copy_file(dir / ".." / "shadows" / "box_on_plane.bin", dir / "numbers" / "box_on_plane.bin",
                      fs::copy_options::overwrite_existing);
        json box = {{"file", "box_on_plane.gltf"}};
        sceneWith("sun_unit.json", {0, -1, 0}, box);
        sceneWith("sun_1e30.json", {0, -1e30, 0}, box);
        sceneWith("sun_diagonal_unit.json", {1, -1, 1}, box);
        sceneWith("sun_diagonal_1e20.json", {1e20, -1e20, 1e20}, box);
        sceneWith("sun_tiny.json", {0, -1e-7, 0}, box);
        sceneWith("bounds_overflow.json", {0, -1, 0},
                  {{"file", "box_on_plane.gltf"},
                   {"position", {9e14, 0, 0}},
                   {"scale", 1e30},
                   {"rotation", {0, 45, 0}}});
        sceneWith("far_1e30.json", {0, -1, 0}, box, {{"far", 1e30}});
        sceneWith("far_over_near_1e6.json", {0, -1, 0}, box, {{"near", 0.01}, {"far", 10000}});
        // The box scene moved 60,000 and 70,000 along x: within and past what 16-bit floats hold.
        sceneWith("at_60000.json", {1, -1, 0.5}, {{"file", "box_on_plane.gltf"}, {"position", {60000, 0, 0}}},
                  {{"position", {60000, 10, 0}}});
        sceneWith("at_70000.json", {1, -1, 0.5}, {{"file", "box_on_plane.gltf"}, {"position", {70000, 0, 0}}},
                  {{"position", {70000, 10, 0}}});
        // ... and, for the chapters whose G-buffer holds no position (10, 14), at 1e6 (32-bit
        // floats 1/16 apart) and at 1e15 (the coordinates' limit: 2^27 apart, the box a point).
        sceneWith("at_1e6.json", {1, -1, 0.5}, {{"file", "box_on_plane.gltf"}, {"position", {1e6, 0, 0}}},
                  {{"position", {1e6, 10, 0}}});
        sceneWith("at_9e14.json", {1, -1, 0.5},
                  {{"file", "box_on_plane.gltf"}, {"position", {9e14, 0, 0}}, {"scale", 1e9}},
                  {{"position", {9e14, 1e10, 0}}, {"near", 1e8}, {"far", 5e10}});
        sceneWith("at_origin.json", {1, -1, 0.5}, box);
    }
    writeMirrors(dir / "mirrors");
}

}  // namespace

// Skins and animations that break the rules (glTF 2.0, 3.7.3 and 3.11), each a small bending arm
// (scenes/figures.hpp) with one thing wrong: chapter-17's loader refuses each in one line.
void writeSkinHostile(const fs::path& dir) {
    fs::create_directories(dir);
    auto make = [&](const std::string& name, const std::function<void(figures::SkinnedMesh&)>& editMesh,
                    const std::function<void(gltf::File&)>& editFile) {
        figures::SkinnedMesh mesh;
        mesh.tube(0.0f, 2.0f, 0.1f, 4, 4,
                  [](float x, glm::u16vec4& j, glm::vec4& w) { figures::blend(x, 0.8f, 1.2f, 0, 1, j, w); });
        if (editMesh) editMesh(mesh);
        std::vector<figures::Joint> joints{{}, {.parent = 0, .translation = {1.0f, 0.0f, 0.0f}}};
        std::vector<figures::Track> tracks{{.joint = 1,
                                            .path = "rotation",
                                            .times = {0.0f, 1.0f},
                                            .values = figures::quats({figures::axisAngle({0, 0, 1}, 0),
                                                                      figures::axisAngle({0, 0, 1}, 90)})}};
        gltf::File file = figures::write(mesh, joints, tracks, {1, 1, 1, 1}, "bend");
        if (editFile) editFile(file);
        file.writeGltf(dir / name);
    };
    make("arm.gltf", nullptr, nullptr);  // the one without a fault
    make(
        "joint_past_skin.gltf",
        [](figures::SkinnedMesh& m) {
            m.joints[7] = {5, 0, 0, 0};
        },
        nullptr);
    make(
        "negative_weight.gltf",
        [](figures::SkinnedMesh& m) {
            m.weights[7] = {1.5f, -0.5f, 0, 0};
        },
        nullptr);
    // Weights of 0 alone (legal: the specification asks sums close to 1 with a SHOULD, and the
    // glTF-Validator's own valid samples hold such vertices): drawn, vertex 7 in the bind pose.
    make(
        "weights_zero.gltf",
        [](figures::SkinnedMesh& m) {
            m.weights[7] = {0, 0, 0, 0};
        },
        nullptr);
    make(
        "weights_sum_half.gltf",
        [](figures::SkinnedMesh& m) {
            m.weights[7] = {0.25f, 0.25f, 0, 0};
        },
        nullptr);
    make(
        "weights_nan.gltf",
        [](figures::SkinnedMesh& m) {
            m.weights[7] = {NAN, 0, 0, 0};
        },
        nullptr);
    // Weights that sum to 1 within 8-bit rounding (0.995): taken, made to sum to 1.
    make(
        "weights_rounded.gltf",
        [](figures::SkinnedMesh& m) {
            m.weights[7] = {0.5f, 0.495f, 0, 0};
        },
        nullptr);
    auto sampler = [](gltf::File& f) -> json& { return f.root["animations"][0]["samplers"][0]; };
    make("times_decreasing.gltf", nullptr, [&](gltf::File& f) {
        std::vector<float> times{1.0f, 0.5f};
        sampler(f)["input"] = f.values(times, gltf::kFloat, "SCALAR");
    });
    make("cubic_one_key.gltf", nullptr, [&](gltf::File& f) {
        std::vector<float> times{0.0f};
        std::vector<float> values{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
        sampler(f) = {{"input", f.values(times, gltf::kFloat, "SCALAR")},
                      {"output", f.values(values, gltf::kFloat, "VEC4")},
                      {"interpolation", "CUBICSPLINE"}};
    });
    make("interpolation_unknown.gltf", nullptr,
         [&](gltf::File& f) { sampler(f)["interpolation"] = "SMOOTH"; });
    make("zero_quaternion.gltf", nullptr, [&](gltf::File& f) {
        std::vector<float> values{0, 0, 0, 1, 0, 0, 0, 0};
        sampler(f)["output"] = f.values(values, gltf::kFloat, "VEC4");
    });
    make("animated_matrix_node.gltf", nullptr, [](gltf::File& f) {
        json& node = f.root["nodes"][1];
        node.erase("translation");
        node.erase("rotation");
        node.erase("scale");
        node["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1};
    });
    make("too_many_joints.gltf", nullptr, [](gltf::File& f) {
        json joints = json::array();
        for (int i = 0; i < 5000; ++i) joints.push_back(i % 2);
        f.root["skins"][0]["joints"] = joints;
    });
    make("too_many_clips.gltf", nullptr, [](gltf::File& f) {
        json clip = f.root["animations"][0];
        for (int i = 0; i < 1024; ++i) f.root["animations"].push_back(clip);
    });
    make("joint_cycle.gltf", nullptr, [](gltf::File& f) { f.root["nodes"][1]["children"] = {0}; });
    // Joint 200 of 2 where the vertex's weight is 0: still refused (every id names a joint).
    make(
        "joint_past_skin_at_weight_0.gltf",
        [](figures::SkinnedMesh& m) {
            m.joints[7] = {0, 200, 0, 0};
        },
        nullptr);
    make("joints_normalized.gltf", nullptr, [](gltf::File& f) {
        int joints = f.root["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"];
        f.root["accessors"][size_t(joints)]["normalized"] = true;
    });
    make("same_target_twice.gltf", nullptr, [](gltf::File& f) {
        json channel = f.root["animations"][0]["channels"][0];
        f.root["animations"][0]["channels"].push_back(channel);
    });
    // A key between the clip's ends that throws the elbow 1e30 away: found at load.
    make("key_far_away.gltf", nullptr, [&](gltf::File& f) {
        std::vector<float> times{0.0f, 0.001f, 1.0f};
        std::vector<float> values{1, 0, 0, 1e30f, 0, 0, 1, 0, 0};
        json channel = {{"sampler", 1}, {"target", {{"node", 1}, {"path", "translation"}}}};
        f.root["animations"][0]["samplers"].push_back({{"input", f.values(times, gltf::kFloat, "SCALAR")},
                                                       {"output", f.values(values, gltf::kFloat, "VEC3")}});
        f.root["animations"][0]["channels"].push_back(channel);
    });
    // An inverse bind matrix that is not affine (its fourth row 0.5, 0, 0, 1): refused, not drawn
    // distorted.
    make("inverse_bind_not_affine.gltf", nullptr, [&](gltf::File& f) {
        std::vector<glm::mat4> inverseBind{glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), vec3(-1, 0, 0))};
        inverseBind[1][0][3] = 0.5f;
        f.root["skins"][0]["inverseBindMatrices"] = f.values(inverseBind, gltf::kFloat, "MAT4");
    });
    // A CUBICSPLINE translation that overshoots between its keys: both keys put the elbow at
    // x = 1, the first out-tangent 455,000 lifts it to 67,408 a third of the way (past the 65,504
    // of the G-buffer's 16-bit positions), where the key times and midpoints alone reach 56,876.
    make("cubic_overshoot.gltf", nullptr, [&](gltf::File& f) {
        std::vector<float> times{0.0f, 1.0f};
        std::vector<float> values{0, 0, 0, 1, 0, 0, 455000, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0};
        json channel = {{"sampler", 1}, {"target", {{"node", 1}, {"path", "translation"}}}};
        f.root["animations"][0]["samplers"].push_back({{"input", f.values(times, gltf::kFloat, "SCALAR")},
                                                       {"output", f.values(values, gltf::kFloat, "VEC3")},
                                                       {"interpolation", "CUBICSPLINE"}});
        f.root["animations"][0]["channels"].push_back(channel);
    });
    // Legal tiny scales (not faults: drawn): a scale key of 1e-40, a denormal float, on the elbow;
    // the normals' matrix, the inverse-transpose, would be 1e40 there.
    make("scale_tiny.gltf", nullptr, [&](gltf::File& f) {
        std::vector<float> times{0.0f, 1.0f};
        std::vector<float> values{1e-40f, 1e-40f, 1e-40f, 1e-40f, 1e-40f, 1e-40f};
        json channel = {{"sampler", 1}, {"target", {{"node", 1}, {"path", "scale"}}}};
        f.root["animations"][0]["samplers"].push_back({{"input", f.values(times, gltf::kFloat, "SCALAR")},
                                                       {"output", f.values(values, gltf::kFloat, "VEC3")}});
        f.root["animations"][0]["channels"].push_back(channel);
    });
    // The book's format: the arm, and what breaks it.
    writeBookFigure(dir, "book_arm");
    writeBookFigure(dir, "book_bone_past", [](json& root) { root["anim_meshes"][0]["bone_ids"][29] = 7; });
    writeBookFigure(dir, "book_weights_sum",
                    [](json& root) { root["anim_meshes"][0]["weights"][28] = 0.25; });
    writeBookFigure(dir, "book_anim_meshes_short", [](json& root) { root["anim_meshes"] = json::array(); });
    writeBookFigure(dir, "book_frames_differ",
                    [](json& root) { root["animations"][0]["frames"][3]["joint_matrices"].erase(1); });
    writeBookFigure(dir, "book_matrix_nan", [](json& root) {
        root["animations"][0]["frames"][2]["joint_matrices"][1]["m30"] = "NaN";
    });
    // A joint matrix that is not affine (m33 2), refused rather than taken for 1.
    writeBookFigure(dir, "book_matrix_m33",
                    [](json& root) { root["animations"][0]["frames"][2]["joint_matrices"][1]["m33"] = 2.0; });
    // A malformed entry of the mesh that repeats the arm's ranges: checked like any.
    writeBookFigure(dir, "book_repeat_weights_none",
                    [](json& root) { root["anim_meshes"][2]["weights"] = "none"; });
    // A bone id nested 100,000 lists deep (a 200 KB file): refused at the parse, never printed (a
    // recursive print of it overflowed the stack). Spliced in as text: writing it with the JSON
    // library would recurse as deep.
    writeBookFigure(dir, "book_bone_nested",
                    [](json& root) { root["anim_meshes"][0]["bone_ids"][29] = "NESTED_HERE"; });
    {
        std::string text = readBytesText(dir / "book_bone_nested.json");
        const std::string mark = "\"NESTED_HERE\"";
        text.replace(text.find(mark), mark.size(), std::string(100000, '[') + "0" + std::string(100000, ']'));
        writeText(dir / "book_bone_nested.json", text);
    }
    // More text than the book's JSON may hold (a sparse file of 300 MiB: refused by its size, before
    // a byte of it is read).
    writeBookFigure(dir, "book_json_too_large");
    fs::resize_file(dir / "book_json_too_large.json", uintmax_t{300} << 20);
    // More JSON values than the parse budget: 9 Mi zeros in a list the format does not read
    // (18 MB): refused as it is parsed, before the document's memory grows past the budget.
    writeBookFigure(dir, "book_many_values", [](json& root) { root["padding"] = "PADDING_HERE"; });
    {
        std::string text = readBytesText(dir / "book_many_values.json");
        const std::string mark = "\"PADDING_HERE\"";
        std::string zeros = "[";
        zeros.reserve(2 * (size_t(9) << 20) + 2);
        for (size_t i = 0; i < (size_t(9) << 20); ++i) zeros += i ? ",0" : "0";
        zeros += "]";
        text.replace(text.find(mark), mark.size(), zeros);
        writeText(dir / "book_many_values.json", text);
    }
}

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: gltf_cases DIR\n");
        return 2;
    }
    try {
        fs::path dir = argv[1];
        writeCases(dir / "cases");
        writeSame(dir / "same");
        writeDegenerate(dir / "degenerate");
        writeFeatures(dir / "features");
        writeShadows(dir / "shadows");
        writeHostile(dir / "hostile");
        writeSkinHostile(dir / "skins");
        writeBookClone(dir / "book");
        writeBookClone(dir / "book-without-tree", BookTree::None);
        writeBookClone(dir / "book-obj-tree", BookTree::Obj);
        writeBookModelHostile(dir / "book-hostile");
        writeExtremes(dir / "extremes");
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "gltf_cases: %s\n", error.what());
        return 1;
    }
}
