// Frustum culling in the renderer: a culled object is never visible, so images with culling on
// and off must be identical to the bit, while culling submits fewer draws. The scene has boxes in
// view, boxes behind the camera (some of them casting shadows into view) and boxes outside a spot
// light's cone, lit by a directional, a spot and a point light (one frustum per cube face).
// A floor of one large primitive, split into chunks on upload, is culled chunk by chunk.
// Also: the draw counts on Sponza from its default framing camera (skipped when it is absent).

#include "GlTestSupport.h"

#include "scene/Bvh.h"
#include "scene/Frustum.h"
#include "scene/GpuScene.h"
#include "scene/SceneBuilder.h"

#include <chrono>
#include <cstdio>

namespace lit::test {
namespace {

class Culling : public GlFixture {
protected:
    struct Frame {
        std::vector<std::uint8_t> rgba8;
        std::vector<float> hdr;
        FrameStats first;   // the frame that also rendered the shadow maps
        FrameStats steady;  // a later frame: shadow maps cached, only the camera view is culled
    };

    // The same scene rendered with culling off, then on (each from a fresh upload).
    struct OffOn {
        Frame off, on;
    };
    OffOn renderCullingOffAndOn(const Scene& scene, RenderSettings settings) {
        settings.output.frustumCulling = false;
        Frame off = renderTwice(scene, settings);
        settings.output.frustumCulling = true;
        return {std::move(off), renderTwice(scene, settings)};
    }

    // Renders `scene` from a fresh upload (so the shadow maps are redrawn under these settings).
    Frame renderTwice(const Scene& scene, const RenderSettings& settings) {
        renderer_->setScene(scene);
        const CameraView camera = cameraFor(scene, settings);
        Frame frame;
        renderer_->render(scene, camera, settings);
        frame.first = renderer_->stats();
        renderer_->render(scene, camera, settings);
        frame.steady = renderer_->stats();
        frame.rgba8 = renderer_->readOutputRgba8();
        frame.hdr = renderer_->readHdrRgb();
        return frame;
    }

    // A floor, three boxes in view, four behind the camera (two tall ones between the sun and
    // the floor in view), two far to the sides; sun, spot and point light; camera at +Z.
    static Scene makeScene() {
        Scene scene;
        const int white = addMaterial(scene, glm::vec3(0.8f), 0.9f, 0.0f, "white");
        const int red = addMaterial(scene, glm::vec3(0.8f, 0.1f, 0.1f), 0.5f, 0.0f, "red");
        addMeshNode(scene, makePlaneMesh("floor", 10.0f, white, 2), glm::vec3(0.0f));
        addMeshNode(scene, makeBoxMesh("in view 1", glm::vec3(0.6f), red), glm::vec3(-0.8f, 0.3f, 0.0f));
        addMeshNode(scene, makeBoxMesh("in view 2", glm::vec3(0.5f, 1.2f, 0.5f), white), glm::vec3(0.9f, 0.6f, -0.5f));
        addMeshNode(scene, makeBoxMesh("in view 3", glm::vec3(0.3f), red), glm::vec3(0.0f, 1.5f, -1.0f));
        // Behind the camera (at z = 5 looking towards −Z): never in the G-buffer. The tall ones
        // stand where the sun (shining towards +Z, down) casts their shadows into view... and
        // the camera cannot see them.
        addMeshNode(scene, makeBoxMesh("behind 1", glm::vec3(0.8f, 4.0f, 0.8f), white), glm::vec3(-1.0f, 2.0f, 7.0f));
        addMeshNode(scene, makeBoxMesh("behind 2", glm::vec3(0.8f, 4.0f, 0.8f), red), glm::vec3(1.5f, 2.0f, 8.0f));
        addMeshNode(scene, makeBoxMesh("behind 3", glm::vec3(0.5f), white), glm::vec3(0.0f, 0.5f, 9.0f));
        addMeshNode(scene, makeBoxMesh("behind 4", glm::vec3(1.0f), red), glm::vec3(3.0f, 3.0f, 6.5f));
        // Far to the sides, outside the camera's view and the spot light's cone.
        addMeshNode(scene, makeBoxMesh("side 1", glm::vec3(1.0f), white), glm::vec3(-4.5f, 0.5f, -4.5f));
        addMeshNode(scene, makeBoxMesh("side 2", glm::vec3(1.0f), white), glm::vec3(4.5f, 0.5f, -4.5f));

        Light sun;
        sun.type = LightType::Directional;
        sun.intensity = 2.0f;
        addLightNode(scene, sun, glm::vec3(0.0f), glm::vec3(0.1f, -0.6f, -1.0f));
        Light spot;
        spot.type = LightType::Spot;
        spot.intensity = 20.0f;
        spot.innerConeAngle = 0.3f;
        spot.outerConeAngle = 0.45f;
        addLightNode(scene, spot, glm::vec3(0.0f, 4.0f, 1.0f), glm::vec3(0.0f, -1.0f, -0.3f));
        Light point;
        point.type = LightType::Point;
        point.intensity = 5.0f;
        point.color = glm::vec3(0.6f, 0.7f, 1.0f);
        addLightNode(scene, point, glm::vec3(0.3f, 2.5f, 1.5f), glm::vec3(0.0f, -1.0f, 0.0f));

        Camera camera;
        camera.yfov = 0.8f;
        camera.znear = 0.1f;
        camera.zfar = 30.0f;
        addCameraNode(scene, camera, glm::vec3(0.0f, 2.0f, 5.0f), glm::vec3(0.0f, 0.5f, 0.0f));
        return scene;
    }

    // Items the camera's frustum keeps, by brute force over every item's world box. The items
    // are a GpuScene's own (large primitives split into chunks, as the renderer uploads them).
    std::size_t visibleFromCamera(const Scene& scene, const RenderSettings& settings) {
        const GpuScene gpuScene(scene, log_);
        const Frustum frustum(cameraFor(scene, settings).viewProjection());
        std::size_t visible = 0;
        for (const Aabb& box : itemWorldBounds(scene, gpuScene.items())) visible += frustum.intersects(box);
        return visible;
    }

    // A 24 m floor of 131072 triangles in one primitive (split into chunks on upload), a few
    // boxes on it, a sun; the camera stands in the middle of the floor, looking along it.
    static Scene makeBigFloorScene() {
        Scene scene;
        const int white = addMaterial(scene, glm::vec3(0.8f), 0.9f, 0.0f, "white");
        const int red = addMaterial(scene, glm::vec3(0.8f, 0.1f, 0.1f), 0.5f, 0.0f, "red");
        addMeshNode(scene, makePlaneMesh("big floor", 24.0f, white, 256), glm::vec3(0.0f));
        addMeshNode(scene, makeBoxMesh("ahead", glm::vec3(1.0f, 2.0f, 1.0f), red), glm::vec3(-1.0f, 1.0f, -4.0f));
        addMeshNode(scene, makeBoxMesh("behind", glm::vec3(1.0f, 3.0f, 1.0f), red), glm::vec3(0.5f, 1.5f, 4.0f));
        Light sun;
        sun.type = LightType::Directional;
        sun.intensity = 2.0f;
        addLightNode(scene, sun, glm::vec3(0.0f), glm::vec3(0.3f, -0.7f, -0.5f));
        Camera camera;
        camera.yfov = 0.8f;
        camera.znear = 0.1f;
        camera.zfar = 40.0f;
        addCameraNode(scene, camera, glm::vec3(0.0f, 1.6f, 0.0f), glm::vec3(0.0f, 0.8f, -6.0f));
        return scene;
    }

    static void expectIdentical(const Frame& on, const Frame& off) {
        ASSERT_EQ(on.rgba8.size(), off.rgba8.size());
        ASSERT_FALSE(on.rgba8.empty());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < on.rgba8.size(); ++i) differing += on.rgba8[i] != off.rgba8[i];
        EXPECT_EQ(differing, 0u) << "tone-mapped bytes that differ with culling on";
        ASSERT_EQ(on.hdr.size(), off.hdr.size());
        differing = 0;
        for (std::size_t i = 0; i < on.hdr.size(); ++i) differing += on.hdr[i] != off.hdr[i];
        EXPECT_EQ(differing, 0u) << "HDR values that differ with culling on";
    }
};

TEST_F(Culling, SameImageFewerDraws) {
    const Scene scene = makeScene();
    RenderSettings settings = smallSettings(128);
    settings.shadows.mapSize = 256;
    const auto [off, on] = renderCullingOffAndOn(scene, settings);
    expectIdentical(on, off);

    constexpr int kItems = 10;
    // The sun's map and its camera cascades, the spot's map, the point light's cube faces.
    const int shadowViews = 1 + settings.shadows.cascades + 1 + 6;
    EXPECT_EQ(off.first.drawsTotal, kItems * (1 + shadowViews));
    EXPECT_EQ(off.first.drawsSubmitted, off.first.drawsTotal);
    EXPECT_EQ(on.first.drawsTotal, off.first.drawsTotal);
    EXPECT_LT(on.first.drawsSubmitted, on.first.drawsTotal) << "camera and shadow views together";
    EXPECT_LT(on.first.drawCalls, off.first.drawCalls);

    // Once the shadow maps are cached only the camera's view is drawn and counted.
    EXPECT_EQ(off.steady.drawsTotal, kItems);
    EXPECT_EQ(off.steady.drawsSubmitted, kItems);
    EXPECT_EQ(on.steady.drawsTotal, kItems);
    EXPECT_EQ(on.steady.drawsSubmitted, static_cast<int>(visibleFromCamera(scene, settings)));
    EXPECT_LE(on.steady.drawsSubmitted, kItems - 4) << "the four boxes behind the camera are culled";
    EXPECT_LT(on.steady.triangles, off.steady.triangles);
    EXPECT_GE(on.steady.cullMs, 0.0);
    std::printf("culling test scene: camera view %d of %d draws; first frame (camera + %d shadow views) %d of %d\n",
                on.steady.drawsSubmitted, on.steady.drawsTotal, shadowViews, on.first.drawsSubmitted,
                on.first.drawsTotal);
}

TEST_F(Culling, SplitPrimitiveSameImageFewerDraws) {
    const Scene scene = makeBigFloorScene();
    const std::size_t floorTriangles = scene.meshes[0].primitives[0].indices.size() / 3;
    ASSERT_GT(floorTriangles, std::size_t{kDefaultChunkTriangles}) << "the floor must be large enough to be split";
    const int items = static_cast<int>(GpuScene(scene, log_).items().size());
    EXPECT_GE(items, static_cast<int>(floorTriangles / kDefaultChunkTriangles) + 2) << "the floor is split into chunks";

    RenderSettings settings = smallSettings(128);
    settings.shadows.mapSize = 256;
    const auto [off, on] = renderCullingOffAndOn(scene, settings);
    expectIdentical(on, off);
    EXPECT_EQ(off.steady.drawsTotal, items);
    EXPECT_EQ(off.steady.drawsSubmitted, items);
    EXPECT_EQ(off.steady.triangles, floorTriangles + 2 * 12);
    EXPECT_EQ(on.steady.drawsSubmitted, static_cast<int>(visibleFromCamera(scene, settings)));
    // Standing in the middle of the floor, the chunks behind the camera (about half) are culled.
    EXPECT_LE(on.steady.drawsSubmitted, items * 3 / 4);
    EXPECT_LT(on.steady.triangles, off.steady.triangles * 3 / 4);
    std::printf("split floor: camera view %d of %d draws, %zu of %zu triangles\n", on.steady.drawsSubmitted,
                on.steady.drawsTotal, on.steady.triangles, off.steady.triangles);
}

TEST_F(Culling, MovedObjectsAreRefitNotLost) {
    Scene scene = makeScene();
    RenderSettings settings = smallSettings(96);
    settings.shadows.mapSize = 256;
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    renderer_->render(scene, camera, settings);

    // Bring "behind 3" (node 6) into view and "in view 3" (node 3) out of it: a transform edit
    // without re-uploading the scene, as the editor does.
    scene.nodes[6].translation = glm::vec3(-0.2f, 0.25f, 1.0f);
    scene.nodes[3].translation = glm::vec3(0.0f, 1.5f, 12.0f);
    scene.updateWorldTransforms();
    ++scene.geometryRevision;
    settings.output.frustumCulling = true;
    renderer_->render(scene, camera, settings);
    renderer_->render(scene, camera, settings);  // shadows cached: camera draws only
    EXPECT_EQ(renderer_->stats().drawsSubmitted, static_cast<int>(visibleFromCamera(scene, settings)));
    const std::vector<float> on = renderer_->readHdrRgb();
    settings.output.frustumCulling = false;
    renderer_->setScene(scene);  // re-render the shadow maps without culling
    renderer_->render(scene, camera, settings);
    const std::vector<float> off = renderer_->readHdrRgb();
    EXPECT_TRUE(on == off) << "moved objects: the culled image differs";
}

TEST_F(Culling, SameImageWithGlobalIllumination) {
    // Voxelization draws everything; the injected light uses the (culled) shadow maps.
    const Scene scene = makeScene();
    RenderSettings settings = smallSettings(64);
    settings.gi.enabled = true;
    settings.gi.voxelResolution = 64;
    settings.shadows.mapSize = 256;
    const auto [off, on] = renderCullingOffAndOn(scene, settings);
    expectIdentical(on, off);
    EXPECT_LT(on.steady.drawsSubmitted, off.steady.drawsSubmitted);
}

TEST_F(Culling, SponzaDrawCountsFromTheDefaultCamera) {
    const std::filesystem::path path = sourceDir() / ".." / "shared" / "scenes" / "sponza" / "Sponza.gltf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "Sponza not found at " << path.string() << ": skipped";
    const auto start = std::chrono::steady_clock::now();
    Scene scene = loadGltf(path, log_);
    addDefaultCamera(scene, log_);
    const double loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RenderSettings settings = smallSettings();
    settings.output.width = 256;  // 16:9, the aspect of 1280×720: culling depends on the aspect, not the size
    settings.output.height = 144;
    settings.shadows.mapSize = 512;
    const auto [off, on] = renderCullingOffAndOn(scene, settings);
    std::printf("Sponza (default camera, 16:9): G-buffer draws %d with culling off, %d of %d with culling on; "
                "triangles %zu -> %zu; culling %.3f ms CPU; load %.1f s\n",
                off.steady.drawsSubmitted, on.steady.drawsSubmitted, on.steady.drawsTotal, off.steady.triangles,
                on.steady.triangles, on.steady.cullMs, loadSeconds);
    RecordProperty("draws_culling_off", off.steady.drawsSubmitted);
    RecordProperty("draws_culling_on", on.steady.drawsSubmitted);
    EXPECT_EQ(off.steady.drawsSubmitted, off.steady.drawsTotal);
    EXPECT_LE(on.steady.drawsSubmitted, off.steady.drawsSubmitted);
    EXPECT_EQ(on.steady.drawsSubmitted, static_cast<int>(visibleFromCamera(scene, settings)));
    expectIdentical(on, off);

    // The default camera frames the whole building, so every item is in view. From inside the
    // atrium (its middle, at a fifth of its height, looking down its long axis) the chunks of the
    // big primitives behind the camera are culled.
    Scene inside = loadGltf(path, log_);
    const Aabb bounds = inside.worldBounds();
    const glm::vec3 size = bounds.size();
    const int longAxis = size.x >= size.z ? 0 : 2;
    glm::vec3 eye = bounds.center();
    eye.y = bounds.min.y + 0.2f * size.y;
    glm::vec3 target = eye;
    target[longAxis] += 1.0f;
    Camera camera;
    camera.yfov = 0.9f;
    camera.znear = 0.05f;
    camera.zfar = 2.0f * glm::length(size);
    addCameraNode(inside, camera, eye, target);
    addDefaultCamera(inside, log_);
    const auto [insideOff, insideOn] = renderCullingOffAndOn(inside, settings);
    std::printf("Sponza (inside the atrium, 16:9): G-buffer draws %d with culling off, %d of %d with culling on; "
                "triangles %zu -> %zu; culling %.3f ms CPU\n",
                insideOff.steady.drawsSubmitted, insideOn.steady.drawsSubmitted, insideOn.steady.drawsTotal,
                insideOff.steady.triangles, insideOn.steady.triangles, insideOn.steady.cullMs);
    RecordProperty("inside_draws_culling_off", insideOff.steady.drawsSubmitted);
    RecordProperty("inside_draws_culling_on", insideOn.steady.drawsSubmitted);
    EXPECT_LT(insideOn.steady.drawsSubmitted, insideOff.steady.drawsSubmitted)
        << "the large primitives are split, so looking down the atrium culls what is behind";
    EXPECT_LT(insideOn.steady.triangles, insideOff.steady.triangles);
    expectIdentical(insideOn, insideOff);
}

}  // namespace
}  // namespace lit::test
