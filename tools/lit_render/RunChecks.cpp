#include "RunChecks.h"

#include <epoxy/gl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace lit::cli {

namespace fs = std::filesystem;

namespace {

// The memory a render at this size needs, estimated before any of it is allocated: 64 bytes per
// pixel (G-buffer, lighting and output targets plus the read-back copies; a 16384² render
// measured 17.5 GB) and 21 bytes per voxel (RGBA16F radiance with its mip chain plus the RGBA8
// albedo, normal and emission volumes).
std::uint64_t estimatedRenderBytes(const RenderSettings& settings) {
    const auto pixels =
        static_cast<std::uint64_t>(settings.output.width) * static_cast<std::uint64_t>(settings.output.height);
    const auto side = static_cast<std::uint64_t>(settings.gi.voxelResolution);
    return pixels * 64 + (settings.gi.enabled ? side * side * side * 21 : 0);
}

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

void checkRenderLimits(const RenderSettings& settings) {
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
    const std::uint64_t needed = estimatedRenderBytes(settings);
    std::uint64_t available = availableRenderBytes();
    // $LIT_MAX_RENDER_MB caps it further (a shared machine, a CI runner).
    if (const char* cap = std::getenv("LIT_MAX_RENDER_MB"); cap && *cap) {
        const std::uint64_t capBytes = std::strtoull(cap, nullptr, 10) * 1'000'000ull;
        if (capBytes > 0 && (available == 0 || capBytes < available)) available = capBytes;
    }
    if (available > 0 && needed > available)
        throw UsageError("a " + std::to_string(settings.output.width) + "x" + std::to_string(settings.output.height) +
                         " render with " + std::to_string(settings.gi.voxelResolution) + "^3 voxels needs about " +
                         std::to_string(needed / 1'000'000) + " MB, more than the " +
                         std::to_string(available / 1'000'000) + " MB available; use a smaller --size or --voxels");
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
