#pragma once
// The voxel volume of voxel cone tracing: a cube around the scene, N voxels per side.
//
//   albedo    r32ui  N³, 1 level   packed RGBA8: rgb base colour (linear), a = sample count (running average)
//   normal    r32ui  N³, 1 level   packed RGBA8: xyz normal·0.5+0.5, a = sample count
//   emission  r32ui  N³, 1 level   packed RGBA8: rgb emitted radiance / emission range, a = sample count
//   radiance  RGBA16F (or RGBA8) N³, full mip chain: rgb outgoing radiance, a opacity (0..1)
//   directional[3]  same format, 3(N/2) × (N/2) × (N/2) with its own mip chain: levels 1.. of the
//             radiance volume as a cone travelling along +axis (x ∈ [0, m)) and −axis
//             (x ∈ [2m, 3m)) sees them, m the level's edge, an empty gap between them so that
//             filtering never mixes the two (anisotropic voxels, docs/GI.md; one volume per axis
//             lets a cone pick its face by a coordinate offset instead of a branch, which llvmpipe
//             would run both sides of); level 0 stays the isotropic radiance volume
//   direct, bounce  same format, N³, 1 level, allocated when more than one bounce is asked for:
//             the direct radiance and the next bounce's radiance (BouncePass)
//
// The material volumes use r32ui because GLSL has atomics only on 32-bit integers: fragments that
// land in the same voxel average with a compare-and-swap loop (voxel.glsl) instead of flickering.
// A voxel is occupied when its albedo count (alpha) is non-zero.

#include <shared.h>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "RenderSettings.h"
#include "gi/VoxelRegions.h"
#include "gl/Objects.h"
#include "scene/Aabb.h"

namespace lit {

class Log;

class VoxelVolume {
public:
    VoxelVolume();

    // Validates `requested` (power of two, 64..512, fits in GPU memory): an invalid value is
    // clamped to the nearest valid one with a warning in `log`. Reallocates when the resolution
    // or format changes and returns true (the caller must re-voxelize).
    bool ensure(int requested, bool radianceRgba8, Log& log);
    // Places the cube around `sceneBounds` (padded by a few voxels so geometry on the bounds is
    // inside, shifted by ¼ voxel in y and z so that surfaces at round heights do not lie on voxel
    // faces) and returns whether it moved (the caller must re-voxelize).
    bool fitTo(const Aabb& sceneBounds);
    // A near level: the cube is `cube` itself (no padding: it is placed around the camera, not
    // around geometry), shifted by the same ¼ voxel in y and z, so that moves of the cube by whole
    // voxels move the grid by whole voxels (VoxelScrollPass). Returns whether it moved.
    bool placeAt(const Aabb& cube);
    // Uploads VoxelUniforms from the volume placement and `settings`, binds it to LIT_UBO_VOXEL.
    void updateUniforms(const RenderSettings& settings, int frameIndex);

    // Zeroes the material volumes (before voxelization), or only the voxels of `box`.
    void clearMaterials() const;
    void clearMaterials(const VoxelBox& box) const;

    // The occupied-voxel list (SSBO at LIT_SSBO_OCCUPIED_VOXELS, std430): uint count, a
    // DispatchIndirectCommand (groups of LIT_INJECT_LIST_GROUP_SIZE over the list), then up to
    // occupiedCapacity() packed coordinates x | y << 10 | z << 20. VoxelizePass appends every voxel
    // it occupies; InjectPass runs over the list with glDispatchComputeIndirect.
    const gl::Buffer& occupiedList() const { return occupied_; }
    std::uint32_t occupiedCapacity() const { return occupiedCapacity_; }
    static constexpr std::size_t kOccupiedHeaderBytes = 16;  // count + dispatch x, y, z
    // Empties the list (before voxelization): count 0, dispatch 0 × 1 × 1, no voxel listed.
    void resetOccupiedList() const;
    // Which voxels the list holds (SSBO at LIT_SSBO_LISTED_VOXELS: one bit per voxel). A
    // voxelization of changed boxes keeps the list and its bits: it appends only voxels not
    // listed yet, so entries keep their places (and their recorded ray hits), and a voxel that
    // became empty stays listed as an empty entry, which every pass over the list skips.
    const gl::Buffer& listedVoxels() const { return listed_; }
    // Voxels appended since the reset; more than occupiedCapacity() when the list overflowed (the
    // excess was not stored). Reads one uint back: waits for the voxelization.
    std::uint32_t readOccupiedCount() const;
    // Which empty voxels lie inside a solid (SSBO at LIT_SSBO_SOLID_VOXELS: one bit per voxel,
    // written by SolidVoxelsPass after each voxelization, read by the voxel rays).
    const gl::Buffer& solidVoxels() const { return solid_; }
    // The boxes the passes over the list are limited to (the list readers skip voxels outside
    // them; empty: every voxel): a near level's update of the slabs a scroll uncovered sets them
    // around its passes (VoxelGi). Applied by dispatchOverVoxels and dispatchListRange.
    const std::vector<VoxelBox>& onlyBoxes() const { return onlyBoxes_; }
    void setOnlyBoxes(std::vector<VoxelBox> boxes) { onlyBoxes_ = std::move(boxes); }
    // The stored coordinates (tests): min(count, capacity) entries in append order.
    std::vector<glm::ivec3> readOccupiedList() const;
    // Grows the list to hold at least `count` voxels (after an overflow; the next voxelization fills it).
    void growOccupiedList(std::uint32_t count);
    // Zeroes level 0 of the radiance volume: injection over the list writes occupied voxels only.
    // With a box: only its voxels (a voxelization of changed boxes).
    void clearRadianceLevel0() const;
    void clearRadianceLevel0(const VoxelBox& box) const;
    // Zeroes levels 1.. of the radiance volume (before voxelization: the mip chain is built over
    // the occupied parents only, so the parents of voxels that are empty now must read as empty),
    // marks the directional chains stale (MipmapPass zeroes them before it next builds them over
    // the parents; they cost 9/8 of level 0 and are only used with anisotropic voxels) and the
    // parent lists invalid (MipmapPass::listOccupiedParents lists them again).
    void clearRadianceMips();

    // The occupied parents of each mip level (SSBO at LIT_SSBO_MIP_PARENTS, shared.h and
    // shaders/include/mip_parents.glsl): header, then per level k = 1..mipCount−1 its list
    // (listOffset[k] uints into the data after the header, room for listCapacity[k] entries)
    // and its bitmask (maskOffset[k], one bit per voxel of the level).
    struct ParentLayout {
        std::array<std::uint32_t, LIT_MIP_LIST_LEVELS> listOffset{}, listCapacity{}, maskOffset{};
        std::uint32_t maskBegin = 0, maskWords = 0;  // the bitmasks: one range, zeroed before listing
        std::uint32_t totalWords = 0;                // uints after the header
    };
    static constexpr std::size_t kParentHeaderBytes = 16 * LIT_MIP_LIST_LEVELS;
    // (Re)allocates the parent lists for the resolution and occupiedCapacity() (MipmapPass).
    void ensureParentLists();
    const gl::Buffer& parentLists() const { return parents_; }
    const ParentLayout& parentLayout() const { return parentLayout_; }
    // Whether the parent lists describe the current voxelization (set by MipmapPass once listed).
    bool parentListsValid() const { return parentListsValid_; }
    void setParentListsValid(bool valid) { parentListsValid_ = valid; }
    // Whether the directional chains may hold values of an earlier voxelization (see clearRadianceMips).
    bool directionalStale() const { return directionalStale_; }
    void setDirectionalStale(bool stale) { directionalStale_ = stale; }
    // Level `level`'s listed parents (tests): its count entries in list order; empty before listing.
    std::vector<glm::ivec3> readParentList(int level) const;
    // Zeroes every level of the three directional volumes.
    void clearDirectional() const;

    int resolution() const { return resolution_; }
    int mipCount() const { return mipCount_; }
    glm::vec3 minCorner() const { return min_; }
    float side() const { return side_; }
    float voxelSize() const { return side_ / static_cast<float>(resolution_); }
    VoxelPlacement placement() const { return {min_, voxelSize(), resolution_}; }
    bool radianceRgba8() const { return rgba8_; }
    GLenum radianceFormat() const { return rgba8_ ? GL_RGBA8 : GL_RGBA16F; }

    const gl::Texture& albedo() const { return albedo_; }
    const gl::Texture& normal() const { return normal_; }
    const gl::Texture& emission() const { return emission_; }
    // Where in each voxel its surface lies (LIT_IMG_VOXEL_SURFACE, voxelize.frag.glsl).
    const gl::Texture& surface() const { return surface_; }
    const gl::Texture& radiance() const { return radiance_; }
    // Two-sided voxels' direct light by side (RG32UI, LIT_IMG_VOXEL_SIDES / LIT_TEX_VOXEL_SIDES): the
    // axis of the slab a voxel holding faces back to back lies in, and the half difference of its two
    // sides' direct light, which level 0 holds the mean of (inject.comp.glsl; voxel.glsl, "Sides").
    const gl::Texture& sides() const { return sides_; }
    // The directional volume of axis 0 X, 1 Y, 2 Z: both faces of the axis side by side along x
    // (see the layout at the top).
    const gl::Texture& directional(int axis) const { return directional_[static_cast<std::size_t>(axis)]; }
    // Binds the three directional volumes to LIT_TEX_VOXEL_DIRECTIONAL_FIRST + axis.
    void bindDirectional() const;
    // Allocates the direct, bounce and (RGBA16F) change volumes if they are missing (multiple bounces).
    void ensureBounceVolumes();
    // The three directional volumes (anisotropic voxels), made zeroed on first use and freed when
    // anisotropic voxels are switched off: the default mode does not pay their memory.
    void ensureDirectionalVolumes();
    void releaseDirectionalVolumes();
    const gl::Texture& direct() const { return direct_; }
    const gl::Texture& bounce() const { return bounce_; }
    // The last bounce's change from the one before, L_k − L_(k−1) (BouncePass::finish writes it,
    // later bounces gather it); RGBA16F volumes only, else empty.
    const gl::Texture& change() const { return change_; }
    const gl::Buffer& uniforms() const { return uniforms_; }

    // Bytes of GPU memory per volume and in total (radiance counted with its mip chain).
    std::size_t materialBytes() const;  // albedo + normal + emission + surface
    std::size_t radianceBytes() const;  // isotropic chain + the six directional chains while they exist + sides
    std::size_t bounceBytes() const;    // direct + bounce + change volumes (0 until allocated)
    std::size_t listBytes() const;      // the occupied-voxel list, its bit per voxel and the solid bits
    std::size_t totalBytes() const { return materialBytes() + radianceBytes() + bounceBytes() + listBytes(); }
    std::string memoryReport() const;  // "albedo 8.0 MiB, normal 8.0 MiB, ... total 54.9 MiB"

    // The r32ui material volumes: albedo, normal, emission, surface (4 bytes per voxel each).
    static constexpr int kMaterialVolumeCount = 4;
    // Radiance that maps to 1.0 in the packed emission volume (W/(sr·m²)).
    static constexpr float kEmissionRange = 16.0f;

private:
    int resolution_ = 0;
    int mipCount_ = 0;
    bool rgba8_ = false;
    glm::vec3 min_{0.0f};
    float side_ = 1.0f;
    gl::Texture albedo_, normal_, emission_, surface_, radiance_, sides_;
    // The r32ui volumes the voxelization writes (kMaterialVolumeCount of them).
    std::array<const gl::Texture*, kMaterialVolumeCount> materialVolumes() const {
        return {&albedo_, &normal_, &emission_, &surface_};
    }
    std::array<gl::Texture, LIT_VOXEL_AXIS_COUNT> directional_;
    gl::Texture direct_, bounce_, change_;
    gl::Buffer uniforms_;
    gl::Buffer occupied_;
    gl::Buffer listed_;
    gl::Buffer solid_;
    std::uint32_t occupiedCapacity_ = 0;
    std::vector<VoxelBox> onlyBoxes_;
    gl::Buffer parents_;
    ParentLayout parentLayout_;
    bool parentListsValid_ = false;
    bool directionalStale_ = false;
};

// Bytes the volumes of an N³ volume take: materials, radiance with mips, the six directional
// chains, (with `bounces` > 1) the direct and bounce volumes and the cached GI mode's four
// irradiance volumes (allocated only in that mode, counted always).
std::size_t voxelVolumeBytes(int n, bool radianceRgba8, bool bounces);
// Largest N the volumes may use given `availableBytes` of GPU memory (0 = unknown → 512).
int largestVoxelResolutionFor(std::size_t availableBytes, bool radianceRgba8);
// GPU memory still free in bytes if the driver says (NVX_gpu_memory_info, ATI_meminfo), else 0.
std::size_t queryFreeGpuMemory();

}  // namespace lit
