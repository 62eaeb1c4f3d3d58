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
    Voxels,
    RoughnessMetalness,
};

std::string_view toString(View view);
std::optional<View> parseView(std::string_view text);  // "final", "direct-diffuse", ...

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
    float voxelSlice = 0.5f;          // debug view: slice position (0..1)
    int voxelSliceAxis = 2;           // debug view: 0 X, 1 Y, 2 Z
    int voxelMip = 0;                 // debug view: mip level

    // Performance
    bool frustumCulling = true;  // G-buffer and shadow views draw only items their frustum may see

    bool operator==(const RenderSettings&) const = default;
};

// JSON in/out with the field names above; unknown keys are ignored, bad values throw
// std::runtime_error naming the key.
std::string toJson(const RenderSettings& settings);
RenderSettings renderSettingsFromJson(std::string_view json, const RenderSettings& defaults = {});

}  // namespace lit
