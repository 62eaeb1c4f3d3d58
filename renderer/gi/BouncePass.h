#pragma once
// Light bounces 2..N (docs/GI.md, "Bounces"): after the injection and a full mip build, each
// occupied voxel gathers its indirect diffuse light (cones through the mips, or voxel rays through
// the grid) and the bounce's radiance is direct radiance + albedo × that gather
// (shaders/bounce.comp.glsl). The direct radiance is volume.direct(), which InjectPass writes
// beside level 0 (InjectOptions::writeDirect; VoxelVolume::ensureBounceVolumes first). A bounce
// may be spread over frames: trace() takes a range of the occupied-voxel list into
// volume.bounce(), reading the radiance volume as it stands; finish(), once every voxel was
// traced, copies the bounce into level 0, and the caller rebuilds the mips from it.

#include <filesystem>
#include <string>
#include <vector>

#include "gi/ConeProgram.h"
#include "gi/GiBudget.h"
#include "gi/RayHitCache.h"
#include "gi/VoxelDispatch.h"
#include "passes/Pass.h"

namespace lit {

class VoxelVolume;

struct BounceTrace {
    ConeFeatures features;      // the cone features (and voxel rays) to gather with (ConeFeatures::of)
    bool secondBounce = false;  // voxel rays take the direct volume's light (else level 0's: the bounce before)
    bool overList = true;       // the occupied-voxel list's voxels; false when it overflowed (whole grid)
    VoxelRange range;           // list entries to trace (count 0: all)
    RayHits rayHits = RayHits::Off;
    bool measureChange = false;  // add to the change sums (readChange), for every bounce until converged
    // ≥ 0: gather the bounce before's change (volume.change()) over this subset of the rays, one in
    // changeStride (changeSubsetFor); −1: gather the light itself over every ray.
    int changeSubset = -1;
    int changeStride = 1;
};

// How the copy into level 0 ends a bounce (BouncePass::finish).
struct BounceFinish {
    bool overList = true;  // the listed voxels (false: the whole grid, the list having overflowed)
    // > 0: add the bounces still to come as tail × this bounce's change (BounceConvergence::tail).
    float tail = 0.0f;
    // The bounce gathered the direct light (BounceTrace::secondBounce): its change is measured from
    // that, not from level 0, which may still hold the last update's light.
    bool fromDirect = false;
    bool keepChange = false;  // keep the bounce's change for the next to gather (when volume.change() exists)
};

// What one bounce did to the voxels' light: the luminance of its bounced light (radiance − direct)
// and of its change from the bounce before, summed over the voxels it traced (W/(sr·m²)).
struct BounceChange {
    double luminance = 0.0;
    double change = 0.0;
    double relative() const { return luminance > 0.0 ? change / luminance : 0.0; }
};

class BouncePass : public Pass {
public:
    explicit BouncePass(std::filesystem::path shaderRoot) : shaderRoot_(std::move(shaderRoot)) {}

    void trace(const VoxelVolume& volume, const RayHitCache& cache, const BounceTrace& bounce);
    // Copies the bounce into level 0: the listed voxels only (bounce_copy.comp.glsl), or the whole
    // grid when the list overflowed. Over the list, a tail adds the bounces still to come, and
    // the bounce's change may be kept for the next to gather (volume.change(), when it exists); the
    // whole grid's copy does neither (changeKept() false).
    void finish(const VoxelVolume& volume, const BounceFinish& how);
    // Whether the last finish kept its bounce's change.
    bool changeKept() const { return changeKept_; }
    // Every bounce after a geometry edit starts from the last update's light (bounce_warm_start.comp.glsl):
    // keepIndirect, before the voxelization, over the old list, keeps each voxel's indirect light in
    // the bounce volume; addKeptIndirect, after the injection, over the new list, adds it to level 0.
    // Only over a complete list (both must be).
    void keepIndirect(const VoxelVolume& volume);
    void addKeptIndirect(const VoxelVolume& volume);
    // The change sums of the traces with measureChange since the last reset. readChange waits for
    // them (a GPU stall: once per bounce, with every bounce).
    void resetChange();
    BounceChange readChange() const;

    std::vector<gl::Program*> programs() override;

private:
    std::filesystem::path shaderRoot_;
    // bounce.comp.glsl for RGBA8 and RGBA16F volumes, built on the first bounce.
    ConeProgram trace8_, trace16f_;
    gl::Program copy8_, copy16f_;  // bounce_copy.comp.glsl, built by the first finish over the list
    gl::Program warm8_, warm16f_;  // bounce_warm_start.comp.glsl, built by the first keepIndirect
    void warmStart(const VoxelVolume& volume, int mode);
    gl::Buffer changeBins_;        // LIT_SSBO_BOUNCE_CHANGE, made by the first resetChange
    bool changeKept_ = false;
};

// The compute program `file` for RGBA8 or RGBA16F volumes (LIT_BOUNCE_RGBA8), built into
// `rgba8Program` or `rgba16fProgram` on first use.
const gl::Program& radianceFormatProgram(const std::filesystem::path& shaderRoot, gl::Program& rgba8Program,
                                         gl::Program& rgba16fProgram, bool rgba8, const std::string& label,
                                         const char* file);
std::string radianceFormatDefine(bool rgba8);

}  // namespace lit
