#pragma once
// Everything a user can tune about a frame: plain data with defaults and units, compared with
// ==, saved as JSON. The editor's settings panel, lit-render's flags and the tests all set these
// same fields; the Renderer reads them and nothing else.

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

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
    Voxels,              // the voxel volume ray-marched as cubes (one mip level, one channel)
    RoughnessMetalness,
    VoxelSlice,          // one slice of the voxel volume filling the viewport (axis, position, mip, channel)
};
// Voxels and VoxelSlice write display values in [0,1] to the HDR image too (radiance and emission
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

// Most light bounces RenderSettings::bounces may ask for (each costs one cone-traced pass over the voxels).
inline constexpr int kMaxBounces = 8;
// The most rays per voxel RenderSettings::voxelRays asks for (more are clamped to it).
inline constexpr int kMaxVoxelRays = 256;
// A spread update (RenderSettings::voxelIrradianceVoxelsPerFrame) traces this many times the
// setting's voxels a frame where they replay their voxel rays' recorded hits (a light edit after
// the first update since the voxelization): a replayed voxel costs about a fifth of a marched one
// (Sponza 256³ on llvmpipe: 1.1 µs against 5.4-6.4 µs), so such a frame costs what a marching
// one did and an edit's light is final in a quarter of the frames (docs/PERFORMANCE.md).
inline constexpr int kReplayVoxelsPerFrameFactor = 4;
// The footprint bound of the accurate GI mode (RenderSettings::coneFootprintPerHeight, with
// anisotropicVoxels on): the largest voxel a cone leaving a surface samples is a quarter of its
// height above it. 0.33 was chosen with the fixed six-cone set; with the stratified cone sets
// 0.15-0.33 were measured again (docs/GI.md, "The footprint bound again"): 0.25 brings the red-wall
// colour bleeding inside its bar (R/G 3.04 / 2.98 at 128³ / 256³ against 3.33 / 3.22; bar ≤ 3.17)
// and halves the sealed room's leak's excess, at ~1.3× 0.33's steps; 0.2 also closes the leak but
// drops the 64³ nook of CornellAccuracy.IndirectOnlyRegionsMatchTheReference below its bar.
inline constexpr float kAccurateGiFootprint = 0.25f;

// The GI presets a user picks by name (lit-render --gi-mode, the editor's settings panel), over
// anisotropicVoxels, coneFootprintPerHeight and diffuseFromVoxelIrradiance:
//   Fast: isotropic voxels, unbounded cones traced per pixel (wrong in places: docs/GI.md);
//   Accurate: anisotropic voxels + kAccurateGiFootprint, cones traced per pixel: the mode docs/GI.md
//     measures against the reference, 5-13× the fast mode's frame on llvmpipe;
//   Cached (the default): the accurate mode's cones traced once per voxel after each light or
//     geometry edit and their irradiance gathered per pixel (docs/GI.md, "Irradiance cached in the
//     voxels"): the accurate mode's light within a few per cent, at about the fast mode's frame
//     cost, but each light edit re-traces every occupied voxel;
//   Custom: any other combination of the three fields.
enum class GiMode { Fast, Accurate, Cached, Custom };
std::string_view toString(GiMode mode);
std::optional<GiMode> parseGiMode(std::string_view text);  // "fast", "accurate", "cached" (not "custom")

// What the background and the cones that leave the scene see (scene/Sky.h evaluates it).
enum class SkyMode {
    Auto,      // Gradient when the scene has no lights (with a default sun), else None
    None,      // black: a scene lit only by its own lights, as Blender's black world
    Uniform,   // skyZenith colour in every direction
    Gradient,  // skyGround below the horizon, skyHorizon → skyZenith above it
    Hdr,       // equirectangular radiance image skyHdrPath (Radiance .hdr through stb_image)
};

std::string_view toString(SkyMode mode);
std::optional<SkyMode> parseSkyMode(std::string_view text);  // "auto", "none", "uniform", "gradient", "hdr"

struct RenderSettings {
    // Output
    int width = 1280;  // pixels
    int height = 720;  // pixels
    View view = View::Final;
    // Exposure in stops as Blender's Film > Exposure: radiance is multiplied by 2^exposureEv before
    // tone mapping (0 = radiance 1 W/(sr·m²) maps to 1). With autoExposure it is a compensation
    // added to the metered value. Old files' linear `exposure` key is read as log2(exposure).
    float exposureEv = 0.0f;  // stops, −10..+20
    bool autoExposure = false;
    float autoExposureKey = 0.18f;     // scene-average luminance (geometric mean) mapped to this value
    float autoExposureSpeed = 3.0f;    // adaptation rate, 1/s (exponential; 0 = instant)
    float autoExposureMinEv = -10.0f;  // metered exposure is clamped to [min, max] stops
    float autoExposureMaxEv = 20.0f;

    // Sky and default lighting (docs/UNITS.md): radiance in W/(sr·m²), times skyIntensity.
    SkyMode skyMode = SkyMode::Auto;
    std::array<float, 3> skyZenith = {0.10f, 0.18f, 0.36f};   // linear RGB radiance straight up
    std::array<float, 3> skyHorizon = {0.30f, 0.34f, 0.40f};  // at the horizon
    std::array<float, 3> skyGround = {0.08f, 0.07f, 0.06f};   // below the horizon
    float skyIntensity = 1.0f;                    // multiplier of the sky colours or the .hdr image
    std::string skyHdrPath;                       // equirectangular .hdr (skyMode Hdr)
    // When the scene has no lights, a sun at this elevation/azimuth (radians) with this irradiance
    // (W/m² perpendicular to it, 2.7 klx at 683 lm/W); 0 = none.
    float defaultSunIrradiance = 4.0f;
    float defaultSunElevation = 1.05f;  // 60° above the horizon: reaches the floor of courtyards
    float defaultSunAzimuth = 1.2f;     // from +Z towards +X (69°)

    float exposureScale() const { return std::exp2(exposureEv); }

    // Terms (each term can be switched off; Final is the sum of those that are on)
    bool directDiffuse = true;
    bool directSpecular = true;
    bool indirectDiffuse = true;
    bool indirectSpecular = true;

    // Shadows
    bool shadows = true;
    int shadowMapSize = 1024;       // texels per side (each light / cube face)
    float shadowDepthBias = 0.0005f;  // constant, in light clip-space depth
    float shadowSlopeBias = 2.0f;     // multiplied by the depth slope (glPolygonOffset factor)
    float shadowNormalOffset = 1.5f;  // receiver offset along the normal, in shadow texels
    float shadowPcfRadius = 1.5f;     // PCF kernel radius, in shadow texels
    int shadowDebugLight = 0;         // light whose shadow map the ShadowMap view shows

    // Global illumination (voxel cone tracing)
    bool gi = true;
    int voxelResolution = 128;  // voxels per side (power of two, 64..512)
    bool voxelRadianceRgba8 = false;  // store radiance as RGBA8 (512³ fits in 512 MiB) instead of RGBA16F
    float voxelRadianceRange = 4.0f;  // RGBA8 only: radiance that maps to 1.0 (W/(sr·m²))
    float indirectIntensity = 1.0f;
    int specularSamples = 2;          // importance samples (cones) for indirect specular, 1..8
    float diffuseConeAperture = 1.0471975511965976f;  // radians (60°)
    float maxTraceDistance = 1.0f;    // fraction of the voxel volume's side
    float coneStepScale = 0.5f;       // step = scale × cone diameter
    // GI accuracy (docs/GI.md): directional (anisotropic) voxels for mip levels ≥ 1; the largest
    // voxel a cone leaving a surface may sample, as a multiple of its height above that surface
    // (keeps cones out of their own surface's voxels; 0 = unbounded); light bounces (1 = direct
    // light only is injected, each more re-injects the voxels' own cone-traced indirect light).
    // Both accuracy features are on by default (the Cached GI mode, with diffuseFromVoxelIrradiance):
    // traced per pixel they cost 2-3× (anisotropic) and 3-5× (footprint) the cone trace on llvmpipe,
    // 7-14× together (docs/GI.md, "Landing: cost and defaults"); traced per voxel once per edit
    // they cost the light edit instead. kAccurateGiFootprint with anisotropic voxels is the mode
    // docs/GI.md measures.
    bool anisotropicVoxels = true;
    // The Cached GI mode (docs/GI.md, "Irradiance cached in the voxels"): after each
    // light or geometry edit, every occupied voxel traces the accurate mode's stratified cones
    // once (bounce.comp.glsl, LIT_BOUNCE_IRRADIANCE) and stores its irradiance/π per side; the
    // per-pixel L_ID gathers it from the voxels around the surface point instead of tracing cones.
    // On by default (with the two accuracy fields: GiMode::Cached).
    bool diffuseFromVoxelIrradiance = true;
    // With it: occupied voxels whose irradiance is traced per frame after an edit, round robin (0 =
    // all in the edit's frame). A light edit then takes ⌈occupied / this⌉ frames, each tracing this
    // many voxels (96 316 at 128³ in the Cornell box, 20-90 µs each on llvmpipe by its load), and
    // the others keep the old light until their turn; after a voxelization untraced voxels are left
    // out of the gather. Stills rendered in one frame need 0 (docs/PERFORMANCE.md, ninth session).
    int voxelIrradianceVoxelsPerFrame = 0;
    // With it: once every voxel holds the current light (each traced with its one cone set),
    // occupied voxels traced again per frame with the other sets in turn, round robin, each voxel
    // averaging the sets it has traced (0 = off). After 15 more rounds over the list every voxel
    // holds all 16 sets, and the bands a few voxels wide that the voxel filter leaves (docs/GI.md,
    // "The cached mode") are gone. Off by default (stills render one frame); the editor: 8192.
    int voxelIrradianceRefineVoxelsPerFrame = 0;
    // Rays per voxel for the light the voxels gather themselves: the cached mode's irradiance and
    // bounces 2..N. Each ray marches the voxel grid (level 0, empty 16³ and 4³ blocks skipped) to the
    // first occupied voxel and takes its radiance; a voxel's rays are cosine-distributed over its
    // hemisphere, offset 16 ways over a 4 × 4 patch of a surface, which the voxel filter averages
    // (16 × voxelRays directions). 0 = the stratified cones of the accurate mode. Rays see what cones blur: light
    // reaching a surface past an edge or through a gap, along a wall, at grazing angles (docs/GI.md,
    // "Voxel rays": with two bounces every Cornell bar is met, which the cones miss). 32 cost about
    // what the cones cost at 128³ on llvmpipe, more at 256³ and up (a ray crosses N voxels).
    int voxelRays = 32;  // 0..kMaxVoxelRays
    float coneFootprintPerHeight = kAccurateGiFootprint;  // × height above the surface (0 = off, the fast mode)
    // Light bounces: 1 = direct light only is injected (one bounce reaches the pixels), 2 = the
    // voxels also reflect the light they gather (issue #11's default: with 32 voxel rays every
    // Cornell region and bleeding ratio within ±20 % of the two-bounce reference, docs/GI.md "Two
    // bounces with voxel rays by default"). Each further bounce is one more trace of every occupied
    // voxel per light or geometry edit (Cornell 128³ on llvmpipe: ≈ 1.5 s; spread over frames in the editor).
    int bounces = 2;                      // 1..8
    float voxelSlice = 0.5f;          // slice view: slice position along the axis (0..1)
    int voxelSliceAxis = 2;           // slice view: 0 X, 1 Y, 2 Z
    int voxelMip = 0;                 // voxel views: mip level (clamped to the volume's levels)
    VoxelChannel voxelChannel = VoxelChannel::Radiance;  // voxel views: what each voxel shows

    // Performance
    bool frustumCulling = true;  // G-buffer and shadow views draw only items their frustum may see
    // Indirect lighting resolution (docs/GI.md, "Reduced resolution and temporal accumulation"):
    // the cones of L_ID (and L_IS of rough surfaces) are traced for one pixel in every
    // indirectScale × indirectScale block and upsampled with depth- and normal-aware weights.
    // 1 traces every pixel (the reference path), 2 (default) or 4.
    int indirectScale = 2;
    // Perceptual roughness below which L_IS is traced per pixel at full resolution (a sharp
    // reflection would blur at reduced resolution); at and above it, with L_ID at indirectScale.
    float specularFullResRoughness = 0.3f;
    // Accumulate both indirect terms over frames (reprojected with the camera, history rejected on
    // disocclusion and scene edits), rotating the cone sets every frame. Off by default so a single
    // still (lit-render, tests) is deterministic and equals one frame's trace; the editor turns it on.
    bool temporalAccumulation = false;
    int temporalMaxFrames = 16;  // frames of history at most (the blend weight never drops below 1/N)
    // With temporal accumulation (either GI mode; in the accurate mode the cones of the texel's
    // stratified set), each low-resolution texel traces the normal cone and two of the five side
    // cones per frame, a different pair per frame and texel (all five every 5 frames), and the
    // accumulation averages them: half the cone marching per frame (docs/GI.md, "Cone subsets").
    // Off: every texel traces all six every frame. Stills without accumulation always trace all six.
    bool temporalConeSubsets = true;
    // Editor: while the camera moves or a value is dragged, the viewport lowers its render scale
    // to hold this frame rate (frames per second; 0 = never), and renders at full scale when still.
    float interactiveFpsTarget = 10.0f;

    bool operator==(const RenderSettings&) const = default;
};

// Which preset the three GI fields (anisotropicVoxels, coneFootprintPerHeight,
// diffuseFromVoxelIrradiance) match, and setting them to a preset (Custom leaves them as they are).
GiMode giModeOf(const RenderSettings& settings);
void setGiMode(RenderSettings& settings, GiMode mode);

// JSON in/out with the field names above (enums by their text names); unknown keys are ignored,
// bad values throw std::runtime_error naming the key.
std::string toJson(const RenderSettings& settings);
RenderSettings renderSettingsFromJson(std::string_view json, const RenderSettings& defaults = {});

}  // namespace lit
