#include <gtest/gtest.h>

#include <algorithm>

#include "PathEditing.h"
#include "ViewportOverlay.h"
#include "Log.h"
#include "Properties.h"
#include "scene/OverlayShapes.h"
#include "scene/SceneBuilder.h"

#include <shared.h>

namespace {

using namespace lit;
using namespace lit::editor;

Document sceneWithLightAndCamera() {
    Scene scene;
    const int material = addMaterial(scene, glm::vec3(0.5f));
    const int box = addMeshNode(scene, makeBoxMesh("box", glm::vec3(1.0f), material), glm::vec3(0.0f));
    scene.nodes[static_cast<std::size_t>(box)].name = "Box";
    Log log;
    Light sun;
    sun.type = LightType::Directional;
    addLightNode(scene, sun, glm::vec3(0.0f), glm::vec3(-0.3f, -1.0f, -0.45f));
    addDefaultCamera(scene, log);
    scene.updateWorldTransforms();
    return Document(std::move(scene), CameraPath{}, {});
}

CameraView viewOf(const Document& doc) { return frameBounds(doc.scene.worldBounds(), 16.0f / 9.0f); }

TEST(ViewportOverlay, MarksLightsAndCamerasAndNothingElseWithoutSelection) {
    const Document doc = sceneWithLightAndCamera();
    ASSERT_FALSE(doc.scene.lights.empty());
    ASSERT_FALSE(doc.scene.cameras.empty());
    const ViewportOverlay overlay = buildViewportOverlay(doc, viewOf(doc), {1280, 720}, OverlayOptions{});
    EXPECT_TRUE(overlay.activeOutline.empty());
    EXPECT_TRUE(overlay.selectedOutline.empty());
    EXPECT_FALSE(overlay.lines.empty());
    EXPECT_TRUE(overlay.linesOnTop.empty());  // no gizmo without a selection

    OverlayOptions none;
    none.markers = false;
    EXPECT_TRUE(buildViewportOverlay(doc, viewOf(doc), {1280, 720}, none).empty());
}

TEST(ViewportOverlay, SelectionGetsAnOutlineAndAGizmoAtTheNode) {
    Document doc = sceneWithLightAndCamera();
    doc.selectedNode = findNode(doc.scene, "Box");
    ASSERT_GE(doc.selectedNode, 0);
    doc.scene.nodes[static_cast<std::size_t>(doc.selectedNode)].translation = {0.5f, 0.25f, -1.0f};
    doc.touched(Change::Transform);
    const ViewportOverlay overlay = buildViewportOverlay(doc, viewOf(doc), {1280, 720}, OverlayOptions{});
    EXPECT_EQ(overlay.activeOutline, std::vector<int>{doc.selectedNode});
    ASSERT_FALSE(overlay.linesOnTop.empty());
    // Every gizmo axis starts at the node.
    int fromNode = 0;
    for (const OverlayLine& line : overlay.linesOnTop)
        if (glm::length(line.a - glm::vec3(0.5f, 0.25f, -1.0f)) < 1e-5f) ++fromNode;
    EXPECT_EQ(fromNode, 3);

    // A clean viewport (screenshots without UI) has neither.
    OverlayOptions clean;
    clean.markers = clean.gizmo = clean.cameraPath = clean.selectionOutline = false;
    EXPECT_TRUE(buildViewportOverlay(doc, viewOf(doc), {1280, 720}, clean).empty());
}

TEST(ViewportOverlay, TheCameraPathIsACurveThroughItsKeys) {
    Document doc = sceneWithLightAndCamera();
    const std::size_t before = buildViewportOverlay(doc, viewOf(doc), {1280, 720}, OverlayOptions{}).lines.size();
    FlyCamera camera;
    camera.position = {0, 1, 4};
    addKey(doc, keyFromCamera(camera, 0.0f));
    camera.position = {2, 1, 3};
    addKey(doc, keyFromCamera(camera, 2.0f));
    const ViewportOverlay overlay = buildViewportOverlay(doc, viewOf(doc), {1280, 720}, OverlayOptions{});
    ASSERT_GT(overlay.lines.size(), before + 2 * kPathCurveSamplesPerKey);
    // The curve starts at key 0 and ends at key 1.
    bool startsAtKey = false, endsAtKey = false;
    for (const OverlayLine& line : overlay.lines) {
        startsAtKey |= glm::length(line.a - glm::vec3(0, 1, 4)) < 1e-4f;
        endsAtKey |= glm::length(line.b - glm::vec3(2, 1, 3)) < 1e-4f;
    }
    EXPECT_TRUE(startsAtKey);
    EXPECT_TRUE(endsAtKey);
}

TEST(ViewportOverlay, ConeDirectionsViewDrawsSixDiffuseConesAndTheSpecularOnes) {
    Document doc = sceneWithLightAndCamera();
    doc.settings.indirect.specularSamples = 2;
    doc.settings.gi.mode = GiMode::Fast;  // the fixed six-cone set's wireframe cones
    OverlayOptions options;
    options.markers = false;
    SurfaceSample surface;
    surface.position = {0.0f, 0.5f, 0.0f};
    surface.normal = {0.0f, 1.0f, 0.0f};
    surface.roughness = 0.5f;
    surface.voxelSize = 0.05f;
    surface.volumeSide = 3.2f;
    options.coneSurface = surface;
    options.coneCameraPosition = {0.0f, 2.0f, 3.0f};
    const ViewportOverlay overlay = buildViewportOverlay(doc, viewOf(doc), {1280, 720}, options);
    const std::size_t cones = tracedCones(surface, options.coneCameraPosition, doc.settings).size();
    EXPECT_GE(cones, 7u);
    EXPECT_EQ(overlay.linesOnTop.size(), cones * coneLines({}, {0, 1, 0}, 1.0f, 1.0f, {}).size());
}

// The accurate mode traces, per low-resolution texel, one of the stratified sets (cone_strata.glsl):
// the view draws the picked pixel's set, each diffuse cone as its axis and the sampled footprint
// (a circle per march sample), not the fixed six-cone set's wireframe cones.
TEST(ViewportOverlay, ConeDirectionsViewDrawsThePixelsStratifiedSetInTheAccurateMode) {
    Document doc = sceneWithLightAndCamera();
    doc.settings.gi.coneFootprintPerHeight = kAccurateGiFootprint;
    doc.settings.indirect.scale = 1;
    OverlayOptions options;
    options.markers = false;
    options.coneCameraPosition = {0.0f, 3.0f, 0.0f};
    SurfaceSample surface;
    surface.position = {0.0f, 0.5f, 0.0f};
    surface.normal = {0.0f, 1.0f, 0.0f};
    surface.roughness = 0.0f;  // a mirror: its specular cone is marched, drawn as a plain cone
    surface.voxelSize = 0.025f;
    surface.volumeSide = 3.2f;
    // The normal cone's end point for two neighbouring pixels: different sets, different cones.
    std::vector<glm::vec3> capEnds;
    for (const glm::ivec2 pixel : {glm::ivec2(10, 20), glm::ivec2(11, 20)}) {
        surface.glPixel = pixel;
        options.coneSurface = surface;
        const ViewportOverlay overlay = buildViewportOverlay(doc, viewOf(doc), {1280, 720}, options);
        const std::vector<TracedCone> cones = tracedCones(surface, options.coneCameraPosition, doc.settings);
        ASSERT_GT(cones.size(), std::size_t(LIT_DIFFUSE_CONE_COUNT));
        const int set = coneSetIndex(pixel);
        std::size_t expectedLines = 0;
        for (int i = 0; i < LIT_DIFFUSE_CONE_COUNT; ++i) {
            const TracedCone& cone = cones[static_cast<std::size_t>(i)];
            const float length = std::min(cone.length, 0.25f * surface.volumeSide);  // as addCones draws it
            EXPECT_EQ(cone.coneSet, set);
            // The set's angle to the normal (the directions themselves: tests/gl/test_cone_mirror.cpp).
            EXPECT_NEAR(glm::dot(cone.direction, surface.normal), stratifiedDiffuseConeDirection(i, set).z, 1e-5f);
            const glm::vec3 end = cone.apex + cone.direction * length;
            const bool axisDrawn = std::any_of(overlay.linesOnTop.begin(), overlay.linesOnTop.end(), [&](const OverlayLine& l) {
                return glm::length(l.a - cone.apex) < 1e-5f && glm::length(l.b - end) < 1e-4f;
            });
            EXPECT_TRUE(axisDrawn) << "cone " << i << ", pixel " << pixel.x;
            if (i == 0) capEnds.push_back(end);
            const std::size_t samples =
                coneSamples(cone, surface.voxelSize, surface.volumeSide, doc.settings.gi.coneStepScale, length).size();
            EXPECT_GT(samples, 5u);
            expectedLines += 1 + samples * std::size_t(kConeSampleCircleSegments);
        }
        // The mirror's specular cones: plain wireframe cones.
        expectedLines += (cones.size() - LIT_DIFFUSE_CONE_COUNT) * coneLines({}, {0, 1, 0}, 1.0f, 1.0f, {}).size();
        EXPECT_EQ(overlay.linesOnTop.size(), expectedLines);
    }
    ASSERT_EQ(capEnds.size(), 2u);
    EXPECT_GT(glm::length(capEnds[0] - capEnds[1]), 1e-3f);
}

}  // namespace

namespace {

using namespace lit;
using namespace lit::editor;

// A selected group outlines its descendants with it (their pixels carry their own node IDs).
TEST(ViewportOverlay, ASelectedParentOutlinesItsChildren) {
    Scene scene;
    const int material = addMaterial(scene, glm::vec3(0.5f));
    const int group = addMeshNode(scene, makeBoxMesh("a", glm::vec3(1.0f), material), glm::vec3(0.0f));
    const int child = addMeshNode(scene, makeBoxMesh("b", glm::vec3(0.5f), material), glm::vec3(2.0f, 0.0f, 0.0f));
    const int grandchild = addMeshNode(scene, makeBoxMesh("c", glm::vec3(0.25f), material), glm::vec3(0.0f, 2.0f, 0.0f));
    const int other = addMeshNode(scene, makeBoxMesh("d", glm::vec3(0.5f), material), glm::vec3(-2.0f, 0.0f, 0.0f));
    const int otherChild = addMeshNode(scene, makeBoxMesh("e", glm::vec3(0.5f), material), glm::vec3(0.0f, 0.0f, 2.0f));
    const auto parent = [&](int node, int to) {
        std::erase(scene.roots, node);
        scene.nodes[static_cast<std::size_t>(node)].parent = to;
        scene.nodes[static_cast<std::size_t>(to)].children.push_back(node);
    };
    parent(child, group);
    parent(grandchild, child);
    parent(otherChild, other);
    scene.updateWorldTransforms();
    Document doc(std::move(scene), CameraPath{}, {});
    doc.select(other);
    doc.select(group, /*additive=*/true);
    const ViewportOverlay overlay = buildViewportOverlay(doc, viewOf(doc), {1280, 720}, OverlayOptions{});
    std::vector<int> active = overlay.activeOutline, selected = overlay.selectedOutline;
    std::sort(active.begin(), active.end());
    std::sort(selected.begin(), selected.end());
    EXPECT_EQ(active, (std::vector<int>{group, child, grandchild}));
    EXPECT_EQ(selected, (std::vector<int>{other, otherChild}));
}

TEST(ViewportOverlay, EverySelectedNodeIsOutlinedAndBoxesOnlyForThoseWithoutPixels) {
    Document doc = sceneWithLightAndCamera();
    const int box = findNode(doc.scene, "Box");
    doc.select(box);
    const ViewportOverlay single = buildViewportOverlay(doc, viewOf(doc), {1280, 720}, OverlayOptions{});
    const int light = doc.scene.nodeOfLight(0);
    doc.select(light, /*additive=*/true);  // the light is active, the box is the other
    const ViewportOverlay both = buildViewportOverlay(doc, viewOf(doc), {1280, 720}, OverlayOptions{});
    EXPECT_EQ(both.activeOutline, std::vector<int>{light});
    EXPECT_EQ(both.selectedOutline, std::vector<int>{box});  // outlined, not boxed
    EXPECT_EQ(both.linesOnTop.size(), single.linesOnTop.size());  // the gizmo (same mode, now at the light)
    doc.select(light);
    doc.select(box, /*additive=*/true);  // the box is active; the light draws nothing to outline
    const ViewportOverlay lightOther = buildViewportOverlay(doc, viewOf(doc), {1280, 720}, OverlayOptions{});
    EXPECT_EQ(lightOther.activeOutline, std::vector<int>{box});
    EXPECT_EQ(lightOther.linesOnTop.size(), single.linesOnTop.size() + 12);  // the light's box: 12 edges

    OverlayOptions rotate;
    rotate.gizmoMode = GizmoMode::Rotate;
    doc.select(box);
    EXPECT_EQ(buildViewportOverlay(doc, viewOf(doc), {1280, 720}, rotate).linesOnTop.size(),
              3u * TransformGizmo::kRingSegments);
}

}  // namespace
