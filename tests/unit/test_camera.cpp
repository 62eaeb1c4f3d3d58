// Camera math (renderer/scene/CameraView.cpp): view and projection conventions, framing,
// scene cameras, the fly camera and directional shadow fitting.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/CameraView.h"
#include "scene/Scene.h"

namespace lit {
namespace {

std::array<glm::vec3, 8> corners(const Aabb& b) {
    std::array<glm::vec3, 8> out;
    for (int i = 0; i < 8; ++i)
        out[static_cast<std::size_t>(i)] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                                            (i & 4) ? b.max.z : b.min.z};
    return out;
}

glm::vec3 toNdc(const glm::mat4& viewProjection, const glm::vec3& p) {
    const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// A camera world matrix: at `position`, rotated by `rotation`.
glm::mat4 pose(const glm::vec3& position, const glm::quat& rotation) {
    return glm::translate(glm::mat4(1.0f), position) * glm::mat4_cast(rotation);
}

TEST(CameraView, ViewMapsPositionToOriginAndForwardToMinusZ) {
    const glm::vec3 position{3.0f, -2.0f, 5.0f};
    const glm::quat rotation = glm::angleAxis(0.9f, glm::normalize(glm::vec3(0.2f, 1.0f, -0.4f)));
    const CameraView v = makeCameraView(pose(position, rotation), 0.8f, 16.0f / 9.0f, 0.1f, 50.0f);

    expectNear(glm::vec3(v.view * glm::vec4(position, 1.0f)), glm::vec3(0.0f));
    const glm::vec3 forwardWorld = rotation * glm::vec3(0.0f, 0.0f, -1.0f);
    expectNear(v.forward(), forwardWorld);
    expectNear(glm::vec3(v.view * glm::vec4(forwardWorld, 0.0f)), glm::vec3(0.0f, 0.0f, -1.0f));
    expectNear(v.position, position);
    // Up stays up: the camera's local +Y maps to view +Y.
    expectNear(glm::vec3(v.view * glm::vec4(rotation * glm::vec3(0, 1, 0), 0.0f)), glm::vec3(0, 1, 0));
}

TEST(CameraView, ScaleInTheWorldMatrixIsIgnored) {
    const glm::mat4 world =
        pose({1, 2, 3}, glm::angleAxis(0.4f, glm::vec3(0, 1, 0))) * glm::scale(glm::mat4(1.0f), glm::vec3(0.008f));
    const CameraView v = makeCameraView(world, 0.8f, 1.0f, 0.1f, 10.0f);
    // A rigid view preserves lengths.
    EXPECT_NEAR(glm::length(glm::vec3(v.view * glm::vec4(1.0f, 0.0f, 0.0f, 0.0f))), 1.0f, 1e-5f);
    expectNear(glm::vec3(v.view * glm::vec4(1, 2, 3, 1)), glm::vec3(0.0f));
}

TEST(CameraView, ProjectionIsOpenGlClipSpace) {
    const CameraView v = makeCameraView(glm::mat4(1.0f), 0.8f, 1.5f, 0.5f, 20.0f);
    // Points on the near and far planes straight ahead land at z_ndc = −1 and +1.
    EXPECT_NEAR(toNdc(v.viewProjection(), {0, 0, -0.5f}).z, -1.0f, 1e-5f);
    EXPECT_NEAR(toNdc(v.viewProjection(), {0, 0, -20.0f}).z, 1.0f, 1e-4f);
    // The top edge of the vertical field of view lands at y_ndc = 1.
    const float y = std::tan(0.4f) * 10.0f;
    EXPECT_NEAR(toNdc(v.viewProjection(), {0, y, -10.0f}).y, 1.0f, 1e-5f);
    EXPECT_NEAR(toNdc(v.viewProjection(), {y * 1.5f, 0, -10.0f}).x, 1.0f, 1e-5f);
}

void expectBoxInsideFrustum(const CameraView& v, const Aabb& box) {
    for (const glm::vec3& c : corners(box)) {
        const glm::vec4 clip = v.viewProjection() * glm::vec4(c, 1.0f);
        EXPECT_GT(clip.w, 0.0f);
        EXPECT_LE(std::abs(clip.x), clip.w * (1.0f + 1e-5f)) << c.x << " " << c.y << " " << c.z;
        EXPECT_LE(std::abs(clip.y), clip.w * (1.0f + 1e-5f)) << c.x << " " << c.y << " " << c.z;
        EXPECT_LE(std::abs(clip.z), clip.w * (1.0f + 1e-5f)) << c.x << " " << c.y << " " << c.z;
    }
}

TEST(CameraView, FrameBoundsKeepsAllCornersInsideTheFrustum) {
    const Aabb boxes[] = {
        {{-1, -1, -1}, {1, 1, 1}},
        {{-15.4f, -1.0f, -9.5f}, {14.4f, 11.4f, 8.8f}},  // Sponza's extent
        {{100, 0, 0}, {100.5f, 20, 0.2f}},               // tall and thin, far from the origin
        {{0, 0, 0}, {1, 0, 1}},                          // flat
    };
    for (float aspect : {0.5f, 1.0f, 16.0f / 9.0f, 3.0f}) {
        for (const Aabb& box : boxes) {
            SCOPED_TRACE(testing::Message() << "aspect " << aspect << " box max " << box.max.x);
            const CameraView v = frameBounds(box, aspect, 0.8f);
            expectBoxInsideFrustum(v, box);
            // Looking at the box from the +Z side and above.
            EXPECT_LT(v.forward().z, 0.0f);
            EXPECT_LT(v.forward().y, 0.0f);
            EXPECT_GT(v.position.z, box.max.z);
        }
    }
}

TEST(CameraView, FrameBoundsIsNotWastefullyFarAway) {
    const Aabb box{{-1, -1, -1}, {1, 1, 1}};
    const CameraView v = frameBounds(box, 1.0f, 0.8f);
    // The sphere (radius √3) must fill the narrower half-angle: distance = r / sin(0.4).
    EXPECT_NEAR(glm::distance(v.position, box.center()), std::sqrt(3.0f) / std::sin(0.4f), 1e-3f);
    // The box's centre is in the middle of the image.
    expectNear(toNdc(v.viewProjection(), box.center()) * glm::vec3(1, 1, 0), glm::vec3(0.0f));
}

TEST(CameraView, FrameBoundsOfAnEmptySceneIsFinite) {
    const CameraView v = frameBounds(Aabb{}, 1.0f);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(v.viewProjection()[c][r]));
}

Scene sceneWithBoxAndCamera(const glm::mat4& cameraPose, float zfar) {
    Scene scene;
    Mesh mesh;
    Primitive p;
    p.bounds = {{-2, 0, -2}, {2, 3, 2}};
    mesh.primitives.push_back(p);
    scene.meshes.push_back(mesh);
    Node box;
    box.mesh = 0;
    scene.nodes.push_back(box);
    scene.cameras.push_back(Camera{"wide", 1.2f, 0.0f, 0.05f, 0.0f});
    scene.cameras.push_back(Camera{"main", 0.6f, 2.0f, 0.2f, zfar});
    Node camera;
    camera.name = "main camera node";
    camera.camera = 1;
    camera.translation = glm::vec3(cameraPose[3]);
    camera.rotation = glm::quat_cast(glm::mat3(cameraPose));
    scene.nodes.push_back(camera);
    scene.roots = {0, 1};
    scene.updateWorldTransforms();
    return scene;
}

TEST(CameraView, SceneCameraViewUsesTheSceneCamera) {
    const glm::mat4 cameraPose = pose({0, 1.5f, 10}, glm::angleAxis(0.1f, glm::vec3(0, 1, 0)));
    const Scene scene = sceneWithBoxAndCamera(cameraPose, 40.0f);
    const CameraView v = sceneCameraView(scene, 1, 1.5f);
    expectNear(v.position, glm::vec3(0, 1.5f, 10));
    expectNear(v.forward(), glm::angleAxis(0.1f, glm::vec3(0, 1, 0)) * glm::vec3(0, 0, -1));
    EXPECT_FLOAT_EQ(v.yfov, 0.6f);
    EXPECT_FLOAT_EQ(v.znear, 0.2f);
    EXPECT_FLOAT_EQ(v.zfar, 40.0f);
    // The output's aspect (1.5) wins over the camera's (2.0), so the image is not stretched.
    EXPECT_NEAR(v.projection[1][1] / v.projection[0][0], 1.5f, 1e-5f);
}

TEST(CameraView, SceneCameraViewFitsNearAndFarWhenZfarIsOpen) {
    const Scene scene = sceneWithBoxAndCamera(pose({0, 1.5f, 30}, glm::quat(1, 0, 0, 0)), 0.0f);
    const CameraView v = sceneCameraView(scene, 1, 1.0f);
    const Aabb bounds = scene.worldBounds();
    // Far covers every corner; near is raised above the camera's 0.2 m towards the scene for
    // depth precision, but never beyond the nearest corner.
    float nearest = 1e9f, farthest = 0.0f;
    for (const glm::vec3& c : corners(bounds)) {
        const float depth = -(v.view * glm::vec4(c, 1.0f)).z;
        nearest = std::min(nearest, depth);
        farthest = std::max(farthest, depth);
    }
    EXPECT_GE(v.zfar, farthest);
    EXPECT_LE(v.zfar, 2.0f * farthest);  // fitted, not an arbitrary huge value
    EXPECT_GE(v.znear, 0.2f);
    EXPECT_LE(v.znear, nearest);
    EXPECT_GT(v.znear, 1.0f);  // camera is 28 m from the box: a 0.2 m near plane would waste precision

    // From inside the scene near stays at the camera's own value.
    const Scene inside = sceneWithBoxAndCamera(pose({0, 1.5f, 0}, glm::quat(1, 0, 0, 0)), 0.0f);
    const CameraView w = sceneCameraView(inside, 1, 1.0f);
    EXPECT_FLOAT_EQ(w.znear, 0.2f);
    EXPECT_GT(w.zfar, glm::length(glm::vec3(2, 1.5f, 2)));
}

TEST(CameraView, SceneCameraViewFallsBackToFramingTheScene) {
    const Scene scene = sceneWithBoxAndCamera(pose({0, 1.5f, 10}, glm::quat(1, 0, 0, 0)), 40.0f);
    const Aabb bounds = scene.worldBounds();
    for (int index : {-1, 7, 0 /* camera 0 is on no node */}) {
        const CameraView v = sceneCameraView(scene, index, 1.0f);
        const CameraView framed = frameBounds(bounds, 1.0f, 0.8f);
        expectNear(v.position, framed.position);
        expectBoxInsideFrustum(v, bounds);
    }
}

TEST(FlyCamera, YawAndPitchFollowTheConventions) {
    FlyCamera fly;
    expectNear(fly.forward(), {0, 0, -1});
    expectNear(fly.right(), {1, 0, 0});
    fly.yaw = glm::half_pi<float>();  // positive yaw turns left (right-handed about +Y)
    expectNear(fly.forward(), {-1, 0, 0});
    expectNear(fly.right(), {0, 0, -1});
    fly.yaw = 0.0f;
    fly.pitch = 0.3f;
    EXPECT_NEAR(fly.forward().y, std::sin(0.3f), 1e-6f);

    fly.position = {1, 2, 3};
    fly.yaw = 0.7f;
    fly.pitch = -0.4f;
    const CameraView v = fly.view(1.3f, 0.1f, 100.0f);
    expectNear(v.forward(), fly.forward());
    expectNear(glm::vec3(v.view * glm::vec4(fly.position, 1.0f)), glm::vec3(0.0f));
    expectNear(glm::vec3(v.view * glm::vec4(fly.right(), 0.0f)), {1, 0, 0});
}

TEST(FlyCamera, LookingStraightDownIsWellDefined) {
    FlyCamera fly;
    fly.pitch = -glm::half_pi<float>();
    const CameraView v = fly.view(1.0f, 0.1f, 10.0f);
    expectNear(v.forward(), {0, -1, 0});
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(v.view[c][r]));
}

TEST(FlyCamera, SetFromViewRoundTrips) {
    FlyCamera source;
    source.position = {-4, 2, 7};
    source.yaw = -2.5f;
    source.pitch = 0.6f;
    source.yfov = 1.1f;
    FlyCamera copy;
    copy.setFromView(source.view(1.0f, 0.1f, 100.0f));
    expectNear(copy.position, source.position);
    EXPECT_NEAR(copy.yaw, source.yaw, 1e-5f);
    EXPECT_NEAR(copy.pitch, source.pitch, 1e-5f);
    EXPECT_NEAR(copy.yfov, 1.1f, 1e-6f);
}

void expectShadowFit(const glm::vec3& direction, const Aabb& box) {
    SCOPED_TRACE(testing::Message() << "direction " << direction.x << " " << direction.y << " " << direction.z);
    const glm::mat4 lightViewProjection = fitDirectionalShadow(direction, box);
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& c : corners(box)) {
        const glm::vec4 clip = lightViewProjection * glm::vec4(c, 1.0f);
        EXPECT_NEAR(clip.w, 1.0f, 1e-6f);  // orthographic
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(clip[k], -1.0f);
            EXPECT_LE(clip[k], 1.0f);
        }
        lo = glm::min(lo, glm::vec2(clip));
        hi = glm::max(hi, glm::vec2(clip));
    }
    // The box's silhouette touches the map's edges in x and y (tight fit, ≥ 99 % per axis), so
    // the box fills most of the map.
    EXPECT_GT(hi.x - lo.x, 1.98f);
    EXPECT_GT(hi.y - lo.y, 1.98f);
    // Points nearer the light have smaller depth: moving against the light direction from the
    // centre decreases z_ndc.
    const glm::vec3 center = box.center();
    const float zCenter = (lightViewProjection * glm::vec4(center, 1.0f)).z;
    const float zTowardsLight = (lightViewProjection * glm::vec4(center - 0.1f * glm::normalize(direction), 1.0f)).z;
    EXPECT_LT(zTowardsLight, zCenter);
}

TEST(DirectionalShadow, AllCornersMapIntoTheClipCubeAndFillTheMap) {
    const Aabb boxes[] = {
        {{-1, -1, -1}, {1, 1, 1}}, {{-15.4f, -1.0f, -9.5f}, {14.4f, 11.4f, 8.8f}}, {{5, 0, 5}, {6, 0.01f, 9}}};
    const glm::vec3 directions[] = {{0, -1, 0},           {0.3f, -1, 0.2f}, {1, 0, 0},
                                    {-0.5f, -0.2f, 0.9f}, {0, 1, 0},        {0, -1, 1e-4f}};
    for (const Aabb& box : boxes)
        for (const glm::vec3& d : directions) expectShadowFit(d, box);
}

TEST(DirectionalShadow, StraightDownOnAUnitBoxIsExactlyTheBox) {
    const glm::mat4 m = fitDirectionalShadow({0, -1, 0}, Aabb{{-1, -1, -1}, {1, 1, 1}});
    // The top face maps onto the whole map (±1 up to the 0.1 % margin).
    for (const glm::vec3& c : corners(Aabb{{-1, -1, -1}, {1, 1, 1}})) {
        const glm::vec4 clip = m * glm::vec4(c, 1.0f);
        EXPECT_NEAR(std::abs(clip.x), 1.0f, 3e-3f);
        EXPECT_NEAR(std::abs(clip.y), 1.0f, 3e-3f);
        EXPECT_NEAR(std::abs(clip.z), 1.0f, 3e-3f);
        // The top (y = +1) is nearest the light.
        EXPECT_LT(clip.z * c.y, 0.0f);
    }
}

TEST(DirectionalShadow, DegenerateInputIsFinite) {
    for (const glm::mat4& m :
         {fitDirectionalShadow({0, 0, 0}, Aabb{{0, 0, 0}, {1, 1, 1}}), fitDirectionalShadow({0, -1, 0}, Aabb{}),
          fitDirectionalShadow({0, -1, 0}, Aabb{{2, 2, 2}, {2, 2, 2}})})
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(m[c][r]));
}

}  // namespace
}  // namespace lit
