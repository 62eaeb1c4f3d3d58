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
    : root_(std::move(root)), label_(std::move(label)), stages_(std::move(stages)), defines_(std::move(defines)) {
    get(initial);
}

const gl::Program& ConeProgram::get(ConeFeatures features) {
    gl::Program& program = variants_[static_cast<std::size_t>(features.index())];
    if (!program) {
        std::string label = label_;
        if (features.anisotropic) label += " (anisotropic)";
        if (features.footprint) label += " (footprint)";
        if (features.voxelRays > 0) label += " (voxel rays)";
        program = gl::Program(root_, label, stages_, defines_ + features.defines());
    }
    return program;
}

void ConeProgram::appendBuilt(std::vector<gl::Program*>& out) {
    for (gl::Program& program : variants_)
        if (program) out.push_back(&program);
}

}  // namespace lit
