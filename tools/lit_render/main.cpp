// lit-render — renders a glTF scene headless (EGL, no window or X server) to PNG/HDR, or
// benchmarks it, or flies a camera path (frames to PNGs, or per-frame timings), or path-traces it
// on the CPU. This file reads the command line, resolves the settings, loads the scene and hands
// it to one kind of run: ReferenceRun, PathRun or StillRun (which also benchmarks).
// Exit status: 0 success, 1 runtime failure (GL errors, a failed write), 2 bad input: the command
// line, a scene, settings or path file that cannot be used, an output folder that cannot be
// written, or a size this GL or this machine's memory cannot render; 130 a --reference render
// interrupted by Ctrl+C (after writing the image so far).

#include <epoxy/gl.h>

#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "Compare.h"
#include "LoadProgressLines.h"
#include "Log.h"
#include "Options.h"
#include "PathRun.h"
#include "ReferenceRun.h"
#include "RenderSettings.h"
#include "Renderer.h"
#include "RunChecks.h"
#include "RunContext.h"
#include "SettingsFile.h"
#include "StillRun.h"
#include "animation/NodeAnimation.h"
#include "context/HeadlessContext.h"
#include "gl/Capabilities.h"
#include "gl/GlError.h"
#include "scene/CameraView.h"
#include "scene/GltfLoader.h"
#include "scene/Scene.h"
#include "scene/SceneBuilder.h"
#include "scene/SceneMemory.h"

namespace lit::cli {

namespace {

namespace fs = std::filesystem;

// Load progress on stderr, for long loads only (LoadProgressLines.h says when a line is printed),
// with the GPU upload as its own stage. Uses the loader's progress callback
// (GltfLoadOptions::progress), which the editor's progress window reads as well.
class LoadProgressPrinter {
public:
    void operator()(const lit::LoadProgress& p) {
        if (const auto line = lines_(p, secondsSince(start_))) {
            std::fprintf(stderr, "%s\n", line->c_str());
            std::fflush(stderr);
        }
    }
    void stage(const char* name) { (*this)(lit::LoadProgress{name, 0, 1}); }
    void done(const char* name) { (*this)(lit::LoadProgress{name, 1, 1}); }

private:
    Clock::time_point start_ = Clock::now();
    LoadProgressLines lines_;
};

lit::Scene loadScene(const Options& options, const lit::RenderSettings& settings, lit::Log& log,
                     LoadProgressPrinter& progress) {
    try {
        lit::GltfLoadOptions loadOptions;
        loadOptions.limits.allowExternalUris = options.allowExternalUris;
        // The file is refused before decoding when it and this render need more memory than
        // $LIT_MAX_RENDER_MB or the default limit (the reference makes no GL textures or voxels,
        // so only the scene counts there).
        const lit::MemoryLimit limit = lit::renderMemoryLimit();
        loadOptions.limits.memoryBudgetBytes = limit.bytes;
        loadOptions.limits.memoryBudgetSource = limit.source;
        if (!options.reference) loadOptions.limits.render = lit::RenderFootprint::of(settings);
        loadOptions.progress = [&](const lit::LoadProgress& p) { progress(p); };
        return lit::loadGltf(options.scene, log, loadOptions);  // logs the summary line (meshes, triangles, MB, ms)
    } catch (const std::exception& e) {
        // The loader's messages usually start with the path already; say it once.
        std::string reason = e.what();
        const std::string prefix = options.scene.string() + ": ";
        if (reason.starts_with(prefix)) reason.erase(0, prefix.size());
        throw UsageError("cannot load " + options.scene.string() + ": " + reason);
    }
}

// --settings, then --set, then the other flags.
lit::RenderSettings resolveSettings(const Options& options, lit::Log& log) {
    lit::RenderSettings settings =
        options.settings.empty() ? lit::RenderSettings{} : loadSettingsFile(options.settings, log);
    std::vector<std::string> deprecated;
    settings = applyOptions(options, settings, &deprecated);
    for (const std::string& message : deprecated) log.warning("--set: " + message);
    // The file was checked and each flag checks its own value: only --set can have put a value out
    // of range.
    if (!options.set.empty()) checkRenderableSettings(settings, "--set", "--set", log);
    return settings;
}

int run(const Options& options) {
    lit::Log log;

    // Everything that needs no GL comes first, so a bad file or camera is reported at once.
    const lit::RenderSettings settings = resolveSettings(options, log);
    const std::optional<lit::HdrImage> compareTruth =
        options.compare.empty() ? std::nullopt : std::optional(readCompareReference(options, settings));
    checkOutputFolders(options);

    LoadProgressPrinter loadProgress;
    lit::Scene scene = loadScene(options, settings, log, loadProgress);
    lit::addDefaultCamera(scene, log);
    const int cameraIndex = resolveCamera(options, scene);
    // Node animations: a still shows them at --time (0 s without it); a path poses them per frame.
    for (const std::string& problem : lit::nodeAnimationProblems(scene)) log.warning(problem);
    if (const lit::NodeAnimationSummary animated = lit::summarizeNodeAnimations(scene); animated.channels > 0) {
        char line[128];
        std::snprintf(line, sizeof line, "node animations: %d channels on %d nodes, 0 to %g s", animated.channels,
                      animated.nodes, animated.endTime);
        log.info(line);
    }
    lit::applyNodeAnimations(scene, options.time.value_or(0.0));
    const RunContext context{options, settings, compareTruth ? &*compareTruth : nullptr, log};
    const std::optional<lit::CameraPath> path = options.path ? std::optional(loadPath(options)) : std::nullopt;
    // The still's camera: the path's view at --time, else the scene camera's.
    const float aspect = static_cast<float>(settings.output.width) / static_cast<float>(settings.output.height);
    const lit::CameraView stillCamera = options.pathStill()
                                            ? *path->view(*options.time, aspect, scene.worldBounds())
                                            : lit::sceneCameraView(scene, cameraIndex, aspect);
    if (options.reference && path && !options.pathStill()) return runReferencePath(context, *path, scene);
    if (options.reference) return runReference(context, scene, stillCamera);

    lit::HeadlessContext glContext;
    lit::gl::requireCapabilities();
    checkRenderLimits(settings, scene);
    // GL errors (debug output of high severity) are counted: a render that had any exits 1 and
    // writes nothing, instead of a wrong image with exit 0.
    std::size_t glErrors = 0;
    log.setSink([&glErrors](const lit::LogMessage& m) {
        if (m.level == lit::LogLevel::Error && m.text.starts_with("GL ")) ++glErrors;
        if (m.level == lit::LogLevel::Info)
            std::fprintf(stderr, "lit: %s\n", m.text.c_str());
        else
            std::fprintf(stderr, "lit: %s: %s\n", lit::toString(m.level), m.text.c_str());
    });
    lit::gl::installDebugOutput(log);
    const fs::path shaderRoot = lit::defaultShaderRoot();
    log.info("shaders from " + shaderRoot.string());  // installed, $LIT_SHADER_DIR or source tree
    lit::Renderer renderer(shaderRoot, log);
    loadProgress.stage("upload");
    renderer.setScene(scene);
    loadProgress.done("upload");
    const auto requireNoGlErrors = [&glErrors] {
        glFinish();
        if (glErrors > 0)
            throw RunError(std::to_string(glErrors) + " GL error" + (glErrors == 1 ? "" : "s") +
                           " during the render (see above); nothing was written");
    };
    const GlRun gl{renderer, glContext.description(), requireNoGlErrors};
    if (path && !options.pathStill()) return runPath(context, *path, scene, gl);
    return runStill(context, scene, stillCamera, gl);
}

}  // namespace

}  // namespace lit::cli

int main(int argc, char** argv) {
    using namespace lit::cli;
    Options options;
    try {
        options = parseOptions(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const UsageError& e) {
        std::fprintf(stderr, "lit-render: %s\n%s", e.what(), shortUsage().c_str());
        return 2;
    }
    if (options.help) {
        std::fputs(usageText().c_str(), stdout);
        return 0;
    }
    try {
        return run(options);
    } catch (const UsageError& e) {  // a camera the scene does not have
        std::fprintf(stderr, "lit-render: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {  // RunError, GlError, EGL and file failures
        std::fprintf(stderr, "lit-render: %s\n", e.what());
        return 1;
    }
}
