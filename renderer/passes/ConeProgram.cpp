#include "passes/ConeProgram.h"

#include "RenderSettings.h"

#include <algorithm>
#include <utility>

namespace lit {

ConeFeatures ConeFeatures::of(const RenderSettings& settings) {
    return {settings.anisotropicVoxels, settings.coneFootprintPerHeight > 0.0f, settings.diffuseFromVoxelIrradiance,
            std::clamp(settings.voxelRays, 0, kMaxVoxelRays)};
}

std::string ConeFeatures::defines() const {
    const auto define = [](const char* name, bool on) { return std::string("#define ") + name + (on ? " 1\n" : " 0\n"); };
    return define("LIT_CONE_ANISOTROPIC", anisotropic) + define("LIT_CONE_FOOTPRINT", footprint) +
           define("LIT_VOXEL_IRRADIANCE", voxelIrradiance) + define("LIT_VOXEL_RAYS", voxelRays > 0);
}

ConeProgram::ConeProgram(std::filesystem::path root, std::string label, std::vector<gl::ShaderStageSource> stages,
                         std::string defines, ConeFeatures initial)
    : variants_(std::move(root), std::move(label), std::move(stages), std::move(defines)) {
    get(initial);
}

const gl::Program& ConeProgram::get(ConeFeatures features) {
    std::string suffix;
    if (features.anisotropic) suffix += " (anisotropic)";
    if (features.footprint) suffix += " (footprint)";
    if (features.voxelRays > 0) suffix += " (voxel rays)";
    return variants_.get(static_cast<std::size_t>(features.index()), features.defines(), suffix);
}

}  // namespace lit
