#pragma once
// What Lit allocates to show a scene, estimated before any of it is allocated, and the one check
// of that estimate against a limit. The loader (io/GltfGuard.h, before decoding), lit-render
// ($LIT_MAX_RENDER_MB) and the editor all use these functions, so a file the loader accepts is
// one the renderer can upload: a glTF file's decoded images, the GL textures made from them (each
// image once, with its mip chain), the geometry on the CPU and in GL buffers, the lights' shadow
// maps, and what the render settings add (voxel volumes, voxel ray hits, render targets). docs/RELIABILITY.md gives the
// numbers.

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace lit {

struct RenderSettings;
struct Scene;

// Bytes by kind.
struct SceneMemory {
    std::uint64_t decodedImages = 0;  // RGBA8 pixels on the CPU, each distinct image once
    std::uint64_t textures = 0;       // GL textures: each image a texture uses once, with mip chain
    std::uint64_t geometry = 0;       // 56-byte vertices and 4-byte indices, on the CPU and in GL buffers
    std::uint64_t voxels = 0;         // the voxel volumes (voxelVolumeBytes), the near levels' included
    std::uint64_t rayHits = 0;        // the voxel rays' hit records at their most (RayHitCache), per volume
    std::uint64_t targets = 0;        // per-pixel render targets and read-back copies
    std::uint64_t shadowMaps = 0;     // depth layers and cube faces, and their sheet colour layers (ShadowPass)
    std::uint64_t total() const;
    // "textures 21.0 GB, decoded images 0.3 GB, geometry 0.1 GB": each non-zero kind, largest
    // first, in the unit of the total.
    std::string describe() const;
};

// What the render settings add to a scene's memory; all zero counts the scene alone.
struct RenderFootprint {
    int width = 0, height = 0;  // output pixels
    int voxelResolution = 0;    // voxels per side; 0 = GI off
    bool radianceRgba8 = false;
    bool bounceVolumes = false;  // more than one bounce (the direct and bounce volumes)
    int voxelRays = 0;           // rays per voxel side whose hits are recorded
    // Near levels asked for (GiSettings::nearLevelCount()): each a volume like the scene's, with its
    // own ray hits. Counted as asked: a scene too small for them never allocates them.
    int nearLevels = 0;
    int shadowMapSize = 0;       // texels per side of each shadow map (clamped as ShadowPass); 0 = shadows off
    int shadowCascades = 0;      // the camera's cascades per directional light (ShadowSettings::cascades, clamped)
    static RenderFootprint of(const RenderSettings& settings);
    bool operator==(const RenderFootprint&) const = default;
};

// An image's size in pixels, and whether a texture uses it (then it is also a GL texture).
struct ImageExtent {
    int width = 0, height = 0;
    bool textured = true;
};

// The shadow maps a scene's lights need: a 2D layer per directional or spot light, a cube per
// point light (each capped as LightSetup caps them), and whether transmissive sheets add a colour
// layer to each. A scene without lights counts one 2D layer: the renderer's default sun.
struct ShadowCasters {
    int maps2d = 0;
    int cubes = 0;
    int directional = 0;  // of maps2d: the directional lights (their cascades add layers)
    bool sheets = false;
    bool operator==(const ShadowCasters&) const = default;
};
ShadowCasters shadowCastersOf(const Scene& scene);
// Bytes ShadowPass allocates for `casters` at `mapSize` texels per side (0: none): 4 per depth
// texel, 8 more per texel with sheets (RGBA16F colour layers), and 4 per texel of the `cascades`
// layers of each of the first LIT_MAX_CASCADED_LIGHTS directional lights.
std::uint64_t shadowMapBytes(const ShadowCasters& casters, int mapSize, int cascades = 0);

// Bytes of an RGBA8 texture of width × height with its full mip chain.
std::uint64_t textureBytesWithMips(int width, int height);

// The estimate from counts, as the loader knows them before decoding: every distinct image,
// the vertices and indices the scene builder will make, and the lights that cast shadows.
SceneMemory estimateSceneMemory(std::span<const ImageExtent> images, std::uint64_t vertices, std::uint64_t indices,
                                const ShadowCasters& casters, const RenderFootprint& render);
// The same for a scene already in memory (an edited scene, one built in code).
SceneMemory estimateSceneMemory(const Scene& scene, const RenderFootprint& render);

// A memory limit and where it came from ("LIT_MAX_RENDER_MB", "the default limit").
struct MemoryLimit {
    std::uint64_t bytes = 0;  // 0 = none
    std::string source;
};

// The limit without $LIT_MAX_RENDER_MB: Sponza needs ~0.7 GB before the render settings' part,
// the default settings add ~0.8 GB (128³ voxels 0.2 GB, their ray hits at most 0.5 GB, 1280×720
// targets 0.06 GB); 8 GB leaves room for large scenes on a 16 GB machine and
// keeps an amplifying file (many entries, one blob of data) from exhausting memory.
inline constexpr std::uint64_t kDefaultSceneMemoryLimit = 8'000'000'000ull;
inline constexpr const char* kDefaultSceneMemoryLimitSource = "the default limit; LIT_MAX_RENDER_MB sets another";

// $LIT_MAX_RENDER_MB (megabytes, 10^6 bytes) when it is set to a positive number, else the
// default limit. lit-render and the editor load and render under it.
MemoryLimit renderMemoryLimit();

// Why `memory` does not fit in `limit` ("scene needs 21.4 GB of memory (textures 21.0 GB, ...),
// over the limit of 8.0 GB (LIT_MAX_RENDER_MB)"), or nothing when it fits.
std::optional<std::string> overMemoryLimit(const SceneMemory& memory, const MemoryLimit& limit);

// `bytes` in GB, MB or kB (powers of 10) with one decimal, the unit chosen by the size of
// `unitOf` (a total its parts are written beside): "21.4 GB", "0.3 GB", "512.0 kB".
std::string formatBytes(std::uint64_t bytes, std::uint64_t unitOf);

}  // namespace lit
