#pragma once
// Edits the selected node: its transform, the material of its mesh, the light or camera it
// holds. Every change goes through the Document's undo bracket, so a slider drag or a colour
// pick is one undo step, and bumps the revision the renderer needs (a transform re-voxelizes, a
// light re-injects).

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "Document.h"
#include "panels/Layout.h"

namespace lit::editor {

class InspectorPanel {
public:
    void draw(Document& doc, const Placement& placement, bool* open);

private:
    void drawTransform(Document& doc, int nodeIndex);
    void drawMaterial(Document& doc, int materialIndex);
    void drawSpecularLayers(Document& doc, Material& material);
    void drawLight(Document& doc, int lightIndex);
    void drawCamera(Document& doc, int cameraIndex);

    // The rotation as shown, in degrees. Converting the quaternion to Euler angles every frame
    // would let a drag flip to an equivalent triple (yaw 180 + pitch 180 ...) under the cursor,
    // so the angles are kept while the node's rotation is the one they produced.
    struct EulerCache {
        int node = -1;
        glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
        glm::vec3 degrees{0.0f};
    };
    EulerCache euler_;
};

}  // namespace lit::editor
