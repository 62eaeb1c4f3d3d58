// Frustum planes and the culling BVH (renderer/scene/Frustum.h, Bvh.h): hand-built boxes with a
// known answer, boxes exactly touching a plane, and the BVH against brute force on randomized
// scenes and frusta (fixed seeds), before and after refits.

#include "passes/LightSetup.h"
#include "scene/Bvh.h"
#include "scene/Frustum.h"
#include "scene/GpuScene.h"
#include "scene/SceneBuilder.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace lit {
namespace {

Aabb box(const glm::vec3& min, const glm::vec3& max) { return Aabb{min, max}; }
Aabb boxAround(const glm::vec3& center, const glm::vec3& size) { return Aabb{center - 0.5f * size, center + 0.5f * size}; }

// The reference: every box tested on its own.
std::vector<std::uint32_t> bruteForce(const std::vector<Aabb>& boxes, const Frustum& frustum) {
    std::vector<std::uint32_t> visible;
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (frustum.intersects(boxes[i])) visible.push_back(static_cast<std::uint32_t>(i));
    return visible;
}

std::vector<std::uint32_t> bvhCull(const Bvh& bvh, const Frustum& frustum) {
    std::vector<std::uint32_t> visible{12345u};  // cull must overwrite, not append
    bvh.cull(frustum, visible);
    return visible;
}

// A camera at `eye` looking at `target`, 90° vertical field of view, square, near 0.1, far 100.
glm::mat4 perspectiveView(const glm::vec3& eye, const glm::vec3& target) {
    return glm::perspective(glm::half_pi<float>(), 1.0f, 0.1f, 100.0f) * glm::lookAt(eye, target, glm::vec3(0, 1, 0));
}

TEST(Frustum, PlanesOfAnOrthographicBoxAreItsSides) {
    // Clip space equals world space in x, y; z ∈ [−10, −1] maps to [−1, 1].
    const Frustum f(glm::ortho(-1.0f, 1.0f, -2.0f, 2.0f, 1.0f, 10.0f));
    const auto& p = f.planes();
    EXPECT_EQ(p[Frustum::Left], glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(p[Frustum::Right], glm::vec4(-1, 0, 0, 1));
    EXPECT_EQ(p[Frustum::Bottom], glm::vec4(0, 1, 0, 2));
    EXPECT_EQ(p[Frustum::Top], glm::vec4(0, -1, 0, 2));
    EXPECT_NEAR(p[Frustum::Near].z, -1.0f, 1e-6f);  // inside is −Z of the near plane z = −1
    EXPECT_NEAR(p[Frustum::Near].w, -1.0f, 1e-6f);
    EXPECT_NEAR(p[Frustum::Far].z, 1.0f, 1e-6f);
    EXPECT_NEAR(p[Frustum::Far].w, 10.0f, 1e-5f);
}

TEST(Frustum, PerspectivePlanesAreNormalizedAndContainTheCameraAxis) {
    const Frustum f(perspectiveView(glm::vec3(3, 1, 2), glm::vec3(3, 1, -5)));
    for (const glm::vec4& plane : f.planes()) {
        EXPECT_NEAR(glm::length(glm::vec3(plane)), 1.0f, 1e-5f);
        // A point on the view axis between near and far is inside every plane.
        EXPECT_GT(glm::dot(glm::vec3(plane), glm::vec3(3, 1, -3)) + plane.w, 0.0f);
    }
    // The near plane is 0.1 m in front of the eye.
    const glm::vec4 nearPlane = f.planes()[Frustum::Near];
    EXPECT_NEAR(glm::dot(glm::vec3(nearPlane), glm::vec3(3, 1, 2 - 0.1f)) + nearPlane.w, 0.0f, 1e-5f);
}

TEST(Frustum, HandBuiltBoxesInsideOutsideAndStraddling) {
    // At the origin looking down −Z: the frustum is |x| ≤ −z, |y| ≤ −z, 0.1 ≤ −z ≤ 100.
    const Frustum f(perspectiveView(glm::vec3(0), glm::vec3(0, 0, -1)));
    struct Case {
        const char* what;
        Aabb box;
        Containment expected;
    };
    const std::vector<Case> cases = {
        {"in front", boxAround({0, 0, -5}, glm::vec3(1)), Containment::Inside},
        {"far off to the right but inside", boxAround({8, 0, -20}, glm::vec3(2)), Containment::Inside},
        {"behind the camera", boxAround({0, 0, 5}, glm::vec3(1)), Containment::Outside},
        {"left of the view", boxAround({-30, 0, -5}, glm::vec3(1)), Containment::Outside},
        {"above the view", boxAround({0, 30, -5}, glm::vec3(1)), Containment::Outside},
        {"beyond the far plane", boxAround({0, 0, -150}, glm::vec3(10)), Containment::Outside},
        {"straddling the left plane", boxAround({-5, 0, -5}, glm::vec3(1)), Containment::Intersecting},
        {"straddling the near plane (around the eye)", boxAround({0, 0, 0}, glm::vec3(1)), Containment::Intersecting},
        {"straddling the far plane", boxAround({0, 0, -100}, glm::vec3(4)), Containment::Intersecting},
        {"containing the whole frustum", boxAround({0, 0, 0}, glm::vec3(1000)), Containment::Intersecting},
        {"empty", Aabb{}, Containment::Outside},
    };
    std::vector<Aabb> boxes;
    std::vector<std::uint32_t> expectedVisible;
    for (const Case& c : cases) {
        EXPECT_EQ(f.classify(c.box), c.expected) << c.what;
        if (c.expected != Containment::Outside) expectedVisible.push_back(static_cast<std::uint32_t>(boxes.size()));
        boxes.push_back(c.box);
    }
    EXPECT_EQ(bvhCull(Bvh(boxes), f), expectedVisible);
}

TEST(Frustum, ABoxExactlyOnAPlaneIsKept) {
    // Orthographic: the planes are exact, so "touching" is exact too.
    const Frustum ortho(glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 1.0f, 10.0f));
    EXPECT_NE(ortho.classify(box({-2, 0, -5}, {-1, 0.5f, -4})), Containment::Outside) << "max.x on the left plane";
    EXPECT_NE(ortho.classify(box({1, 0, -5}, {2, 0.5f, -4})), Containment::Outside) << "min.x on the right plane";
    EXPECT_NE(ortho.classify(box({0, 1, -5}, {0.5f, 3, -4})), Containment::Outside) << "min.y on the top plane";
    EXPECT_NE(ortho.classify(box({0, 0, -12}, {0.5f, 0.5f, -10})), Containment::Outside) << "max.z on the far plane";
    EXPECT_NE(ortho.classify(box({0, 0, -1}, {0.5f, 0.5f, 3})), Containment::Outside) << "min.z on the near plane";
    EXPECT_NE(ortho.classify(box({-1, -1, -1}, {-1, -1, -1})), Containment::Outside) << "a point on a corner";
    EXPECT_NE(ortho.classify(box({-3, 0, -5}, {-1, 0, -5})), Containment::Outside) << "a flat box on a plane";
    EXPECT_EQ(ortho.classify(box({-2, 0, -5}, {-1.001f, 0.5f, -4})), Containment::Outside) << "1 mm beyond";

    // Perspective with a 90° field of view: the left plane is x = z, the top plane y = −z. Each
    // box below lies outside but for one corner on the plane (x ∈ [−6, −5], z ∈ [−5, −4]: only
    // (−5, y, −5) has x = z). The plane extraction rounds, which must not cull it.
    const Frustum persp(perspectiveView(glm::vec3(0), glm::vec3(0, 0, -1)));
    EXPECT_NE(persp.classify(box({-6, -0.5f, -5}, {-5, 0.5f, -4})), Containment::Outside) << "corner on the left plane";
    EXPECT_NE(persp.classify(box({-0.5f, 5, -5}, {0.5f, 6, -4})), Containment::Outside) << "corner on the top plane";
    EXPECT_NE(persp.classify(box({-0.05f, -0.05f, -0.1f}, {0.05f, 0.05f, 0.5f})), Containment::Outside)
        << "face on the near plane";
    EXPECT_EQ(persp.classify(box({-6, -0.5f, -5}, {-5.01f, 0.5f, -4})), Containment::Outside) << "1 cm beyond";
    EXPECT_EQ(persp.classify(box({-0.5f, 5.01f, -5}, {0.5f, 6, -4})), Containment::Outside) << "1 cm above";

    // And through the BVH, where the touching box shares nodes with boxes well inside.
    const std::vector<Aabb> boxes = {box({-6, -0.5f, -5}, {-5, 0.5f, -4}), boxAround({0, 0, -5}, glm::vec3(1)),
                                     box({-6, -0.5f, -5}, {-5.01f, 0.5f, -4}), boxAround({0, 0, 5}, glm::vec3(1))};
    EXPECT_EQ(bvhCull(Bvh(boxes), persp), (std::vector<std::uint32_t>{0, 1}));
}

TEST(Frustum, InfiniteFarPlaneKeepsEverythingInFront) {
    const Frustum f(glm::infinitePerspective(1.0f, 1.0f, 0.1f) * glm::lookAt(glm::vec3(0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0)));
    EXPECT_EQ(f.planes()[Frustum::Far], glm::vec4(0, 0, 0, 1)) << "degenerate plane constrains nothing";
    EXPECT_EQ(f.classify(boxAround({0, 0, -1e6f}, glm::vec3(1))), Containment::Inside);
    EXPECT_EQ(f.classify(boxAround({0, 0, 10}, glm::vec3(1))), Containment::Outside);
}

TEST(Frustum, DefaultFrustumKeepsEverything) {
    const Frustum all;
    EXPECT_EQ(all.classify(boxAround({1e6f, -1e6f, 3}, glm::vec3(1))), Containment::Inside);
    EXPECT_EQ(all.classify(Aabb{}), Containment::Outside);
}

// ---- randomized: BVH == brute force ----

struct Random {
    explicit Random(unsigned seed) : engine(seed) {}
    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(engine); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine); }
    glm::vec3 point(float extent) { return {uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)}; }
    std::mt19937 engine;
};

// Boxes of very different sizes, some flat or a single point, a few empty.
std::vector<Aabb> randomBoxes(Random& random, int count) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < count; ++i) {
        const int kind = random.integer(0, 19);
        if (kind == 0) {
            boxes.push_back(Aabb{});
            continue;
        }
        glm::vec3 size(std::exp(random.uniform(std::log(0.01f), std::log(40.0f))), std::exp(random.uniform(-4.0f, 3.0f)),
                       std::exp(random.uniform(-4.0f, 3.0f)));
        if (kind == 1) size = glm::vec3(0.0f);                 // a point
        if (kind == 2) size[random.integer(0, 2)] = 0.0f;      // a flat quad
        boxes.push_back(boxAround(random.point(60.0f), size));
    }
    return boxes;
}

glm::mat4 randomViewProjection(Random& random) {
    const glm::vec3 eye = random.point(50.0f);
    glm::vec3 target = random.point(50.0f);
    if (glm::length(target - eye) < 1.0f) target = eye + glm::vec3(0, 0, -1);
    const glm::vec3 forward = glm::normalize(target - eye);
    const glm::vec3 up = std::abs(forward.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::mat4 view = glm::lookAt(eye, target, up);
    const float nearPlane = std::exp(random.uniform(std::log(0.01f), std::log(5.0f)));
    const float farPlane = nearPlane + random.uniform(1.0f, 200.0f);
    switch (random.integer(0, 3)) {
        case 0: {  // orthographic, e.g. a directional light's shadow view
            const float w = random.uniform(0.5f, 60.0f), h = random.uniform(0.5f, 60.0f);
            const float shift = random.uniform(-20.0f, 20.0f);
            return glm::ortho(-w + shift, w + shift, -h, h, random.uniform(-50.0f, 5.0f), farPlane) * view;
        }
        case 1: {  // a point light's cube face
            glm::mat4 faces[6];
            cubeFaceViewProjections(eye, nearPlane, farPlane, faces);
            return faces[random.integer(0, 5)];
        }
        case 2:  // infinitely far
            return glm::infinitePerspective(random.uniform(0.1f, 2.5f), random.uniform(0.3f, 3.0f), nearPlane) * view;
        default:
            return glm::perspective(random.uniform(0.1f, 2.5f), random.uniform(0.3f, 3.0f), nearPlane, farPlane) * view;
    }
}

// A point strictly inside clip space (with a small margin against rounding) is visible.
bool clearlyVisible(const glm::mat4& viewProjection, const glm::vec3& p) {
    const glm::vec4 c = viewProjection * glm::vec4(p, 1.0f);
    const float inner = c.w * (1.0f - 1e-3f);
    return c.w > 0.0f && std::abs(c.x) < inner && std::abs(c.y) < inner && std::abs(c.z) < inner;
}

// Independent of Frustum::classify: if any of a box's corners, its centre or some of its points
// is clearly visible, the culling result must hold the box.
void expectNoVisibleBoxCulled(Random& random, const std::vector<Aabb>& boxes, const glm::mat4& viewProjection,
                              const std::vector<std::uint32_t>& visible, int& checkedVisible) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Aabb& b = boxes[i];
        if (b.empty()) continue;
        bool seen = clearlyVisible(viewProjection, b.center());
        for (int corner = 0; corner < 8 && !seen; ++corner)
            seen = clearlyVisible(viewProjection, {(corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                                                   (corner & 4) ? b.max.z : b.min.z});
        for (int s = 0; s < 8 && !seen; ++s)
            seen = clearlyVisible(viewProjection, glm::mix(b.min, b.max, glm::vec3(random.uniform(0, 1), random.uniform(0, 1),
                                                                                   random.uniform(0, 1))));
        if (!seen) continue;
        ++checkedVisible;
        ASSERT_TRUE(std::binary_search(visible.begin(), visible.end(), static_cast<std::uint32_t>(i)))
            << "box " << i << " has a visible point but was culled";
    }
}

TEST(Bvh, EqualsBruteForceOnRandomScenesAndFrusta) {
    int cases = 0, culledSomething = 0, keptSomething = 0, checkedVisible = 0;
    for (unsigned seed = 1; seed <= 150; ++seed) {
        Random random(seed);
        const std::vector<Aabb> boxes = randomBoxes(random, random.integer(0, 400));
        const Bvh bvh(boxes);
        ASSERT_EQ(bvh.itemCount(), boxes.size());
        ASSERT_LT(bvh.nodeCount(), 2 * boxes.size() + 1);
        for (int f = 0; f < 20; ++f) {
            const glm::mat4 viewProjection = randomViewProjection(random);
            const Frustum frustum(viewProjection);
            const std::vector<std::uint32_t> expected = bruteForce(boxes, frustum);
            const std::vector<std::uint32_t> got = bvhCull(bvh, frustum);
            ASSERT_EQ(got, expected) << "seed " << seed << ", frustum " << f;
            expectNoVisibleBoxCulled(random, boxes, viewProjection, got, checkedVisible);
            ++cases;
            culledSomething += got.size() < boxes.size();
            keptSomething += !got.empty();
        }
    }
    EXPECT_EQ(cases, 3000);
    // The random frusta must exercise both outcomes, not keep or cull everything.
    EXPECT_GT(culledSomething, cases / 2);
    EXPECT_GT(keptSomething, cases / 2);
    EXPECT_GT(checkedVisible, 10000);
}

TEST(Bvh, RefitAfterMovingBoxesStillEqualsBruteForce) {
    int cases = 0;
    for (unsigned seed = 1000; seed < 1060; ++seed) {
        Random random(seed);
        std::vector<Aabb> boxes = randomBoxes(random, random.integer(1, 300));
        Bvh bvh(boxes);
        for (int step = 0; step < 5; ++step) {
            // Move a random subset, some far; some boxes become empty or reappear (a rebuild).
            for (Aabb& b : boxes) {
                const int what = random.integer(0, 9);
                if (what < 3 && !b.empty()) {
                    const glm::vec3 offset = random.point(what == 0 ? 100.0f : 5.0f);
                    b.min += offset;
                    b.max += offset;
                } else if (what == 3 && step == 2) {
                    b = b.empty() ? boxAround(random.point(60.0f), glm::vec3(1.0f)) : Aabb{};
                }
            }
            bvh.refit(boxes);
            ASSERT_EQ(bvh.itemBounds().size(), boxes.size());
            for (int f = 0; f < 10; ++f) {
                const Frustum frustum(randomViewProjection(random));
                ASSERT_EQ(bvhCull(bvh, frustum), bruteForce(boxes, frustum)) << "seed " << seed << ", step " << step;
                ++cases;
            }
        }
        for (const Aabb& b : boxes)
            if (!b.empty()) {
                EXPECT_EQ(glm::min(bvh.bounds().min, b.min), bvh.bounds().min);
                EXPECT_EQ(glm::max(bvh.bounds().max, b.max), bvh.bounds().max);
            }
    }
    EXPECT_EQ(cases, 3000);
}

TEST(Bvh, StaysShallowAndHandlesCoincidentBoxes) {
    Random random(7);
    const Bvh bvh(randomBoxes(random, 4096));
    EXPECT_LE(bvh.depth(), 30) << "4096 random boxes";
    // All boxes identical: no centroid split exists; the tree splits by position in the list.
    const std::vector<Aabb> same(100, boxAround({1, 2, 3}, glm::vec3(1)));
    const Bvh stack(same);
    EXPECT_LE(stack.depth(), 8);
    const Frustum f(perspectiveView(glm::vec3(1, 2, 10), glm::vec3(1, 2, 3)));
    EXPECT_EQ(bvhCull(stack, f).size(), 100u);
    EXPECT_TRUE(bvhCull(Bvh(std::vector<Aabb>{}), f).empty());
    EXPECT_TRUE(bvhCull(Bvh(std::vector<Aabb>(5)), f).empty()) << "only empty boxes";
}

TEST(Bvh, AFrustumAroundEverythingAcceptsTheRootWhole) {
    Random random(3);
    const std::vector<Aabb> boxes = randomBoxes(random, 200);
    const Frustum everything(glm::ortho(-100.0f, 100.0f, -100.0f, 100.0f, -100.0f, 100.0f));
    std::vector<std::uint32_t> expected;
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (!boxes[i].empty()) expected.push_back(static_cast<std::uint32_t>(i));
    EXPECT_EQ(everything.classify(Bvh(boxes).bounds()), Containment::Inside);
    EXPECT_EQ(bvhCull(Bvh(boxes), everything), expected);
}

// ---- built from a scene's draw items ----

// The draw items GpuScene would make (GpuScene itself needs GL): one per primitive per node.
std::vector<DrawItem> drawItemsOf(const Scene& scene) {
    std::vector<DrawItem> items;
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        const Node& node = scene.nodes[n];
        if (node.mesh < 0) continue;
        for (const Primitive& p : scene.meshes[static_cast<std::size_t>(node.mesh)].primitives)
            items.push_back({static_cast<int>(n), p.material, 0, 0, static_cast<std::uint32_t>(p.indices.size()), p.bounds});
    }
    return items;
}

TEST(Bvh, RefitFollowsTheSceneHierarchy) {
    Scene scene;
    Random random(11);
    // A parent with children: moving the parent moves them all.
    const int parent = addMeshNode(scene, makeBoxMesh("parent", glm::vec3(1), -1), glm::vec3(0, 0, -5));
    for (int i = 0; i < 30; ++i) {
        const int child = addMeshNode(scene, makeBoxMesh("child", glm::vec3(random.uniform(0.1f, 2.0f)), -1), random.point(10.0f));
        scene.roots.erase(std::find(scene.roots.begin(), scene.roots.end(), child));
        scene.nodes[static_cast<std::size_t>(child)].parent = parent;
        scene.nodes[static_cast<std::size_t>(parent)].children.push_back(child);
    }
    for (int i = 0; i < 50; ++i)
        addMeshNode(scene, makeBoxMesh("loose", glm::vec3(random.uniform(0.1f, 3.0f)), -1), random.point(40.0f),
                    glm::angleAxis(random.uniform(0.0f, 6.0f), glm::normalize(random.point(1.0f) + glm::vec3(0, 0.01f, 0))));
    scene.updateWorldTransforms();
    const std::vector<DrawItem> items = drawItemsOf(scene);
    ASSERT_EQ(items.size(), 81u);
    Bvh bvh(scene, items);

    const Frustum frustum(perspectiveView(glm::vec3(0, 0, 10), glm::vec3(0, 0, 0)));
    const auto check = [&](const char* when) {
        const std::vector<Aabb> boxes = itemWorldBounds(scene, items);
        EXPECT_EQ(bvhCull(bvh, frustum), bruteForce(boxes, frustum)) << when;
        return bruteForce(boxes, frustum);
    };
    const std::vector<std::uint32_t> before = check("as built");
    EXPECT_TRUE(std::binary_search(before.begin(), before.end(), 0u)) << "the parent is in view";

    // Move the parent (and so its children) behind the camera, and a few loose boxes.
    scene.nodes[static_cast<std::size_t>(parent)].translation = glm::vec3(0, 0, 60);
    for (int i = 0; i < 10; ++i) scene.nodes[static_cast<std::size_t>(31 + i)].translation = random.point(40.0f);
    scene.updateWorldTransforms();
    ++scene.geometryRevision;
    bvh.refit(scene);
    const std::vector<std::uint32_t> after = check("after refit");
    for (std::uint32_t i = 0; i <= 30; ++i)
        EXPECT_FALSE(std::binary_search(after.begin(), after.end(), i)) << "item " << i << " moved behind the camera";
}

TEST(Bvh, ClearErrors) {
    Scene scene;
    addMeshNode(scene, makeBoxMesh("box", glm::vec3(1), -1), glm::vec3(0));
    scene.updateWorldTransforms();
    std::vector<DrawItem> items = drawItemsOf(scene);
    Bvh fromScene(scene, items);

    Bvh fromBoxes(std::vector<Aabb>{boxAround({0, 0, 0}, glm::vec3(1))});
    EXPECT_THROW(fromBoxes.refit(scene), std::invalid_argument);
    EXPECT_THROW(fromBoxes.refit(std::vector<Aabb>(2)), std::invalid_argument);

    const Scene empty;
    try {
        fromScene.refit(empty);
        FAIL() << "refit against a scene without the item's node";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "draw item 0 refers to node 0, but the scene has 0 nodes: the items belong to another scene");
    }
    items[0].node = 5;
    EXPECT_THROW(Bvh(scene, items), std::invalid_argument);
}

}  // namespace
}  // namespace lit
