// chapter-16, beyond the book: what the shadow pass draws each frame.
#include "shadow_cache.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/model/model.hpp"

TexelRect intersect(const TexelRect& a, const TexelRect& b) {
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

//> exposed-bands
std::vector<TexelRect> exposedBands(glm::i64vec2 shift, int32_t mapSize) {
    // The new box's column j is the old box's column j + dx: the old box covered j in -dx..N-dx-1.
    int32_t n = mapSize, dx = int32_t(shift.x), dy = int32_t(shift.y);
    std::vector<TexelRect> bands;
    if (dx > 0) bands.push_back({n - dx, 0, n, n});
    if (dx < 0) bands.push_back({0, 0, -dx, n});
    // The rows the move exposed, in the columns the first band did not take.
    int32_t x0 = dx < 0 ? -dx : 0, x1 = dx > 0 ? n - dx : n;
    if (dy > 0) bands.push_back({x0, n - dy, x1, n});
    if (dy < 0) bands.push_back({x0, 0, x1, -dy});
    return bands;
}
//< exposed-bands

//> place-in-layer
std::vector<LayerPiece> placeInLayer(const TexelRect& box, glm::ivec2 offset, int32_t mapSize) {
    // Box column j lives in the layer at (j + offset) mod N: columns below N - offset at j + offset
    // (the viewport starts at offset), the others at j + offset - N (it starts at offset - N).
    std::vector<LayerPiece> pieces;
    TexelRect layer{0, 0, mapSize, mapSize};
    for (int32_t wrapY : {0, 1})
        for (int32_t wrapX : {0, 1}) {
            glm::ivec2 viewport(offset.x - wrapX * mapSize, offset.y - wrapY * mapSize);
            TexelRect placed{box.x0 + viewport.x, box.y0 + viewport.y, box.x1 + viewport.x,
                             box.y1 + viewport.y};
            TexelRect piece = intersect(placed, layer);
            if (!piece.empty()) pieces.push_back({piece, viewport});
        }
    return pieces;
}
//< place-in-layer

CasterBounds casterBounds(const glm::mat4& lightView, const glm::mat4& model, glm::vec3 meshMin,
                          glm::vec3 meshMax) {
    glm::mat4 toLight = lightView * model;
    CasterBounds bounds{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (int i = 0; i < 8; ++i) {
        glm::vec3 p = glm::vec3(toLight * glm::vec4(common::boxCorner(i, meshMin, meshMax), 1.0f));
        bounds.min = glm::min(bounds.min, p);
        bounds.max = glm::max(bounds.max, p);
    }
    return bounds;
}

//> caster-texels
TexelRect casterTexels(const Cascade& cascade, const CasterBounds& bounds, int32_t mapSize) {
    TexelRect box{0, 0, mapSize, mapSize};
    bool finite = std::isfinite(bounds.min.x) && std::isfinite(bounds.min.y) && std::isfinite(bounds.max.x) &&
                  std::isfinite(bounds.max.y) && std::isfinite(bounds.max.z);
    if (!finite) return box;  // nothing known: everywhere
    // Wholly beyond the depth window (farther from the light than its far side): it covers no
    // texel. Nearer than the window it still casts, at depth 0 (depth clamping).
    if (-double(bounds.max.z) > double(cascade.depthFar)) return {};
    // Whole texels of the light's view, one to spare on every side (rasterisation at a texel's edge).
    auto first = [&](float v, int64_t origin) {
        double t = std::floor(double(v) / double(cascade.texel)) - double(origin) - 1.0;
        return int32_t(std::clamp(t, 0.0, double(mapSize)));
    };
    auto last = [&](float v, int64_t origin) {
        double t = std::floor(double(v) / double(cascade.texel)) - double(origin) + 2.0;
        return int32_t(std::clamp(t, 0.0, double(mapSize)));
    };
    TexelRect texels{first(bounds.min.x, cascade.origin.x), first(bounds.min.y, cascade.origin.y),
                     last(bounds.max.x, cascade.origin.x), last(bounds.max.y, cascade.origin.y)};
    return texels.empty() ? TexelRect{} : texels;
}
//< caster-texels

ShadowCache createShadowCache(ShadowRedraw form, uint32_t mapSize, uint32_t count, size_t draws) {
    ShadowCache cache;
    cache.form = form;
    cache.mapSize = int32_t(mapSize);
    cache.count = count;
    cache.models.assign(draws, glm::mat4(1.0f));
    cache.meshBounds.assign(draws, {glm::vec3(0.0f), glm::vec3(0.0f)});
    cache.still.assign(draws, 0);
    cache.moving.assign(draws, 0);
    return cache;
}

namespace {

bool sameMatrix(const glm::mat4& a, const glm::mat4& b) {
    return std::memcmp(&a, &b, sizeof(glm::mat4)) == 0;
}

// The cascade's layer holds this cascade's view, texel and depth window (its origin aside).
bool sameKey(const ShadowCache::Held& held, const Cascade& cascade) {
    return held.valid && sameMatrix(held.view, cascade.view) && held.texel == cascade.texel &&
           held.depthNear == cascade.depthNear && held.depthFar == cascade.depthFar;
}

int32_t wrap(int64_t v, int32_t n) {
    int64_t r = v % n;
    return int32_t(r < 0 ? r + n : r);
}

// Batches for a box-space region of cascade `i`: a piece per place it wraps to, each with the
// draws (among `candidates`) whose texels reach into the piece.
void addRegion(ShadowPlan& plan, std::vector<ShadowBatch>& batches, const TexelRect& region, uint32_t i,
               const std::vector<uint32_t>& candidates, const std::vector<TexelRect>& footprints,
               const std::vector<CasterInput>& casters, int32_t mapSize, uint64_t& culled) {
    for (const LayerPiece& piece : placeInLayer(region, plan.layerOffset[i], mapSize)) {
        TexelRect inBox{piece.scissor.x0 - piece.viewport.x, piece.scissor.y0 - piece.viewport.y,
                        piece.scissor.x1 - piece.viewport.x, piece.scissor.y1 - piece.viewport.y};
        ShadowBatch batch{piece.scissor, piece.viewport, 1u << i, {}};
        for (uint32_t d : candidates) {
            if (intersect(footprints[d], inBox).empty()) {
                ++culled;
                continue;
            }
            batch.draws.push_back({d, 1u << i});
            ++plan.draws[i];
            plan.triangles[i] += casters[d].triangles;
        }
        plan.texels[i] += uint64_t(piece.scissor.area());
        batches.push_back(std::move(batch));
    }
}

}  // namespace

//> plan-shadows
ShadowPlan planShadows(ShadowCache& cache, const std::vector<Cascade>& cascades,
                       const std::vector<CasterInput>& casters) {
    ShadowPlan plan;
    const int32_t n = cache.mapSize;
    const uint32_t count = uint32_t(std::min<size_t>(cascades.size(), cache.count));
    if (cache.models.size() != casters.size()) {  // another scene: nothing held is known
        std::vector<std::pair<uint32_t, TexelRect>> movingDrawn = std::move(cache.movingDrawn);
        cache = createShadowCache(cache.form, uint32_t(n), cache.count, casters.size());
        cache.movingDrawn = std::move(movingDrawn);  // still to be cleared in the moving map
    }
    bool scrolls = cache.form == ShadowRedraw::Scrolled || cache.form == ShadowRedraw::ScrolledTogether;
    bool apart = cache.form == ShadowRedraw::Scrolled;

    // Which draws moved since the last frame; their bounds before and after, in the light's view.
    glm::mat4 lightView = count > 0 ? cascades[0].view : glm::mat4(1.0f);
    std::vector<uint8_t> moved(casters.size(), 0);
    bool anyMoved = false;
    std::vector<CasterBounds> bounds(casters.size()), oldBounds(casters.size());
    for (size_t d = 0; d < casters.size(); ++d) {
        moved[d] = cache.valid && (!sameMatrix(cache.models[d], casters[d].model) || casters[d].deforms);
        anyMoved = anyMoved || moved[d];
        bounds[d] = casterBounds(lightView, casters[d].model, casters[d].meshMin, casters[d].meshMax);
        if (moved[d])
            oldBounds[d] = casterBounds(lightView, cache.models[d], cache.meshBounds[d].first,
                                        cache.meshBounds[d].second);
    }

    // Which layers are drawn whole: all of them the first time (or after a reload or resize) and
    // every frame with Always; a cascade whose view, texel or depth window changed, or that moved
    // by a map or more (or at all, unless it scrolls); every cascade when a caster moved (Changed).
    uint32_t whole = 0;
    if (!cache.valid || cache.form == ShadowRedraw::Always) whole = (1u << cache.count) - 1u;
    if (cache.form == ShadowRedraw::Changed && anyMoved) whole = (1u << cache.count) - 1u;
    for (uint32_t i = 0; i < count; ++i) {
        const ShadowCache::Held& held = cache.held[i];
        glm::i64vec2 shift = cascades[i].origin - held.origin;
        bool far = shift.x <= -n || shift.x >= n || shift.y <= -n || shift.y >= n;
        // Past 2^18 texels from the light view's origin a float holds the box's edge to no better
        // than 1/64 texel: such a cascade is drawn whole whenever it moves.
        const int64_t kScrollLimit = int64_t(1) << 18;
        bool exact =
            std::abs(cascades[i].origin.x) < kScrollLimit && std::abs(cascades[i].origin.y) < kScrollLimit;
        bool scrolled = scrolls && exact;
        if (!sameKey(held, cascades[i]) || far || (!scrolled && shift != glm::i64vec2(0))) whole |= 1u << i;
    }
    for (uint32_t i = count; i < kMaxCascades; ++i) cache.held[i].valid = false;

    // The draws' classes (Scrolled): a draw that moved is drawn apart from now on; one that has
    // been still for kSettleFrames goes back into the cached map. Each change is a footprint to
    // redraw in the cached map: where the draw was (without it), or where it settled (with it).
    std::vector<uint32_t> becameMoving, settled;
    for (size_t d = 0; d < casters.size(); ++d) {
        cache.still[d] = moved[d] ? 0 : std::min(cache.still[d] + 1, kSettleFrames);
        if (!apart) {
            cache.moving[d] = 0;
            continue;
        }
        if (moved[d] && !cache.moving[d]) {
            cache.moving[d] = 1;
            becameMoving.push_back(uint32_t(d));
        } else if (cache.moving[d] && cache.still[d] >= kSettleFrames) {
            cache.moving[d] = 0;
            settled.push_back(uint32_t(d));
        }
    }
    std::vector<uint32_t> cachedDraws, movingDraws;
    for (size_t d = 0; d < casters.size(); ++d)
        (cache.moving[d] ? movingDraws : cachedDraws).push_back(uint32_t(d));

    for (uint32_t i = 0; i < count; ++i) {
        ShadowCache::Held& held = cache.held[i];
        if (whole >> i & 1u) {
            held = {true,
                    cascades[i].view,
                    cascades[i].texel,
                    cascades[i].depthNear,
                    cascades[i].depthFar,
                    cascades[i].origin,
                    cascades[i].origin};
        }
        plan.layerOffset[i] = glm::ivec2(wrap(cascades[i].origin.x - held.base.x, n),
                                         wrap(cascades[i].origin.y - held.base.y, n));
    }

    // The layers drawn whole: one batch, each draw into the layers whose box it reaches (with
    // Always, the book's way, into every layer: no culling, the reference the others must match).
    if (whole != 0) {
        ShadowBatch batch{{0, 0, n, n}, {0, 0}, whole, {}};
        bool cull = cache.form != ShadowRedraw::Always;
        for (uint32_t d : cachedDraws) {
            uint32_t layers = 0;
            for (uint32_t i = 0; i < count; ++i) {
                if ((whole >> i & 1u) == 0) continue;
                if (cull && casterTexels(cascades[i], bounds[d], n).empty()) {
                    ++cache.culled;
                    continue;
                }
                layers |= 1u << i;
                ++plan.draws[i];
                plan.triangles[i] += casters[d].triangles;
            }
            if (layers) batch.draws.push_back({d, layers});
        }
        for (uint32_t i = 0; i < cache.count; ++i)
            if (whole >> i & 1u) plan.texels[i] += uint64_t(n) * uint64_t(n);
        plan.cached.push_back(std::move(batch));
    }
    plan.wholeLayers = whole;

    // The other layers: the bands their scroll exposed, and the footprints of draws that moved
    // (ScrolledTogether: where they were and where they are) or changed class (Scrolled).
    for (uint32_t i = 0; i < count; ++i) {
        if (whole >> i & 1u) continue;
        ShadowCache::Held& held = cache.held[i];
        std::vector<TexelRect> regions = exposedBands(cascades[i].origin - held.origin, n);
        held.origin = cascades[i].origin;
        auto footprint = [&](const CasterBounds& b) {
            TexelRect t = casterTexels(cascades[i], b, n);
            if (!t.empty()) regions.push_back(t);
        };
        for (size_t d = 0; d < casters.size(); ++d)
            if (cache.form == ShadowRedraw::ScrolledTogether && moved[d]) {
                footprint(oldBounds[d]);
                footprint(bounds[d]);
            }
        for (uint32_t d : becameMoving) footprint(oldBounds[d]);
        for (uint32_t d : settled) footprint(bounds[d]);
        if (regions.empty()) continue;
        std::vector<TexelRect> footprints(casters.size());
        for (uint32_t d : cachedDraws) footprints[d] = casterTexels(cascades[i], bounds[d], n);
        for (const TexelRect& region : regions)
            addRegion(plan, plan.cached, region, i, cachedDraws, footprints, casters, n, cache.culled);
    }

    // The moving casters' map: where it held casters last frame is cleared, and each moving draw
    // drawn into the cascades its bounds reach, at the layer's current offset.
    plan.movingClears = cache.movingDrawn;
    cache.movingDrawn.clear();
    for (uint32_t i = 0; i < count; ++i)
        for (uint32_t d : movingDraws) {
            TexelRect t = casterTexels(cascades[i], bounds[d], n);
            if (t.empty()) {
                ++cache.culled;
                continue;
            }
            for (const LayerPiece& piece : placeInLayer(t, plan.layerOffset[i], n)) {
                plan.moving.push_back({piece.scissor, piece.viewport, 1u << i, {{d, 1u << i}}});
                plan.movingClears.push_back({i, piece.scissor});
                cache.movingDrawn.push_back({i, piece.scissor});
                plan.texels[i] += uint64_t(piece.scissor.area());
                ++plan.draws[i];
                plan.triangles[i] += casters[d].triangles;
            }
            plan.movingLayers |= 1u << i;
        }

    for (size_t d = 0; d < casters.size(); ++d) {
        cache.models[d] = casters[d].model;
        cache.meshBounds[d] = {casters[d].meshMin, casters[d].meshMax};
    }
    cache.valid = true;
    ++cache.frames;
    for (uint32_t i = 0; i < cache.count; ++i) {
        if (plan.texels[i] > 0) ++cache.redraws[i];
        if (whole >> i & 1u) ++cache.wholeRedraws[i];
        if (plan.movingLayers >> i & 1u) ++cache.movingFrames[i];
        cache.texels[i] += plan.texels[i];
        cache.draws[i] += plan.draws[i];
        cache.triangles[i] += plan.triangles[i];
    }
    return plan;
}
//< plan-shadows
