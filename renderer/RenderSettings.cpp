#include "RenderSettings.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
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

constexpr std::array<std::pair<SkyMode, std::string_view>, 5> kSkyModeNames{{
    {SkyMode::Auto, "auto"},
    {SkyMode::None, "none"},
    {SkyMode::Uniform, "uniform"},
    {SkyMode::Gradient, "gradient"},
    {SkyMode::Hdr, "hdr"},
}};

// Custom is written but not parsed: it names "neither preset", not settings one could ask for.
constexpr std::array<std::pair<GiMode, std::string_view>, 4> kGiModeNames{{
    {GiMode::Fast, "fast"},
    {GiMode::Accurate, "accurate"},
    {GiMode::Cached, "cached"},
    {GiMode::Custom, "custom"},
}};

// Text of an enum field in JSON, and back (overloads picked by the field's type).
std::optional<VoxelChannel> parseEnum(std::string_view text, VoxelChannel*) { return parseVoxelChannel(text); }
std::optional<SkyMode> parseEnum(std::string_view text, SkyMode*) { return parseSkyMode(text); }

template <typename T>
constexpr bool kIsFloatArray = false;
template <std::size_t N>
constexpr bool kIsFloatArray<std::array<float, N>> = true;

// One table drives both directions so a new field cannot be saved but not loaded.
template <typename Visitor>
void visitFields(RenderSettings& s, Visitor&& visit) {
    visit("width", s.width);
    visit("height", s.height);
    visit("exposureEv", s.exposureEv);
    visit("autoExposure", s.autoExposure);
    visit("autoExposureKey", s.autoExposureKey);
    visit("autoExposureSpeed", s.autoExposureSpeed);
    visit("autoExposureMinEv", s.autoExposureMinEv);
    visit("autoExposureMaxEv", s.autoExposureMaxEv);
    visit("skyMode", s.skyMode);
    visit("skyZenith", s.skyZenith);
    visit("skyHorizon", s.skyHorizon);
    visit("skyGround", s.skyGround);
    visit("skyIntensity", s.skyIntensity);
    visit("skyHdrPath", s.skyHdrPath);
    visit("defaultSunIrradiance", s.defaultSunIrradiance);
    visit("defaultSunElevation", s.defaultSunElevation);
    visit("defaultSunAzimuth", s.defaultSunAzimuth);
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
    visit("anisotropicVoxels", s.anisotropicVoxels);
    visit("coneFootprintPerHeight", s.coneFootprintPerHeight);
    visit("diffuseFromVoxelIrradiance", s.diffuseFromVoxelIrradiance);
    visit("voxelIrradianceVoxelsPerFrame", s.voxelIrradianceVoxelsPerFrame);
    visit("voxelIrradianceRefineVoxelsPerFrame", s.voxelIrradianceRefineVoxelsPerFrame);
    visit("voxelRays", s.voxelRays);
    visit("bounces", s.bounces);
    visit("voxelSlice", s.voxelSlice);
    visit("voxelSliceAxis", s.voxelSliceAxis);
    visit("voxelMip", s.voxelMip);
    visit("voxelChannel", s.voxelChannel);
    visit("frustumCulling", s.frustumCulling);
    visit("indirectScale", s.indirectScale);
    visit("specularFullResRoughness", s.specularFullResRoughness);
    visit("temporalAccumulation", s.temporalAccumulation);
    visit("temporalMaxFrames", s.temporalMaxFrames);
    visit("temporalConeSubsets", s.temporalConeSubsets);
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

std::string_view toString(SkyMode mode) {
    for (const auto& [m, name] : kSkyModeNames)
        if (m == mode) return name;
    return "auto";
}

std::optional<SkyMode> parseSkyMode(std::string_view text) {
    for (const auto& [m, name] : kSkyModeNames)
        if (name == text) return m;
    return std::nullopt;
}

std::string_view toString(GiMode mode) {
    for (const auto& [m, name] : kGiModeNames)
        if (m == mode) return name;
    return "custom";
}

std::optional<GiMode> parseGiMode(std::string_view text) {
    for (const auto& [m, name] : kGiModeNames)
        if (name == text && m != GiMode::Custom) return m;
    return std::nullopt;
}

GiMode giModeOf(const RenderSettings& settings) {
    if (!settings.anisotropicVoxels && settings.coneFootprintPerHeight == 0.0f && !settings.diffuseFromVoxelIrradiance)
        return GiMode::Fast;
    if (settings.anisotropicVoxels && settings.coneFootprintPerHeight == kAccurateGiFootprint)
        return settings.diffuseFromVoxelIrradiance ? GiMode::Cached : GiMode::Accurate;
    return GiMode::Custom;
}

void setGiMode(RenderSettings& settings, GiMode mode) {
    if (mode == GiMode::Custom) return;
    const bool accurateCones = mode == GiMode::Accurate || mode == GiMode::Cached;
    settings.anisotropicVoxels = accurateCones;
    settings.coneFootprintPerHeight = accurateCones ? kAccurateGiFootprint : 0.0f;
    settings.diffuseFromVoxelIrradiance = mode == GiMode::Cached;
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
        } else if constexpr (kIsFloatArray<T>) {
            if (!it->is_array() || it->size() != value.size() ||
                !std::all_of(it->begin(), it->end(), [](const nlohmann::json& e) { return e.is_number(); }))
                throw std::runtime_error(std::string("render settings: '") + key + "' expects " +
                                         std::to_string(value.size()) + " numbers");
            value = it->template get<T>();
        } else if constexpr (std::is_same_v<T, std::string>) {
            if (!it->is_string()) throw std::runtime_error(std::string("render settings: '") + key + "' expects a string");
            value = it->template get<std::string>();
        } else {
            const bool ok = std::is_same_v<T, bool> ? it->is_boolean()
                            : std::is_integral_v<T> ? it->is_number_integer()
                                                    : it->is_number();
            if (!ok) throw std::runtime_error(std::string("render settings: '") + key + "' has the wrong type");
            value = it->template get<T>();
        }
    });
    // Files from before exposure stops hold a linear multiplier; a file with both keys means the stops.
    if (auto it = j.find("exposure"); it != j.end() && !j.contains("exposureEv")) {
        if (!it->is_number() || it->get<double>() <= 0.0)
            throw std::runtime_error("render settings: 'exposure' (linear, from older files) must be a positive number");
        s.exposureEv = static_cast<float>(std::log2(it->get<double>()));
    }
    if (auto it = j.find("view"); it != j.end()) {
        const auto view = it->is_string() ? parseView(it->get<std::string>()) : std::nullopt;
        if (!view) throw std::runtime_error("render settings: 'view' is not a known view name");
        s.view = *view;
    }
    return s;
}

}  // namespace lit
