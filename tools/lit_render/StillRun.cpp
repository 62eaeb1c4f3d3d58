#include "StillRun.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "Bench.h"
#include "Compare.h"
#include "GiUpdateBench.h"
#include "Renderer.h"
#include "gl/Capabilities.h"
#include "image/ImageIO.h"
#include "passes/TemporalAntialiasPass.h"
#include "scene/CameraView.h"
#include "scene/Scene.h"

namespace lit::cli {

int runStill(const RunContext& run, Scene& scene, const CameraView& camera, const GlRun& gl) {
    const Options& options = run.options;
    const RenderSettings& settings = run.settings;
    Renderer& renderer = gl.renderer;

    const Clock::time_point renderStart = Clock::now();
    BenchResult bench;
    // With temporal accumulation or anti-aliasing a still renders until the history is full, so
    // it shows the converged image (docs/GI.md, "Temporal accumulation"; docs/ARCHITECTURE.md,
    // "Anti-aliasing"); --frames or --bench choose the count themselves.
    const bool settle = !options.frames && options.benchFrames == 0;
    const int frames = settle && settings.indirect.temporalAccumulation
                           ? std::max(settings.indirect.temporalMaxFrames, 1)
                           : options.frameCount();
    // Anti-aliasing's history starts in the frame after the GI's light last changed: the frame
    // count it needs is known once it runs (at most two more than its own).
    const int antialiasFrames =
        settle && TemporalAntialiasPass::applies(settings) ? TemporalAntialiasPass::frames(settings) : 0;
    const auto antialiasing = [&](int frame) {
        return renderer.stats().antialiasFrames < antialiasFrames && frame < frames + antialiasFrames + 2;
    };
    for (int frame = 0; frame < frames || antialiasing(frame); ++frame) {
        const Clock::time_point frameStart = Clock::now();
        renderer.render(scene, camera, settings, giBudgetFor(options));
        if (options.benchFrames > 0) recordBenchFrame(bench, renderer, frameStart);
    }
    lit::gl::injectGlErrorIfRequested();  // LIT_TEST_GL_ERROR=1: the test of the check below
    glFinish();
    if (settings.output.autoExposure)
        std::printf("auto exposure: %+.2f EV\n", static_cast<double>(renderer.exposureEv(settings)));
    // Every bounce stops when the light has converged: how many it took says how much of the
    // image is bounced light (docs/GI.md, "Bounces").
    if (settings.gi.enabled && renderer.stats().giEveryBounce && renderer.stats().giUpdateDone >= 1.0f)
        std::printf("GI: every bounce, converged after %d\n", renderer.stats().giBounces);
    if (options.benchFrames > 0 && settings.gi.enabled) bench.mipmaps = renderer.benchmarkMipmaps(7);
    if (options.giUpdateRounds > 0 && settings.gi.enabled)
        benchGiUpdates(options.giUpdateRounds, scene, camera, renderer, settings, giBudgetFor(options));
    if (options.giMoveRounds > 0 && settings.gi.enabled)
        benchGiMoves(options.giMoveRounds, scene, camera, renderer, settings, giBudgetFor(options));

    if (options.benchFrames > 0) {
        printBench(bench, settings, renderer.stats());
        if (!options.benchJson.empty())
            writeBenchJson(options.benchJson, benchJson(bench, options, settings, gl.device, renderer.stats()));
    }

    gl.requireNoGlErrors();
    std::string written;
    if (!options.out.empty()) {
        const std::vector<std::uint8_t> rgba = renderer.readOutputRgba8();
        lit::writePng(options.out, settings.output.width, settings.output.height, rgba);
        written = options.out.string();
    }
    if (!options.hdr.empty() || run.compareTruth) {
        const std::vector<float> rgb = renderer.readHdrRgb();
        if (!options.hdr.empty()) {
            lit::writeHdr(options.hdr, settings.output.width, settings.output.height, rgb);
            written += (written.empty() ? "" : " and ") + options.hdr.string();
        }
        if (run.compareTruth) compareWithReference(options, *run.compareTruth, rgb);
    }
    if (!written.empty())
        std::printf("wrote %s (%d\u00d7%d, %.2f s)\n", written.c_str(), settings.output.width, settings.output.height,
                    secondsSince(renderStart));
    return 0;
}

}  // namespace lit::cli
