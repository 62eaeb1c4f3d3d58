#include "GiUpdateBench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "RenderSettings.h"
#include "Renderer.h"
#include "scene/CameraView.h"
#include "scene/Scene.h"

namespace lit::cli {

void benchGiUpdates(int rounds, lit::Scene& scene, const lit::CameraView& camera, lit::Renderer& renderer,
                    const lit::RenderSettings& settings, const lit::GiBudget& budget) {
    const auto passMs = [&](const char* name) { return renderer.profiler().gpuMs(name); };
    std::printf(
        "GI updates at %d³, %u occupied voxels (%.2f %% of the grid), %d rounds:\n", settings.gi.voxelResolution,
        renderer.stats().occupiedVoxels,
        100.0 * renderer.stats().occupiedVoxels / std::pow(static_cast<double>(settings.gi.voxelResolution), 3.0),
        rounds);
    // The cached GI mode's irradiance pass and filter (and any bounces) follow every edit: they
    // belong to its cost (0 in the modes without them).
    const auto cachedMs = [&] {
        return passMs("bounces") + passMs("voxel irradiance") + passMs("voxel irradiance filter");
    };
    // An update spread over frames (--gi-update-per-frame, as the editor runs it) goes on
    // after the timed frame: the next edit is timed once it is done, as a user's next edit usually
    // comes after the last one's light settled (and only then is the voxel rays' hit cache
    // recorded, which the light edits of the editor replay). Returns the frames it took and their
    // GI passes' GPU ms (the time to the final light is those frames).
    struct Settle {
        int frames = 0;
        double giMs = 0.0;
    };
    const auto settle = [&] {
        constexpr int kMaxFrames = 20000;
        Settle done;
        while (renderer.stats().giUpdateDone < 1.0f && done.frames < kMaxFrames) {
            renderer.render(scene, camera, settings, budget);
            renderer.profiler().flush();
            ++done.frames;
            done.giMs += cachedMs();
        }
        return done;
    };
    settle();
    std::vector<double> ratios;
    for (int round = 1; round <= rounds; ++round) {
        // A: light edit. The first light's intensity changes by a part in 10⁴ and back next round.
        if (!scene.lights.empty()) scene.lights[0].intensity *= (round % 2) ? 1.0001f : 1.0f / 1.0001f;
        ++scene.lightRevision;
        renderer.render(scene, camera, settings, budget);
        renderer.profiler().flush();
        const double editInject = passMs("inject"), editMipmap = passMs("mipmap"), editCached = cachedMs();
        const double edit = editInject + editMipmap + editCached, editShadow = passMs("shadow");
        const Settle editRest = settle();
        // B: geometry edit without moving anything: the volume is voxelized again.
        ++scene.geometryRevision;
        renderer.render(scene, camera, settings, budget);
        renderer.profiler().flush();
        const double lists = passMs("solid voxels") + passMs("mip lists"), revoxelizeCached = cachedMs();
        const double revoxelize = passMs("voxelize") + lists + passMs("inject") + passMs("mipmap") + revoxelizeCached,
                     fullShadow = passMs("shadow");
        const Settle revoxelizeRest = settle();
        ratios.push_back(edit / revoxelize);
        std::printf(
            "gi-update round %d: light edit %.1f ms (inject %.1f + mipmap %.1f + bounces/voxel irradiance %.1f) | "
            "re-voxelize %.1f ms (voxelize + solid voxels and mip lists %.1f + inject + mipmap + bounces/voxel irradiance %.1f) | "
            "ratio %.3f | shadow maps %.1f / %.1f ms\n",
            round, edit, editInject, editMipmap, editCached, revoxelize, lists, revoxelizeCached, edit / revoxelize,
            editShadow, fullShadow);
        if (editRest.frames > 0 || revoxelizeRest.frames > 0)
            std::printf(
                "gi-update round %d, spread over frames: the light edit's update took %d more frames (GI passes "
                "%.1f ms), the re-voxelization's %d (%.1f ms)\n",
                round, editRest.frames, editRest.giMs, revoxelizeRest.frames, revoxelizeRest.giMs);
    }
    std::sort(ratios.begin(), ratios.end());
    std::printf("gi-update median ratio (light edit / re-voxelize): %.3f\n", ratios[ratios.size() / 2]);
}

}  // namespace lit::cli
