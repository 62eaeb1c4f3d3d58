// Scenes built in code, and the defaults given to scenes without lights or cameras.
#include "Log.h"
#include "scene/SceneBuilder.h"

#include <gtest/gtest.h>

namespace lit {
namespace {

TEST(SceneBuilder, BoxHasOutwardNormalsAndCounterClockwiseFaces) {
    const Mesh box = makeBoxMesh("box", glm::vec3(2.0f, 1.0f, 0.5f), 0);
    ASSERT_EQ(box.primitives.size(), 1u);
    const Primitive& p = box.primitives[0];
    EXPECT_EQ(p.indices.size(), 36u);
    EXPECT_EQ(p.bounds.min, glm::vec3(-1.0f, -0.5f, -0.25f));
    EXPECT_EQ(p.bounds.max, glm::vec3(1.0f, 0.5f, 0.25f));
    for (std::size_t i = 0; i < p.indices.size(); i += 3) {
        const Vertex& a = p.vertices[p.indices[i]];
        const Vertex& b = p.vertices[p.indices[i + 1]];
        const Vertex& c = p.vertices[p.indices[i + 2]];
        const glm::vec3 faceNormal = glm::cross(b.position - a.position, c.position - a.position);
        EXPECT_GT(glm::dot(faceNormal, a.normal), 0.0f) << "triangle " << i / 3 << " is wound clockwise";
        EXPECT_GT(glm::dot(a.normal, a.position), 0.0f) << "normal points inwards";
    }
}

TEST(SceneBuilder, LightNodeShinesAlongTheGivenDirection) {
    Scene scene;
    Light light;
    light.type = LightType::Spot;
    const int node = addLightNode(scene, light, glm::vec3(1, 2, 3), glm::vec3(0, -1, 1));
    const glm::vec3 forward = glm::vec3(scene.nodes[std::size_t(node)].world * glm::vec4(0, 0, -1, 0));
    EXPECT_NEAR(glm::dot(glm::normalize(forward), glm::normalize(glm::vec3(0, -1, 1))), 1.0f, 1e-5f);
    EXPECT_EQ(glm::vec3(scene.nodes[std::size_t(node)].world[3]), glm::vec3(1, 2, 3));
}

TEST(SceneDefaults, SceneWithoutCamerasGetsOneAndNoLight) {
    Scene scene;
    addMeshNode(scene, makeBoxMesh("box", glm::vec3(1.0f), -1), glm::vec3(0.0f));
    Log log;
    log.setSink(nullptr);
    EXPECT_TRUE(addDefaultCamera(scene, log));
    // No light node: the renderer lights a scene without lights itself (default sun and sky), so
    // a save does not write a light the user never made.
    EXPECT_TRUE(scene.lights.empty());
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_GE(scene.nodeOfCamera(0), 0);
    // Never the framing view's near plane (metres outside a large scene): flying in must not clip.
    EXPECT_LE(scene.cameras[0].znear, 0.05f);
    const auto messages = log.recent();
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].text.find("no cameras"), std::string::npos);
    // A second call adds nothing.
    EXPECT_FALSE(addDefaultCamera(scene, log));
    EXPECT_EQ(scene.cameras.size(), 1u);
}

}  // namespace
}  // namespace lit
