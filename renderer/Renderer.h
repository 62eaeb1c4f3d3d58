#pragma once
// The renderer: owns the GPU copy of a Scene and the passes, and renders a frame from a
// CameraView with RenderSettings into its own output textures. Front ends (lit-editor,
// lit-render, tests) use only this API; none of them reaches into a pass.
//
// Frame (see docs/ARCHITECTURE.md): shadow maps → G-buffer → [voxelize → inject → mipmaps when
// dirty] → lighting terms → compose → tone map. The output is an sRGB8 texture; the linear HDR
// image of the chosen view is kept too, for --hdr and the tests.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Log.h"
#include "Overlay.h"
#include "Profiler.h"
#include "RenderSettings.h"
#include "gi/GiBudget.h"
#include "scene/CameraView.h"

namespace lit {

struct Scene;
struct MipmapTimings;
class VoxelVolume;
namespace gl {
class Texture;
}

struct FrameStats {
    int drawCalls = 0;          // draw calls issued this frame (all passes)
    std::size_t triangles = 0;  // triangles drawn in the G-buffer pass
    bool voxelized = false;     // the voxel volume was rebuilt this frame
    int voxelizedBoxes = 0;     // ... in this many changed boxes only (0: the whole volume)
    // The near levels that scrolled this frame (moved by whole voxels: only the slabs they uncovered
    // were voxelized), and the voxels the near levels voxelized (slabs, or whole levels that moved
    // too far or not by whole voxels).
    int nearLevelsScrolled = 0;
    std::int64_t nearVoxelizedVoxels = 0;
    bool injected = false;      // radiance was re-injected this frame
    std::size_t voxelBytes = 0; // GPU memory of the voxel volumes
    // Each near level's side (m) and GPU memory (its volumes, caches and ray hits), finest first;
    // the scene's volume holds voxelBytes less their sum.
    struct NearLevelMemory {
        float side = 0.0f;
        std::size_t bytes = 0;
    };
    std::vector<NearLevelMemory> nearLevels;
    std::size_t shadowMapBytes = 0;  // GPU memory of the shadow maps and their sheet colour layers
    int shadowCascadesDrawn = 0;  // the camera's shadow cascades drawn this frame (a cascade is kept while its fit is)
    // Entries of the occupied-voxel list (inject runs over these): the voxels the last voxelization
    // of the whole volume occupied, plus those voxelizations of changed boxes added since.
    std::uint32_t occupiedVoxels = 0;
    // The GI update after the last light or geometry edit, which a GiBudget may spread over
    // frames: the share of it done after this frame (1: every voxel holds the current light) and
    // what it is at ("bounce 2".."bounce N", "irradiance"; "refining" while the refinement rounds
    // run with the light already right; "" when nothing is left).
    float giUpdateDone = 1.0f;
    std::string giUpdateStage;
    // Voxels the refinement (GiBudget::refineVoxels) traced this frame; 0 when it waited (a budget
    // of 0, e.g. the editor's while the camera moves) or had nothing left.
    std::uint32_t refinedVoxels = 0;
    // Refinement rounds are still to run after the update (or after the one under way).
    bool giRefining = false;
    // The bounces of light the voxels hold (GiFrameReport::bounces) and whether that is every
    // bounce, the light iterated until it converged (GiSettings::bounces kAllBounces).
    int giBounces = 0;
    // Frames the anti-aliased image holds (TemporalAntialiasPass::historyFrames; 0 when it is off
    // or the view is not anti-aliased): output.antialiasingFrames once a still view has settled.
    int antialiasFrames = 0;
    bool giEveryBounce = false;
    // The indirect diffuse light shown is the last complete update's while the update after a
    // geometry edit is traced (GiFrameReport::showingPrevious).
    bool giShowingPrevious = false;
    // An update completed this frame (GiFrameReport::updateCompleted).
    bool giUpdateCompleted = false;
    // Frustum culling, over the views rendered this frame: the camera's G-buffer pass and the
    // shadow views when shadow maps were re-rendered (voxelization draws everything, uncounted).
    int drawsSubmitted = 0;     // scene draws those views issued
    int drawsTotal = 0;         // scene draws they would have issued without culling
    double cullMs = 0.0;        // CPU time of BVH refit and culling, milliseconds
};

class Renderer {
public:
    // Needs a current GL 4.5 core context; throws gl::GlError when it lacks features or the
    // shaders do not build. `shaderRoot` is the shaders/ folder.
    Renderer(std::filesystem::path shaderRoot, Log& log);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Uploads meshes, materials and textures. Call again after loading another scene.
    void setScene(const Scene& scene);

    // Renders one frame of `scene` (the one given to setScene, possibly edited since) into the
    // output textures, sized settings.output.width × settings.output.height. A 0×0 size renders nothing.
    // `budget`: the GI work this frame may do (gi/GiBudget.h); the default finishes a GI update in
    // this frame and leaves the refinement waiting.
    void render(const Scene& scene, const CameraView& camera, const RenderSettings& settings,
                const GiBudget& budget = GiBudget::updateOnly());
    // The GI work of a frame without the frame: the scene's changes, the lights and their shadow
    // maps, and the GI update under `budget`. The output images stay the last render()'s; the
    // GI fields of stats() are this call's, the others the last render()'s. A front end that
    // spreads the GI over frames calls it where rendering the image each time would cost more
    // than the work (the editor while the GI converges: editor/ViewportRedraw.h).
    void advanceGi(const Scene& scene, const CameraView& camera, const RenderSettings& settings, const GiBudget& budget);

    // Output of the last frame: tone-mapped sRGB (GL_SRGB8_ALPHA8) and linear HDR (GL_RGBA16F
    // → GL_RGBA32F on read) of settings.debug.view.
    const gl::Texture& outputTexture() const;
    const gl::Texture& hdrTexture() const;
    std::vector<std::uint8_t> readOutputRgba8() const;  // bottom-up rows, RGBA8
    std::vector<float> readHdrRgb() const;              // bottom-up rows, linear RGB float
    // The last frame's G-buffer depth (window space, 1 = background), bottom-up rows: with the
    // camera's matrices it gives each pixel's world point (flicker measure, temporal tests).
    std::vector<float> readDepth() const;

    // Viewport overlay drawn by every later render() into the output texture (not the HDR one):
    // selection outline, depth-tested lines, lines on top. An empty overlay costs nothing.
    void setOverlay(ViewportOverlay overlay);
    const ViewportOverlay& overlay() const;
    // Picking in the last frame. `pixel` is in output-texture pixels with the origin at the TOP
    // left (as windows report the mouse). Both read one G-buffer texel back (a GPU stall: call on
    // a click, not every frame).
    int pickNode(glm::ivec2 pixel) const;  // node index drawn there; -1 for background, out of range or no frame
    // The node and the primitive of its mesh drawn there (a one-node scene's parts); nullopt where
    // pickNode is -1.
    std::optional<PickedPrimitive> pickPrimitive(glm::ivec2 pixel) const;
    std::optional<SurfaceSample> surfaceAt(glm::ivec2 pixel) const;  // nullopt where pickNode is -1

    // Recompiles shaders whose files changed; on error the log says so and the last good
    // program stays. Returns true if anything was reloaded.
    bool reloadChangedShaders();

    // Times the compute mip chain, over the whole grid and over the occupied parents, against
    // glGenerateTextureMipmap on the current radiance volume (after a GI frame; returns zeros
    // before one). With the last injection's anisotropic setting.
    MipmapTimings benchmarkMipmaps(int repetitions);
    // The exposure (stops) the last frame was tone-mapped with: the metered one when
    // settings.output.autoExposure was on for it (reads a GPU buffer back: tools and tests), else
    // settings.output.exposureEv.
    float exposureEv(const RenderSettings& settings) const;
    // The voxel volume of the last GI frame, for debug views and tests; nullptr before one.
    const VoxelVolume* voxels() const;
    // The volume the voxel views show with `settings` (DebugViewSettings::voxelLevel: the scene's
    // or a near level's); nullptr before it was voxelized.
    const VoxelVolume* shownVoxels(const RenderSettings& settings) const;
    // Every volume the last GI frame ran, finest first: the near levels, then the scene's volume
    // (what View::VoxelLevels draws); empty before GI has run.
    std::vector<const VoxelVolume*> voxelLevels(const RenderSettings& settings) const;

    Profiler& profiler();
    const FrameStats& stats() const;
    Log& log();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Where shaders/ and assets/ are, first found of: $LIT_SHADER_DIR / $LIT_ASSET_DIR when set (a
// development override); ../share/lit/shaders and ../share/lit/assets beside the running
// executable (an installed program, `cmake --install`); the source tree this binary was built
// from (a run from the build tree).
std::filesystem::path defaultShaderRoot();
std::filesystem::path defaultAssetRoot();
std::filesystem::path defaultScenePath();  // the built-in Cornell box

}  // namespace lit
