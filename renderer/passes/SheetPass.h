#pragma once
// Transmissive sheets (KHR_materials_transmission drawn as a thin sheet, docs/MATERIALS.md,
// "Transmission"): after the composite, each sheet the camera sees adds its own light over the
// HDR image and lets its transmittance of the image behind it through (sheet.frag.glsl), farthest
// first. The G-buffer, the shadow maps and the voxels leave sheets out, so the image under a
// sheet is what lies behind it. Then the sheets' node IDs go into the G-buffer's ID target, for
// picking and the selection outline (sheet_id.frag.glsl). A refracting volume's front face reads
// what lies where its bent path leaves it from a copy of the image taken before the sheets.

#include "gl/ProgramVariants.h"
#include "passes/LightSetup.h"
#include "passes/Pass.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <utility>
#include <vector>

namespace lit {

class GpuScene;
struct DrawCounters;
struct RenderSettings;
struct Scene;

class SheetPass : public Pass {
public:
    explicit SheetPass(const std::filesystem::path& shaderRoot);

    struct Targets {
        const gl::Texture& hdr;    // the composite's image, blended over
        const gl::Texture& depth;  // the G-buffer's depth: sheets behind opaque surfaces are hidden
        const gl::Texture& nodeId; // the G-buffer's ID target (its lighting passes have run)
    };
    struct Frame {
        ShadowKinds shadows;                                  // the light table's shadow maps (variant)
        glm::vec3 cameraPosition{0.0f};                       // for the farthest-first order
        const std::vector<std::uint32_t>* visibleItems = nullptr;  // the camera's culled items (nullptr: all)
        bool indirect = false;                                // the voxel volume and its UBO are bound
    };
    // Whether `settings`' view shows sheets: the final image and the four lighting terms.
    static bool drawsView(const RenderSettings& settings);
    // Draws the scene's sheets. Expects the frame UBO, the light table, the shadow maps, the
    // material table and (with `frame.indirect`) the voxel volume, its UBO and the specular
    // albedo table bound.
    void execute(const Scene& scene, const GpuScene& gpuScene, const Targets& targets, const RenderSettings& settings,
                 const Frame& frame, DrawCounters& counters);
    std::vector<gl::Program*> programs() override {
        std::vector<gl::Program*> all = programs_.built();
        all.push_back(&idProgram_);
        return all;
    }

private:
    gl::ProgramVariants<ShadowKinds::kVariants> programs_;
    gl::Program idProgram_;
    gl::Framebuffer framebuffer_, idFramebuffer_;
    // The image before the sheets and its depth (scenes with refracting volumes only).
    gl::Texture behind_, behindDepth_;
    GLuint hdrId_ = 0, depthId_ = 0, nodeIdId_ = 0;  // the targets the framebuffers were made for
    std::vector<std::uint32_t> order_;  // the sheets of this frame, farthest first
    std::vector<std::pair<float, std::uint32_t>> byDistance_;  // squared distance, item (the sort's keys)
};

}  // namespace lit
