#pragma once
// Everything a user can tune about a frame: plain data with defaults and units, grouped by
// concern, compared with ==, saved as JSON with one object per group. The editor's settings
// panel, lit-render's flags and the tests all set these same fields; the Renderer reads them and
// nothing else. What only a front end needs (the editor's interactive scale, how much GI work a
// frame may do) lives in that front end, not here.

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lit {

enum class View {
    Final,
    DirectDiffuse,
    IndirectDiffuse,
    DirectSpecular,
    IndirectSpecular,
    Albedo,
    Normal,
    ShadowMap,
    Voxels,  // the voxel volume ray-marched as cubes (one mip level, one channel)
    RoughnessMetalness,
    VoxelSlice,   // one slice of the voxel volume filling the viewport (axis, position, mip, channel)
    VoxelLevels,  // the voxels of every volume running ray-marched, each coloured by its level
};
// Voxels, VoxelSlice and VoxelLevels write display values in [0,1] to the HDR image too (radiance and emission
// already tone-mapped with the exposure), so tests read what the user sees.

std::string_view toString(View view);
std::optional<View> parseView(std::string_view text);  // "final", "direct-diffuse", ..., "voxel-slice"

// What the voxel debug views show of each voxel.
enum class VoxelChannel {
    Radiance,  // outgoing radiance after injection, tone-mapped with the exposure
    Albedo,    // base colour as voxelized
    Normal,    // averaged normal as 0.5 + 0.5·n
    Opacity,   // radiance volume alpha as grey
    Emission,  // emitted radiance, tone-mapped with the exposure
};

std::string_view toString(VoxelChannel channel);
std::optional<VoxelChannel> parseVoxelChannel(std::string_view text);  // "radiance", "albedo", ...

// Most light bounces GiSettings::bounces may ask for by count (each costs one pass over the
// occupied voxels).
inline constexpr int kMaxBounces = 8;
// GiSettings::bounces for every bounce: the update repeats bounce passes until the voxels' light
// stops changing (docs/GI.md, "Bounces"), at most kMaxConvergingBounces.
inline constexpr int kAllBounces = 0;
inline constexpr int kMaxConvergingBounces = 64;
// The most rays per voxel GiSettings::voxelRays asks for (more are clamped to it).
inline constexpr int kMaxVoxelRays = 256;
// The most GiSettings::laterBounceRayStride asks for (more are clamped to it).
inline constexpr int kMaxLaterBounceRayStride = 16;
// Near levels around the camera at most (GiSettings::nearLevels; shared.h LIT_MAX_NEAR_LEVELS).
inline constexpr int kMaxNearLevels = 5;
// The footprint bound of the accurate and cached modes' diffuse cones (GiSettings::
// coneFootprintPerHeight): the largest voxel a cone leaving a surface samples is a quarter of its
// height above it. Why a quarter: docs/GI.md, "Footprint-bounded cones".
inline constexpr float kAccurateGiFootprint = 0.25f;

// How the indirect light is computed (docs/GI.md, "Modes"):
//   Fast: the classic six-cone voxel cone tracing, per pixel, over isotropic voxels; for teaching,
//     the cone-directions view and comparison; wrong in places (docs/GI.md, "Known limits");
//   Accurate: per-pixel cones over directional (anisotropic) voxels, footprint-bounded and
//     stratified; several times the fast mode's frame;
//   Cached (the default): the voxels gather their own irradiance once per light or geometry edit
//     (rays through the voxel grid) and each pixel gathers it from the voxels around it.
enum class GiMode { Fast, Accurate, Cached };
std::string_view toString(GiMode mode);
std::optional<GiMode> parseGiMode(std::string_view text);  // "fast", "accurate", "cached"

// What the background and the cones that leave the scene see (scene/Sky.h evaluates it).
enum class SkyMode {
    Auto,      // Gradient when the scene has no lights (with a default sun), else None
    None,      // black: a scene lit only by its own lights, as Blender's black world
    Uniform,   // zenith colour in every direction
    Gradient,  // ground below the horizon, horizon → zenith above it
    Hdr,       // equirectangular radiance image hdrPath (Radiance .hdr through stb_image)
};

std::string_view toString(SkyMode mode);
std::optional<SkyMode> parseSkyMode(std::string_view text);  // "auto", "none", "uniform", "gradient", "hdr"

// The image: its size, exposure and what is drawn of the scene.
struct OutputSettings {
    int width = 1280;  // pixels
    int height = 720;  // pixels
    // Exposure in stops as Blender's Film > Exposure: radiance is multiplied by 2^exposureEv before
    // tone mapping (0 = radiance 1 W/(sr·m²) maps to 1). With autoExposure it is a compensation
    // added to the metered value.
    float exposureEv = 0.0f;  // stops, −10..+20
    bool autoExposure = false;
    float autoExposureKey = 0.18f;     // scene-average luminance (geometric mean) mapped to this value
    float autoExposureSpeed = 3.0f;    // adaptation rate, 1/s (exponential; 0 = instant)
    float autoExposureMinEv = -10.0f;  // metered exposure is clamped to [min, max] stops
    float autoExposureMaxEv = 20.0f;
    bool frustumCulling = true;  // G-buffer and shadow views draw only items their frustum may see
    // Temporal anti-aliasing (TemporalAntialiasPass, docs/ARCHITECTURE.md "Anti-aliasing"): each
    // frame is drawn with a sub-pixel offset and the HDR image is blended with the last frames'.
    // A still converges to the mean of `antialiasingFrames` offsets over each pixel's area (the
    // first frame after a reset is drawn at the pixel centres, as without it).
    bool antialiasing = true;
    int antialiasingFrames = 8;  // offsets in the cycle, and the history's length (blend weight ≥ 1/N), 1..64
    // Geometric specular anti-aliasing (docs/MATERIALS.md "Specular anti-aliasing"): every
    // direct-light specular lobe is widened by the spread of its normal over the pixel, so highlights smaller
    // than a pixel neither alias nor flicker.
    bool specularAntialiasing = true;

    float exposureScale() const { return std::exp2(exposureEv); }
    bool operator==(const OutputSettings&) const = default;
};

// Sky and default lighting (docs/UNITS.md): radiance in W/(sr·m²), times intensity.
struct SkySettings {
    SkyMode mode = SkyMode::Auto;
    std::array<float, 3> zenith = {0.10f, 0.18f, 0.36f};   // linear RGB radiance straight up
    std::array<float, 3> horizon = {0.30f, 0.34f, 0.40f};  // at the horizon
    std::array<float, 3> ground = {0.08f, 0.07f, 0.06f};   // below the horizon
    float intensity = 1.0f;                                // multiplier of the sky colours or the .hdr image
    std::string hdrPath;                                   // equirectangular .hdr (mode Hdr)
    // When the scene has no lights, a sun at this elevation/azimuth (radians) with this irradiance
    // (W/m² perpendicular to it, 2.7 klx at 683 lm/W); 0 = none.
    float sunIrradiance = 4.0f;
    float sunElevation = 1.05f;  // 60° above the horizon: reaches the floor of courtyards
    float sunAzimuth = 1.2f;     // from +Z towards +X (69°)
    bool operator==(const SkySettings&) const = default;
};

// Shadow maps of the lights (2D array for directional and spot lights, cube array for point lights).
struct ShadowSettings {
    bool enabled = true;
    int mapSize = 1024;         // texels per side (each light / cube face)
    float depthBias = 0.0005f;  // constant, a share of the shadow map's depth range (linear depth for spot and point lights)
    float slopeBias = 2.0f;     // multiplied by the depth slope (glPolygonOffset factor)
    float normalOffset = 1.5f;  // receiver offset along the normal, in shadow texels
    float pcfRadius = 1.5f;     // PCF kernel radius, in shadow texels
    // Directional lights also get maps fitted to slices of the camera's view (docs/ARCHITECTURE.md,
    // "Shadow cascades"): `cascades` maps (0..LIT_MAX_SHADOW_CASCADES; 0 = only the map over the whole
    // scene, which the voxel injection always uses), covering the view out to `cascadeDistance`
    // metres (0 = the scene's diagonal), split at λ·log + (1 − λ)·uniform spacing, λ = `cascadeSplit`.
    int cascades = 4;
    float cascadeDistance = 0.0f;
    float cascadeSplit = 0.75f;
    bool operator==(const ShadowSettings&) const = default;
};

// The voxel GI (docs/GI.md): everything here changes the light in the voxels, so changing it
// starts a new GI update (the indirect group below changes only how pixels read it).
struct GiSettings {
    bool enabled = true;
    GiMode mode = GiMode::Cached;
    int voxelResolution = 128;       // voxels per side (power of two, 64..512)
    // A moved node (gizmo, node animation) voxelizes again only the boxes it covered and covers
    // (VoxelChangeTracker), and the voxel rays that miss them keep their hits; off: the whole volume.
    bool voxelizeChangesOnly = true;
    bool radianceRgba8 = false;      // store radiance as RGBA8 (512³ fits in 512 MiB) instead of RGBA16F
    float radianceRange = 4.0f;      // RGBA8 only: radiance that maps to 1.0 (W/(sr·m²))
    float indirectIntensity = 1.0f;  // multiplier of the indirect light (1 = physically based)
    // Light bounces: kAllBounces (0, the default) = every bounce, the update repeating passes until
    // the light converges; 1 = direct light only is injected (one bounce reaches the pixels), 2 = the
    // voxels also reflect the light they gather, and so on (for comparison with the reference's
    // bounce counts). Each bounce past the first is one more pass over every occupied voxel per
    // light or geometry edit (docs/GI.md, "Bounces").
    int bounces = kAllBounces;  // 0 (all) or 1..kMaxBounces
    // Rays per voxel for the light the voxels gather themselves (the cached mode's irradiance and
    // bounces 2..N): cosine-distributed over the voxel's hemisphere and marched through the voxel
    // grid to the first occupied voxel (docs/GI.md, "Voxel rays"). 0 = the accurate mode's
    // stratified cones instead.
    int voxelRays = 32;  // 0..kMaxVoxelRays
    // With voxel rays and RGBA16F radiance, each bounce after an update's first gathers only the
    // change of the bounce before, over one in this many of a voxel's rays (docs/GI.md, "Bounces"):
    // 1 = every ray. Effective only with at least two rays per subset.
    int laterBounceRayStride = 4;  // 1..kMaxLaterBounceRayStride
    // Cones (docs/GI.md, "Marching a cone"). The diffuse cones' aperture; the farthest a cone
    // goes, as a fraction of the volume's side; the step, × the cone's diameter there.
    float diffuseConeAperture = 1.0471975511965976f;  // radians (60°)
    float maxTraceDistance = 1.0f;                    // fraction of the voxel volume's side
    float coneStepScale = 0.5f;                       // step = scale × cone diameter
    // Accurate and cached modes: the largest voxel a diffuse cone leaving a surface samples, × its
    // height above the surface (keeps cones out of their own surface's voxels; 0 = unbounded).
    // The fast mode's cones are unbounded.
    float coneFootprintPerHeight = kAccurateGiFootprint;
    // The cached mode's near levels (docs/GI.md, "Near levels"): up to kMaxNearLevels more volumes
    // of voxelResolution³ voxels, cubes around the camera of nearLevelSide metres, twice that,
    // four times that (each moved in eighths of its side), whose voxels gather their own light with
    // their rays continuing in the next level out and then in the scene's volume where they leave
    // it; pixels gather from the finest level around them. A level runs only in scenes at least
    // twice its side across (smaller ones get no finer voxels from it). nearLevels 0 or
    // nearLevelSide 0 = off (one volume around the whole scene).
    float nearLevelSide = 64.0f;
    int nearLevels = 1;  // 0..kMaxNearLevels

    // What the mode implies (ConeFeatures::of reads these).
    bool anisotropicVoxels() const { return mode != GiMode::Fast; }  // directional voxels for mip levels ≥ 1
    float footprintPerHeight() const { return mode == GiMode::Fast ? 0.0f : std::fmax(coneFootprintPerHeight, 0.0f); }
    bool voxelIrradiance() const { return mode == GiMode::Cached; }  // L_ID gathered from the voxels
    // The near levels run (as many as nearLevelCount()): the cached mode with voxel rays, a positive side.
    bool nearLevel() const { return nearLevelCount() > 0; }
    int nearLevelCount() const {
        return voxelIrradiance() && voxelRays > 0 && nearLevelSide > 0.0f ? std::clamp(nearLevels, 0, kMaxNearLevels) : 0;
    }
    bool operator==(const GiSettings&) const = default;
};

// How the pixels read the voxel GI: resolution, specular cones, temporal accumulation
// (docs/GI.md, "Reduced resolution and temporal accumulation").
struct IndirectSettings {
    // One pixel in every scale × scale block traces (or gathers) the indirect light, upsampled with
    // depth- and normal-aware weights: 1 (every pixel), 2 (default) or 4.
    int scale = 2;
    int specularSamples = 1;  // cones for indirect specular, 1..8: 1 = the lobe's core around the mirror direction, more = GGX samples
    // Perceptual roughness below which L_IS is traced per pixel at full resolution (a sharp
    // reflection would blur at reduced resolution); at and above it, with L_ID at scale.
    float specularFullResRoughness = 0.3f;
    // Accumulate both indirect terms over frames (reprojected with the camera, history rejected on
    // disocclusion and scene edits), rotating the cone sets every frame. Off by default so a still
    // is deterministic and equals one frame's trace.
    bool temporalAccumulation = false;
    int temporalMaxFrames = 16;  // frames of history at most (the blend weight never drops below 1/N)
    // With temporal accumulation in the per-pixel cone modes, each traced texel marches the normal
    // cone and two of the five side cones per frame, a different pair per frame (all five every
    // 5 frames), and the accumulation averages them (docs/GI.md, "Cone subsets").
    bool temporalConeSubsets = true;
    bool operator==(const IndirectSettings&) const = default;
};

// The four lighting terms; Final is the sum of those that are on.
struct TermSettings {
    bool directDiffuse = true;
    bool directSpecular = true;
    bool indirectDiffuse = true;
    bool indirectSpecular = true;
    bool operator==(const TermSettings&) const = default;
};

// What is shown instead of the final image, and the debug views' parameters.
struct DebugViewSettings {
    View view = View::Final;
    int shadowMapLight = 0;                              // light whose shadow map the ShadowMap view shows
    float voxelSlice = 0.5f;                             // slice view: slice position along the axis (0..1)
    int voxelSliceAxis = 2;                              // slice view: 0 X, 1 Y, 2 Z
    int voxelMip = 0;                                    // voxel views: mip level (clamped to the volume's levels)
    // Voxel views: the volume shown: 0 the scene's, k near level k (1 the finest; past the levels
    // running, the coarsest running; the scene's without any).
    int voxelLevel = 0;
    VoxelChannel voxelChannel = VoxelChannel::Radiance;  // voxel views: what each voxel shows
    bool operator==(const DebugViewSettings&) const = default;
};

struct RenderSettings {
    OutputSettings output;
    SkySettings sky;
    ShadowSettings shadows;
    GiSettings gi;
    IndirectSettings indirect;
    TermSettings terms;
    DebugViewSettings debug;

    bool operator==(const RenderSettings&) const = default;
};

// JSON in/out: one object per group with the field names above ({"gi": {"voxelResolution": 128},
// ...}; enums by their text names). Unknown keys are ignored (files from newer versions still
// load); bad values throw std::runtime_error naming the key. The flat keys of older files
// ("voxelResolution", "gi": true, ...) are read into their new places, and each adds a
// deprecation message naming the new key to `warnings` (when given).
std::string toJson(const RenderSettings& settings);
RenderSettings renderSettingsFromJson(std::string_view json, const RenderSettings& defaults = {},
                                      std::vector<std::string>* warnings = nullptr);

// The keys of every setting as "group.field" ("gi.voxelResolution"), in the order toJson writes
// them: what scripts and lit-render's --set accept.
std::vector<std::string> renderSettingKeys();
// Sets one setting by its "group.field" key (or an older flat key, adding a deprecation message
// to `warnings`) from a JSON value ("128", "true", "\"cached\"" or a bare word taken as a
// string). Throws std::runtime_error naming the key for an unknown key or a bad value.
void setRenderSetting(RenderSettings& settings, std::string_view key, std::string_view value,
                      std::vector<std::string>* warnings = nullptr);

}  // namespace lit
