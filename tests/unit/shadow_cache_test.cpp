// chapter-16's shadow cache (chapter-16/shadow_cache.cpp): the bands a scroll exposes, their places in
// a toroidally addressed layer, per-cascade culling, and what each form of --shadow-redraw draws.
#include <gtest/gtest.h>

#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "chapter-16/shadow_cache.hpp"

namespace {

// Every texel of `rects`, once each (a texel covered twice fails).
std::set<std::pair<int, int>> texelsOf(const std::vector<TexelRect>& rects) {
    std::set<std::pair<int, int>> texels;
    for (const TexelRect& r : rects)
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) EXPECT_TRUE(texels.insert({x, y}).second) << x << "," << y;
    return texels;
}

// A cascade with the light straight down, texel 1 cm, its box at `origin`.
Cascade cascadeAt(glm::i64vec2 origin) {
    Cascade c;
    c.view = glm::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    c.texel = 0.01f;
    c.origin = origin;
    c.depthNear = -10.0f;
    c.depthFar = 10.0f;
    return c;
}

// A unit cube's draw placed at `position`, 12 triangles.
CasterInput cube(glm::vec3 position, float size = 0.02f) {
    return {glm::scale(glm::translate(glm::mat4(1.0f), position), glm::vec3(size)), glm::vec3(-0.5f),
            glm::vec3(0.5f), 12};
}

}  // namespace

TEST(ShadowCache, ExposedBandsAreExactlyTheNewTexels) {
    const int n = 8;
    for (int dy = -n + 1; dy < n; ++dy)
        for (int dx = -n + 1; dx < n; ++dx) {
            std::set<std::pair<int, int>> exposed = texelsOf(exposedBands({dx, dy}, n));
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    // Covered by the old box: the old box's column x + dx, row y + dy.
                    bool old = x + dx >= 0 && x + dx < n && y + dy >= 0 && y + dy < n;
                    EXPECT_EQ(exposed.count({x, y}) == 1, !old)
                        << dx << "," << dy << " texel " << x << "," << y;
                }
        }
}

TEST(ShadowCache, PiecesPlaceEveryTexelAtItsToroidalPlace) {
    const int n = 8;
    for (int oy = 0; oy < n; ++oy)
        for (int ox = 0; ox < n; ++ox)
            for (TexelRect box : {TexelRect{0, 0, n, n}, TexelRect{5, 2, 8, 7}, TexelRect{0, 0, 1, 1}}) {
                std::vector<LayerPiece> pieces = placeInLayer(box, {ox, oy}, n);
                EXPECT_LE(pieces.size(), 4u);
                std::vector<TexelRect> scissors;
                for (const LayerPiece& piece : pieces) {
                    scissors.push_back(piece.scissor);
                    // The viewport puts box texel (x, y) at (x, y) + viewport, inside the scissor.
                    for (int y = piece.scissor.y0; y < piece.scissor.y1; ++y)
                        for (int x = piece.scissor.x0; x < piece.scissor.x1; ++x) {
                            int bx = x - piece.viewport.x, by = y - piece.viewport.y;
                            EXPECT_TRUE(bx >= box.x0 && bx < box.x1 && by >= box.y0 && by < box.y1);
                            EXPECT_EQ(x, (bx + ox) % n);
                            EXPECT_EQ(y, (by + oy) % n);
                        }
                }
                EXPECT_EQ(texelsOf(scissors).size(), size_t(box.area()));
            }
}

TEST(ShadowCache, CasterTexelsCullOutsideTheBoxAndBeyondItsDepth) {
    Cascade c = cascadeAt({0, 0});
    glm::mat4 view = c.view;
    // The light straight down, its up +z: light-view x is world -x, y is world z. A cube at the
    // box covers texels, one far outside none, one beyond the depth window none.
    CasterInput inside = cube({0.0f, 0.0f, 0.0f});
    TexelRect t = casterTexels(c, casterBounds(view, inside.model, inside.meshMin, inside.meshMax), 16);
    EXPECT_FALSE(t.empty());
    CasterInput outside = cube({-5.0f, 0.0f, 5.0f});
    EXPECT_TRUE(
        casterTexels(c, casterBounds(view, outside.model, outside.meshMin, outside.meshMax), 16).empty());
    CasterInput below = cube({-0.08f, -20.0f, 0.08f});
    EXPECT_TRUE(casterTexels(c, casterBounds(view, below.model, below.meshMin, below.meshMax), 16).empty());
    CasterInput above = cube({-0.08f, 50.0f, 0.08f});  // nearer the light than the window: casts
    EXPECT_FALSE(casterTexels(c, casterBounds(view, above.model, above.meshMin, above.meshMax), 16).empty());
}

TEST(ShadowCache, ScrolledDrawsWholeOnceThenOnlyExposedBands) {
    const int n = 16;
    ShadowCache cache = createShadowCache(ShadowRedraw::Scrolled, n, 1, 1);
    std::vector<CasterInput> casters{cube({-0.08f, 0.0f, 0.08f}, 0.5f)};  // covers the whole box
    ShadowPlan first = planShadows(cache, {cascadeAt({0, 0})}, casters);
    EXPECT_EQ(first.wholeLayers, 1u);
    EXPECT_EQ(first.texels[0], uint64_t(n * n));
    ShadowPlan same = planShadows(cache, {cascadeAt({0, 0})}, casters);
    EXPECT_TRUE(same.cached.empty());
    EXPECT_EQ(same.texels[0], 0u);
    ShadowPlan scrolled = planShadows(cache, {cascadeAt({3, -2})}, casters);
    EXPECT_EQ(scrolled.wholeLayers, 0u);
    EXPECT_EQ(scrolled.texels[0], uint64_t(3 * n + 2 * (n - 3)));
    EXPECT_EQ(scrolled.layerOffset[0], glm::ivec2(3, n - 2));
    // A move of a whole map or more, or a changed depth window: whole again, offset reset.
    ShadowPlan jumped = planShadows(cache, {cascadeAt({3 + n, -2})}, casters);
    EXPECT_EQ(jumped.wholeLayers, 1u);
    EXPECT_EQ(jumped.layerOffset[0], glm::ivec2(0, 0));
    Cascade deeper = cascadeAt({3 + n, -2});
    deeper.depthFar = 11.0f;
    EXPECT_EQ(planShadows(cache, {deeper}, casters).wholeLayers, 1u);
    // Far from the light view's origin (2^18 texels and more) a move draws whole.
    ShadowCache distant = createShadowCache(ShadowRedraw::Scrolled, n, 1, 1);
    planShadows(distant, {cascadeAt({int64_t(1) << 18, 0})}, casters);
    EXPECT_EQ(planShadows(distant, {cascadeAt({(int64_t(1) << 18) + 1, 0})}, casters).wholeLayers, 1u);
    // changed: any move draws whole; always: every frame.
    for (ShadowRedraw form : {ShadowRedraw::Changed, ShadowRedraw::Always}) {
        ShadowCache other = createShadowCache(form, n, 1, 1);
        planShadows(other, {cascadeAt({0, 0})}, casters);
        EXPECT_EQ(planShadows(other, {cascadeAt({1, 0})}, casters).wholeLayers, 1u);
        EXPECT_EQ(planShadows(other, {cascadeAt({1, 0})}, casters).wholeLayers,
                  form == ShadowRedraw::Always ? 1u : 0u);
    }
}

TEST(ShadowCache, MovingCasterIsDrawnApartAndSettlesBack) {
    const int n = 64;
    ShadowCache cache = createShadowCache(ShadowRedraw::Scrolled, n, 2, 2);
    // A floor over both cascades' boxes, and a small cube in the first only.
    std::vector<CasterInput> casters{cube({-1.0f, -1.0f, 1.0f}, 10.0f), cube({-0.1f, 0.0f, 0.1f})};
    std::vector<Cascade> cascades{cascadeAt({0, 0}), cascadeAt({200, 200})};
    planShadows(cache, cascades, casters);
    casters[1] = cube({-0.3f, 0.0f, 0.1f});
    ShadowPlan moved = planShadows(cache, cascades, casters);
    // Its old place redrawn in the cached map without it (the floor only); it goes to the moving
    // map of the first cascade alone.
    ASSERT_FALSE(moved.cached.empty());
    for (const ShadowBatch& batch : moved.cached)
        for (const ShadowDraw& draw : batch.draws) EXPECT_EQ(draw.draw, 0u);
    ASSERT_FALSE(moved.moving.empty());
    EXPECT_EQ(moved.movingLayers, 1u);
    for (const ShadowBatch& batch : moved.moving) EXPECT_EQ(batch.draws.at(0).draw, 1u);
    // Still: only the moving map, cleared where it was; then, settled, back into the cached map.
    for (uint32_t frame = 1; frame < kSettleFrames; ++frame) {
        ShadowPlan still = planShadows(cache, cascades, casters);
        EXPECT_TRUE(still.cached.empty()) << frame;
        EXPECT_EQ(still.movingLayers, 1u);
        EXPECT_FALSE(still.movingClears.empty());
    }
    ShadowPlan settled = planShadows(cache, cascades, casters);
    EXPECT_EQ(settled.movingLayers, 0u);
    ASSERT_FALSE(settled.cached.empty());
    bool drawsCube = false;
    for (const ShadowBatch& batch : settled.cached)
        for (const ShadowDraw& draw : batch.draws) drawsCube = drawsCube || draw.draw == 1u;
    EXPECT_TRUE(drawsCube);
    EXPECT_FALSE(settled.movingClears.empty());  // where it was in the moving map
    ShadowPlan after = planShadows(cache, cascades, casters);
    EXPECT_TRUE(after.cached.empty() && after.moving.empty() && after.movingClears.empty());
}

TEST(ShadowCache, ScrolledTogetherRedrawsOldAndNewPlaceWithEveryCaster) {
    const int n = 64;
    ShadowCache cache = createShadowCache(ShadowRedraw::ScrolledTogether, n, 1, 2);
    std::vector<CasterInput> casters{cube({-1.0f, -1.0f, 1.0f}, 10.0f), cube({-0.1f, 0.0f, 0.1f})};
    planShadows(cache, {cascadeAt({0, 0})}, casters);
    casters[1] = cube({-0.3f, 0.0f, 0.1f});
    ShadowPlan moved = planShadows(cache, {cascadeAt({0, 0})}, casters);
    EXPECT_TRUE(moved.moving.empty());
    EXPECT_EQ(moved.wholeLayers, 0u);
    EXPECT_GT(moved.texels[0], 0u);
    EXPECT_LT(moved.texels[0], uint64_t(n * n));
}
