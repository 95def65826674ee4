// pbr_numeric_test SHADER.spv --check finite|random|hard [--samples N] [--device NAME] [--validation]
//
// The shading math of shaders/include/pbr.glsl, run on the GPU (shaders/tests/pbr_numeric.comp,
// which includes that very file) and compared with its fp64 twin (tests/accuracy/pbr_reference.cpp) on
// the same inputs (the fp32 values the GPU reads, widened to double).
//
// Inputs: N random valid samples (default 100,000) and named hard cases. Outputs compared: the GGX
// term D, the visibility term Vis = G / (4 NdotV NdotL), the Fresnel term F, and the full
// contribution of the light (evaluateLight).
//
// The error metric, for each output: the relative error in the max norm,
//     e = max_c |gpu_c - ref_c| / max_c |ref_c|      (0 when both are 0; infinite when only ref is 0)
// over the colour channels c (one channel for D and Vis).
//
// --check finite: every GPU output finite and >= 0, on all inputs.
// --check random: on the random samples, e <= 1e-3 at the 99.9th percentile and <= 1e-2 at worst.
// --check hard:   on every hard case, e <= 1e-3 for every output (the fp64 value of the same robust
//                 formula), and the light is used or skipped exactly as the reference does it.
// --deviations:   no GPU; in fp64, our formula with one of its deviations from the book's shader
//                 undone at a time (and the book's shader whole), on the random samples and the
//                 hard cases: how often each gives NaN or infinity, and how far it moves the result.
// Every mode prints the table of worst cases. Exit 0 when the check passes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "../tools/gpu_compute.hpp"
#include "common/app/cli.hpp"
#include "common/core/check.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/instance.hpp"
#include "tests/accuracy/pbr_reference.hpp"

namespace {

using glm::dvec3;
using glm::vec3;
using glm::vec4;

struct Sample {  // as in pbr_numeric.comp (std430)
    vec4 storedNormalRoughness;
    vec4 worldPositionMetallic;
    vec4 cameraPosition;
    vec4 lightPositionDirectional;
    vec4 lightColorIntensity;
    vec4 albedo;
};
struct Result {
    vec4 terms;  // D, Vis, NdotL, valid
    vec4 fresnel;
    vec4 radiance;
};
static_assert(sizeof(Sample) == 96 && sizeof(Result) == 48);

struct Case {
    std::string name;
    Sample sample;
};

constexpr const char* kOutputs[4] = {"D", "Vis", "F", "radiance"};

// A case from directions: the surface at `position` with stored normal `normal`, the camera at
// `position + view * 5`, a directional light arriving along `toLight` (or a point light at
// `position + toLight` when `point`).
Case makeCase(std::string name, vec3 normal, vec3 view, vec3 toLight, float roughness = 0.5f,
              float metallic = 0.5f, vec3 albedo = vec3(0.5f), bool point = false, float intensity = 1.0f,
              vec3 position = vec3(0.0f)) {
    Sample s{};
    s.storedNormalRoughness = vec4(normal, roughness);
    s.worldPositionMetallic = vec4(position, metallic);
    s.cameraPosition = vec4(position + view * 5.0f, 0.0f);
    s.lightPositionDirectional = point ? vec4(position + toLight, 0.0f) : vec4(-toLight, 1.0f);
    s.lightColorIntensity = vec4(1.0f, 0.9f, 0.8f, intensity);
    s.albedo = vec4(albedo, 0.0f);
    return {std::move(name), s};
}

std::vector<Case> hardCases() {
    vec3 up(0, 0, 1);
    vec3 v45 = glm::normalize(vec3(1, 0, 1)), l45 = glm::normalize(vec3(-1, 0, 1));
    vec3 offPeak = glm::normalize(vec3(-0.9f, 0, 1));
    return {
        makeCase("roughness 0, N = H (the GGX peak)", up, v45, l45, 0.0f),
        makeCase("roughness 1e-6, N = H", up, v45, l45, 1e-6f),
        makeCase("roughness 0, off the peak", up, v45, offPeak, 0.0f),
        makeCase("roughness 1", up, v45, offPeak, 1.0f),
        makeCase("NdotV = 0", up, vec3(1, 0, 0), up),
        makeCase("NdotV = 1e-6", up, glm::normalize(vec3(1, 0, 1e-6f)), up),
        makeCase("NdotL = 0", up, v45, vec3(1, 0, 0)),
        makeCase("NdotL = 1e-6", up, v45, glm::normalize(vec3(1, 0, 1e-6f))),
        makeCase("NdotV = NdotL = 1e-6, roughness 0", up, glm::normalize(vec3(1, 0, 1e-6f)),
                 glm::normalize(vec3(-1, 0, 1e-6f)), 0.0f),
        makeCase("V = -L", up, -l45, l45),
        makeCase("V = -L within 1e-4 rad", up, -glm::normalize(l45 + vec3(0, 1e-4f, 0)), l45),
        makeCase("V = L = N", up, up, up),
        makeCase("V = L = N, roughness 0", up, up, up, 0.0f),
        makeCase("point light at distance 0", up, v45, vec3(0.0f), 0.5f, 0.5f, vec3(0.5f), true),
        makeCase("point light at distance 1e-6", up, v45, vec3(0, 0, 1e-6f), 0.5f, 0.5f, vec3(0.5f), true),
        makeCase("point light touching at 1e-3", up, v45, vec3(0, 0, 1e-3f), 0.2f, 0.0f, vec3(0.5f), true),
        makeCase("intensity 1e6, point at distance 1", up, v45, offPeak, 0.3f, 0.5f, vec3(0.5f), true, 1e6f),
        makeCase("intensity 1e6, directional, roughness 0", up, v45, l45, 0.0f, 1.0f, vec3(1.0f), false,
                 1e6f),
        makeCase("world coordinates 1e4", up, v45, offPeak * 3.0f, 0.5f, 0.5f, vec3(0.5f), true, 1.0f,
                 vec3(1e4f, 1e4f, 1e4f)),
        makeCase("world coordinates 1e5", up, v45, offPeak * 3.0f, 0.5f, 0.5f, vec3(0.5f), true, 1.0f,
                 vec3(1e5f, -1e5f, 1e5f)),
        makeCase("zero-length normal", vec3(0.0f), v45, offPeak),
        makeCase("normal of length 7.5", vec3(0, 0, 7.5f), v45, offPeak),
        makeCase("normal of length 1e-3, tilted", vec3(1e-3f, 0, 2e-3f), v45, offPeak),
        makeCase("metallic 0", up, v45, offPeak, 0.4f, 0.0f),
        makeCase("metallic 1", up, v45, offPeak, 0.4f, 1.0f),
        makeCase("albedo 0", up, v45, offPeak, 0.4f, 0.5f, vec3(0.0f)),
        makeCase("albedo 1, metallic 1", up, v45, offPeak, 0.4f, 1.0f, vec3(1.0f)),
        makeCase("camera at the surface point", up, vec3(0.0f), offPeak),
    };
}

std::vector<Case> randomCases(size_t count) {
    std::mt19937 random(20261121);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), sym(-1.0f, 1.0f);
    auto direction = [&] {
        for (;;) {
            vec3 v(sym(random), sym(random), sym(random));
            float l = glm::length(v);
            if (l > 1e-2f && l <= 1.0f) return v / l;
        }
    };
    std::vector<Case> cases;
    for (size_t i = 0; i < count; ++i) {
        vec3 n = direction(), v = direction(), l = direction();
        if (glm::dot(n, v) < 0.0f) v = -v;  // valid: the camera and the light above the surface
        if (glm::dot(n, l) < 0.0f) l = -l;
        vec3 position(sym(random) * 10.0f, sym(random) * 10.0f, sym(random) * 10.0f);
        bool point = unit(random) < 0.5f;
        float distance = 0.1f + unit(random) * 20.0f;
        Case c = makeCase("random", n, v, l * distance, unit(random), unit(random),
                          vec3(unit(random), unit(random), unit(random)), point, 0.1f + 10.0f * unit(random),
                          position);
        c.sample.cameraPosition = vec4(position + v * (0.5f + 20.0f * unit(random)), 0.0f);
        if (!point) c.sample.lightPositionDirectional = vec4(-l, 1.0f);
        c.sample.lightColorIntensity =
            vec4(unit(random), unit(random), unit(random), c.sample.lightColorIntensity.w);
        cases.push_back(c);
    }
    return cases;
}

struct Reference {
    bool valid;
    double D, Vis;
    dvec3 F, radiance;
};

Reference reference(const Sample& s) {
    namespace pbr = common::pbr;
    dvec3 position(s.worldPositionMetallic), N = pbr::surfaceNormal(dvec3(s.storedNormalRoughness));
    dvec3 V = pbr::viewDirection(position, dvec3(s.cameraPosition), N);
    bool directional = s.lightPositionDirectional.w != 0.0f;
    dvec3 light(s.lightPositionDirectional), albedo(s.albedo);
    double metallic = s.worldPositionMetallic.w, roughness = s.storedNormalRoughness.w;
    Reference r{};
    dvec3 L;
    double attenuation;
    if (pbr::incidentLight(directional, light, position, L, attenuation)) {
        pbr::BrdfTerms t = pbr::cookTorranceTerms(N, V, L, albedo, metallic, roughness);
        r = {t.valid, t.D, t.Vis, t.F, dvec3(0.0)};
    }
    r.radiance = pbr::evaluateLight(directional, light, dvec3(s.lightColorIntensity), s.lightColorIntensity.w,
                                    position, N, V, albedo, metallic, roughness);
    return r;
}

double relativeError(const double* gpu, const double* ref, int n) {
    double diff = 0.0, scale = 0.0;
    for (int c = 0; c < n; ++c) {
        diff = std::max(diff, std::abs(gpu[c] - ref[c]));
        scale = std::max(scale, std::abs(ref[c]));
    }
    if (!(diff == diff)) return INFINITY;  // NaN
    if (diff == 0.0) return 0.0;
    return scale == 0.0 ? INFINITY : diff / scale;
}

struct Evaluated {
    double error[4];           // per output
    bool finite = true;        // every GPU output finite and >= 0
    bool sameDecision = true;  // light used or skipped as the reference does
    Reference ref;
    Result gpu;
};

Evaluated evaluate(const Sample& s, const Result& g) {
    Evaluated e{};
    e.ref = reference(s);
    e.gpu = g;
    const float* all = &g.terms.x;
    for (int i = 0; i < 12; ++i)
        if (!std::isfinite(all[i]) || all[i] < 0.0f) e.finite = false;
    e.sameDecision = (g.terms.w != 0.0f) == e.ref.valid;
    double gD = g.terms.x, gVis = g.terms.y, gF[3] = {g.fresnel.x, g.fresnel.y, g.fresnel.z},
           gR[3] = {g.radiance.x, g.radiance.y, g.radiance.z};
    double rF[3] = {e.ref.F.x, e.ref.F.y, e.ref.F.z},
           rR[3] = {e.ref.radiance.x, e.ref.radiance.y, e.ref.radiance.z};
    e.error[0] = relativeError(&gD, &e.ref.D, 1);
    e.error[1] = relativeError(&gVis, &e.ref.Vis, 1);
    e.error[2] = relativeError(gF, rF, 3);
    e.error[3] = relativeError(gR, rR, 3);
    return e;
}

std::string check;
size_t sampleCount = 100000;
const char* shaderPath = nullptr;

// ---- --deviations: the book's chapter-15 shading, and ours with one deviation undone ----------

struct Variant {
    const char* name;
    bool bookDirection = false;  // L = normalize((light - P) - P)
    bool bookEpsilon = false;    // D G F / (4 NdotV NdotL + 0.0001) instead of D Vis F
    bool noRoughnessClamp = false;
    bool bookHalfVector = false;    // H = normalize(V + L), no fallback
    bool noSkip = false;            // multiply by max(NdotL, 0) instead of skipping the light
    bool bookFalloff = false;       // 1 / d^2 instead of 1 / max(d^2, 1e-4)
    bool bookDistribution = false;  // GGX with 1 - NdotH^2 instead of |N x H|^2
};

dvec3 variantRadiance(const Sample& s, const Variant& v) {
    namespace pbr = common::pbr;
    dvec3 P(s.worldPositionMetallic), N = pbr::surfaceNormal(dvec3(s.storedNormalRoughness));
    dvec3 V = pbr::viewDirection(P, dvec3(s.cameraPosition), N), albedo(s.albedo);
    double metallic = std::clamp(double(s.worldPositionMetallic.w), 0.0, 1.0);
    double roughness = v.noRoughnessClamp ? std::clamp(double(s.storedNormalRoughness.w), 0.0, 1.0)
                                          : std::clamp(double(s.storedNormalRoughness.w), 0.045, 1.0);
    dvec3 light(s.lightPositionDirectional), L;
    double attenuation = 1.0;
    if (s.lightPositionDirectional.w != 0.0f) {
        L = glm::normalize(-light);
    } else {
        dvec3 toLight = light - P;
        double d2 = glm::dot(toLight, toLight);
        if (!v.bookDirection && !v.bookFalloff && !(d2 > 0.0)) return dvec3(0.0);
        L = glm::normalize(v.bookDirection ? toLight - P : toLight);
        attenuation = v.bookFalloff ? 1.0 / d2 : 1.0 / std::max(d2, 1e-4);
    }
    double NdotL = glm::dot(N, L);
    if (!v.noSkip && !(NdotL > 0.0)) return dvec3(0.0);
    dvec3 h = V + L;
    dvec3 H = v.bookHalfVector ? glm::normalize(h) : (glm::dot(h, h) > 1e-6 ? glm::normalize(h) : N);
    double NdotV = std::max(glm::dot(N, V), 0.0), NL = std::clamp(NdotL, 0.0, 1.0);
    double NdotH = std::max(glm::dot(N, H), 0.0), HdotV = std::max(glm::dot(H, V), 0.0);
    double alpha = roughness * roughness, D;
    if (v.bookDistribution || v.noRoughnessClamp) {  // the book's form
        double a2 = alpha * alpha, denom = NdotH * NdotH * (a2 - 1.0) + 1.0;
        D = a2 / (pbr::kPi * denom * denom);
    } else {
        D = pbr::distributionGGX(N, H, std::min(NdotH, 1.0), roughness);
    }
    dvec3 F = pbr::fresnelSchlick(HdotV, glm::mix(dvec3(0.04), albedo, metallic));
    dvec3 specular;
    if (v.bookEpsilon) {
        double k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
        double G = NdotV / (NdotV * (1 - k) + k) * (NL / (NL * (1 - k) + k));
        specular = D * G * F / (4.0 * NdotV * NL + 0.0001);
    } else {
        specular = D * pbr::visibilitySmithSchlick(NdotV, NL, roughness) * F;
    }
    dvec3 kD = (dvec3(1.0) - F) * (1.0 - metallic);
    return (kD * albedo / pbr::kPi + specular) * dvec3(s.lightColorIntensity) *
           double(s.lightColorIntensity.w) * attenuation * NL;
}

void reportDeviations() {
    std::vector<Case> cases = randomCases(sampleCount);
    size_t randomCount = cases.size();
    std::vector<Case> hard = hardCases();
    cases.insert(cases.end(), hard.begin(), hard.end());
    const Variant variants[] = {
        {.name = "ours"},
        {.name = "point-light direction of the book", .bookDirection = true},
        {.name = "epsilon 0.0001 in the denominator", .bookEpsilon = true},
        {.name = "no roughness clamp", .noRoughnessClamp = true},
        {.name = "1 - NdotH^2 GGX form", .bookDistribution = true},
        {.name = "H without the V = -L fallback", .bookHalfVector = true},
        {.name = "max(NdotL, 0) instead of a skip", .noSkip = true},
        {.name = "1/d^2 without the 1 cm bound", .bookFalloff = true},
        {.name = "the book's shader, all of the above",
         .bookDirection = true,
         .bookEpsilon = true,
         .noRoughnessClamp = true,
         .bookHalfVector = true,
         .noSkip = true,
         .bookFalloff = true,
         .bookDistribution = true},
    };
    std::printf("%-38s %9s %9s %12s %12s %12s\n", "variant (fp64)", "NaN/inf", "NaN/inf", "median e",
                "99th pct e", "max e");
    std::printf("%-38s %9s %9s %12s %12s %12s\n", "", "(random)", "(hard)", "(random)", "(random)",
                "(random)");
    for (const Variant& variant : variants) {
        size_t badRandom = 0, badHard = 0;
        std::vector<double> errors;
        for (size_t i = 0; i < cases.size(); ++i) {
            dvec3 ours = variantRadiance(cases[i].sample, variants[0]);
            dvec3 theirs = variantRadiance(cases[i].sample, variant);
            bool finite = std::isfinite(theirs.x) && std::isfinite(theirs.y) && std::isfinite(theirs.z);
            if (!finite) (i < randomCount ? badRandom : badHard) += 1;
            if (i >= randomCount || !finite) continue;
            double o[3] = {ours.x, ours.y, ours.z}, t[3] = {theirs.x, theirs.y, theirs.z};
            errors.push_back(relativeError(t, o, 3));
        }
        std::sort(errors.begin(), errors.end());
        auto at = [&](double p) {
            return errors.empty() ? 0.0
                                  : errors[std::min(errors.size() - 1, size_t(p * double(errors.size())))];
        };
        std::printf("%-38s %9zu %9zu %12.3e %12.3e %12.3e\n", variant.name, badRandom, badHard, at(0.5),
                    at(0.99), errors.empty() ? 0.0 : errors.back());
    }
    std::printf(
        "e: relative difference of the light's contribution from ours (max norm over RGB), %zu random "
        "samples, "
        "%zu hard cases\n",
        randomCount, hard.size());
}

void run(const common::Options& options) {
    std::vector<Case> cases = check == "hard" ? hardCases() : randomCases(sampleCount);
    if (check == "finite") {
        std::vector<Case> hard = hardCases();
        cases.insert(cases.end(), hard.begin(), hard.end());
    }

    common::Instance instance = common::createInstance("pbr_numeric_test", options.validation, {});
    common::Device device = common::createDevice(instance, VK_NULL_HANDLE, options.device);
    VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    common::Buffer input = common::createBuffer(device, cases.size() * sizeof(Sample),
                                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, host, "samples");
    common::Buffer output = common::createBuffer(device, cases.size() * sizeof(Result),
                                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, host, "results");
    for (size_t i = 0; i < cases.size(); ++i)
        std::memcpy(static_cast<Sample*>(input.mapped) + i, &cases[i].sample, sizeof(Sample));
    uint32_t count = uint32_t(cases.size());
    runCompute(device, shaderPath,
               {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, input.handle},
                {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, output.handle}},
               &count, sizeof(count), (count + 63) / 64);
    std::vector<Result> results(static_cast<const Result*>(output.mapped),
                                static_cast<const Result*>(output.mapped) + cases.size());
    common::destroyBuffer(device, output);
    common::destroyBuffer(device, input);
    std::string deviceName = device.properties.deviceName;
    common::destroyDevice(device);
    common::destroyInstance(instance);

    std::vector<Evaluated> evaluated;
    size_t notFinite = 0, decisionsDiffer = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
        evaluated.push_back(evaluate(cases[i].sample, results[i]));
        notFinite += !evaluated.back().finite;
        decisionsDiffer += !evaluated.back().sameDecision;
    }
    std::printf("%zu inputs (%s), device %s\n", cases.size(),
                check == "hard" ? "hard cases" : "random samples", deviceName.c_str());

    bool pass = true;
    if (check == "finite") {
        std::printf("outputs not finite or negative: %zu of %zu inputs\n", notFinite, cases.size());
        pass = notFinite == 0;
    }
    if (check == "random" || check == "finite") {
        std::printf("%-9s %14s %14s   worst input\n", "output", "99.9th pct e", "max e");
        for (int o = 0; o < 4; ++o) {
            std::vector<std::pair<double, size_t>> errors;
            for (size_t i = 0; i < evaluated.size(); ++i) errors.push_back({evaluated[i].error[o], i});
            std::sort(errors.begin(), errors.end());
            double p999 = errors[std::min(errors.size() - 1, size_t(double(errors.size()) * 0.999))].first;
            auto [worst, at] = errors.back();
            const Sample& s = cases[at].sample;
            std::printf("%-9s %14.3e %14.3e   N=(%.3g,%.3g,%.3g) roughness %.3g metallic %.3g\n", kOutputs[o],
                        p999, worst, s.storedNormalRoughness.x, s.storedNormalRoughness.y,
                        s.storedNormalRoughness.z, s.storedNormalRoughness.w, s.worldPositionMetallic.w);
            if (check == "random") pass = pass && p999 <= 1e-3 && worst <= 1e-2;
        }
        if (check == "random") {
            std::printf("light used/skipped differently from fp64: %zu\n", decisionsDiffer);
            pass = pass && decisionsDiffer == 0;
        }
    }
    if (check == "hard") {
        std::printf("%-42s %10s %10s %10s %10s  %12s %s\n", "hard case", "e(D)", "e(Vis)", "e(F)",
                    "e(radiance)", "radiance.r", "");
        for (size_t i = 0; i < evaluated.size(); ++i) {
            const Evaluated& e = evaluated[i];
            double worst = *std::max_element(e.error, e.error + 4);
            bool ok = e.finite && e.sameDecision && worst <= 1e-3;
            std::printf("%-42s %10.2e %10.2e %10.2e %10.2e  %12.5g %s\n", cases[i].name.c_str(), e.error[0],
                        e.error[1], e.error[2], e.error[3], e.gpu.radiance.x,
                        ok ? "ok"
                           : (!e.finite         ? "NOT FINITE"
                              : !e.sameDecision ? "DECIDED OTHERWISE"
                                                : "TOO FAR"));
            pass = pass && ok;
        }
    }
    if (!pass) throw common::Failure("the " + check + " check failed");
    std::printf("the %s check passes\n", check.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<const char*> rest = {argv[0]};
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--deviations") {
            reportDeviations();
            return 0;
        }
        if (arg == "--check" && i + 1 < argc)
            check = argv[++i];
        else if (arg == "--samples" && i + 1 < argc)
            sampleCount = std::stoul(argv[++i]);
        else if (!shaderPath && arg.rfind("--", 0) != 0)
            shaderPath = argv[i];
        else
            rest.push_back(argv[i]);
    }
    if (!shaderPath || (check != "finite" && check != "random" && check != "hard")) {
        std::fprintf(
            stderr,
            "usage: pbr_numeric_test SHADER.spv --check finite|random|hard [--samples N] | --deviations\n");
        return 2;
    }
    return common::runChapter(int(rest.size()), rest.data(),
                              {"pbr_numeric_test", "GPU shading against fp64", {}}, run);
}
