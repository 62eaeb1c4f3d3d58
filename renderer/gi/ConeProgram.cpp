#include "gi/ConeProgram.h"

#include <algorithm>
#include <utility>

#include "RenderSettings.h"
#include "passes/MaterialLayersVariant.h"

namespace lit {

ConeFeatures ConeFeatures::of(const RenderSettings& settings, bool materialLayers) {
    return {settings.gi.anisotropicVoxels(), settings.gi.footprintPerHeight() > 0.0f, settings.gi.voxelIrradiance(),
            std::clamp(settings.gi.voxelRays, 0, kMaxVoxelRays), materialLayers, settings.gi.nearLevelCount(), false};
}

std::string ConeFeatures::defines() const {
    const auto define = [](const char* name, bool on) {
        return std::string("#define ") + name + (on ? " 1\n" : " 0\n");
    };
    return define("LIT_CONE_ANISOTROPIC", anisotropic) + define("LIT_CONE_FOOTPRINT", footprint) +
           define("LIT_VOXEL_IRRADIANCE", voxelIrradiance) + define("LIT_VOXEL_RAYS", voxelRays > 0) +
           MaterialLayersVariant{materialLayers}.defines() + "#define LIT_NEAR_GATHER " + std::to_string(nearGatherLevels) + "\n" +
           define("LIT_NEAR_LEVEL", nearLevel);
}

ConeProgram::ConeProgram(std::filesystem::path root, std::string label, std::vector<gl::ShaderStageSource> stages,
                         std::string defines, ConeFeatures initial)
    : variants_(std::move(root), std::move(label), std::move(stages), std::move(defines)) {
    get(initial);
}

std::string ConeFeatures::label() const {
    std::string suffix;
    if (anisotropic) suffix += " (anisotropic)";
    if (footprint) suffix += " (footprint)";
    if (voxelRays > 0) suffix += " (voxel rays)";
    if (nearGatherLevels > 0) suffix += " (near gather " + std::to_string(nearGatherLevels) + ")";
    if (nearLevel) suffix += " (near level)";
    return suffix + MaterialLayersVariant{materialLayers}.label();
}

const gl::Program& ConeProgram::get(ConeFeatures features) { return variants_.get(features); }

}  // namespace lit
