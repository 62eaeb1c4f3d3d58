#include "RunChecks.h"

#include <epoxy/gl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace lit::cli {

namespace fs = std::filesystem;

namespace {

// Bytes the GL can still give: system memory for a software rasterizer (llvmpipe renders into
// RAM), free video memory where the driver says (NVX_gpu_memory_info); 0 = unknown.
std::uint64_t availableRenderBytes() {
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos) {
        std::ifstream meminfo("/proc/meminfo");
        std::string key;
        std::uint64_t kib = 0;
        std::string unit;
        while (meminfo >> key >> kib >> unit)
            if (key == "MemAvailable:") return kib * 1024;
        return 0;
    }
    if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
        GLint kib = 0;
        glGetIntegerv(0x9049, &kib);  // GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX
        return static_cast<std::uint64_t>(std::max(kib, 0)) * 1024;
    }
    return 0;
}

}  // namespace

void checkRenderLimits(const RenderSettings& settings, const Scene& scene) {
    GLint maxTexture = 0, maxRenderbuffer = 0, maxWidth = 0, maxHeight = 0, max3d = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &maxWidth);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &maxHeight);
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3d);
    const int maxSide = std::min({maxTexture, maxRenderbuffer, maxWidth, maxHeight});
    if (settings.output.width > maxSide || settings.output.height > maxSide)
        throw UsageError("the size " + std::to_string(settings.output.width) + "x" +
                         std::to_string(settings.output.height) + " is larger than this GL can render (" +
                         std::to_string(maxSide) + " per side)");
    // The voxel irradiance volumes are N × N × 2N (InjectPass).
    if (settings.gi.enabled && 2 * settings.gi.voxelResolution > max3d)
        throw UsageError(std::to_string(settings.gi.voxelResolution) +
                         "^3 voxels are more than this GL's 3D textures hold (" + std::to_string(max3d) +
                         " per side, 2N needed)");
    // Everything the scene and the render take (the loader checked the same figure against
    // renderMemoryLimit() before decoding). What this GL can still give is compared with what is
    // yet to be allocated: the decoded images and the CPU half of the geometry are already in
    // memory (and no longer in MemAvailable).
    const SceneMemory needed = estimateSceneMemory(scene, RenderFootprint::of(settings));
    const std::uint64_t resident = needed.decodedImages + needed.geometry / 2;
    MemoryLimit limit = renderMemoryLimit();
    if (const std::uint64_t available = availableRenderBytes(); available > 0 && available + resident < limit.bytes)
        limit = {available + resident, "this machine's available memory"};
    if (const std::optional<std::string> over = overMemoryLimit(needed, limit))
        throw UsageError(*over + "; use a smaller --size or --voxels");
}

void checkWritableFolder(const fs::path& file, const char* what) {
    const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
    std::error_code ec;
    if (fs::is_directory(file, ec))
        throw UsageError(std::string(what) + " " + file.string() + " is a folder, not a file");
    fs::create_directories(folder, ec);
    if (ec || !fs::is_directory(folder, ec))
        throw UsageError(std::string("cannot create the folder ") + folder.string() + " for " + what + " " +
                         file.string() + (ec ? " (" + ec.message() + ")" : std::string(" (a file is in the way)")));
    const fs::path probe = folder / (".lit-render-probe-" + std::to_string(::getpid()));
    {
        std::ofstream out(probe, std::ios::binary);
        if (!out)
            throw UsageError(std::string("cannot write ") + what + " " + file.string() + ": the folder " +
                             folder.string() + " is not writable");
    }
    fs::remove(probe, ec);
}

void checkOutputFolders(const Options& options) {
    for (const fs::path* file : {&options.out, &options.hdr, &options.benchJson, &options.difference})
        if (!file->empty()) checkWritableFolder(*file, "the output");
    if (!options.framesOut.empty()) checkWritableFolder(options.framesOut / "frame_00000.png", "the frames");
}

}  // namespace lit::cli
