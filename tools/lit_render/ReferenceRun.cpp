#include "ReferenceRun.h"

#include <tbb/info.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "Compare.h"
#include "Log.h"
#include "NodeMap.h"
#include "PathRun.h"
#include "animation/NodeAnimation.h"
#include "image/ImageIO.h"
#include "reference/DifferenceImage.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"
#include "scene/CameraView.h"
#include "scene/Scene.h"
#include "scene/Sky.h"

namespace lit::cli {

namespace {

// Set by SIGINT while a reference render runs: the render stops after the tiles in flight and
// writes the image so far. A lock-free atomic is async-signal-safe; a signal handler has no other
// way to reach the render than through static storage.
std::atomic<bool>& interruptRequested() {
    static std::atomic<bool> requested{false};
    return requested;
}
extern "C" void onInterrupt(int) { interruptRequested().store(true); }

// The tracer's settings for this run. Without --bounces the reference follows --gi and the
// settings' bounces: the same light paths as the VCT, or direct light only. Rays that leave the
// scene see the same sky as the rasterizer's background and cones.
lit::reference::ReferenceSettings referenceSettingsFor(const RunContext& run, const Scene& scene) {
    const Options& options = run.options;
    const RenderSettings& settings = run.settings;
    lit::reference::ReferenceSettings reference;
    const int giBounces = settings.gi.bounces == lit::kAllBounces ? lit::reference::kAllBounces : settings.gi.bounces;
    reference.bounces = options.bounces.value_or(settings.gi.enabled ? giBounces : 0);
    reference.seed = options.seed.value_or(0);
    reference.pixelCentres = options.pixelCentres;
    std::string skyError;
    reference.environment = lit::makeSkyFunction(scene, settings, &skyError);
    if (!skyError.empty()) run.log.error(skyError + "; using the gradient sky");
    return reference;
}

// A scene without lights is lit by the rasterizer's default sun (scene/Sky.h); the reference gets
// the same sun as a light of its own copy of the scene.
lit::Scene withDefaultSun(const Scene& scene, const RenderSettings& settings) {
    lit::Scene withSun = scene;
    lit::addDefaultSun(withSun, settings);
    return withSun;
}

// Ctrl+C is caught while `this` lives (interruptRequested), then handled as before.
class InterruptScope {
public:
    InterruptScope() {
        interruptRequested().store(false);
        struct sigaction action {};
        action.sa_handler = onInterrupt;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &previous_);
    }
    ~InterruptScope() { sigaction(SIGINT, &previous_, nullptr); }
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;

private:
    struct sigaction previous_ {};
};

}  // namespace

int runReference(const RunContext& run, const Scene& scene, const CameraView& camera) {
    const Options& options = run.options;
    const RenderSettings& settings = run.settings;
    Log& log = run.log;
    const Clock::time_point buildStart = Clock::now();
    const lit::Scene withSun = withDefaultSun(scene, settings);
    const lit::reference::ReferenceScene referenceScene(withSun, log);
    const double buildSeconds = secondsSince(buildStart);

    const lit::reference::ReferenceSettings reference = referenceSettingsFor(run, scene);
    lit::reference::PathTracer tracer(referenceScene, camera, settings.output.width, settings.output.height, reference);
    if (!options.nodeMap.empty()) {
        std::string error;
        const auto hits =
            lit::reference::traceFirstHits(referenceScene, camera, settings.output.width, settings.output.height);
        if (!writeNodeMap(options.nodeMap, scene, hits, settings.output.width, settings.output.height, error)) {
            log.error(error);
            return 1;
        }
    }

    std::optional<InterruptScope> interruptible(std::in_place);
    const int spp = options.referenceSpp();
    const bool terminal = isatty(fileno(stderr)) != 0;
    const Clock::time_point renderStart = Clock::now();
    double lastPrint = -1.0;
    bool interrupted = false;
    bool printed = false;
    while (tracer.samplesDone() < spp) {
        if (!tracer.addSamples(1, &interruptRequested())) {
            interrupted = true;
            break;
        }
        const double elapsed = secondsSince(renderStart);
        const int done = tracer.samplesDone();
        if (elapsed - lastPrint >= (terminal ? 0.2 : 1.0) || done == spp) {
            lastPrint = elapsed;
            printed = true;
            const double raysPerSecond = elapsed > 0.0 ? static_cast<double>(tracer.raysTraced()) / elapsed : 0.0;
            const double remaining = elapsed / done * (spp - done);
            char line[160];
            std::snprintf(line, sizeof line, "reference: %d/%d spp, %.2f Mrays/s, %.1f s elapsed, ETA %.1f s", done,
                          spp, raysPerSecond * 1e-6, elapsed, remaining);
            if (terminal)
                std::fprintf(stderr, "\r%-72s", line);
            else
                std::fprintf(stderr, "%s\n", line);
            std::fflush(stderr);
        }
    }
    interruptible.reset();
    if (printed && terminal) std::fputc('\n', stderr);
    const double seconds = secondsSince(renderStart);

    const std::string bounces =
        reference.bounces == lit::reference::kAllBounces ? "all" : std::to_string(reference.bounces);
    std::printf(
        "reference: %dx%d, %u spp (min per pixel), bounces %s, seed %llu: %.1f M rays in %.2f s = %.2f Mrays/s "
        "on %d threads (scene build %.2f s, %zu triangles)\n",
        settings.output.width, settings.output.height, tracer.image().minSamples(), bounces.c_str(),
        static_cast<unsigned long long>(reference.seed), static_cast<double>(tracer.raysTraced()) * 1e-6, seconds,
        seconds > 0.0 ? static_cast<double>(tracer.raysTraced()) / seconds * 1e-6 : 0.0,
        tbb::info::default_concurrency(), buildSeconds, referenceScene.triangleCount());

    const std::vector<float> rgb = tracer.image().viewRgb(settings.debug.view, settings);
    std::string written;
    if (!options.out.empty()) {
        lit::writePng(options.out, settings.output.width, settings.output.height,
                      lit::reference::toneMapToRgba8(rgb, settings.output.exposureScale()));
        written = options.out.string();
    }
    if (!options.hdr.empty()) {
        lit::writeHdr(options.hdr, settings.output.width, settings.output.height, rgb);
        written += (written.empty() ? "" : " and ") + options.hdr.string();
    }
    if (!written.empty()) std::printf("wrote %s\n", written.c_str());
    if (run.compareTruth) compareWithReference(options, *run.compareTruth, rgb);
    if (interrupted) {
        std::fprintf(stderr, "lit-render: interrupted after %d of %d samples per pixel; the image so far was written\n",
                     tracer.samplesDone(), spp);
        return 130;  // the shell's status for a SIGINT
    }
    return 0;
}

int runReferencePath(const RunContext& run, const CameraPath& path, Scene& scene) {
    const Options& options = run.options;
    const RenderSettings& settings = run.settings;
    const std::vector<double> times = pathFrameTimes(options, path, scene);
    makeFramesFolder(options.framesOut);
    const lit::reference::ReferenceSettings reference = referenceSettingsFor(run, scene);
    const float aspect = static_cast<float>(settings.output.width) / static_cast<float>(settings.output.height);
    const int spp = options.referenceSpp();
    const InterruptScope interruptible;
    const Clock::time_point start = Clock::now();
    for (std::size_t i = 0; i < times.size(); ++i) {
        // Posed at the frame's time as the rasterized path is: the tracer builds from this pose.
        lit::applyNodeAnimations(scene, times[i]);
        const lit::CameraView view = *path.view(times[i], aspect, scene.worldBounds());
        const lit::Scene withSun = withDefaultSun(scene, settings);
        const lit::reference::ReferenceScene referenceScene(withSun, run.log);
        lit::reference::PathTracer tracer(referenceScene, view, settings.output.width, settings.output.height,
                                          reference);
        const bool complete = tracer.addSamples(spp, &interruptRequested());
        const std::vector<float> rgb = tracer.image().viewRgb(settings.debug.view, settings);
        lit::writePng(frameFile(options.framesOut, i), settings.output.width, settings.output.height,
                      lit::reference::toneMapToRgba8(rgb, settings.output.exposureScale()));
        std::fprintf(stderr, "reference path: frame %zu of %zu (%.3f s), %u spp, %.1f s elapsed\n", i + 1, times.size(),
                     times[i], tracer.image().minSamples(), secondsSince(start));
        if (!complete) {
            std::fprintf(stderr, "lit-render: interrupted in frame %zu of %zu; it was written with the samples so far\n",
                         i + 1, times.size());
            return 130;
        }
    }
    std::printf("wrote %zu reference frames to %s (%dx%d, %g fps, %d spp, %.2f s)\n", times.size(),
                options.framesOut.string().c_str(), settings.output.width, settings.output.height, options.pathFps(),
                spp, secondsSince(start));
    return 0;
}

}  // namespace lit::cli
