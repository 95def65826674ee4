// shadow_reference SCENE.json GBUFFER_DIR [--compare NAME=VISIBILITY.pfm]... [--json FILE]
//                  [--errors NAME=IMAGE.png] [--max-wrong FRACTION]
//
// The reference for chapter-15-lab's shadow study: the sun's visibility at every pixel of a frame,
// found without a shadow map -- a ray from the pixel's surface point toward the sun, against the
// scene's triangles, through a bounding volume hierarchy (Intel Embree) -- and the error of the
// shadow maps' visibility against it.
//
// GBUFFER_DIR is what chapter-15-lab --gbuffer reference --dump wrote: position.pfm (world, fp32)
// and coverage.pfm; the camera is the scene's (the lab's, unmoved). Each pixel's triangle is found
// by a ray from the camera through its G-buffer point, for its geometric normal. The scene's models are
// loaded as the chapters load them (their transforms applied), cut-outs included: a ray passes where the
// material's alpha at the hit is below its cutoff (the texel nearest the hit's texture coordinates). A
// VISIBILITY.pfm is the light output of chapter-15-lab --shadows ... --view visibility --dump (the visibility
// in each channel).
//
// Only pixels whose triangle faces the sun count (N.L > 0 for its geometric normal: elsewhere the
// sun adds nothing, whatever the map says). Each is classed by the reference (lit or shadowed) and by the map
// (lit where its visibility is at least 0.5):
//   wrong:        the two disagree;
//   edge:         wrong within 2 pixels of a pixel whose reference class differs (the outline of a
//                 shadow: aliasing, blur);
//   false shadow: wrong away from any outline, shadowed where the sun reaches -- acne;
//   false light:  wrong away from any outline, lit where the sun does not reach -- light leaking
//                 under an occluder (peter-panning);
//   bleeding:     the mean visibility the map gives the reference's shadowed pixels away from any
//                 outline (partial light in full shadow: the variance map's light bleeding);
//   MAE:          the mean |reference - visibility| over every counted pixel.
// Fractions are of the counted pixels. --max-wrong F fails (exit 1) when a compared image's wrong
// fraction is above F. A frame with no counted pixel, or whose G-buffer the camera's rays miss
// on over 1% of its surface pixels, is refused (exit 2): there would be nothing to compare. --errors writes a
// picture of a comparison: white lit and grey shadowed where both agree, red false shadow, blue false light,
// yellow wrong at an edge.
#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <stb_image_write.h>
#include <nlohmann/json.hpp>

#include "common/core/check.hpp"
#include "common/model/load_model.hpp"
#include "common/model/model.hpp"
#include "common/scene/scene.hpp"
#include "common/vk/texture.hpp"
#include "tests/accuracy/pfm.hpp"

namespace {

using accuracy::Pfm;
using accuracy::readPfm;
using glm::dvec3;

// A cut-out mesh's triangles, for the filter that lets rays through its transparent texels.
struct CutoutMesh {
    const common::MeshData* mesh = nullptr;
    const common::Pixels* alpha = nullptr;  // the base colour texture (RGBA), or null
    common::SamplerDesc sampler;
    float factor = 1.0f;  // the base colour factor's alpha
    float cutoff = 0.5f;
};

double wrap(double t, common::Wrap mode) {
    if (mode == common::Wrap::ClampToEdge) return std::clamp(t, 0.0, 1.0);
    double f = t - std::floor(t);
    if (mode == common::Wrap::MirroredRepeat && int64_t(std::floor(t)) % 2 != 0) f = 1.0 - f;
    return f;
}

float alphaAt(const CutoutMesh& cut, glm::vec2 uv) {
    if (!cut.alpha || cut.alpha->width == 0) return cut.factor;
    double u = wrap(uv.x, cut.sampler.wrapU), v = wrap(uv.y, cut.sampler.wrapV);
    uint32_t x = std::min(uint32_t(u * cut.alpha->width), cut.alpha->width - 1);
    uint32_t y = std::min(uint32_t(v * cut.alpha->height), cut.alpha->height - 1);
    return cut.factor * float(cut.alpha->rgba[(size_t(y) * cut.alpha->width + x) * 4 + 3]) / 255.0f;
}

// Embree calls this for every hit of an occlusion ray on a cut-out: the hit is dropped where the
// surface is transparent.
void cutoutFilter(const RTCFilterFunctionNArguments* args) {
    const CutoutMesh& cut = *static_cast<const CutoutMesh*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        unsigned triangle = RTCHitN_primID(args->hit, args->N, i);
        float b1 = RTCHitN_u(args->hit, args->N, i), b2 = RTCHitN_v(args->hit, args->N, i);
        const std::vector<uint32_t>& indices = cut.mesh->indices;
        const std::vector<common::Vertex>& v = cut.mesh->vertices;
        glm::vec2 uv = (1.0f - b1 - b2) * v[indices[3 * triangle]].uv + b1 * v[indices[3 * triangle + 1]].uv +
                       b2 * v[indices[3 * triangle + 2]].uv;
        if (alphaAt(cut, uv) < cut.cutoff) args->valid[i] = 0;
    }
}

struct Counts {
    size_t counted = 0, wrong = 0, edge = 0, falseShadow = 0, falseLight = 0, shadowInterior = 0;
    double bleeding = 0.0, absError = 0.0;
};

void fail(const std::string& message) {
    throw common::InputError(message);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc < 3)
            fail(
                "usage: shadow_reference SCENE.json GBUFFER_DIR [--compare NAME=VISIBILITY.pfm]... [--json "
                "FILE] "
                "[--errors NAME=IMAGE.png] [--max-wrong FRACTION]");
        std::string dir = argv[2];
        std::vector<std::pair<std::string, std::string>> compares;
        std::map<std::string, std::string> errorImages;
        std::string jsonPath;
        double maxWrong = -1.0;
        auto fraction = [&](const std::string& text) {
            size_t used = 0;
            double value = -1.0;
            try {
                value = std::stod(text, &used);
            } catch (const std::exception&) {
            }
            if (used != text.size() || !(value >= 0.0 && value <= 1.0))
                fail("--max-wrong takes a fraction 0..1, got '" + text + "'");
            return value;
        };
        for (int i = 3; i < argc; ++i) {
            std::string arg = argv[i];
            if (i + 1 >= argc) fail(arg + " needs a value");
            std::string value = argv[++i];
            size_t eq = value.find('=');
            if ((arg == "--compare" || arg == "--errors") && (eq == std::string::npos || eq == 0))
                fail(arg + " takes NAME=FILE, got '" + value + "'");
            if (arg == "--compare")
                compares.push_back({value.substr(0, eq), value.substr(eq + 1)});
            else if (arg == "--errors")
                errorImages[value.substr(0, eq)] = value.substr(eq + 1);
            else if (arg == "--json")
                jsonPath = value;
            else if (arg == "--max-wrong")
                maxWrong = fraction(value);
            else
                fail("unknown option " + arg);
        }

        common::Scene scene = common::loadSceneFile(argv[1]);
        const common::Light* sun = nullptr;
        for (const common::Light& light : scene.lights)
            if (light.type == common::Light::Type::Directional) {
                sun = &light;
                break;
            }
        if (!sun) fail(std::string(argv[1]) + ": the scene has no directional light");
        dvec3 toSun = -glm::normalize(dvec3(sun->direction));

        // The scene's triangles in the world, in Embree's BVH.
        // Released however this ends (a refused input throws).
        std::unique_ptr<RTCDeviceTy, void (*)(RTCDevice)> deviceHandle(rtcNewDevice(nullptr),
                                                                       rtcReleaseDevice);
        RTCDevice device = deviceHandle.get();
        if (!device) fail("Embree could not start");
        std::unique_ptr<RTCSceneTy, void (*)(RTCScene)> sceneHandle(rtcNewScene(device), rtcReleaseScene);
        RTCScene rtScene = sceneHandle.get();
        rtcSetSceneFlags(rtScene, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(rtScene, RTC_BUILD_QUALITY_HIGH);
        common::ModelCache models;
        std::vector<std::unique_ptr<CutoutMesh>> cutouts;
        // Decoded images, by image and by whether the alpha comes from the first channel (an OBJ's
        // map_d) or the fourth.
        std::map<std::pair<common::ImageSource, bool>, common::Pixels> alphaImages;
        glm::vec3 low(1e30f), high(-1e30f);
        size_t triangles = 0;
        for (const common::ModelInstance& instance : scene.models) {
            const common::ModelData& model = common::loadModelCached(models, instance.file);
            glm::mat4 matrix = instance.transform.matrix();
            for (const common::MeshData& mesh : model.meshes) {
                if (mesh.indices.empty()) continue;
                std::unique_ptr<RTCGeometryTy, void (*)(RTCGeometry)> geometryHandle(
                    rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE), rtcReleaseGeometry);
                RTCGeometry geometry = geometryHandle.get();
                auto* vertices = static_cast<float*>(
                    rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                            3 * sizeof(float), mesh.vertices.size()));
                for (size_t v = 0; v < mesh.vertices.size(); ++v) {
                    glm::vec3 p = glm::vec3(matrix * glm::vec4(mesh.vertices[v].position, 1.0f));
                    std::memcpy(&vertices[3 * v], &p, sizeof(p));
                    low = glm::min(low, p);
                    high = glm::max(high, p);
                }
                auto* indices = static_cast<uint32_t*>(
                    rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                            3 * sizeof(uint32_t), mesh.indices.size() / 3));
                std::memcpy(indices, mesh.indices.data(), mesh.indices.size() / 3 * 3 * sizeof(uint32_t));
                triangles += mesh.indices.size() / 3;
                // Cut-outs, as the chapters decide them (common/scene/gpu_scene.cpp): MASK, or an OBJ
                // material with alpha below 1 in its factor or texture; the scene's overrides of a
                // material's diffuse colour and texture applied as the chapters apply them.
                common::MaterialData material = model.materials[mesh.material];
                if (auto o = instance.materials.find(material.name); o != instance.materials.end()) {
                    if (o->second.diffuse) material.diffuse = *o->second.diffuse;
                    if (o->second.diffuseTexture)
                        material.diffuseTexture.image =
                            common::ImageSource{.file = *o->second.diffuseTexture};
                }
                bool firstChannel = !material.alphaTexture.empty();
                const common::TextureRef& texture =
                    firstChannel ? material.alphaTexture : material.diffuseTexture;
                const common::Pixels* pixels = nullptr;
                if (!texture.empty()) {
                    auto found = alphaImages.find({texture.image, firstChannel});
                    if (found == alphaImages.end()) {
                        common::Pixels decoded = texture.image.embedded
                                                     ? common::decodePixels(texture.image.embedded->data(),
                                                                            texture.image.embedded->size(),
                                                                            texture.image.name(), 16384)
                                                     : common::loadPixels(texture.image.file, 16384);
                        if (firstChannel)  // map_d: its first channel is the alpha
                            for (size_t t = 0; t < decoded.rgba.size(); t += 4)
                                decoded.rgba[t + 3] = decoded.rgba[t];
                        found =
                            alphaImages.emplace(std::pair{texture.image, firstChannel}, std::move(decoded))
                                .first;
                    }
                    pixels = &found->second;
                }
                bool textureAlpha = false;
                for (size_t t = 3; pixels && t < pixels->rgba.size() && !textureAlpha; t += 4)
                    textureAlpha = pixels->rgba[t] < 255;
                bool cutout = material.alphaMode == common::AlphaMode::Mask ||
                              (material.alphaMode == common::AlphaMode::Auto &&
                               (material.diffuse.a < 1.0f || textureAlpha));
                if (cutout) {
                    cutouts.push_back(std::make_unique<CutoutMesh>(CutoutMesh{
                        &mesh, pixels, texture.sampler, material.diffuse.a,
                        material.alphaMode == common::AlphaMode::Mask ? material.alphaCutoff : 0.5f}));
                    rtcSetGeometryUserData(geometry, cutouts.back().get());
                    rtcSetGeometryOccludedFilterFunction(geometry, cutoutFilter);
                    rtcSetGeometryIntersectFilterFunction(geometry, cutoutFilter);
                }
                rtcCommitGeometry(geometry);
                rtcAttachGeometry(rtScene, geometry);  // the scene holds it from here
            }
        }
        rtcCommitScene(rtScene);
        double sceneSize = glm::length(glm::dvec3(high - low));

        Pfm position = readPfm(dir + "/position.pfm"), coverage = readPfm(dir + "/coverage.pfm");
        if (coverage.width != position.width || coverage.height != position.height)
            fail(dir + ": position.pfm and coverage.pfm differ in size");
        int width = position.width, height = position.height;
        size_t pixels = size_t(width) * size_t(height);

        // The reference: 1 lit, 0 shadowed, -1 not counted (no surface, a surface facing away from
        // the sun, or one the camera's ray does not find where the G-buffer has it).
        std::vector<int8_t> reference(pixels, -1);
        size_t unmatched = 0;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        dvec3 camera(scene.camera.position);
        for (size_t p = 0; p < pixels; ++p) {
            if (coverage.at(p).x < 0.5) continue;
            // The triangle the pixel shows, and its geometric normal: a ray from the camera through
            // the G-buffer's point (the G-buffer's normal is the shading normal, bent by normal
            // maps; whether the sun can reach a surface at all is the triangle's matter).
            dvec3 target = position.at(p), toTarget = target - camera;
            double distance = glm::length(toTarget);
            if (!(distance > 0.0)) continue;
            dvec3 view = toTarget / distance;
            RTCRayHit hit{};
            hit.ray.org_x = float(camera.x), hit.ray.org_y = float(camera.y), hit.ray.org_z = float(camera.z);
            hit.ray.dir_x = float(view.x), hit.ray.dir_y = float(view.y), hit.ray.dir_z = float(view.z);
            hit.ray.tnear = 0.0f;
            hit.ray.tfar = float(distance * 1.01 + 1e-4 * sceneSize);
            hit.ray.mask = 0xffffffffu;
            hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(rtScene, &context, &hit);
            if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID ||
                std::abs(double(hit.ray.tfar) - distance) > 0.005 * distance + 1e-5 * sceneSize) {
                ++unmatched;
                continue;
            }
            dvec3 n = glm::normalize(dvec3(hit.hit.Ng_x, hit.hit.Ng_y, hit.hit.Ng_z));
            if (glm::dot(n, view) > 0.0) n = -n;  // the side the camera sees
            if (glm::dot(n, toSun) <= 0.0) continue;
            // Off the surface by a millionth of the scene's size (and of the distance from the
            // origin) along the normal, so that the ray does not hit the triangle it starts on.
            dvec3 surface = camera + view * double(hit.ray.tfar);
            dvec3 origin = surface + n * (1e-6 * sceneSize + 1e-6 * glm::length(surface));
            RTCRay ray{};
            ray.org_x = float(origin.x), ray.org_y = float(origin.y), ray.org_z = float(origin.z);
            ray.dir_x = float(toSun.x), ray.dir_y = float(toSun.y), ray.dir_z = float(toSun.z);
            ray.tnear = 0.0f;
            ray.tfar = std::numeric_limits<float>::infinity();
            ray.mask = 0xffffffffu;
            rtcOccluded1(rtScene, &context, &ray);
            reference[p] = ray.tfar < 0.0f ? 0 : 1;  // Embree sets tfar to -inf when something is hit
        }

        // A pixel at an outline: one within 2 pixels whose reference class differs.
        std::vector<uint8_t> outline(pixels, 0);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                int8_t r = reference[size_t(y) * size_t(width) + size_t(x)];
                if (r < 0) continue;
                for (int dy = -2; dy <= 2 && !outline[size_t(y) * size_t(width) + size_t(x)]; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) {
                        int xx = x + dx, yy = y + dy;
                        if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;
                        int8_t other = reference[size_t(yy) * size_t(width) + size_t(xx)];
                        if (other >= 0 && other != r) {
                            outline[size_t(y) * size_t(width) + size_t(x)] = 1;
                            break;
                        }
                    }
            }
        size_t lit = 0, counted = 0;
        for (int8_t r : reference) {
            counted += r >= 0;
            lit += r == 1;
        }
        std::printf(
            "reference: %dx%d, %zu triangles, %zu pixels facing the sun, %.1f%% of them lit; %zu pixels "
            "whose surface the camera's ray did not find\n",
            width, height, triangles, counted, counted ? 100.0 * double(lit) / double(counted) : 0.0,
            unmatched);

        // Nothing to compare is a failure, not a pass: a G-buffer the camera's rays do not find
        // (positions in another space, another camera) or a frame without a sunlit surface.
        size_t covered = 0;
        for (size_t p = 0; p < pixels; ++p) covered += coverage.at(p).x >= 0.5 ? 1 : 0;
        if (counted == 0) fail(dir + ": no pixel shows a surface facing the sun: nothing to compare");
        if (double(unmatched) > 0.01 * double(covered))
            fail(dir + ": the camera's rays miss " + std::to_string(unmatched) +
                 " of the G-buffer's surface pixels (over 1%): not this scene's frame");
        nlohmann::json report = {{"width", width},
                                 {"height", height},
                                 {"counted", counted},
                                 {"lit", lit},
                                 {"unmatched", unmatched}};
        std::printf("%-24s %9s %9s %9s %9s %9s %9s\n", "compared", "wrong%", "edge%", "acne%", "leak%",
                    "bleeding", "MAE");
        bool failed = false;
        for (const auto& [name, file] : compares) {
            Pfm visibility = readPfm(file);
            if (visibility.width != width || visibility.height != height)
                fail(file + ": not " + std::to_string(width) + "x" + std::to_string(height));
            Counts c;
            std::vector<uint8_t> picture(pixels * 3, 0);
            for (size_t p = 0; p < pixels; ++p) {
                if (reference[p] < 0) continue;
                double v = visibility.at(p).x;
                if (!std::isfinite(v) || v < -1e-6 || v > 1.0 + 1e-6)
                    fail(file + ": a visibility outside 0..1 at pixel " + std::to_string(p));
                ++c.counted;
                bool mapLit = v >= 0.5, refLit = reference[p] == 1;
                c.absError += std::abs(double(reference[p]) - v);
                if (!refLit && !outline[p]) {
                    ++c.shadowInterior;
                    c.bleeding += v;
                }
                uint8_t* rgb = &picture[p * 3];
                if (mapLit == refLit) {
                    uint8_t grey = refLit ? 255 : 90;
                    rgb[0] = rgb[1] = rgb[2] = grey;
                    continue;
                }
                ++c.wrong;
                if (outline[p]) {
                    ++c.edge;
                    rgb[0] = 230, rgb[1] = 200, rgb[2] = 0;
                } else if (refLit) {
                    ++c.falseShadow;
                    rgb[0] = 230, rgb[1] = 30, rgb[2] = 30;
                } else {
                    ++c.falseLight;
                    rgb[0] = 40, rgb[1] = 80, rgb[2] = 255;
                }
            }
            double n = std::max<double>(1.0, double(c.counted));
            double wrongFraction = double(c.wrong) / n;
            double bleeding = c.shadowInterior ? c.bleeding / double(c.shadowInterior) : 0.0;
            std::printf("%-24s %9.3f %9.3f %9.3f %9.3f %9.4f %9.4f\n", name.c_str(), 100.0 * wrongFraction,
                        100.0 * double(c.edge) / n, 100.0 * double(c.falseShadow) / n,
                        100.0 * double(c.falseLight) / n, bleeding, c.absError / n);
            report["compared"][name] = {{"wrong", wrongFraction},
                                        {"edge", double(c.edge) / n},
                                        {"false_shadow", double(c.falseShadow) / n},
                                        {"false_light", double(c.falseLight) / n},
                                        {"bleeding", bleeding},
                                        {"mae", c.absError / n}};
            if (auto image = errorImages.find(name); image != errorImages.end())
                if (!stbi_write_png(image->second.c_str(), width, height, 3, picture.data(), width * 3))
                    fail("cannot write '" + image->second + "'");
            if (maxWrong >= 0.0 && wrongFraction > maxWrong) {
                std::printf("FAIL %s: %.3f%% of the pixels wrong, allowed %.3f%%\n", name.c_str(),
                            100.0 * wrongFraction, 100.0 * maxWrong);
                failed = true;
            }
        }
        if (!jsonPath.empty()) {
            std::ofstream out(jsonPath);
            out << report.dump(2) << "\n";
            if (!out) fail("cannot write '" + jsonPath + "'");
        }
        return failed ? 1 : 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "shadow_reference: %s\n", e.what());
        return 2;
    }
}
