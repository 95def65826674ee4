// reference_render SCENE.json GBUFFER_DIR --compare NAME=LIGHT.pfm... [--max-abs A] [--min-psnr P]
//                  [--better NAME_A NAME_B]   (A's worst pixel closer than B's)
//
// The CPU reference renderer for chapter-15's deferred lighting. It reads a G-buffer that
// chapter-15 --dump wrote (position, albedo, normal, pbr, coverage as fp32 PFM files), shades every
// pixel in double precision with tests/accuracy/pbr_reference.cpp -- the fp64 twin of the shader's math --
// using the lights, ambient light and camera of SCENE.json, and compares GPU light outputs
// (light.pfm of chapter-15 --dump) with the result.
//
// Errors are measured on what reaches the screen: each value clamped to [0, 1] and sRGB-encoded
// (as the post pass does), not quantised; per colour channel, in units of 1/255:
//   max abs: the largest difference;  RMSE: root mean square over all channels of all pixels;
//   PSNR: 20 log10(255 / RMSE) dB;     over 2/255: the fraction of channels differing by more.
// Pixels where a layout sees another surface than the reference does are left out of these
// measures and counted: that is visibility (two surfaces at nearly the same depth, along an
// intersection, resolved differently by another depth format), not shading accuracy. A pixel
// counts as another surface when its distance (distance.pfm, next to the light.pfm compared)
// differs from the reference's by more than 1%, or its normal (normal.pfm) by more than 8 degrees;
// more than 0.1% of the surface pixels so excluded fails the run.
// --max-abs / --min-psnr bound every comparison; --better A B requires max abs(A) < max abs(B):
// the worst pixel, where a precision failure shows as an artifact (banding, a hot spot), where
// RMSE would be dominated by small quantisation noise spread over every pixel.
// A GPU value that is NaN, infinite or negative fails the run. Exit 0 when everything holds.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "common/core/check.hpp"
#include "common/scene/scene.hpp"
#include "tests/accuracy/pbr_reference.hpp"
#include "tests/accuracy/pfm.hpp"

namespace {

using accuracy::Pfm;
using accuracy::readPfm;
using glm::dvec3;

double display(double linear) {
    double c = std::clamp(linear, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

struct Metrics {
    double maxAbs = 0, rmse = 0, psnr = 0, over = 0;
    size_t worstPixel = 0;
    size_t otherSurface = 0;  // pixels left out: another surface visible
    size_t invalid = 0;       // NaN, infinite or negative GPU values
};

struct Surfaces {  // what tells which surface a pixel shows
    const Pfm& coverage;
    const Pfm& distance;
    const Pfm& normal;
};

Metrics compare(const std::vector<dvec3>& reference, const Pfm& gpu, const Surfaces& expected,
                const Surfaces& seen) {
    Metrics m;
    double sum = 0;
    size_t over = 0, counted = 0;
    for (size_t p = 0; p < reference.size(); ++p) {
        double referenceDepth = expected.distance.at(p).x, gpuDepth = seen.distance.at(p).x;
        // Where the reference sees no surface there is no distance to compare (each layout has
        // its own far plane): the pixel is compared as it is, and must be black in both.
        bool surface = expected.coverage.at(p).x >= 0.5;
        bool otherDistance = std::abs(gpuDepth - referenceDepth) > 0.01 * std::abs(referenceDepth);
        bool otherNormal =
            glm::dot(glm::normalize(expected.normal.at(p)), glm::normalize(seen.normal.at(p))) < 0.99;
        if (surface && (otherDistance || otherNormal)) {
            ++m.otherSurface;
            continue;
        }
        ++counted;
        dvec3 g = gpu.at(p);
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(g[c]) || g[c] < 0) {
                ++m.invalid;
                continue;
            }
            double d = std::abs(display(g[c]) - display(reference[p][c])) * 255.0;
            if (d > m.maxAbs) m.maxAbs = d, m.worstPixel = p;
            sum += d * d;
            over += d > 2.0;
        }
    }
    double count = double(std::max<size_t>(counted, 1) * 3);
    m.rmse = std::sqrt(sum / count);
    m.psnr = m.rmse > 0 ? 20.0 * std::log10(255.0 / m.rmse) : INFINITY;
    m.over = double(over) / count;
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc < 3)
            throw common::InputError("usage: reference_render SCENE.json GBUFFER_DIR --compare NAME=FILE...");
        common::Scene scene = common::loadSceneFile(argv[1]);
        std::string dir = argv[2];
        std::vector<std::pair<std::string, std::string>> compares;
        double maxAbs = INFINITY, minPsnr = -INFINITY;
        std::string betterA, betterB;
        for (int i = 3; i < argc; ++i) {
            std::string arg = argv[i];
            if (arg == "--compare" && i + 1 < argc) {
                std::string spec = argv[++i];
                size_t eq = spec.find('=');
                if (eq == std::string::npos) throw common::InputError("--compare expects NAME=FILE.pfm");
                compares.push_back({spec.substr(0, eq), spec.substr(eq + 1)});
            } else if (arg == "--max-abs" && i + 1 < argc) {
                maxAbs = std::stod(argv[++i]);
            } else if (arg == "--min-psnr" && i + 1 < argc) {
                minPsnr = std::stod(argv[++i]);
            } else if (arg == "--better" && i + 2 < argc) {
                betterA = argv[++i];
                betterB = argv[++i];
            } else {
                throw common::InputError("unknown argument '" + arg + "'");
            }
        }

        Pfm distance = readPfm(dir + "/distance.pfm");
        Pfm position = readPfm(dir + "/position.pfm"), albedo = readPfm(dir + "/albedo.pfm"),
            normal = readPfm(dir + "/normal.pfm"), pbr = readPfm(dir + "/pbr.pfm"),
            coverage = readPfm(dir + "/coverage.pfm");
        size_t pixels = size_t(position.width) * size_t(position.height);

        // The reference image: chapter-15's light pass, in double, camera-relative like the GPU's.
        namespace ref = common::pbr;
        dvec3 camera(scene.camera.position);
        std::vector<dvec3> image(pixels, dvec3(0.0));
        size_t surfaces = 0;
        for (size_t p = 0; p < pixels; ++p) {
            if (coverage.at(p).x < 0.5) continue;  // no surface: black
            ++surfaces;
            dvec3 P = position.at(p) - camera, a = albedo.at(p), material = pbr.at(p);
            dvec3 N = ref::surfaceNormal(normal.at(p));
            dvec3 V = ref::viewDirection(P, dvec3(0.0), N);
            dvec3 color = dvec3(scene.ambientColor) * double(scene.ambientIntensity) * a;
            for (const common::Light& light : scene.lights) {
                bool directional = light.type == common::Light::Type::Directional;
                dvec3 where = directional ? dvec3(light.direction) : dvec3(light.position) - camera;
                // A point light's range (scene file "range"): the windowed falloff; none, unbounded.
                double window =
                    directional ? 1.0 : ref::rangeWindow(glm::dot(where - P, where - P), light.range);
                color += ref::evaluateLight(directional, where, dvec3(light.color), light.intensity * window,
                                            P, N, V, a, material.z, material.y);
            }
            image[p] = color;
        }
        std::printf("reference: %dx%d, %zu surface pixels, %zu lights, shaded in fp64\n", position.width,
                    position.height, surfaces, scene.lights.size());

        bool pass = true;
        std::map<std::string, Metrics> results;
        for (const auto& [name, file] : compares) {
            Pfm gpu = readPfm(file);
            if (gpu.width != position.width || gpu.height != position.height || gpu.channels != 3)
                throw common::InputError(file + ": not a " + std::to_string(position.width) + "x" +
                                         std::to_string(position.height) + " RGB image");
            std::string gpuDir = file.substr(0, file.find_last_of('/') + 1);
            Pfm gpuDistance = readPfm(gpuDir + "distance.pfm"), gpuNormal = readPfm(gpuDir + "normal.pfm");
            Metrics m = compare(image, gpu, {coverage, distance, normal}, {coverage, gpuDistance, gpuNormal});
            results[name] = m;
            bool ok = m.invalid == 0 && m.maxAbs <= maxAbs && m.psnr >= minPsnr &&
                      double(m.otherSurface) <= 0.001 * double(surfaces);
            std::printf(
                "%-10s max abs %8.4f/255  RMSE %9.5f/255  PSNR %7.2f dB  over 2/255 %8.4f%%  %s  "
                "(worst at %zu,%zu; %zu pixels see another surface)\n",
                name.c_str(), m.maxAbs, m.rmse, m.psnr, m.over * 100.0,
                m.invalid ? "NaN/INF/NEGATIVE"
                : ok      ? "ok"
                          : "OUT OF BOUNDS",
                m.worstPixel % size_t(position.width), m.worstPixel / size_t(position.width), m.otherSurface);
            pass = pass && ok;
        }
        if (!betterA.empty()) {
            if (!results.count(betterA) || !results.count(betterB))
                throw common::InputError("--better names an image not compared");
            bool ok = results[betterA].maxAbs < results[betterB].maxAbs;
            std::printf("%s's worst pixel is %s than %s's (max abs %.4f vs %.4f /255)\n", betterA.c_str(),
                        ok ? "closer" : "NOT closer", betterB.c_str(), results[betterA].maxAbs,
                        results[betterB].maxAbs);
            pass = pass && ok;
        }
        if (std::isfinite(maxAbs) || std::isfinite(minPsnr))
            std::printf("bounds: max abs <= %g/255, PSNR >= %g dB\n", maxAbs, minPsnr);
        std::printf("%s\n", pass ? "accuracy holds" : "accuracy FAILS");
        return pass ? 0 : 1;
    } catch (const common::InputError& error) {
        std::fprintf(stderr, "reference_render: %s\n", error.what());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "reference_render: %s\n", error.what());
        return 1;
    }
}
