#include "GiUpdateBench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "RenderSettings.h"
#include "animation/NodeAnimation.h"
#include "Renderer.h"
#include "scene/CameraView.h"
#include "scene/Scene.h"

namespace lit::cli {

namespace {

// The mesh node with the smallest world box (a prop, not the room), or -1.
int smallestMeshNode(const Scene& scene) {
    int best = -1;
    float bestSize = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const Node& node = scene.nodes[i];
        if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= scene.meshes.size()) continue;
        Aabb bounds;
        for (const Primitive& p : scene.meshes[static_cast<std::size_t>(node.mesh)].primitives)
            bounds.extend(p.bounds.transformed(node.world));
        if (bounds.empty()) continue;
        const float size = bounds.radius();
        if (size < bestSize) {
            bestSize = size;
            best = static_cast<int>(i);
        }
    }
    return best;
}

double giMs(Renderer& renderer) {
    double sum = 0.0;
    for (const char* name : {"voxelize", "solid voxels", "mip lists", "inject", "mipmap", "bounces", "voxel irradiance",
                             "voxel irradiance filter"})
        sum += renderer.profiler().gpuMs(name);
    return sum;
}

struct MoveCost {
    double editFrameMs = 0.0;  // the edit's frame: voxelize, lists, inject, mipmaps, traces
    double voxelizeMs = 0.0;
    double totalMs = 0.0;      // every frame's GI passes up to the final light (refinement included)
    double worstFrameMs = 0.0;  // the most one of those frames' GI passes took
    int frames = 0;
    int boxes = 0;
};

}  // namespace

void benchGiMoves(int rounds, Scene& scene, const CameraView& camera, Renderer& renderer,
                  const RenderSettings& settings, const GiBudget& budget) {
    const int node = smallestMeshNode(scene);
    if (node < 0) {
        std::printf("gi-move: the scene has no mesh node to move\n");
        return;
    }
    Node& moved = scene.nodes[static_cast<std::size_t>(node)];
    Aabb bounds;
    for (const Primitive& p : scene.meshes[static_cast<std::size_t>(moved.mesh)].primitives)
        bounds.extend(p.bounds.transformed(moved.world));
    const float step = 0.1f * std::max(bounds.size().x, std::max(bounds.size().y, bounds.size().z));
    // Until the update and the refinement (when the budget runs one) are done: the next edit
    // starts from settled light.
    const auto settle = [&](MoveCost& cost) {
        constexpr int kMaxFrames = 20000;
        const auto pending = [&] {
            return renderer.stats().giUpdateDone < 1.0f || (budget.refineVoxels > 0 && renderer.stats().giRefining);
        };
        while (pending() && cost.frames < kMaxFrames) {
            renderer.render(scene, camera, settings, budget);
            renderer.profiler().flush();
            ++cost.frames;
            cost.totalMs += giMs(renderer);
            cost.worstFrameMs = std::max(cost.worstFrameMs, giMs(renderer));
        }
    };
    // A scene with node animations moves as they play, a frame (1/30 s) at a time; another scene
    // moves its smallest mesh node.
    const bool animated = summarizeNodeAnimations(scene).nodes > 0;
    const std::vector<Node> restNodes = scene.nodes;
    double seconds = 0.0;
    // A move: the node animations posed at `at` s, or the node moved `by` m along x.
    const auto moveTo = [&](double at, float by) {
        if (animated) {
            applyNodeAnimations(scene, at);
        } else {
            moved.translation.x += by;
            scene.updateWorldTransforms();
            ++scene.geometryRevision;
        }
    };
    // One move and its frame (the edit's GI passes run in it), with or without changed boxes.
    const auto moveAndRender = [&](bool changesOnly, float by) {
        RenderSettings s = settings;
        s.gi.voxelizeChangesOnly = changesOnly;
        seconds += 1.0 / 30.0;
        moveTo(seconds, by);
        renderer.render(scene, camera, s, budget);
        renderer.profiler().flush();
    };
    const auto move = [&](bool changesOnly, float by) {
        moveAndRender(changesOnly, by);
        MoveCost cost;
        cost.boxes = renderer.stats().voxelizedBoxes;
        cost.editFrameMs = giMs(renderer);
        cost.voxelizeMs = renderer.profiler().gpuMs("voxelize");
        cost.totalMs = cost.editFrameMs;
        cost.worstFrameMs = cost.editFrameMs;
        settle(cost);
        return cost;
    };
    MoveCost warm;
    settle(warm);
    if (animated)
        std::printf("GI moves at %d³: the node animations advance 1/30 s a move, %d rounds:\n",
                    settings.gi.voxelResolution, rounds);
    else
        std::printf("GI moves at %d³: node '%s' moves %.3f m along x and back, %d rounds:\n",
                    settings.gi.voxelResolution, moved.name.c_str(), static_cast<double>(step), rounds);
    // worstRatios: the move's busiest frame against the whole volume's update (all its frames), the
    // bar's measure (a quarter at most).
    std::vector<double> frameRatios, totalRatios, worstRatios, wholeTotals;
    for (int round = 1; round <= rounds; ++round) {
        const float sign = (round % 2) ? 1.0f : -1.0f;
        // Interleaved, the order turned each round: the one that runs second starts from the first's light.
        const bool boxesFirst = round % 2 == 1;
        MoveCost boxes, whole;
        if (boxesFirst) {
            boxes = move(true, sign * step);
            whole = move(false, -sign * step);
        } else {
            whole = move(false, sign * step);
            boxes = move(true, -sign * step);
        }
        frameRatios.push_back(boxes.editFrameMs / whole.editFrameMs);
        totalRatios.push_back(boxes.totalMs / whole.totalMs);
        worstRatios.push_back(boxes.worstFrameMs / whole.totalMs);
        wholeTotals.push_back(whole.totalMs);
        std::printf(
            "gi-move round %d: changed boxes (%d) edit frame %.1f ms (voxelize %.2f), to the final light %.1f ms in %d "
            "frames (at most %.1f ms a frame) | whole volume edit frame %.1f ms (voxelize %.2f), to the final light "
            "%.1f ms in %d frames | ratios %.3f / %.3f, busiest frame %.3f of the whole volume's update\n",
            round, boxes.boxes, boxes.editFrameMs, boxes.voxelizeMs, boxes.totalMs, boxes.frames + 1,
            boxes.worstFrameMs, whole.editFrameMs, whole.voxelizeMs, whole.totalMs, whole.frames + 1,
            frameRatios.back(), totalRatios.back(), worstRatios.back());
    }
    std::sort(frameRatios.begin(), frameRatios.end());
    std::sort(totalRatios.begin(), totalRatios.end());
    std::sort(worstRatios.begin(), worstRatios.end());
    std::sort(wholeTotals.begin(), wholeTotals.end());
    const double wholeUpdateMs = wholeTotals[wholeTotals.size() / 2];
    std::printf(
        "gi-move median ratios (changed boxes / whole volume): edit frame %.3f, to the final light %.3f, busiest frame "
        "%.3f of the whole volume's update (bar: 0.25)\n",
        frameRatios[frameRatios.size() / 2], totalRatios[totalRatios.size() / 2], worstRatios[worstRatios.size() / 2]);

    // Playback: a move every frame without waiting for the light, as the editor plays an animation
    // (the node there and back). Counted: the updates completed while it plays (each brings the
    // pixels' GI up to the poses it was traced at; with none, the GI stays at the pose before).
    constexpr int kPlaybackFrames = 30;
    const auto playback = [&](bool changesOnly) {
        int completed = 0, firstCompleted = 0;
        double ms = 0.0, worstMs = 0.0;
        for (int f = 0; f < kPlaybackFrames; ++f) {
            moveAndRender(changesOnly, f < kPlaybackFrames / 2 ? step : -step);
            if (renderer.stats().giUpdateCompleted && completed++ == 0) firstCompleted = f + 1;
            ms += giMs(renderer);
            worstMs = std::max(worstMs, giMs(renderer));
        }
        MoveCost rest;
        settle(rest);
        std::printf(
            "gi-move playback, %d frames, %s: %d updates completed while playing (the first in frame %d), GI passes "
            "%.1f ms a frame (at most %.1f)\n",
            kPlaybackFrames, changesOnly ? "changed boxes" : "whole volume", completed, firstCompleted,
            ms / kPlaybackFrames, worstMs);
    };
    playback(true);
    playback(false);

    // Recovery: after one move of half the object's size (changed boxes; with node animations,
    // from their pose at 0.5 s to the one at 1 s), how far each of the next frames' indirect diffuse
    // term is from the light it settles to, over the pixels the move changed (by more than 1 % of
    // the image's mean between the settled images before and after): Σ|frame − settled| / Σ settled
    // there (the bar: within 10 % by the 8th frame), and the share of the move's change not shown
    // yet, Σ|frame − settled| / Σ|settled before − settled|.
    {
        constexpr int kRecoveryFrames = 8;
        RenderSettings s = settings;
        s.debug.view = View::IndirectDiffuse;
        s.gi.voxelizeChangesOnly = true;
        if (animated) moveTo(0.5, 0.0f);
        MoveCost before;
        renderer.render(scene, camera, s, budget);
        settle(before);
        renderer.render(scene, camera, s, budget);
        const std::vector<float> settledBefore = renderer.readHdrRgb();
        std::vector<std::vector<float>> frames;
        std::vector<double> frameGiMs;
        for (int f = 0; f < kRecoveryFrames; ++f) {
            if (f == 0) moveTo(1.0, 5.0f * step);
            renderer.render(scene, camera, s, budget);
            frames.push_back(renderer.readHdrRgb());
            renderer.profiler().flush();
            frameGiMs.push_back(giMs(renderer));
        }
        MoveCost after;
        settle(after);
        renderer.render(scene, camera, s, budget);
        const std::vector<float> settled = renderer.readHdrRgb();
        double mean = 0.0;
        for (const float v : settled) mean += v;
        mean /= std::max<std::size_t>(settled.size(), 1);
        std::vector<bool> changed(settled.size() / 3, false);
        std::size_t changedPixels = 0;
        for (std::size_t p = 0; p < changed.size(); ++p) {
            double d = 0.0;
            for (int c = 0; c < 3; ++c) d += std::abs(settled[3 * p + c] - settledBefore[3 * p + c]);
            changed[p] = d > 0.03 * mean;  // 1 % of the mean per channel
            changedPixels += changed[p];
        }
        std::printf("gi-move recovery (changed boxes, %zu pixels changed by the move), error against the settled light:",
                    changedPixels);
        int within = -1;
        std::vector<double> missing;
        for (int f = 0; f < kRecoveryFrames; ++f) {
            double error = 0.0, total = 0.0, change = 0.0;
            for (std::size_t p = 0; p < changed.size(); ++p) {
                if (!changed[p]) continue;
                for (int c = 0; c < 3; ++c) {
                    error += std::abs(frames[static_cast<std::size_t>(f)][3 * p + c] - settled[3 * p + c]);
                    total += settled[3 * p + c];
                    change += std::abs(settledBefore[3 * p + c] - settled[3 * p + c]);
                }
            }
            const double relative = total > 0.0 ? error / total : 0.0;
            if (within < 0 && relative <= 0.1) within = f + 1;
            missing.push_back(change > 0.0 ? error / change : 0.0);
            std::printf(" %.1f %%", 100.0 * relative);
        }
        std::printf("; the move's change not shown yet:");
        for (const double m : missing) std::printf(" %.0f %%", 100.0 * m);
        std::printf("; GI passes a frame (share of the whole volume's update):");
        for (const double ms : frameGiMs) std::printf(" %.1f ms (%.2f)", ms, ms / wholeUpdateMs);
        if (within > 0)
            std::printf("; within 10 %% from frame %d (bar: 8)\n", within);
        else
            std::printf("; not within 10 %% in %d frames (bar: 8), settled after %d more\n", kRecoveryFrames,
                        after.frames);
    }

    scene.nodes = restNodes;
    scene.updateWorldTransforms();
    ++scene.geometryRevision;
}

}  // namespace lit::cli
