#pragma once
// The programs that trace cones (shaders/include/cone.glsl) come in compile-time variants, one per
// combination of the optional cone features (anisotropic voxels, footprint-bounded cones).
// llvmpipe runs both sides of a branch, a uniform one included, so a feature behind a runtime
// `if` costs its texture reads whether it is on or not: the anisotropic branch in sampleRadiance
// made the cone trace 3-4× slower with every feature off (docs/GI.md, "Modes"). Each variant is
// built on first use, so settings that stay at their defaults compile one program.

#include <filesystem>
#include <string>
#include <vector>

#include "gl/ProgramVariants.h"
#include "gl/Shader.h"

namespace lit {

struct RenderSettings;

// The cone features a program is compiled with (LIT_CONE_ANISOTROPIC, LIT_CONE_FOOTPRINT).
struct ConeFeatures {
    bool anisotropic = false;  // directional voxels for levels ≥ 1 (GiSettings::anisotropicVoxels())
    bool footprint = false;    // footprint-bounded diffuse cones (GiSettings::coneFootprintPerHeight > 0)
    // The cached GI mode (docs/GI.md, "Voxel irradiance cache"): L_ID gathered from the voxels' cached
    // irradiance (GiSettings::voxelIrradiance()) instead of per-pixel diffuse cones.
    bool voxelIrradiance = false;
    // Rays per voxel for the light the voxels gather themselves (the cached mode's irradiance and
    // bounces 2..N; GiSettings::voxelRays): > 0 compiles the per-voxel passes with rays marched
    // through the voxel grid (LIT_VOXEL_RAYS) instead of cones; the count itself is a uniform.
    int voxelRays = 0;
    // The passes that light the G-buffer: whether the scene's materials have specular layers
    // (MaterialLayersVariant, passes/MaterialLayersVariant.h); the voxel passes leave it on.
    bool materialLayers = true;
    // The cached mode's near levels (GiSettings::nearLevelCount(), docs/GI.md "Near levels"): the
    // pixel passes gather from this many near levels' voxels (LIT_NEAR_GATHER) ...
    int nearGatherLevels = 0;
    // ... and a near level's own voxel passes continue a ray that leaves it in the next volume out,
    // then the scene's (LIT_NEAR_LEVEL); VoxelGi sets it for a near level's passes.
    bool nearLevel = false;

    // `materialLayers`: the scene's (GpuScene::hasMaterialLayers), for the passes that light the G-buffer.
    static ConeFeatures of(const RenderSettings& settings, bool materialLayers = true);
    std::string defines() const;
    std::string label() const;  // " (anisotropic)" ..., for the program's name
    int index() const {
        return (anisotropic ? 1 : 0) + (footprint ? 2 : 0) + (voxelIrradiance ? 4 : 0) + (voxelRays > 0 ? 8 : 0) +
               (materialLayers ? 16 : 0) + 32 * nearGatherLevels + (nearLevel ? 128 : 0);
    }
    bool operator==(const ConeFeatures&) const = default;
};

class ConeProgram {
public:
    ConeProgram() = default;
    // Builds the variant `initial` now (so a broken shader fails at start-up); the others on first use.
    ConeProgram(std::filesystem::path root, std::string label, std::vector<gl::ShaderStageSource> stages,
                std::string defines, ConeFeatures initial);

    // The variant for `features`, built now if it was not yet (throws GlError if that fails).
    const gl::Program& get(ConeFeatures features);
    // True for a default-constructed one (no program description).
    bool empty() const { return variants_.empty(); }
    // The variants built so far (for hot reload).
    void appendBuilt(std::vector<gl::Program*>& out) { variants_.appendBuilt(out); }

private:
    gl::ProgramVariants<256> variants_;  // by ConeFeatures::index()
};

}  // namespace lit
