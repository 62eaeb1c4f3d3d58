#pragma once
// What the legend in the viewport's corner says about the debug view on screen: what a pixel
// shows, its colour ramps with their numbers, what the cone directions' colours mean, and why a
// term may be near black (the scene's materials, GI off). Built from the view's name, the render
// settings and the scene; window-free (lit_editor_core): panels/LegendPanel draws it, scripts log
// it ("layout") and the tests read it.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "RenderSettings.h"
#include "scene/Scene.h"

namespace lit::editor {

// One stop of a colour ramp: where along the ramp (0..1), the colour drawn there (sRGB-encoded,
// as the viewport shows it) and its label ("" for none).
struct LegendStop {
    float position = 0.0f;
    std::array<float, 3> color{};
    std::string label;
};

// A ramp drawn as a gradient between its stops, with the stops' labels under it.
struct LegendRamp {
    std::string label;  // what the ramp measures: "R: roughness"
    std::vector<LegendStop> stops;
};

// A colour and what it means ("+X", "diffuse cone").
struct LegendSwatch {
    std::array<float, 4> color{};  // sRGB-encoded, alpha for faint overlay lines
    std::string meaning;
};

struct ViewLegend {
    std::string title;               // the view's menu label
    std::vector<std::string> lines;  // what a pixel shows, one statement a line
    std::vector<LegendRamp> ramps;
    std::vector<LegendSwatch> swatches;
    std::string note;            // why the view may look empty or dark ("" when no reason is known)
    bool voxelControls = false;  // the box carries the voxel views' mip and channel
    bool sliceControls = false;  // ... and the slice's axis and position
    bool empty() const { return title.empty(); }
};

// The voxel volume the voxel views read, as far as the legend needs it (resolution 0: none yet).
struct LegendVolume {
    int resolution = 0;  // voxels per side at level 0
    int mipCount = 0;
    float voxelSize = 0.0f;  // metres, level 0
};

struct LegendInputs {
    std::string_view view;  // currentViewName: a RenderSettings view name or "cone-directions"
    const RenderSettings& settings;
    const Scene& scene;
    float exposureEv = 0.0f;  // the exposure the frame was tone-mapped with (stops; metered with auto exposure)
    int shadowMapLight = 0;   // the light whose shadow map is shown (the selected one, else the setting's)
    LegendVolume volume{};
    std::vector<LegendVolume> levels{};  // the voxel-levels view's volumes, finest first, the scene's last
    bool coneSurfacePicked = false;  // cone directions: a surface was clicked
};

// The legend of the view, or an empty one for the final image (which needs none).
ViewLegend describeDebugView(const LegendInputs& inputs);

// The legend as one line, for the log and the tests: "title | line | ... | ramp: a .. b | note".
std::string legendText(const ViewLegend& legend);

// The scene's materials, as far as they decide how bright the specular terms can be.
struct MaterialSpread {
    int count = 0;
    float minRoughness = 1.0f;  // roughnessFactor (a texture can only lower it: glTF multiplies)
    float maxRoughness = 0.0f;
    float maxMetalness = 0.0f;  // metallicFactor
    bool textured = false;      // some material has a metallic-roughness texture
};
MaterialSpread materialSpread(const Scene& scene);

// Linear [0,1] to the sRGB encoding the viewport shows (IEC 61966-2-1).
float srgbEncode(float linear);
// The tone curve of the HDR views (shaders/include/tonemap.glsl: Narkowicz 2015's ACES fit).
float acesFilmic(float x);

}  // namespace lit::editor
