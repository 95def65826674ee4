// The model structures' own functions: tangent generation, an image's name for messages.
#include "common/model/model.hpp"

#include <cmath>

#include "common/core/files.hpp"

namespace common {
namespace {

// A unit vector orthogonal to unit `n` (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
glm::vec3 anyOrthogonal(const glm::vec3& n) {
    float sign = std::copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    return glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

}  // namespace

std::string ImageSource::name() const {
    return embedded ? utf8(file) + " (" + label + ")" : utf8(file);
}

void computeTangents(MeshData& mesh) {
    std::vector<glm::dvec3> tangents(mesh.vertices.size(), glm::dvec3(0.0));
    std::vector<glm::dvec3> bitangents(mesh.vertices.size(), glm::dvec3(0.0));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        uint32_t ids[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
        const Vertex &a = mesh.vertices[ids[0]], &b = mesh.vertices[ids[1]], &c = mesh.vertices[ids[2]];
        // Solve [e1 e2] = [t b] * [du; dv] in double: UV areas of a texel or less are common.
        glm::dvec3 e1 = glm::dvec3(b.position - a.position), e2 = glm::dvec3(c.position - a.position);
        // uv.y was flipped at load; the tangent frame follows the OBJ's v (up in the image), the
        // convention normal maps are authored in, so the v differences are negated back.
        glm::dvec2 d1 = glm::dvec2(b.uv - a.uv) * glm::dvec2(1, -1),
                   d2 = glm::dvec2(c.uv - a.uv) * glm::dvec2(1, -1);
        double det = d1.x * d2.y - d2.x * d1.y;
        double area = glm::length(glm::cross(e1, e2));
        if (!(std::abs(det) > 1e-12) || !(area > 1e-20)) continue;  // degenerate UVs or zero area
        glm::dvec3 t = (e1 * d2.y - e2 * d1.y) / det;
        glm::dvec3 bt = (e2 * d1.x - e1 * d2.x) / det;
        // Weight by the triangle's area so slivers do not dominate; t and bt scale with 1/det,
        // so normalise first.
        double tl = glm::length(t), bl = glm::length(bt);
        if (!(tl > 0.0) || !(bl > 0.0) || !std::isfinite(tl) || !std::isfinite(bl)) continue;
        for (uint32_t id : ids) {
            tangents[id] += t / tl * area;
            bitangents[id] += bt / bl * area;
        }
    }
    for (size_t k = 0; k < mesh.vertices.size(); ++k) {
        Vertex& v = mesh.vertices[k];
        // Gram-Schmidt against the normal made unit in double: a float normal is unit only to ~1e-7,
        // which would leave a part of a tangent along the normal behind, to be normalised into one.
        glm::dvec3 n = glm::dvec3(v.normal);
        if (glm::length(n) > 0.0) n = glm::normalize(n);
        glm::dvec3 t = tangents[k] - n * glm::dot(n, tangents[k]);
        double length = glm::length(t);
        // Relative to the accumulated tangent: one along the normal leaves only rounding error.
        glm::vec3 tangent = (length > 1e-6 * glm::length(tangents[k]) && std::isfinite(length))
                                ? glm::vec3(t / length)
                                : anyOrthogonal(v.normal);
        // The bitangent is the cross product, flipped where the UVs are mirrored.
        glm::vec3 bitangent = glm::cross(v.normal, tangent);
        if (glm::dot(glm::dvec3(bitangent), bitangents[k]) < 0.0) bitangent = -bitangent;
        v.tangent = tangent;
        v.bitangent = bitangent;
    }
}

}  // namespace common
