// Picking and the viewport overlay on the Cornell box (GI off unless said): the G-buffer's node
// IDs (Renderer::pickNode), the surface read back from a pixel (surfaceAt), the selection outline
// and overlay lines (OverlayPass). Nodes of assets/cornell_box.gltf: 0 floor, 1 ceiling, 2 back
// wall, 3 left wall (red, x = −1), 4 right wall (green, x = +1), 5 tall box, 6 short box.
#include <cstdio>
#include <cstdlib>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "GlTestSupport.h"
#include "gi/VoxelVolume.h"
#include "image/ImageIO.h"
#include "passes/OverlayPass.h"
#include "scene/OverlayShapes.h"

namespace lit::test {
namespace {

class Picking : public GlFixture {
protected:
    // Node world bounds (all primitives of its mesh).
    static Aabb nodeBounds(const Scene& scene, int node) {
        Aabb box;
        const Node& n = scene.nodes[static_cast<std::size_t>(node)];
        for (const Primitive& p : scene.meshes[static_cast<std::size_t>(n.mesh)].primitives)
            box.extend(p.bounds.transformed(n.world));
        return box;
    }
    // Where `world` appears, in top-left pixel coordinates (as pickNode takes them).
    glm::ivec2 topLeftPixel(const Scene& scene, const RenderSettings& settings, const glm::vec3& world) const {
        const glm::ivec2 p =
            projectToPixel(cameraFor(scene, settings), world, settings.output.width, settings.output.height);
        return {p.x, settings.output.height - 1 - p.y};
    }
    std::vector<std::uint8_t> renderRgba8(const Scene& scene, const RenderSettings& settings) {
        renderer_->render(scene, cameraFor(scene, settings), settings);
        return renderer_->readOutputRgba8();
    }
    // Sum over the image of |a − b| over RGB (bytes).
    static long difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
        long sum = 0;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (i % 4 != 3) sum += std::abs(int(a[i]) - int(b[i]));
        return sum;
    }
};

TEST_F(Picking, ObjectCentresPickTheirNodes) {
    const Scene scene = loadCornellBox();
    const RenderSettings settings = smallSettings(96);
    EXPECT_EQ(renderer_->pickNode({48, 48}), -1) << "no frame rendered yet";
    render(scene, settings);
    // Nodes whose bounds centre nothing else hides from the scene's camera.
    for (const int node : {3, 4, 5, 6}) {
        const glm::ivec2 pixel = topLeftPixel(scene, settings, nodeBounds(scene, node).center());
        EXPECT_EQ(renderer_->pickNode(pixel), node)
            << scene.nodes[static_cast<std::size_t>(node)].name << " at pixel " << pixel.x << "," << pixel.y;
    }
    // The top-left origin: the ceiling is in the top row of the image, the floor near the bottom.
    EXPECT_EQ(renderer_->pickNode({48, 1}), 1) << "ceiling at the top";
    EXPECT_EQ(renderer_->pickNode(topLeftPixel(scene, settings, {-0.6f, 0.0f, 0.6f})), 0) << "floor";
    for (const glm::ivec2 outside : {glm::ivec2(-1, 10), glm::ivec2(96, 10), glm::ivec2(10, -1), glm::ivec2(10, 96)})
        EXPECT_EQ(renderer_->pickNode(outside), -1) << outside.x << "," << outside.y;
}

// The Cornell box with both boxes as two primitives of one node's mesh (a one-node scene's parts):
// the tall box's node draws the short box too (its vertices moved into the tall box's frame), and
// the short box's node draws nothing.
Scene boxesAsOneMesh(Scene scene) {
    Node& tall = scene.nodes[5];
    Node& shortBox = scene.nodes[6];
    const glm::mat4 toTall = glm::inverse(tall.world) * shortBox.world;
    const glm::mat3 normalToTall = glm::mat3(toTall);  // rotations only in this scene
    std::vector<Primitive> moved = scene.meshes[static_cast<std::size_t>(shortBox.mesh)].primitives;
    for (Primitive& p : moved) {
        p.bounds = {};
        for (Vertex& v : p.vertices) {
            v.position = glm::vec3(toTall * glm::vec4(v.position, 1.0f));
            v.normal = glm::normalize(normalToTall * v.normal);
            v.tangent = glm::vec4(glm::normalize(normalToTall * glm::vec3(v.tangent)), v.tangent.w);
            p.bounds.extend(v.position);
        }
    }
    Mesh& mesh = scene.meshes[static_cast<std::size_t>(tall.mesh)];
    EXPECT_EQ(mesh.primitives.size(), 1u);
    mesh.primitives.insert(mesh.primitives.end(), moved.begin(), moved.end());
    shortBox.mesh = -1;
    return scene;
}

TEST_F(Picking, APrimitiveOfAOneNodeMeshIsPickedAndOutlinedAlone) {
    const Scene scene = boxesAsOneMesh(loadCornellBox());
    const RenderSettings settings = smallSettings(96);
    renderer_->setScene(scene);
    const std::vector<std::uint8_t> plain = renderRgba8(scene, settings);
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(scene.nodes[5].mesh)];
    const Aabb tallBounds = mesh.primitives[0].bounds.transformed(scene.nodes[5].world);
    const Aabb shortBounds = mesh.primitives[1].bounds.transformed(scene.nodes[5].world);
    const glm::ivec2 tallPixel = topLeftPixel(scene, settings, tallBounds.center());
    const glm::ivec2 shortPixel = topLeftPixel(scene, settings, shortBounds.center());
    EXPECT_EQ(renderer_->pickPrimitive(tallPixel), (PickedPrimitive{5, 0}));
    EXPECT_EQ(renderer_->pickPrimitive(shortPixel), (PickedPrimitive{5, 1}));
    EXPECT_EQ(renderer_->pickNode(shortPixel), 5);
    EXPECT_EQ(renderer_->pickPrimitive(topLeftPixel(scene, settings, {-0.6f, 0.0f, 0.6f})), (PickedPrimitive{0, 0}));
    // The whole node outlined, then its second primitive alone: the ring moves off the tall box.
    const int w = settings.output.width, h = settings.output.height;
    std::vector<std::optional<PickedPrimitive>> ids(static_cast<std::size_t>(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ids[static_cast<std::size_t>(y * w + x)] = renderer_->pickPrimitive({x, y});
    // Pixels of the background walls within 2 px of exactly one of the two primitives.
    const auto ringOf = [&](int primitive) {
        std::vector<int> ring;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::optional<PickedPrimitive>& id = ids[static_cast<std::size_t>(y * w + x)];
                if (id && id->node == 5) continue;
                bool near[2] = {false, false};
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) {
                        if (dx * dx + dy * dy > 5 || x + dx < 0 || y + dy < 0 || x + dx >= w || y + dy >= h) continue;
                        const std::optional<PickedPrimitive>& q = ids[static_cast<std::size_t>((y + dy) * w + x + dx)];
                        if (q && q->node == 5) near[q->primitive] = true;
                    }
                if (near[primitive] && !near[1 - primitive]) ring.push_back(y * w + x);
            }
        return ring;
    };
    const auto changedAt = [&](const std::vector<std::uint8_t>& image, const std::vector<int>& pixels) {
        int changed = 0;
        for (const int p : pixels) {
            const int x = p % w, y = h - 1 - p / w;  // readOutputRgba8 rows are bottom-up
            const std::size_t i = 4 * static_cast<std::size_t>(y * w + x);
            changed += std::abs(int(image[i]) - int(plain[i])) + std::abs(int(image[i + 1]) - int(plain[i + 1])) > 20;
        }
        return changed;
    };
    const std::vector<int> tallRing = ringOf(0), shortRing = ringOf(1);
    ASSERT_GT(tallRing.size(), 20u);
    ASSERT_GT(shortRing.size(), 20u);
    ViewportOverlay overlay;
    overlay.activeOutline = {5};
    renderer_->setOverlay(overlay);
    const std::vector<std::uint8_t> whole = renderRgba8(scene, settings);
    EXPECT_GT(changedAt(whole, tallRing), static_cast<int>(tallRing.size()) * 9 / 10);
    EXPECT_GT(changedAt(whole, shortRing), static_cast<int>(shortRing.size()) * 9 / 10);
    overlay.activePrimitive = PickedPrimitive{5, 1};
    renderer_->setOverlay(overlay);
    const std::vector<std::uint8_t> part = renderRgba8(scene, settings);
    EXPECT_EQ(changedAt(part, tallRing), 0) << "the tall box is not the picked primitive";
    EXPECT_GT(changedAt(part, shortRing), static_cast<int>(shortRing.size()) * 9 / 10);
    renderer_->setOverlay({});
}

TEST_F(Picking, BackgroundPicksNothing) {
    const Scene scene = loadCornellBox();
    const RenderSettings settings = smallSettings(64);
    renderer_->setScene(scene);
    // From outside the box, looking away from it.
    const glm::mat4 awayWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 4.0f)) *
                                glm::rotate(glm::mat4(1.0f), glm::pi<float>(), glm::vec3(0, 1, 0));
    renderer_->render(scene, makeCameraView(awayWorld, 0.8f, 1.0f, 0.1f, 20.0f), settings);
    for (const glm::ivec2 p : {glm::ivec2(0, 0), glm::ivec2(32, 32), glm::ivec2(63, 63)}) {
        EXPECT_EQ(renderer_->pickNode(p), -1);
        EXPECT_FALSE(renderer_->surfaceAt(p).has_value());
    }
}

TEST_F(Picking, SurfaceAtReadsNormalPositionAndMaterial) {
    const Scene scene = loadCornellBox();
    RenderSettings settings = smallSettings(96);
    settings.gi.enabled = true;  // so the sample carries the voxel volume it was traced in
    settings.gi.voxelResolution = 64;
    render(scene, settings);
    struct Case {
        int node;
        glm::vec3 world, normal;
    };
    for (const Case& c : {Case{3, {-1.0f, 1.2f, 0.3f}, {1, 0, 0}}, Case{4, {1.0f, 1.2f, 0.3f}, {-1, 0, 0}},
                          Case{0, {-0.6f, 0.0f, 0.6f}, {0, 1, 0}}, Case{1, {0.3f, 2.0f, 0.3f}, {0, -1, 0}},
                          Case{2, {0.2f, 1.6f, -1.0f}, {0, 0, 1}}}) {
        const glm::ivec2 pixel = topLeftPixel(scene, settings, c.world);
        const std::optional<SurfaceSample> s = renderer_->surfaceAt(pixel);
        ASSERT_TRUE(s.has_value()) << "node " << c.node;
        EXPECT_EQ(s->node, c.node);
        EXPECT_GT(glm::dot(s->normal, c.normal), 0.999f) << "node " << c.node;
        // The unprojected position lies on the face (the plane through c.world with that normal)
        // and within a pixel's footprint of the point projected (≈ 3 cm at this distance and size).
        EXPECT_NEAR(glm::dot(s->position - c.world, c.normal), 0.0f, 2e-3f) << "node " << c.node;
        EXPECT_LT(glm::length(s->position - c.world), 0.06f) << "node " << c.node;
        EXPECT_NEAR(s->roughness, 0.9f, 1.0f / 255.0f);
        EXPECT_NEAR(s->metalness, 0.0f, 1.0f / 255.0f);
        EXPECT_EQ(s->glPixel, glm::ivec2(pixel.x, settings.output.height - 1 - pixel.y));
        ASSERT_NE(renderer_->voxels(), nullptr);
        EXPECT_FLOAT_EQ(s->volumeSide, renderer_->voxels()->side());
        EXPECT_FLOAT_EQ(s->voxelSize, renderer_->voxels()->voxelSize());
    }
}

TEST_F(Picking, HighlightOutlinesOnlyTheSelectedSilhouette) {
    const Scene scene = loadCornellBox();
    const RenderSettings settings = smallSettings(96);
    renderer_->setScene(scene);
    const std::vector<std::uint8_t> plain = renderRgba8(scene, settings);
    const std::vector<float> plainHdr = renderer_->readHdrRgb();
    constexpr int kNode = 5;  // tall box
    ViewportOverlay overlay;
    overlay.activeOutline = {kNode};
    renderer_->setOverlay(overlay);
    const std::vector<std::uint8_t> outlined = renderRgba8(scene, settings);
    EXPECT_TRUE(renderer_->readHdrRgb() == plainHdr) << "the overlay must not touch the HDR image";
    const int w = settings.output.width, h = settings.output.height;
    std::vector<int> ids(static_cast<std::size_t>(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ids[static_cast<std::size_t>(y * w + x)] = renderer_->pickNode({x, y});
    const auto idAt = [&](int x, int y) { return ids[static_cast<std::size_t>(y * w + x)]; };
    int changed = 0, ring = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // Within the 2 px disc outside the silhouette (not on the node itself)?
            bool nearNode = false;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx)
                    if (dx * dx + dy * dy <= 5 && x + dx >= 0 && y + dy >= 0 && x + dx < w && y + dy < h &&
                        idAt(x + dx, y + dy) == kNode)
                        nearNode = true;
            const bool inRing = nearNode && idAt(x, y) != kNode;
            ring += inRing;
            // readOutputRgba8 rows are bottom-up.
            const std::size_t i = (static_cast<std::size_t>(h - 1 - y) * w + x) * 4;
            const bool differs = outlined[i] != plain[i] || outlined[i + 1] != plain[i + 1] || outlined[i + 2] != plain[i + 2];
            changed += differs;
            if (differs) {
                EXPECT_TRUE(inRing) << "pixel " << x << "," << y << " changed away from the outline";
            }
            if (inRing) {
                // Orange: sRGB (255, 140, 0) give or take the 8-bit encoding.
                EXPECT_EQ(outlined[i], 255);
                EXPECT_NEAR(outlined[i + 1], 140, 2);
                EXPECT_EQ(outlined[i + 2], 0);
            }
        }
    }
    EXPECT_GT(ring, 40) << "the tall box's outline should be a long ring at 96²";
    EXPECT_GE(changed, ring * 9 / 10) << "ring pixels that already were orange-ish may not change";
    std::printf("outline: %d ring pixels, %d changed\n", ring, changed);

    // No overlay again: the output is exactly the plain image.
    renderer_->setOverlay({});
    EXPECT_TRUE(renderRgba8(scene, settings) == plain);
}

// A selection of two nodes (as Blender draws it): the active tall box ringed in light orange, the
// other selected node, the short box, in darker orange; pixels of either box are never covered.
TEST_F(Picking, EverySelectedNodeIsOutlinedTheActiveOneBrighter) {
    const Scene scene = loadCornellBox();
    const RenderSettings settings = smallSettings(96);
    renderer_->setScene(scene);
    const std::vector<std::uint8_t> plain = renderRgba8(scene, settings);
    constexpr int kTall = 5, kShort = 6;
    ViewportOverlay overlay;
    overlay.activeOutline = {kTall};
    overlay.selectedOutline = {kShort};
    renderer_->setOverlay(overlay);
    const std::vector<std::uint8_t> outlined = renderRgba8(scene, settings);
    const int w = settings.output.width, h = settings.output.height;
    std::vector<int> ids(static_cast<std::size_t>(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ids[static_cast<std::size_t>(y * w + x)] = renderer_->pickNode({x, y});
    const auto idAt = [&](int x, int y) { return ids[static_cast<std::size_t>(y * w + x)]; };
    const auto near = [&](int x, int y, int node) {
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx)
                if (dx * dx + dy * dy <= 5 && x + dx >= 0 && y + dy >= 0 && x + dx < w && y + dy < h &&
                    idAt(x + dx, y + dy) == node)
                    return true;
        return false;
    };
    int activeRing = 0, selectedRing = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = (static_cast<std::size_t>(h - 1 - y) * w + x) * 4;  // rows bottom-up
            const int id = idAt(x, y);
            if (id == kTall || id == kShort) {
                EXPECT_TRUE(outlined[i] == plain[i] && outlined[i + 1] == plain[i + 1] && outlined[i + 2] == plain[i + 2])
                    << "pixel " << x << "," << y << " of a selected box was drawn over";
                continue;
            }
            if (near(x, y, kTall)) {  // the active colour wins where both rings meet
                ++activeRing;
                EXPECT_EQ(outlined[i], 255);
                EXPECT_NEAR(outlined[i + 1], 140, 2);
                EXPECT_EQ(outlined[i + 2], 0);
            } else if (near(x, y, kShort)) {
                ++selectedRing;
                EXPECT_NEAR(outlined[i], 230, 2);  // sRGB (230, 80, 0) give or take the 8-bit encoding
                EXPECT_NEAR(outlined[i + 1], 80, 2);
                EXPECT_EQ(outlined[i + 2], 0);
            } else {
                EXPECT_TRUE(outlined[i] == plain[i] && outlined[i + 1] == plain[i + 1] && outlined[i + 2] == plain[i + 2])
                    << "pixel " << x << "," << y << " changed away from the outlines";
            }
        }
    EXPECT_GT(activeRing, 40);
    EXPECT_GT(selectedRing, 30) << "the short box's outline should be a ring too at 96²";
    std::printf("outlines: %d active, %d selected ring pixels\n", activeRing, selectedRing);
}

TEST_F(Picking, LinesOnTopAndBehindWalls) {
    const Scene scene = loadCornellBox();
    const RenderSettings settings = smallSettings(96);
    renderer_->setScene(scene);
    const std::vector<std::uint8_t> plain = renderRgba8(scene, settings);
    const glm::vec4 cyan(0.0f, 1.0f, 1.0f, 1.0f);
    // Inside the box, in free space in front of the back wall.
    const OverlayLine open{{-0.5f, 1.5f, 0.5f}, {0.5f, 1.5f, 0.5f}, cyan};
    // Behind the back wall (z = −1): hidden from the camera.
    const OverlayLine hidden{{-0.5f, 1.5f, -1.5f}, {0.5f, 1.5f, -1.5f}, cyan};

    const auto renderWith = [&](std::vector<OverlayLine> tested, std::vector<OverlayLine> onTop) {
        ViewportOverlay overlay;
        overlay.lines = std::move(tested);
        overlay.linesOnTop = std::move(onTop);
        renderer_->setOverlay(std::move(overlay));
        return renderRgba8(scene, settings);
    };

    // The on-top line changes the pixels it crosses: sample along its projection.
    const std::vector<std::uint8_t> onTop = renderWith({}, {open});
    const glm::ivec2 a =
        projectToPixel(cameraFor(scene, settings), open.a, settings.output.width, settings.output.height);
    const glm::ivec2 b =
        projectToPixel(cameraFor(scene, settings), open.b, settings.output.width, settings.output.height);
    int crossed = 0, samples = 0;
    for (float t = 0.05f; t < 0.96f; t += 0.05f, ++samples) {
        const glm::ivec2 p = glm::ivec2(glm::mix(glm::vec2(a), glm::vec2(b), t) + 0.5f);
        bool changed = false;  // the rasterized line may sit one pixel off the rounded point
        for (int dy = -1; dy <= 1; ++dy) {
            const std::size_t i = (static_cast<std::size_t>(p.y + dy) * settings.output.width + p.x) * 4;
            changed |= onTop[i] != plain[i] || onTop[i + 1] != plain[i + 1] || onTop[i + 2] != plain[i + 2];
        }
        crossed += changed;
    }
    EXPECT_EQ(crossed, samples) << "points along the on-top line that changed";

    // A depth-tested line in free space is drawn as strongly as on top.
    const long openTested = difference(renderWith({open}, {}), plain);
    const long openOnTop = difference(onTop, plain);
    EXPECT_GT(openOnTop, 0);
    EXPECT_EQ(openTested, openOnTop) << "nothing hides this line";

    // Behind the wall: faint when depth-tested, full strength on top.
    const long behindTested = difference(renderWith({hidden}, {}), plain);
    const long behindOnTop = difference(renderWith({}, {hidden}), plain);
    std::printf("line pixel difference: open %ld (tested) / %ld (on top); behind wall %ld (tested) / %ld (on top)\n",
                openTested, openOnTop, behindTested, behindOnTop);
    EXPECT_GT(behindTested, 0) << "hidden parts are drawn faint, not dropped";
    EXPECT_LT(behindTested, behindOnTop * 3 / 4) << "hidden parts are faint (the difference is in sRGB bytes)";
    // Exactly as faint as the same line on top with its alpha scaled by kHiddenLineOpacity.
    OverlayLine faint = hidden;
    faint.color.a *= OverlayPass::kHiddenLineOpacity;
    EXPECT_TRUE(renderWith({hidden}, {}) == renderWith({}, {faint}));
}

TEST_F(Picking, ProfiledAsOverlayOnlyWhenThereIsOne) {
    const Scene scene = loadCornellBox();
    const RenderSettings settings = smallSettings(256);
    renderer_->setScene(scene);
    renderer_->render(scene, cameraFor(scene, settings), settings);
    renderer_->profiler().flush();
    EXPECT_EQ(renderer_->profiler().lastRun("overlay"), nullptr);
    ViewportOverlay overlay;
    overlay.activeOutline = {5};
    overlay.linesOnTop = translateGizmoLines(glm::vec3(0.0f, 1.0f, 0.0f), 0.3f);
    renderer_->setOverlay(overlay);
    // The first frame with an overlay also compiles its shaders' draw state on llvmpipe.
    for (int frame = 0; frame < 3; ++frame) renderer_->render(scene, cameraFor(scene, settings), settings);
    renderer_->profiler().flush();
    const PassTiming* timing = renderer_->profiler().lastRun("overlay");
    ASSERT_NE(timing, nullptr);
    std::printf("overlay pass (outline + gizmo, %dx%d): %.3f ms GPU, %.3f ms CPU\n", settings.output.width,
                settings.output.height, timing->gpuMs, timing->cpuMs);
}

// Everything the editor draws, in one picture for people to look at (tests/output/overlay.png):
// the tall box outlined with the gizmo at its centre, the spot light's and the camera's markers,
// and the cones traced from a floor pixel (diffuse white, specular yellow).
TEST_F(Picking, WritesAnOverlayPicture) {
    const Scene scene = loadCornellBox();
    RenderSettings settings = smallSettings(192);
    settings.gi.enabled = true;
    settings.gi.voxelResolution = 64;
    renderer_->setScene(scene);
    const CameraView camera = cameraFor(scene, settings);
    renderer_->render(scene, camera, settings);
    const glm::ivec2 floorPixel = topLeftPixel(scene, settings, {-0.3f, 0.0f, 0.5f});
    const std::optional<SurfaceSample> sample = renderer_->surfaceAt(floorPixel);
    ASSERT_TRUE(sample.has_value());
    ASSERT_EQ(sample->node, 0);

    ViewportOverlay overlay;
    overlay.activeOutline = {5};
    overlay.linesOnTop = translateGizmoLines(nodeBounds(scene, 5).center(), 0.4f);
    const int spotNode = scene.nodeOfLight(0);
    ASSERT_GE(spotNode, 0);
    const std::vector<OverlayLine> spot = lightMarkerLines(scene.lights[0], scene.nodes[static_cast<std::size_t>(spotNode)].world, 0.3f);
    overlay.lines.insert(overlay.lines.end(), spot.begin(), spot.end());
    for (const TracedCone& cone : tracedCones(*sample, camera.position, settings)) {
        const glm::vec4 color = cone.specular ? glm::vec4(1.0f, 0.9f, 0.1f, 1.0f) : glm::vec4(1.0f);
        const std::vector<OverlayLine> lines = coneLines(cone.apex, cone.direction, cone.aperture, std::min(cone.length, 0.5f), color);
        overlay.lines.insert(overlay.lines.end(), lines.begin(), lines.end());
    }
    // A second camera looking at the box from the side, to show a frustum marker.
    const glm::mat4 sideCamera = glm::translate(glm::mat4(1.0f), glm::vec3(0.6f, 1.4f, 0.2f)) *
                                 glm::rotate(glm::mat4(1.0f), 1.2f, glm::vec3(0, 1, 0));
    const std::vector<OverlayLine> frustum = cameraFrustumLines(sideCamera, 0.6f, 1.5f, 0.3f, glm::vec4(0.4f, 0.8f, 1.0f, 1.0f));
    overlay.lines.insert(overlay.lines.end(), frustum.begin(), frustum.end());
    renderer_->setOverlay(overlay);
    renderer_->render(scene, camera, settings);
    const std::vector<std::uint8_t> image = renderer_->readOutputRgba8();
    writePng(outputDir() / "overlay.png", settings.output.width, settings.output.height, image);
    EXPECT_EQ(renderer_->pickNode(floorPixel), 0) << "the overlay does not change the ID buffer";
}

}  // namespace
}  // namespace lit::test
