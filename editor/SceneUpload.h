#pragma once
// Keeps the renderer's GPU copy of the scene (its GpuScene) in step with the document: uploads a
// newly opened document, and rebuilds the copy when nodes, meshes or materials were added or
// removed (a structural edit, or its undo), since the GpuScene's draw items are per node and
// primitive. Transforms and material values the renderer reads from the Scene each frame.

#include <cstdint>
#include <vector>

#include "Log.h"
#include "Renderer.h"
#include "scene/Scene.h"

namespace lit::editor {

class SceneUpload {
public:
    explicit SceneUpload(Renderer& renderer) : renderer_(renderer) {}

    // Makes `scene` the renderer's; throws what Renderer::setScene throws (a texture over the
    // driver's limits...), and then the renderer keeps what it had.
    void upload(const Scene& scene);
    // Once a frame: uploads again when the structure changed since the last upload. A failure is
    // logged; it is not retried until the structure changes again.
    void syncStructure(const Scene& scene, Log& log);
    // How many times the renderer was given a scene: a new one tells the viewport to redraw.
    std::uint64_t uploads() const { return uploads_; }

private:
    Renderer& renderer_;
    // What the GpuScene was built from: per node its mesh, per mesh its primitives' materials,
    // and the material count.
    std::vector<int> uploaded_;
    std::uint64_t uploads_ = 0;
};

}  // namespace lit::editor
