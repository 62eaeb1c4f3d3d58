#include "scene/SceneBuilder.h"

#include "scene/Tangents.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace lit {

namespace {
void addQuad(Primitive& p, const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v, const glm::vec3& normal) {
    const auto base = static_cast<std::uint32_t>(p.vertices.size());
    const glm::vec3 corners[4] = {origin, origin + u, origin + u + v, origin + v};
    const glm::vec2 uvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    for (int i = 0; i < 4; ++i) {
        Vertex vertex;
        vertex.position = corners[i];
        vertex.normal = normal;
        vertex.uv = uvs[i];
        vertex.uv1 = uvs[i];
        p.vertices.push_back(vertex);
        p.bounds.extend(corners[i]);
    }
    // Counter-clockwise seen from the side the normal points to.
    const bool ccw = glm::dot(glm::cross(u, v), normal) > 0.0f;
    const std::uint32_t order[6] = {0, 1, 2, 0, 2, 3};
    for (std::uint32_t i : order) p.indices.push_back(base + (ccw ? i : (i == 0 ? 0 : 4 - i)));
}
}  // namespace

Mesh makeBoxMesh(const std::string& name, const glm::vec3& size, int material) {
    Mesh mesh;
    mesh.name = name;
    Primitive p;
    p.material = material;
    const glm::vec3 h = 0.5f * size;
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int axis = 0; axis < 3; ++axis) {
        const glm::vec3 n = axes[axis];
        const glm::vec3 a = axes[(axis + 1) % 3] * size[(axis + 1) % 3];
        const glm::vec3 b = axes[(axis + 2) % 3] * size[(axis + 2) % 3];
        for (float sign : {1.0f, -1.0f}) {
            const glm::vec3 centre = n * (sign * h[axis]);
            addQuad(p, centre - 0.5f * a - 0.5f * b, a, b, sign * n);
        }
    }
    computeTangents(p);
    mesh.primitives.push_back(std::move(p));
    return mesh;
}

Mesh makePlaneMesh(const std::string& name, float size, int material, int subdivisions) {
    Mesh mesh;
    mesh.name = name;
    Primitive p;
    p.material = material;
    const int n = std::max(subdivisions, 1);
    const float step = size / static_cast<float>(n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec3 origin(-0.5f * size + i * step, 0.0f, -0.5f * size + j * step);
            addQuad(p, origin, {0, 0, step}, {step, 0, 0}, {0, 1, 0});
        }
    computeTangents(p);
    mesh.primitives.push_back(std::move(p));
    return mesh;
}

int addMaterial(Scene& scene, const glm::vec3& baseColor, float roughness, float metallic, const std::string& name) {
    Material m;
    m.name = name.empty() ? "material " + std::to_string(scene.materials.size()) : name;
    m.baseColorFactor = glm::vec4(baseColor, 1.0f);
    m.roughness = roughness;
    m.metallic = metallic;
    scene.materials.push_back(m);
    ++scene.materialRevision;
    return static_cast<int>(scene.materials.size() - 1);
}

namespace {
int addNode(Scene& scene, Node node) {
    scene.nodes.push_back(std::move(node));
    const int index = static_cast<int>(scene.nodes.size() - 1);
    scene.roots.push_back(index);
    scene.updateWorldTransforms();
    return index;
}
}  // namespace

int addMeshNode(Scene& scene, Mesh mesh, const glm::vec3& translation, const glm::quat& rotation) {
    Node node;
    node.name = mesh.name;
    node.translation = translation;
    node.rotation = rotation;
    scene.meshes.push_back(std::move(mesh));
    node.mesh = static_cast<int>(scene.meshes.size() - 1);
    ++scene.geometryRevision;
    return addNode(scene, std::move(node));
}

glm::quat rotationLookingAlong(const glm::vec3& direction) {
    const glm::vec3 d = glm::normalize(direction);
    const glm::vec3 up = std::abs(d.y) > 0.999f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    // glm::quatLookAt builds the rotation whose −Z looks along `d` (right-handed).
    return glm::quatLookAtRH(d, up);
}

int addLightNode(Scene& scene, const Light& light, const glm::vec3& position, const glm::vec3& direction) {
    Node node;
    node.name = light.name.empty() ? "light " + std::to_string(scene.lights.size()) : light.name;
    node.translation = position;
    node.rotation = rotationLookingAlong(direction);
    scene.lights.push_back(light);
    node.light = static_cast<int>(scene.lights.size() - 1);
    ++scene.lightRevision;
    return addNode(scene, std::move(node));
}

int addCameraNode(Scene& scene, const Camera& camera, const glm::vec3& position, const glm::vec3& target) {
    Node node;
    node.name = camera.name.empty() ? "camera " + std::to_string(scene.cameras.size()) : camera.name;
    node.translation = position;
    node.rotation = rotationLookingAlong(target - position);
    scene.cameras.push_back(camera);
    node.camera = static_cast<int>(scene.cameras.size() - 1);
    return addNode(scene, std::move(node));
}

}  // namespace lit

#include "Log.h"
#include "scene/CameraView.h"
#include "scene/OpeningView.h"

namespace lit {

bool addDefaultCamera(Scene& scene, Log& log, DefaultCameraPlacement placement) {
    bool added = false;
    if (scene.cameras.empty()) {
        const Aabb bounds = scene.worldBounds();
        const std::optional<OpeningView> opening = placement == DefaultCameraPlacement::InsideLargestSpace && !bounds.empty()
                                                       ? findOpeningView(scene)
                                                       : std::nullopt;
        if (opening) {
            Camera camera;
            camera.name = "default camera";
            camera.yfov = 1.2f;  // 69°: a room seen from inside needs a wider view than an object
            camera.znear = 0.05f;
            camera.zfar = 0.0f;
            addCameraNode(scene, camera, opening->position, opening->position + opening->forward);
            log.info("the scene has no cameras: added a default camera inside its largest enclosed space");
            added = true;
        } else if (!bounds.empty()) {
            const CameraView framing = frameBounds(bounds, 16.0f / 9.0f);
            Camera camera;
            camera.name = "default camera";
            camera.yfov = framing.yfov;
            // Not the framing view's planes: its near plane is metres from a large scene's
            // outside, and the camera is meant to fly in.
            camera.znear = 0.05f;
            camera.zfar = 0.0f;
            addCameraNode(scene, camera, framing.position, framing.position + framing.forward());
            log.info("the scene has no cameras: added a default camera framing its bounds");
            added = true;
        }
    }
    return added;
}

}  // namespace lit
