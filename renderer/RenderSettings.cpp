#include "RenderSettings.h"

#include <nlohmann/json.hpp>

#include <array>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace lit {

namespace {
constexpr std::array<std::pair<View, std::string_view>, 11> kViewNames{{
    {View::Final, "final"},
    {View::DirectDiffuse, "direct-diffuse"},
    {View::IndirectDiffuse, "indirect-diffuse"},
    {View::DirectSpecular, "direct-specular"},
    {View::IndirectSpecular, "indirect-specular"},
    {View::Albedo, "albedo"},
    {View::Normal, "normal"},
    {View::ShadowMap, "shadow-map"},
    {View::Voxels, "voxels"},
    {View::RoughnessMetalness, "roughness-metalness"},
    {View::VoxelSlice, "voxel-slice"},
}};

constexpr std::array<std::pair<VoxelChannel, std::string_view>, 5> kVoxelChannelNames{{
    {VoxelChannel::Radiance, "radiance"},
    {VoxelChannel::Albedo, "albedo"},
    {VoxelChannel::Normal, "normal"},
    {VoxelChannel::Opacity, "opacity"},
    {VoxelChannel::Emission, "emission"},
}};

// Text of an enum field in JSON, and back (overloads picked by the field's type).
std::optional<VoxelChannel> parseEnum(std::string_view text, VoxelChannel*) { return parseVoxelChannel(text); }

// One table drives both directions so a new field cannot be saved but not loaded.
template <typename Visitor>
void visitFields(RenderSettings& s, Visitor&& visit) {
    visit("width", s.width);
    visit("height", s.height);
    visit("exposure", s.exposure);
    visit("directDiffuse", s.directDiffuse);
    visit("directSpecular", s.directSpecular);
    visit("indirectDiffuse", s.indirectDiffuse);
    visit("indirectSpecular", s.indirectSpecular);
    visit("shadows", s.shadows);
    visit("shadowMapSize", s.shadowMapSize);
    visit("shadowDepthBias", s.shadowDepthBias);
    visit("shadowSlopeBias", s.shadowSlopeBias);
    visit("shadowNormalOffset", s.shadowNormalOffset);
    visit("shadowPcfRadius", s.shadowPcfRadius);
    visit("shadowDebugLight", s.shadowDebugLight);
    visit("gi", s.gi);
    visit("voxelResolution", s.voxelResolution);
    visit("voxelRadianceRgba8", s.voxelRadianceRgba8);
    visit("voxelRadianceRange", s.voxelRadianceRange);
    visit("indirectIntensity", s.indirectIntensity);
    visit("specularSamples", s.specularSamples);
    visit("diffuseConeAperture", s.diffuseConeAperture);
    visit("maxTraceDistance", s.maxTraceDistance);
    visit("coneStepScale", s.coneStepScale);
    visit("voxelSlice", s.voxelSlice);
    visit("voxelSliceAxis", s.voxelSliceAxis);
    visit("voxelMip", s.voxelMip);
    visit("voxelChannel", s.voxelChannel);
    visit("frustumCulling", s.frustumCulling);
    visit("indirectScale", s.indirectScale);
    visit("specularFullResRoughness", s.specularFullResRoughness);
    visit("temporalAccumulation", s.temporalAccumulation);
    visit("temporalMaxFrames", s.temporalMaxFrames);
    visit("interactiveFpsTarget", s.interactiveFpsTarget);
}
}  // namespace

std::string_view toString(View view) {
    for (const auto& [v, name] : kViewNames)
        if (v == view) return name;
    return "final";
}

std::optional<View> parseView(std::string_view text) {
    for (const auto& [v, name] : kViewNames)
        if (name == text) return v;
    return std::nullopt;
}

std::string_view toString(VoxelChannel channel) {
    for (const auto& [c, name] : kVoxelChannelNames)
        if (c == channel) return name;
    return "radiance";
}

std::optional<VoxelChannel> parseVoxelChannel(std::string_view text) {
    for (const auto& [c, name] : kVoxelChannelNames)
        if (name == text) return c;
    return std::nullopt;
}

std::string toJson(const RenderSettings& settings) {
    nlohmann::json j;
    RenderSettings copy = settings;
    visitFields(copy, [&](const char* key, auto& value) {
        if constexpr (std::is_enum_v<std::decay_t<decltype(value)>>)
            j[key] = std::string(toString(value));
        else
            j[key] = value;
    });
    j["view"] = std::string(toString(settings.view));
    return j.dump(2);
}

RenderSettings renderSettingsFromJson(std::string_view text, const RenderSettings& defaults) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::runtime_error(std::string("render settings: not valid JSON: ") + e.what());
    }
    if (!j.is_object()) throw std::runtime_error("render settings: expected a JSON object");
    RenderSettings s = defaults;
    visitFields(s, [&](const char* key, auto& value) {
        using T = std::decay_t<decltype(value)>;
        auto it = j.find(key);
        if (it == j.end()) return;
        if constexpr (std::is_enum_v<T>) {
            const auto parsed = it->is_string() ? parseEnum(it->template get<std::string>(), &value) : std::nullopt;
            if (!parsed) throw std::runtime_error(std::string("render settings: '") + key + "' is not a known name");
            value = *parsed;
        } else {
            const bool ok = std::is_same_v<T, bool> ? it->is_boolean()
                            : std::is_integral_v<T> ? it->is_number_integer()
                                                    : it->is_number();
            if (!ok) throw std::runtime_error(std::string("render settings: '") + key + "' has the wrong type");
            value = it->template get<T>();
        }
    });
    if (auto it = j.find("view"); it != j.end()) {
        const auto view = it->is_string() ? parseView(it->get<std::string>()) : std::nullopt;
        if (!view) throw std::runtime_error("render settings: 'view' is not a known view name");
        s.view = *view;
    }
    return s;
}

}  // namespace lit
