#pragma once
// A small scene for the Document / Properties / DocumentIO tests: a box with a material of its
// own, a box on the default material, a spot light, a camera and an empty node, each with a
// name the tests select by.

#include "Document.h"
#include "scene/SceneBuilder.h"

namespace lit::editor::testing {

inline Scene fixtureScene() {
    Scene scene;
    scene.name = "fixture";
    const int red = addMaterial(scene, {0.8f, 0.1f, 0.1f}, 0.5f, 0.0f, "Red");
    addMeshNode(scene, makeBoxMesh("Box", {1.0f, 1.0f, 1.0f}, red), {0.0f, 0.5f, 0.0f});
    addMeshNode(scene, makeBoxMesh("Plain", {0.5f, 0.5f, 0.5f}, -1), {2.0f, 0.25f, 0.0f});
    Light spot;
    spot.name = "Lamp";
    spot.type = LightType::Spot;
    spot.intensity = 10.0f;
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.6f;
    addLightNode(scene, spot, {0.0f, 3.0f, 0.0f}, {0.0f, -1.0f, 0.0f});
    Camera camera;
    camera.name = "Cam";
    camera.zfar = 50.0f;
    addCameraNode(scene, camera, {0.0f, 1.0f, 5.0f}, {0.0f, 0.5f, 0.0f});
    Node empty;
    empty.name = "Empty";
    scene.nodes.push_back(empty);
    scene.roots.push_back(static_cast<int>(scene.nodes.size()) - 1);
    scene.updateWorldTransforms();
    return scene;
}

inline CameraPath fixturePath() {
    std::vector<CameraKey> keys(2);
    keys[0].time = 0.0f;
    keys[0].position = {0.0f, 1.0f, 5.0f};
    keys[1].time = 2.0f;
    keys[1].position = {3.0f, 1.0f, 4.0f};
    keys[1].yfov = 0.7f;
    return CameraPath(keys);
}

inline Document fixtureDocument() { return Document(fixtureScene(), fixturePath(), "fixture.gltf"); }

}  // namespace lit::editor::testing
