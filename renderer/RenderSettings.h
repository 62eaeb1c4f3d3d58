#pragma once
// Everything a user can tune about a frame: plain data with defaults and units, compared with
// ==, saved as JSON. The editor's settings panel, lit-render's flags and the tests all set these
// same fields; the Renderer reads them and nothing else.

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

struct RenderSettings {
    // Output
    int width = 1280;  // pixels
    int height = 720;  // pixels
    View view = View::Final;
    float exposure = 1.0f;  // linear multiplier applied before tone mapping

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
    // Editor: while the camera moves or a value is dragged, the viewport lowers its render scale
    // to hold this frame rate (frames per second; 0 = never), and renders at full scale when still.
    float interactiveFpsTarget = 10.0f;

    bool operator==(const RenderSettings&) const = default;
};

// JSON in/out with the field names above (enums by their text names); unknown keys are ignored,
// bad values throw std::runtime_error naming the key.
std::string toJson(const RenderSettings& settings);
RenderSettings renderSettingsFromJson(std::string_view json, const RenderSettings& defaults = {});

}  // namespace lit
