#pragma once
// Building scenes in code: boxes, planes, lights and cameras. Used by tests (scenes with a known
// answer) and to give a scene without lights or cameras sensible defaults.

#include "scene/Scene.h"

#include <string>

namespace lit {

// An axis-aligned box mesh of the given size centred on the origin, outward normals, UVs per face.
Mesh makeBoxMesh(const std::string& name, const glm::vec3& size, int material);
// A square in the XZ plane (normal +Y) of side `size`, centred on the origin, split n×n.
Mesh makePlaneMesh(const std::string& name, float size, int material, int subdivisions = 1);

// Appends and returns the new index. Nodes are added as roots.
int addMaterial(Scene& scene, const glm::vec3& baseColor, float roughness = 0.9f, float metallic = 0.0f,
                const std::string& name = {});
int addMeshNode(Scene& scene, Mesh mesh, const glm::vec3& translation, const glm::quat& rotation = glm::quat(1, 0, 0, 0));
// A light node at `position` shining along `direction` (ignored for point lights).
int addLightNode(Scene& scene, const Light& light, const glm::vec3& position, const glm::vec3& direction);
int addCameraNode(Scene& scene, const Camera& camera, const glm::vec3& position, const glm::vec3& target);

// The rotation that turns a node's local −Z (the glTF light/camera forward) to `direction`.
glm::quat rotationLookingAlong(const glm::vec3& direction);

}  // namespace lit

namespace lit {
class Log;

// Where addDefaultCamera puts the camera.
enum class DefaultCameraPlacement {
    FramingBounds,       // outside, framing the scene's bounds
    InsideLargestSpace,  // the opening view (scene/OpeningView.h) when the scene encloses a space, else framing
};

// Gives a scene without cameras a camera (near plane 5 cm, far plane fitted when rendering, so
// flying inside the scene clips nothing), reported in `log`. Returns true if it added one. Front
// ends call it after loading: the editor inside the largest space, lit-render framing. A scene
// without lights gets no light node: the renderer lights it with a default sun and sky instead
// (RenderSettings sky fields, scene/Sky.h), which a save does not write into the file.
bool addDefaultCamera(Scene& scene, Log& log,
                      DefaultCameraPlacement placement = DefaultCameraPlacement::FramingBounds);
}  // namespace lit
