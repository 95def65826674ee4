// Posing a model's rig: sampling clips, the node hierarchy, the palette, the reference skinning.
#include "common/model/animation.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace common {
namespace {

glm::dvec4 keyValue(const AnimationChannel& channel, size_t key, size_t components) {
    // CubicSpline stores (in-tangent, value, out-tangent) per key (Appendix C).
    size_t element = channel.interpolation == Interpolation::CubicSpline ? 3 * key + 1 : key;
    glm::dvec4 v(0.0);
    for (size_t c = 0; c < components; ++c) v[int(c)] = channel.values[element * components + c];
    return v;
}

glm::dvec4 tangentValue(const AnimationChannel& channel, size_t key, size_t components, bool out) {
    size_t element = 3 * key + (out ? 2 : 0);
    glm::dvec4 v(0.0);
    for (size_t c = 0; c < components; ++c) v[int(c)] = channel.values[element * components + c];
    return v;
}

glm::dquat quat(const glm::dvec4& v) {  // glTF's (x, y, z, w)
    glm::dquat q(v.w, v.x, v.y, v.z);
    double length = glm::length(q);
    return length > 0.0 ? q / length : glm::dquat(1.0, 0.0, 0.0, 0.0);
}

//> slerp
// Appendix C's spherical linear interpolation: the shorter way round (q and -q are the same
// rotation), linear where the angle is too small for sin() to divide by.
glm::dquat slerp(glm::dquat a, glm::dquat b, double t) {
    double d = glm::dot(a, b);
    if (d < 0.0) {
        b = -b;
        d = -d;
    }
    if (d > 0.9999995) return glm::normalize(a * (1.0 - t) + b * t);
    double angle = std::acos(std::min(d, 1.0));
    double s = std::sin(angle);
    return glm::normalize(a * (std::sin((1.0 - t) * angle) / s) + b * (std::sin(t * angle) / s));
}
//< slerp

//> sample
// The channel's value at clip time t (3.11, Appendix C): before the first key its first value,
// after the last its last.
glm::dvec4 sample(const AnimationChannel& channel, double t, size_t components) {
    const std::vector<float>& times = channel.times;
    if (t <= times.front()) return keyValue(channel, 0, components);
    if (t >= times.back()) return keyValue(channel, times.size() - 1, components);
    size_t k = size_t(std::upper_bound(times.begin(), times.end(), float(t)) - times.begin());
    k = std::clamp<size_t>(k, 1, times.size() - 1) - 1;  // times[k] <= t < times[k + 1]
    while (k > 0 && double(times[k]) > t) --k;           // t between two floats: the key below it
    while (k + 2 < times.size() && double(times[k + 1]) <= t) ++k;
    const double t0 = times[k], t1 = times[k + 1], span = t1 - t0;
    const double u = std::clamp((t - t0) / span, 0.0, 1.0);
    const bool rotation = channel.path == AnimatedPath::Rotation;
    switch (channel.interpolation) {
        case Interpolation::Step:
            return keyValue(channel, k, components);
        case Interpolation::Linear: {
            glm::dvec4 a = keyValue(channel, k, components), b = keyValue(channel, k + 1, components);
            if (!rotation) return a + (b - a) * u;
            glm::dquat q = slerp(quat(a), quat(b), u);
            return {q.x, q.y, q.z, q.w};
        }
        case Interpolation::CubicSpline: {
            // Hermite spline with tangents scaled by the keys' distance in time (Appendix C).
            const double u2 = u * u, u3 = u2 * u;
            glm::dvec4 v = (2 * u3 - 3 * u2 + 1) * keyValue(channel, k, components) +
                           span * (u3 - 2 * u2 + u) * tangentValue(channel, k, components, true) +
                           (-2 * u3 + 3 * u2) * keyValue(channel, k + 1, components) +
                           span * (u3 - u2) * tangentValue(channel, k + 1, components, false);
            if (rotation) {
                glm::dquat q = quat(v);
                return {q.x, q.y, q.z, q.w};
            }
            return v;
        }
    }
    return keyValue(channel, k, components);
}
//< sample

// The book's format: each key frame's joint matrices as they are; between two key frames each
// matrix's entries blended linearly (its key frames are close: the md5 clips run at 24 a second).
void poseBookClip(const Rig& rig, const AnimationClip& clip, double t, Pose& pose) {
    const size_t joints = rig.joints.size();
    const size_t frames = clip.frames.size() / std::max<size_t>(joints, 1);
    double position = clip.frameSeconds > 0.0 ? t / clip.frameSeconds : 0.0;
    size_t f0 = std::min(size_t(position), frames - 1), f1 = (f0 + 1) % frames;
    double u = std::clamp(position - double(f0), 0.0, 1.0);
    for (size_t j = 0; j < joints; ++j) {
        glm::dmat4 a(clip.frames[f0 * joints + j]), b(clip.frames[f1 * joints + j]);
        pose.joints[j] = a + (b - a) * u;
    }
}

}  // namespace

double clipTime(const AnimationClip& clip, double seconds) {
    if (!(clip.duration > 0.0) || !std::isfinite(seconds)) return 0.0;
    double t = std::fmod(seconds, clip.duration);
    return t < 0.0 ? t + clip.duration : t;
}

void poseRig(const Rig& rig, int clip, double seconds, Pose& pose) {
    pose.world.resize(rig.nodes.size());
    pose.joints.resize(rig.joints.size());
    const AnimationClip* playing =
        clip >= 0 && size_t(clip) < rig.clips.size() ? &rig.clips[size_t(clip)] : nullptr;
    const double t = playing ? clipTime(*playing, seconds) : 0.0;
    if (playing && !playing->frames.empty()) {
        poseBookClip(rig, *playing, t, pose);
        return;
    }
    if (rig.nodes.empty()) {  // the book's format at rest: its meshes as stored
        for (glm::dmat4& joint : pose.joints) joint = glm::dmat4(1.0);
        return;
    }
    // Each node's translation, rotation and scale: its rest values, then what the clip says.
    struct Local {
        glm::dvec3 translation;
        glm::dquat rotation;
        glm::dvec3 scale;
    };
    std::vector<Local> locals(rig.nodes.size());
    for (size_t i = 0; i < rig.nodes.size(); ++i)
        locals[i] = {rig.nodes[i].translation, rig.nodes[i].rotation, rig.nodes[i].scale};
    if (playing)
        for (const AnimationChannel& channel : playing->channels) {
            Local& local = locals[channel.node];
            switch (channel.path) {
                case AnimatedPath::Translation:
                    local.translation = glm::dvec3(sample(channel, t, 3));
                    break;
                case AnimatedPath::Rotation:
                    local.rotation = quat(sample(channel, t, 4));
                    break;
                case AnimatedPath::Scale:
                    local.scale = glm::dvec3(sample(channel, t, 3));
                    break;
            }
        }
    for (size_t i = 0; i < rig.nodes.size(); ++i) {
        const RigNode& node = rig.nodes[i];
        glm::dmat4 local = node.matrix;
        if (!node.hasMatrix)
            local = glm::scale(
                glm::translate(glm::dmat4(1.0), locals[i].translation) * glm::mat4_cast(locals[i].rotation),
                locals[i].scale);
        pose.world[i] = node.parent >= 0 ? pose.world[size_t(node.parent)] * local : local;
    }
    for (size_t j = 0; j < rig.joints.size(); ++j)
        pose.joints[j] = pose.world[rig.joints[j].node] * rig.joints[j].inverseBind;
}

namespace {

// The normals' matrix of a joint: the inverse-transpose of its upper 3x3, which is the matrix of
// its cofactors (columns b x c, c x a, a x b of columns a, b, c) over its determinant. Where that
// quotient leaves 32-bit floats (a legal tiny scale: 1e-40 makes it 1e40), the cofactors alone,
// scaled to a largest entry of 1, with the determinant's sign: the same directions, which is all a
// normal needs (the joint's share in a blend of several then shrinks with it, as its size does).
// A singular joint (a scale of 0) gives 0: the normal falls back to the bind pose's.
glm::dmat3 normalMatrix(const glm::dmat4& joint) {
    glm::dmat3 m(joint);
    glm::dmat3 cofactors(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
    double det = glm::dot(m[0], cofactors[0]);
    if (!(det != 0.0) || !std::isfinite(det)) return glm::dmat3(0.0);
    glm::dmat3 inverseTranspose = cofactors / det;
    double largest = 0.0, largestCofactor = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) {
            largest = std::max(largest, std::abs(inverseTranspose[c][r]));
            largestCofactor = std::max(largestCofactor, std::abs(cofactors[c][r]));
        }
    if (largest <= 1e30 && std::isfinite(largest)) return inverseTranspose;
    if (!(largestCofactor > 0.0) || !std::isfinite(largestCofactor)) return glm::dmat3(0.0);
    return cofactors * ((det < 0.0 ? -1.0 : 1.0) / largestCofactor);
}

glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback) {
    double length = glm::length(v);
    return length > 1e-30 && std::isfinite(length) ? v / length : fallback;
}

}  // namespace

PaletteEntry paletteEntry(const glm::dmat4& joint) {
    return {glm::mat4(joint), glm::mat4(glm::dmat4(normalMatrix(joint)))};
}

SkinnedVertex skinVertex(const Vertex& vertex, const VertexSkin& skin,
                         const std::vector<glm::dmat4>& joints) {
    if (skin.weights == glm::vec4(0.0f))  // no joint moves it: the bind pose
        return {glm::dvec3(vertex.position), glm::dvec3(vertex.normal), glm::dvec3(vertex.tangent),
                glm::dvec3(vertex.bitangent)};
    glm::dvec3 p(0.0), n(0.0), t(0.0), b(0.0);
    for (int i = 0; i < 4; ++i) {
        double w = skin.weights[i];
        if (w == 0.0) continue;
        const glm::dmat4& m = joints[skin.joints[i]];
        p += w * glm::dvec3(m * glm::dvec4(glm::dvec3(vertex.position), 1.0));
        n += w * (normalMatrix(m) * glm::dvec3(vertex.normal));
        t += w * (glm::dmat3(m) * glm::dvec3(vertex.tangent));
        b += w * (glm::dmat3(m) * glm::dvec3(vertex.bitangent));
    }
    SkinnedVertex out;
    out.position = p;
    out.normal = unitOr(n, glm::dvec3(vertex.normal));
    out.tangent = unitOr(t - out.normal * glm::dot(out.normal, t), glm::dvec3(vertex.tangent));
    glm::dvec3 side = glm::cross(out.normal, out.tangent);
    out.bitangent = glm::dot(side, b) < 0.0 ? -side : side;
    return out;
}

SkinBounds skinBounds(const MeshData& mesh) {
    SkinBounds bounds;
    std::vector<int32_t> slot;
    for (size_t v = 0; v < mesh.skin.size(); ++v) {
        if (mesh.skin[v].weights == glm::vec4(0.0f)) {  // no joint moves it
            glm::dvec3 p(mesh.vertices[v].position);
            bounds.stillMin = bounds.still ? glm::min(bounds.stillMin, p) : p;
            bounds.stillMax = bounds.still ? glm::max(bounds.stillMax, p) : p;
            bounds.still = true;
            continue;
        }
        for (int i = 0; i < 4; ++i) {
            if (!(mesh.skin[v].weights[i] > 0.0f)) continue;
            uint32_t joint = mesh.skin[v].joints[i];
            if (joint >= slot.size()) slot.resize(joint + 1, -1);
            glm::dvec3 p(mesh.vertices[v].position);
            if (slot[joint] < 0) {
                slot[joint] = int32_t(bounds.joints.size());
                bounds.joints.push_back(joint);
                bounds.min.push_back(p);
                bounds.max.push_back(p);
            }
            size_t s = size_t(slot[joint]);
            bounds.min[s] = glm::min(bounds.min[s], p);
            bounds.max[s] = glm::max(bounds.max[s], p);
        }
    }
    return bounds;
}

void posedBounds(const SkinBounds& bounds, const std::vector<glm::dmat4>& joints, glm::vec3& min,
                 glm::vec3& max) {
    bool first = !bounds.still;
    if (bounds.still) min = glm::vec3(bounds.stillMin), max = glm::vec3(bounds.stillMax);
    for (size_t s = 0; s < bounds.joints.size(); ++s)
        for (int c = 0; c < 8; ++c) {
            glm::dvec3 p = glm::dvec3(joints[bounds.joints[s]] *
                                      glm::dvec4(boxCorner(c, bounds.min[s], bounds.max[s]), 1.0));
            min = first ? glm::vec3(p) : glm::min(min, glm::vec3(p));
            max = first ? glm::vec3(p) : glm::max(max, glm::vec3(p));
            first = false;
        }
}

namespace {

// Where a CUBICSPLINE channel's curve turns: for each segment and component, the times within it
// where the Hermite cubic's derivative is 0 (a quadratic's roots). A cubic segment may overshoot
// its keys (a tangent of 455,000 between two keys of 1 peaks at 67,408, a third of the way, past
// the key times and midpoints that are sampled otherwise); posed there too, each translation and
// scale component's reach is in the bounds exactly.
// At most `limit` of them (the samples a clip is thinned to): a clip of very many keys is sampled,
// not bounded exactly.
std::vector<double> cubicExtremeTimes(const AnimationClip& clip, size_t limit) {
    std::vector<double> result;
    for (const AnimationChannel& channel : clip.channels) {
        if (result.size() >= limit) break;
        if (channel.interpolation != Interpolation::CubicSpline) continue;
        const size_t components = channel.path == AnimatedPath::Rotation ? 4 : 3;
        for (size_t k = 0; k + 1 < channel.times.size() && result.size() < limit; ++k) {
            const double t0 = channel.times[k], span = double(channel.times[k + 1]) - t0;
            if (!(span > 0.0)) continue;
            const glm::dvec4 p0 = keyValue(channel, k, components), p1 = keyValue(channel, k + 1, components);
            const glm::dvec4 m0 = span * tangentValue(channel, k, components, true),
                             m1 = span * tangentValue(channel, k + 1, components, false);
            for (size_t c = 0; c < components; ++c) {
                // d/du of (2u^3 - 3u^2 + 1) p0 + (u^3 - 2u^2 + u) m0 + (-2u^3 + 3u^2) p1 + (u^3 - u^2) m1.
                const int i = int(c);
                const double a = 6 * p0[i] + 3 * m0[i] - 6 * p1[i] + 3 * m1[i];
                const double b = -6 * p0[i] - 4 * m0[i] + 6 * p1[i] - 2 * m1[i];
                const double e = m0[i];
                double roots[2];
                int found = 0;
                if (std::abs(a) < 1e-300) {
                    if (std::abs(b) > 1e-300) roots[found++] = -e / b;
                } else {
                    const double discriminant = b * b - 4 * a * e;
                    if (discriminant >= 0.0) {
                        const double root = std::sqrt(discriminant);
                        roots[found++] = (-b - root) / (2 * a);
                        roots[found++] = (-b + root) / (2 * a);
                    }
                }
                for (int r = 0; r < found; ++r)
                    if (roots[r] > 0.0 && roots[r] < 1.0 && std::isfinite(roots[r]) && result.size() < limit)
                        result.push_back(t0 + roots[r] * span);
            }
        }
    }
    return result;
}

}  // namespace

void animatedBounds(const ModelData& model, glm::vec3& min, glm::vec3& max) {
    bool first = true;
    auto add = [&](const glm::vec3& lo, const glm::vec3& hi) {
        min = first ? lo : glm::min(min, lo);
        max = first ? hi : glm::max(max, hi);
        first = false;
    };
    // The static meshes as they are; the skinned ones as one box per joint, over every mesh.
    const size_t jointCount = model.rig.joints.size();
    SkinBounds joints;
    std::vector<int32_t> slot(jointCount, -1);
    for (const MeshData& mesh : model.meshes) {
        if (mesh.skin.empty()) {
            for (const Vertex& v : mesh.vertices) add(v.position, v.position);
            continue;
        }
        SkinBounds bounds = skinBounds(mesh);
        if (bounds.still) add(glm::vec3(bounds.stillMin), glm::vec3(bounds.stillMax));
        for (size_t k = 0; k < bounds.joints.size(); ++k) {
            const uint32_t j = bounds.joints[k];
            if (slot[j] < 0) {
                slot[j] = int32_t(joints.joints.size());
                joints.joints.push_back(j);
                joints.min.push_back(bounds.min[k]);
                joints.max.push_back(bounds.max[k]);
            }
            joints.min[size_t(slot[j])] = glm::min(joints.min[size_t(slot[j])], bounds.min[k]);
            joints.max[size_t(slot[j])] = glm::max(joints.max[size_t(slot[j])], bounds.max[k]);
        }
    }
    if (joints.joints.empty()) return;
    Pose pose;
    auto addPose = [&](int clip, double seconds) {
        poseRig(model.rig, clip, seconds, pose);
        glm::vec3 lo, hi;
        posedBounds(joints, pose.joints, lo, hi);
        add(lo, hi);
    };
    addPose(-1, 0.0);
    // Each clip at its key times and halfway between them -- thinned to a number of samples that
    // keeps the whole work within about 2^28 node and joint poses, however many clips, nodes and
    // keys the model has. A pose between the samples may still reach further: chapter-17 checks
    // every frame's pose as it plays.
    size_t clips = 0, channels = 0;
    for (const AnimationClip& clip : model.rig.clips) {
        if (clip.channels.empty() && clip.frames.empty()) continue;
        ++clips;
        channels = std::max(channels, clip.channels.size());
    }
    if (clips == 0) return;
    const double perSample =
        double(model.rig.nodes.size() + channels + jointCount + 8 * joints.joints.size());
    const size_t cap =
        size_t(std::clamp(double(uint64_t{1} << 28) / (double(clips) * perSample), 2.0, 1024.0));
    std::vector<double> times;
    for (size_t c = 0; c < model.rig.clips.size(); ++c) {
        const AnimationClip& clip = model.rig.clips[c];
        if (clip.channels.empty() && clip.frames.empty()) continue;
        times.clear();
        for (const AnimationChannel& channel : clip.channels)
            for (float t : channel.times) times.push_back(t);
        std::vector<double> extremes = cubicExtremeTimes(clip, cap);
        if (!clip.frames.empty()) {
            const size_t frames = clip.frames.size() / std::max<size_t>(jointCount, 1);
            for (size_t f = 0; f < frames; ++f) times.push_back(clip.frameSeconds * double(f));
        }
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end()), times.end());
        const size_t keys = times.size();
        for (size_t k = 0; k + 1 < keys; ++k) times.push_back(0.5 * (times[k] + times[k + 1]));
        times.insert(times.end(), extremes.begin(), extremes.end());
        std::sort(times.begin(), times.end());
        const size_t samples = std::min(times.size(), cap);
        for (size_t i = 0; i < samples; ++i) {
            const size_t k = samples == times.size()
                                 ? i
                                 : size_t(double(i) * double(times.size() - 1) / double(samples - 1));
            addPose(int(c), std::min(times[k], std::nextafter(clip.duration, 0.0)));
        }
    }
}

}  // namespace common
