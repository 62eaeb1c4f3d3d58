#pragma once
// Radiance injection: lights the voxel volume. For every occupied voxel, the outgoing radiance of
// a Lambertian surface under the scene's direct light (with shadows) plus its emission goes into
// level 0 of the radiance volume; empty voxels get 0 (opacity 0). See shaders/inject.comp.glsl.

#include "gl/ProgramVariants.h"
#include "passes/ConeProgram.h"
#include "passes/LightSetup.h"
#include "passes/Pass.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lit {

class VoxelVolume;

// What a voxel-ray trace does with the ray-hit cache (InjectPass::ensureRayHits).
enum class RayHits { Off, Record, Replay };

class InjectPass : public Pass {
public:
    explicit InjectPass(const std::filesystem::path& shaderRoot);

    // Writes level 0 of volume.radiance() from the material volumes (after VoxelizePass).
    // The caller must have bound, as for the direct-lighting pass:
    //   - the frame UBO at LIT_UBO_FRAME (only counts.x, the light count, is read),
    //   - the light table SSBO at LIT_SSBO_LIGHTS,
    //   - the shadow maps (ShadowPass::bindMaps) at LIT_TEX_SHADOW_2D / LIT_TEX_SHADOW_CUBE.
    // Binds itself: the voxel UBO (volume.uniforms(), which must be up to date) and the image
    // units LIT_IMG_VOXEL_ALBEDO/NORMAL/EMISSION (read) and LIT_IMG_VOXEL_RADIANCE (write).
    // Ends with an image-access + texture-fetch barrier; the mip levels are left to the mipmap pass.
    // `fromList`: only the voxels of volume.occupiedList() (complete, not overflowed), with an
    // indirect dispatch; empty voxels are then not written (VoxelizePass zeroed them). Otherwise
    // every voxel of the grid, empty ones written as 0.
    // `writeDirect` (light bounces follow; volume.direct() must be allocated, else it is ignored):
    // the same radiance goes to the direct volume too. `writeLevel0` false with it: only the
    // direct volume is written and level 0 keeps what it holds (the last update's light, while a
    // light edit's bounces run).
    void execute(const VoxelVolume& volume, bool fromList = true, bool writeLevel0 = true, bool writeDirect = false,
                 ShadowKinds shadows = {});

    // Light bounces: after execute() and a full mip build (MipmapPass::execute), each bounce makes
    // level 0 direct radiance + albedo × the voxel's traced indirect diffuse (shaders/bounce.comp.glsl),
    // and the caller rebuilds the mips after it. The direct radiance is volume.direct(), which
    // execute() writes beside level 0 when it is allocated (VoxelVolume::ensureBounceVolumes, which
    // the caller must call before execute()). traceBounce traces the list entries [first, first +
    // count) (count 0: all of them; the cached mode spreads a bounce over frames, Renderer) into
    // volume.bounce(), reading the radiance volume as it stands; endBounce, once every voxel was
    // traced, copies the bounce into level 0: the listed voxels only (bounce_copy.comp.glsl), or
    // the whole grid when `fromList` is false. `fromList`: only the occupied-voxel list's voxels
    // trace (as execute); false when the list overflowed. `features`: the cone features to trace
    // with (ConeFeatures::of the settings). `secondBounce`: the voxel rays take the direct volume's
    // light where they end (level 0 may then hold anything), else level 0's (the bounce before);
    // cones read the mips of level 0 either way. executeBounce is one whole bounce.
    void traceBounce(const VoxelVolume& volume, ConeFeatures features, bool secondBounce, bool fromList = true,
                     std::uint32_t first = 0, std::uint32_t count = 0, RayHits hits = RayHits::Off);
    void endBounce(const VoxelVolume& volume, bool fromList = true);
    void executeBounce(const VoxelVolume& volume, ConeFeatures features, bool secondBounce, bool fromList = true,
                       RayHits hits = RayHits::Off);

    // The cached GI mode (RenderSettings::diffuseFromVoxelIrradiance): after execute() and a full
    // mip build, occupied voxels trace diffuse cones (bounce.comp.glsl with LIT_BOUNCE_IRRADIANCE)
    // and their irradiance/π per side goes to the "raw" volume (alpha 1 where traced); then every
    // occupied voxel averages the raw values over one period of the cone sets' pattern along its
    // surface (voxel_irradiance_filter.comp.glsl) into the volume bindIrradiance() binds for the
    // per-pixel gather (voxel_irradiance.glsl). The radiance volume is left as it is. Both are
    // N × N × 2N (the two sides stacked in z) in the radiance volume's format and encoding (RGBA8 or
    // RGBA16F).
    // prepareIrradiance makes the volumes for the volume's resolution and format; `clear` (after a
    // voxelization: old values sit at old geometry) marks every voxel not traced (alpha 0, which
    // the filter and the gather skip). A light edit keeps the old values until they are traced again.
    void prepareIrradiance(const VoxelVolume& volume, bool clear);
    // Traces the occupied-voxel list's entries [first, first + count) (RenderSettings::
    // voxelIrradianceVoxelsPerFrame: a light edit's voxels spread over frames); `count` 0 = the
    // whole list. `fromList` false (the list overflowed): the whole N³ grid, first/count ignored.
    // Writes the raw volume only: filterIrradiance() must follow before the gather reads them.
    // `setOffset` k > 0 (the refinement, RenderSettings::voxelIrradianceRefineVoxelsPerFrame): each
    // voxel traces the set k after its own and averages it into its value with weight 1 / (k + 1).
    void executeIrradiance(const VoxelVolume& volume, ConeFeatures features, bool fromList, std::uint32_t first = 0,
                           std::uint32_t count = 0, int setOffset = 0, RayHits hits = RayHits::Off);

    // The voxel rays' first hits (bounce.comp.glsl, LIT_SSBO_VOXEL_RAY_HITS): one uint per entry of
    // the occupied list, side and ray. A ray's hit depends on the voxels, not on their light, so a
    // trace over the list with RayHits::Record keeps them and the traces of the same rays after a
    // light edit replay them (RayHits::Replay: no ray marched) until the voxels change. The bounce
    // and the irradiance's first set trace the same rays. Makes (or keeps) the buffer for `rays`
    // rays over `entries` list entries (the occupied count); false when that needs more than
    // kMaxRayHitBytes (the passes then march every time). A new buffer holds no hits.
    bool ensureRayHits(int rays, std::uint32_t entries);
    std::size_t rayHitBytes() const { return rayHits_.size(); }
    static constexpr std::size_t kMaxRayHitBytes = std::size_t{1} << 30;  // 1 GiB
    // The filter over the list's entries [first, first + count) (`count` 0 = every occupied voxel:
    // the list, or the grid when `fromList` is false). A voxel's filtered value reads its
    // neighbours', which a range of the list may have traced though the voxel itself lies elsewhere
    // in the list: filtering only the traced range leaves those neighbours' values stale until
    // their own range is traced, so the frame that completes an update filters the whole list.
    void filterIrradiance(const VoxelVolume& volume, bool fromList, std::uint32_t first = 0, std::uint32_t count = 0);
    // Binds the gather texels (LIT_TEX_VOXEL_IRRADIANCE: each voxel's normal and both sides'
    // filtered irradiance, voxel.glsl's packGatherTexel) for the cone passes.
    void bindIrradiance() const;

    std::vector<gl::Program*> programs() override;

private:
    // bounce.comp.glsl (LIT_BOUNCE_IRRADIANCE) for RGBA8 and RGBA16F volumes, and the filter.
    ConeProgram irradiance8_, irradiance16f_;
    gl::Program filter_;
    // As traced, one cone set per voxel: N × N × 2N in the radiance format, the side of the voxel's
    // averaged normal at z < N, the other at z + N (otherSideTexel, voxel.glsl).
    gl::Texture raw_;
    // Filtered over the sets, what the gather reads: N³ RGBA32UI gather texels (packGatherTexel).
    gl::Texture irradiance_;
    int irradianceResolution_ = 0;
    bool irradianceRgba8_ = false;
    // Sets uRayHits (and binds the buffer) for a voxel-ray program; nothing for cones.
    void bindRayHits(const gl::Program& program, ConeFeatures features, RayHits hits) const;
    gl::Buffer rayHits_;  // ensureRayHits
    gl::ProgramVariants<ShadowKinds::kVariants> injectPrograms_;  // inject.comp.glsl by ShadowKinds::index()
    // bounce.comp.glsl for RGBA8 and RGBA16F volumes, built on the first bounce (most frames have one).
    ConeProgram bounce8_, bounce16f_;
    gl::Program copy8_, copy16f_;  // bounce_copy.comp.glsl, built by the first endBounce over the list
    // The compute program `file` for the volumes' format (LIT_BOUNCE_RGBA8), built on first use.
    const gl::Program& formatProgram(gl::Program& rgba8Program, gl::Program& rgba16fProgram, bool rgba8,
                                     const std::string& label, const char* file);
    std::filesystem::path shaderRoot_;
};

// Level `level` of the radiance volume as linear radiance, rgb W/(sr·m²), a opacity; x fastest,
// then y, then z. An RGBA8 volume is decoded with `rgba8Range`, the RenderSettings::
// voxelRadianceRange it was injected with. Stalls the pipeline (tests, debug tools).
std::vector<glm::vec4> readRadianceVoxels(const VoxelVolume& volume, int level = 0, float rgba8Range = 1.0f);

}  // namespace lit
