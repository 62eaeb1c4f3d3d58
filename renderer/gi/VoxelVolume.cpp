#include "gi/VoxelVolume.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>

#include "Log.h"

namespace lit {

namespace {
constexpr const char* kAxisNames[LIT_VOXEL_AXIS_COUNT] = {"±X", "±Y", "±Z"};
constexpr int kMinResolution = 64;
constexpr int kMaxResolution = 512;

// What the default settings allocate (one bounce, the cached GI mode's irradiance volumes): at 512³
// RGBA8 4.7 GiB, 5.7 GiB with the bounce volumes (bounces > 1), so an 8 GB GPU keeps 512³ with the
// quarter of its free memory this leaves to everything else.
std::size_t bytesFor(int n, bool rgba8) { return voxelVolumeBytes(n, rgba8, false); }

std::string mib(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return text;
}
}  // namespace

std::size_t voxelVolumeBytes(int n, bool rgba8, bool bounces) {
    const std::size_t voxels = static_cast<std::size_t>(n) * n * n;
    const std::size_t texel = rgba8 ? 4 : 8;
    const std::size_t material = voxels * 4 * VoxelVolume::kMaterialVolumeCount  // r32ui each
                                 + voxels / 8 * 2;                               // listed and solid bits
    // A full 3D mip chain adds 1/8 + 1/64 + ... ≈ 1/7 of the base level; each directional volume
    // (one per axis, its two faces and a gap between them side by side) starts at 3·(N/2)³, 3/8 of
    // the base, so the three add 9/7 of it.
    // Plus the two-sided voxels' split of their direct light by side (RG32UI).
    const std::size_t radiance = voxels * texel * 8 / 7 + 9 * (voxels / 8) * texel * 8 / 7 + voxels * 8;
    // The cached GI mode's irradiance volumes (VoxelIrradianceCache::prepare: the traced one,
    // N × N × 2N for two sides in the radiance format, and two sets of RGBA32UI gather texels, the
    // one shown while the other is written after a geometry edit); counted in every mode.
    const std::size_t irradiance = 2 * voxels * texel + 2 * voxels * 16;
    // Bounces: the direct and bounce volumes, and with RGBA16F the change volume (a bounce's
    // change, which the later bounces gather: BouncePass).
    return material + radiance + (bounces ? (rgba8 ? 2 : 3) * voxels * texel : 0) + irradiance;
}

std::size_t queryFreeGpuMemory() {
    GLint kb[4] = {0, 0, 0, 0};
    if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
        glGetIntegerv(GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX, kb);
        return static_cast<std::size_t>(kb[0]) * 1024;
    }
    if (epoxy_has_gl_extension("GL_ATI_meminfo")) {
        glGetIntegerv(GL_TEXTURE_FREE_MEMORY_ATI, kb);
        return static_cast<std::size_t>(kb[0]) * 1024;
    }
    return 0;
}

int largestVoxelResolutionFor(std::size_t availableBytes, bool radianceRgba8) {
    if (availableBytes == 0) return kMaxResolution;
    int n = kMaxResolution;
    // Leave a quarter of the free memory to everything else.
    while (n > kMinResolution && bytesFor(n, radianceRgba8) > availableBytes / 4 * 3) n /= 2;
    return n;
}

VoxelVolume::VoxelVolume() : uniforms_("voxel uniforms", sizeof(gpu::VoxelUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT) {}

bool VoxelVolume::ensure(int requested, bool radianceRgba8, Log& log) {
    int n = requested;
    if (n < kMinResolution || n > kMaxResolution || !std::has_single_bit(static_cast<unsigned>(std::max(n, 1)))) {
        // Nearest power of two inside the supported range.
        const int clamped = std::clamp(n, kMinResolution, kMaxResolution);
        const int below = static_cast<int>(std::bit_floor(static_cast<unsigned>(clamped)));
        n = (clamped - below < below * 2 - clamped || below * 2 > kMaxResolution) ? below : below * 2;
        log.warning("voxel resolution " + std::to_string(requested) + " is not a power of two in [" +
                    std::to_string(kMinResolution) + ", " + std::to_string(kMaxResolution) + "]; using " +
                    std::to_string(n));
    }
    GLint max3d = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3d);
    // The cached GI mode's irradiance volumes stack a voxel's two sides in z: N × N × 2N
    // (InjectPass). GL 4.5 guarantees 2048, so this only binds below the spec.
    const int limit = max3d / 2;
    if (n > limit) {
        log.warning("voxel resolution " + std::to_string(n) + " exceeds this GPU's 3D texture limit " +
                    std::to_string(max3d) + " (2N deep for the voxel irradiance); using " + std::to_string(limit));
        n = static_cast<int>(std::bit_floor(static_cast<unsigned>(std::max(limit, 1))));
    }
    if (n == resolution_ && radianceRgba8 == rgba8_) return false;
    const std::size_t free = queryFreeGpuMemory();
    const int fits = largestVoxelResolutionFor(free, radianceRgba8);
    if (n > fits) {
        log.warning("a " + std::to_string(n) + "³ voxel volume needs " + mib(bytesFor(n, radianceRgba8)) +
                    " but the GPU reports " + mib(free) + " free; using " + std::to_string(fits) + "³");
        n = fits;
        if (n == resolution_ && radianceRgba8 == rgba8_) return false;
    }

    resolution_ = n;
    rgba8_ = radianceRgba8;
    mipCount_ = gl::Texture::mipCount(n, n, n);
    albedo_ = gl::Texture("voxel albedo", {GL_TEXTURE_3D, GL_R32UI, n, n, n, 1});
    normal_ = gl::Texture("voxel normal", {GL_TEXTURE_3D, GL_R32UI, n, n, n, 1});
    emission_ = gl::Texture("voxel emission", {GL_TEXTURE_3D, GL_R32UI, n, n, n, 1});
    surface_ = gl::Texture("voxel surface", {GL_TEXTURE_3D, GL_R32UI, n, n, n, 1});
    for (const gl::Texture* t : materialVolumes()) t->setFilter(GL_NEAREST, GL_NEAREST);
    radiance_ = gl::Texture("voxel radiance", {GL_TEXTURE_3D, radianceFormat(), n, n, n, mipCount_});
    radiance_.setFilter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    sides_ = gl::Texture("voxel sides", {GL_TEXTURE_3D, GL_RG32UI, n, n, n, 1});
    sides_.setFilter(GL_NEAREST, GL_NEAREST);
    const std::uint32_t noSplit[2] = {0, 0};
    glClearTexImage(sides_.id(), 0, GL_RG_INTEGER, GL_UNSIGNED_INT, noSplit);
    radiance_.setWrap(GL_CLAMP_TO_BORDER);  // outside the volume is empty: opacity 0
    const float transparent[4] = {0, 0, 0, 0};
    glTextureParameterfv(radiance_.id(), GL_TEXTURE_BORDER_COLOR, transparent);
    for (int level = 0; level < mipCount_; ++level)
        glClearTexImage(radiance_.id(), level, GL_RGBA, GL_FLOAT, transparent);
    // The directional chains are made by the first anisotropic mipmap build (ensureDirectionalVolumes):
    // the default mode never reads them, and at 512³ they are 0.6 GiB (RGBA8) or 1.3 GiB (RGBA16F).
    directional_ = {};
    direct_ = {};
    bounce_ = {};
    change_ = {};
    parentListsValid_ = false;  // the chains above are zero: nothing stale
    directionalStale_ = false;
    clearMaterials();
    listed_ = gl::Buffer("listed voxels", std::max<std::size_t>(static_cast<std::size_t>(n) * n * n / 8, 4), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    solid_ = gl::Buffer("solid voxels", std::max<std::size_t>(static_cast<std::size_t>(n) * n * n / 8, 4), nullptr,
                        GL_DYNAMIC_STORAGE_BIT);
    glClearNamedBufferData(solid_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    // A surface crosses about N² voxels per N² of area; 16·N² holds the Cornell box (≈ 6·N²) and
    // Sponza at 256³ with room. An overflow is detected (readOccupiedCount) and grows the list.
    growOccupiedList(static_cast<std::uint32_t>(
        std::min<std::size_t>(static_cast<std::size_t>(n) * n * n, static_cast<std::size_t>(16) * n * n)));
    log.info("voxel volume " + std::to_string(n) + "³ (" + (rgba8_ ? "RGBA8" : "RGBA16F") +
             " radiance): " + memoryReport());
    return true;
}

bool VoxelVolume::fitTo(const Aabb& sceneBounds) {
    const Aabb bounds = sceneBounds.empty() ? Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)} : sceneBounds;
    const float extent = std::max({bounds.size().x, bounds.size().y, bounds.size().z, 1e-3f});
    // Pad by 2 voxels on each side so surfaces on the bounds (walls) lie inside, with room for
    // the conservative-rasterization expansion.
    const float side = extent * static_cast<float>(resolution_) / static_cast<float>(std::max(resolution_ - 4, 1));
    // The grid is shifted by a quarter voxel along y and z (padding 2¼ voxels below, 1¾ above), so
    // that surfaces at whole-voxel distances from the bounds do not lie on the faces between two
    // voxels: there the voxelization depends on sub-pixel rounding of the rows an edge only
    // touches (the Cornell box at 64³ read its ceiling and back wall 8-14 % brighter than at
    // 128³). voxelize.geom.glsl's kTouchMargin covers those rows and removes most of it, but
    // without the shift the red-wall nook still reads 0.89 of the reference at 64³ (0.95 with it).
    // A quarter, not a half: a half puts surfaces at half-voxel distances on faces instead. x is
    // not shifted, so that the grid stays mirror-symmetric about the scene's centre in x, the axis
    // the Cornell mirror tests flip. docs/GI.md, "Surfaces on voxel faces"; the shifts that did not
    // work: "Approaches that did not work".
    const glm::vec3 shift = glm::vec3(0.0f, 0.25f, 0.25f) * (side / static_cast<float>(resolution_));
    const glm::vec3 min = bounds.center() - glm::vec3(0.5f * side) - shift;
    const bool moved = side != side_ || min != min_;
    side_ = side;
    min_ = min;
    return moved;
}

bool VoxelVolume::placeAt(const Aabb& cube) {
    const float side = std::max(cube.size().x, 1e-3f);
    const glm::vec3 shift = glm::vec3(0.0f, 0.25f, 0.25f) * (side / static_cast<float>(resolution_));
    const glm::vec3 min = cube.min - shift;
    const bool moved = side != side_ || min != min_;
    side_ = side;
    min_ = min;
    return moved;
}

void VoxelVolume::updateUniforms(const RenderSettings& settings, int frameIndex) {
    gpu::VoxelUniforms u{};
    u.volumeMin = glm::vec4(min_, side_);
    const float n = static_cast<float>(resolution_);
    u.voxelInfo = glm::vec4(n, 1.0f / n, side_ / n, static_cast<float>(mipCount_));
    u.traceParams = glm::vec4(settings.gi.indirectIntensity, settings.gi.maxTraceDistance * side_,
                              std::max(settings.gi.coneStepScale, 0.05f), settings.gi.diffuseConeAperture);
    u.traceOptions = glm::ivec4(std::clamp(settings.indirect.specularSamples, 1, 8), frameIndex,
                                rgba8_ ? LIT_RADIANCE_RGBA8 : LIT_RADIANCE_FLOAT16, 0);
    u.giParams = glm::vec4(settings.gi.footprintPerHeight(), settings.gi.anisotropicVoxels() ? 1.0f : 0.0f, 0.0f, 0.0f);
    const float range = rgba8_ ? std::max(settings.gi.radianceRange, 1e-3f) : 1.0f;
    u.radianceScale = glm::vec4(1.0f / range, range, 0.0f, 0.0f);
    uniforms_.update(u);
    uniforms_.bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
}

void VoxelVolume::clearMaterials() const {
    const GLuint zero = 0;
    for (const gl::Texture* t : materialVolumes())
        if (*t) glClearTexImage(t->id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void VoxelVolume::clearMaterials(const VoxelBox& box) const {
    if (box.empty()) return;
    const GLuint zero = 0;
    const glm::ivec3 size = box.max - box.min;
    for (const gl::Texture* t : materialVolumes())
        if (*t)
            glClearTexSubImage(t->id(), 0, box.min.x, box.min.y, box.min.z, size.x, size.y, size.z, GL_RED_INTEGER,
                               GL_UNSIGNED_INT, &zero);
}

void VoxelVolume::growOccupiedList(std::uint32_t count) {
    // Indirect dispatch: at most 65535 groups along x.
    const std::uint32_t limit = 65535u * LIT_INJECT_LIST_GROUP_SIZE;
    const std::uint32_t capacity = std::min(count, limit);
    if (capacity <= occupiedCapacity_ && occupied_) return;
    occupiedCapacity_ = capacity;
    occupied_ = gl::Buffer("occupied voxels", kOccupiedHeaderBytes + static_cast<std::size_t>(capacity) * 4, nullptr,
                           GL_DYNAMIC_STORAGE_BIT);
    resetOccupiedList();
}

void VoxelVolume::resetOccupiedList() const {
    if (!occupied_) return;
    const std::uint32_t header[4] = {0u, 0u, 1u, 1u};
    glNamedBufferSubData(occupied_.id(), 0, sizeof header, header);
    if (listed_) glClearNamedBufferData(listed_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
}

std::size_t VoxelVolume::listBytes() const { return occupied_.size() + listed_.size() + solid_.size(); }

std::uint32_t VoxelVolume::readOccupiedCount() const {
    if (!occupied_) return 0;
    std::uint32_t count = 0;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(occupied_.id(), 0, sizeof count, &count);
    return count;
}

std::vector<glm::ivec3> VoxelVolume::readOccupiedList() const {
    const std::uint32_t count = std::min(readOccupiedCount(), occupiedCapacity_);
    std::vector<std::uint32_t> packed(count);
    if (count) glGetNamedBufferSubData(occupied_.id(), kOccupiedHeaderBytes, count * 4, packed.data());
    std::vector<glm::ivec3> voxels;
    voxels.reserve(count);
    for (std::uint32_t p : packed)
        voxels.emplace_back(static_cast<int>(p & 1023u), static_cast<int>((p >> 10) & 1023u),
                            static_cast<int>(p >> 20));
    return voxels;
}

void VoxelVolume::clearRadianceLevel0() const {
    const float transparent[4] = {0, 0, 0, 0};
    if (radiance_) glClearTexImage(radiance_.id(), 0, GL_RGBA, GL_FLOAT, transparent);
}

void VoxelVolume::clearRadianceLevel0(const VoxelBox& box) const {
    if (!radiance_ || box.empty()) return;
    const float transparent[4] = {0, 0, 0, 0};
    const glm::ivec3 size = box.max - box.min;
    glClearTexSubImage(radiance_.id(), 0, box.min.x, box.min.y, box.min.z, size.x, size.y, size.z, GL_RGBA, GL_FLOAT,
                       transparent);
}

void VoxelVolume::clearRadianceMips() {
    const float transparent[4] = {0, 0, 0, 0};
    if (radiance_)
        for (int level = 1; level < radiance_.desc().levels; ++level)
            glClearTexImage(radiance_.id(), level, GL_RGBA, GL_FLOAT, transparent);
    directionalStale_ = true;
    parentListsValid_ = false;
}

void VoxelVolume::clearDirectional() const {
    const float transparent[4] = {0, 0, 0, 0};
    // Each level holds the +axis face at x 0 and the −axis face at x 2·edge: the gap between them
    // is never written (a third of the texels left alone).
    for (const gl::Texture& t : directional_)
        if (t)
            for (int level = 0; level < t.desc().levels; ++level) {
                const int edge = std::max(t.desc().height >> level, 1);
                for (const int x : {0, 2 * edge})
                    glClearTexSubImage(t.id(), level, x, 0, 0, edge, edge, edge, GL_RGBA, GL_FLOAT, transparent);
            }
}

std::vector<glm::ivec3> VoxelVolume::readParentList(int level) const {
    if (!parents_ || level < 1 || level >= std::min(mipCount_, LIT_MIP_LIST_LEVELS)) return {};
    const auto k = static_cast<std::size_t>(level);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::uint32_t count = 0;
    glGetNamedBufferSubData(parents_.id(), static_cast<GLintptr>(16 * k), sizeof count, &count);
    count = std::min(count, parentLayout_.listCapacity[k]);
    std::vector<std::uint32_t> packed(count);
    if (count)
        glGetNamedBufferSubData(
            parents_.id(), static_cast<GLintptr>(kParentHeaderBytes + std::size_t{4} * parentLayout_.listOffset[k]),
            static_cast<GLsizeiptr>(std::size_t{4} * count), packed.data());
    std::vector<glm::ivec3> voxels;
    voxels.reserve(count);
    for (std::uint32_t p : packed)
        voxels.emplace_back(static_cast<int>(p & 1023u), static_cast<int>((p >> 10) & 1023u),
                            static_cast<int>(p >> 20));
    return voxels;
}

void VoxelVolume::ensureParentLists() {
    ParentLayout layout;
    std::uint32_t words = 0;
    for (int level = 1; level < std::min(mipCount_, LIT_MIP_LIST_LEVELS); ++level) {
        const auto edge = static_cast<std::uint64_t>(std::max(resolution_ >> level, 1));
        const auto k = static_cast<std::size_t>(level);
        // No level lists more parents than the occupied list holds children (shaders/mipmap_parents.comp.glsl).
        layout.listCapacity[k] =
            static_cast<std::uint32_t>(std::min<std::uint64_t>(occupiedCapacity_, edge * edge * edge));
        layout.listOffset[k] = words;
        words += layout.listCapacity[k];
    }
    layout.maskBegin = words;
    for (int level = 1; level < std::min(mipCount_, LIT_MIP_LIST_LEVELS); ++level) {
        const auto edge = static_cast<std::uint64_t>(std::max(resolution_ >> level, 1));
        layout.maskOffset[static_cast<std::size_t>(level)] = words;
        words += static_cast<std::uint32_t>((edge * edge * edge + 31) / 32);
    }
    layout.maskWords = words - layout.maskBegin;
    layout.totalWords = words;
    const bool same = parents_ && layout.totalWords == parentLayout_.totalWords &&
                      layout.listOffset == parentLayout_.listOffset && layout.maskOffset == parentLayout_.maskOffset;
    if (same) return;
    parentLayout_ = layout;
    parents_ = gl::Buffer("occupied parents", kParentHeaderBytes + static_cast<std::size_t>(words) * 4, nullptr,
                          GL_DYNAMIC_STORAGE_BIT);
    parentListsValid_ = false;
}

std::size_t VoxelVolume::materialBytes() const {
    return static_cast<std::size_t>(resolution_) * resolution_ * resolution_ * 4 * kMaterialVolumeCount;
}

std::size_t VoxelVolume::radianceBytes() const {
    std::size_t bytes = 0;
    for (int level = 0, n = resolution_; level < mipCount_; ++level, n = std::max(n / 2, 1))
        bytes += static_cast<std::size_t>(n) * n * n * (rgba8_ ? 4 : 8) *
                 (level == 0 || !directional_[0] ? 1 : 1 + 3 * LIT_VOXEL_AXIS_COUNT);
    return bytes + static_cast<std::size_t>(resolution_) * resolution_ * resolution_ * 8;  // the sides
}

std::size_t VoxelVolume::bounceBytes() const {
    const std::size_t volumes = (direct_ ? 2 : 0) + (change_ ? 1 : 0);
    return volumes * static_cast<std::size_t>(resolution_) * resolution_ * resolution_ * (rgba8_ ? 4 : 8);
}

void VoxelVolume::bindDirectional() const {
    for (int axis = 0; axis < LIT_VOXEL_AXIS_COUNT; ++axis)
        directional_[static_cast<std::size_t>(axis)].bind(LIT_TEX_VOXEL_DIRECTIONAL_FIRST + axis);
}

void VoxelVolume::ensureDirectionalVolumes() {
    if (directional_[0] || resolution_ <= 0) return;
    const int half = std::max(resolution_ / 2, 1);
    const float transparent[4] = {0, 0, 0, 0};
    for (int axis = 0; axis < LIT_VOXEL_AXIS_COUNT; ++axis) {
        gl::Texture& t = directional_[static_cast<std::size_t>(axis)];
        // +axis face at x ∈ [0, m), an empty gap [m, 2m), −axis face at [2m, 3m) (m = the level's edge).
        t = gl::Texture("voxel radiance " + std::string(kAxisNames[axis]),
                        {GL_TEXTURE_3D, radianceFormat(), 3 * half, half, half, std::max(mipCount_ - 1, 1)});
        t.setFilter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
        t.setWrap(GL_CLAMP_TO_BORDER);
        glTextureParameterfv(t.id(), GL_TEXTURE_BORDER_COLOR, transparent);
        for (int level = 0; level < t.desc().levels; ++level)
            glClearTexImage(t.id(), level, GL_RGBA, GL_FLOAT, transparent);
    }
    directionalStale_ = false;  // zero, as the whole-grid build leaves voxels off the lists
}

void VoxelVolume::releaseDirectionalVolumes() { directional_ = {}; }

void VoxelVolume::ensureBounceVolumes() {
    if (direct_ || resolution_ <= 0) return;
    const int n = resolution_;
    direct_ = gl::Texture("voxel direct radiance", {GL_TEXTURE_3D, radianceFormat(), n, n, n, 1});
    bounce_ = gl::Texture("voxel bounce radiance", {GL_TEXTURE_3D, radianceFormat(), n, n, n, 1});
    // A change may be negative (a bounce after a warm start): RGBA8 cannot hold it, and its
    // bounces gather the whole light every time.
    if (!rgba8_) {
        change_ = gl::Texture("voxel bounce change", {GL_TEXTURE_3D, radianceFormat(), n, n, n, 1});
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glClearTexImage(change_.id(), 0, GL_RGBA, GL_FLOAT, zero);
    }
}

std::string VoxelVolume::memoryReport() const {
    const std::size_t each = materialBytes() / kMaterialVolumeCount;
    return "albedo " + mib(each) + ", normal " + mib(each) + ", emission " + mib(each) + ", surface " + mib(each) +
           ", radiance " + mib(radianceBytes()) +
           (directional_[0] ? " (with mips and 6 directional chains)" : " (with mips)") +
           (direct_ ? ", bounce " + mib(bounceBytes()) : std::string()) + ", total " + mib(totalBytes());
}

}  // namespace lit
