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
constexpr std::array<std::pair<View, std::string_view>, 12> kViewNames{{
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
    {View::VoxelLevels, "voxel-levels"},
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

constexpr std::array<std::pair<GiMode, std::string_view>, 3> kGiModeNames{{
    {GiMode::Fast, "fast"},
    {GiMode::Accurate, "accurate"},
    {GiMode::Cached, "cached"},
}};

template <typename Enum, std::size_t N>
std::string_view nameOf(const std::array<std::pair<Enum, std::string_view>, N>& names, Enum value) {
    for (const auto& [v, name] : names)
        if (v == value) return name;
    return names[0].second;
}

template <typename Enum, std::size_t N>
std::optional<Enum> valueOf(const std::array<std::pair<Enum, std::string_view>, N>& names, std::string_view text) {
    for (const auto& [v, name] : names)
        if (name == text) return v;
    return std::nullopt;
}

// Text of an enum field in JSON, and back (overloads picked by the field's type).
std::optional<View> parseEnum(std::string_view text, View*) { return parseView(text); }
std::optional<VoxelChannel> parseEnum(std::string_view text, VoxelChannel*) { return parseVoxelChannel(text); }
std::optional<SkyMode> parseEnum(std::string_view text, SkyMode*) { return parseSkyMode(text); }
std::optional<GiMode> parseEnum(std::string_view text, GiMode*) { return parseGiMode(text); }

template <typename T>
constexpr bool kIsFloatArray = false;
template <std::size_t N>
constexpr bool kIsFloatArray<std::array<float, N>> = true;

// One table drives writing, reading and the key list, so a new field cannot be saved but not
// loaded. visit(group, field, member).
template <typename Visitor>
void visitFields(RenderSettings& s, Visitor&& visit) {
    OutputSettings& o = s.output;
    visit("output", "width", o.width);
    visit("output", "height", o.height);
    visit("output", "exposureEv", o.exposureEv);
    visit("output", "autoExposure", o.autoExposure);
    visit("output", "autoExposureKey", o.autoExposureKey);
    visit("output", "autoExposureSpeed", o.autoExposureSpeed);
    visit("output", "autoExposureMinEv", o.autoExposureMinEv);
    visit("output", "autoExposureMaxEv", o.autoExposureMaxEv);
    visit("output", "frustumCulling", o.frustumCulling);
    visit("output", "antialiasing", o.antialiasing);
    visit("output", "antialiasingFrames", o.antialiasingFrames);
    visit("output", "specularAntialiasing", o.specularAntialiasing);
    SkySettings& sky = s.sky;
    visit("sky", "mode", sky.mode);
    visit("sky", "zenith", sky.zenith);
    visit("sky", "horizon", sky.horizon);
    visit("sky", "ground", sky.ground);
    visit("sky", "intensity", sky.intensity);
    visit("sky", "hdrPath", sky.hdrPath);
    visit("sky", "sunIrradiance", sky.sunIrradiance);
    visit("sky", "sunElevation", sky.sunElevation);
    visit("sky", "sunAzimuth", sky.sunAzimuth);
    ShadowSettings& sh = s.shadows;
    visit("shadows", "enabled", sh.enabled);
    visit("shadows", "mapSize", sh.mapSize);
    visit("shadows", "depthBias", sh.depthBias);
    visit("shadows", "slopeBias", sh.slopeBias);
    visit("shadows", "normalOffset", sh.normalOffset);
    visit("shadows", "pcfRadius", sh.pcfRadius);
    visit("shadows", "cascades", sh.cascades);
    visit("shadows", "cascadeDistance", sh.cascadeDistance);
    visit("shadows", "cascadeSplit", sh.cascadeSplit);
    GiSettings& gi = s.gi;
    visit("gi", "enabled", gi.enabled);
    visit("gi", "mode", gi.mode);
    visit("gi", "voxelResolution", gi.voxelResolution);
    visit("gi", "voxelizeChangesOnly", gi.voxelizeChangesOnly);
    visit("gi", "radianceRgba8", gi.radianceRgba8);
    visit("gi", "radianceRange", gi.radianceRange);
    visit("gi", "indirectIntensity", gi.indirectIntensity);
    visit("gi", "bounces", gi.bounces);
    visit("gi", "voxelRays", gi.voxelRays);
    visit("gi", "laterBounceRayStride", gi.laterBounceRayStride);
    visit("gi", "diffuseConeAperture", gi.diffuseConeAperture);
    visit("gi", "maxTraceDistance", gi.maxTraceDistance);
    visit("gi", "coneStepScale", gi.coneStepScale);
    visit("gi", "coneFootprintPerHeight", gi.coneFootprintPerHeight);
    visit("gi", "nearLevelSide", gi.nearLevelSide);
    visit("gi", "nearLevels", gi.nearLevels);
    IndirectSettings& in = s.indirect;
    visit("indirect", "scale", in.scale);
    visit("indirect", "specularSamples", in.specularSamples);
    visit("indirect", "specularFullResRoughness", in.specularFullResRoughness);
    visit("indirect", "temporalAccumulation", in.temporalAccumulation);
    visit("indirect", "temporalMaxFrames", in.temporalMaxFrames);
    visit("indirect", "temporalConeSubsets", in.temporalConeSubsets);
    TermSettings& t = s.terms;
    visit("terms", "directDiffuse", t.directDiffuse);
    visit("terms", "directSpecular", t.directSpecular);
    visit("terms", "indirectDiffuse", t.indirectDiffuse);
    visit("terms", "indirectSpecular", t.indirectSpecular);
    DebugViewSettings& d = s.debug;
    visit("debug", "view", d.view);
    visit("debug", "shadowMapLight", d.shadowMapLight);
    visit("debug", "voxelSlice", d.voxelSlice);
    visit("debug", "voxelSliceAxis", d.voxelSliceAxis);
    visit("debug", "voxelMip", d.voxelMip);
    visit("debug", "voxelLevel", d.voxelLevel);
    visit("debug", "voxelChannel", d.voxelChannel);
}

// The flat keys of files written before the settings had groups, and where each went.
constexpr std::array<std::pair<std::string_view, std::string_view>, 53> kFlatKeys{{
    {"width", "output.width"},
    {"height", "output.height"},
    {"exposureEv", "output.exposureEv"},
    {"autoExposure", "output.autoExposure"},
    {"autoExposureKey", "output.autoExposureKey"},
    {"autoExposureSpeed", "output.autoExposureSpeed"},
    {"autoExposureMinEv", "output.autoExposureMinEv"},
    {"autoExposureMaxEv", "output.autoExposureMaxEv"},
    {"frustumCulling", "output.frustumCulling"},
    {"skyMode", "sky.mode"},
    {"skyZenith", "sky.zenith"},
    {"skyHorizon", "sky.horizon"},
    {"skyGround", "sky.ground"},
    {"skyIntensity", "sky.intensity"},
    {"skyHdrPath", "sky.hdrPath"},
    {"defaultSunIrradiance", "sky.sunIrradiance"},
    {"defaultSunElevation", "sky.sunElevation"},
    {"defaultSunAzimuth", "sky.sunAzimuth"},
    {"shadows", "shadows.enabled"},
    {"shadowMapSize", "shadows.mapSize"},
    {"shadowDepthBias", "shadows.depthBias"},
    {"shadowSlopeBias", "shadows.slopeBias"},
    {"shadowNormalOffset", "shadows.normalOffset"},
    {"shadowPcfRadius", "shadows.pcfRadius"},
    {"shadowDebugLight", "debug.shadowMapLight"},
    {"gi", "gi.enabled"},
    {"voxelResolution", "gi.voxelResolution"},
    {"voxelRadianceRgba8", "gi.radianceRgba8"},
    {"voxelRadianceRange", "gi.radianceRange"},
    {"indirectIntensity", "gi.indirectIntensity"},
    {"bounces", "gi.bounces"},
    {"voxelRays", "gi.voxelRays"},
    {"diffuseConeAperture", "gi.diffuseConeAperture"},
    {"maxTraceDistance", "gi.maxTraceDistance"},
    {"coneStepScale", "gi.coneStepScale"},
    {"coneFootprintPerHeight", "gi.coneFootprintPerHeight"},
    {"specularSamples", "indirect.specularSamples"},
    {"indirectScale", "indirect.scale"},
    {"specularFullResRoughness", "indirect.specularFullResRoughness"},
    {"temporalAccumulation", "indirect.temporalAccumulation"},
    {"temporalMaxFrames", "indirect.temporalMaxFrames"},
    {"temporalConeSubsets", "indirect.temporalConeSubsets"},
    {"directDiffuse", "terms.directDiffuse"},
    {"directSpecular", "terms.directSpecular"},
    {"indirectDiffuse", "terms.indirectDiffuse"},
    {"indirectSpecular", "terms.indirectSpecular"},
    {"view", "debug.view"},
    {"giMode", "gi.mode"},  // the editor scripts' name for the mode
    {"voxelSlice", "debug.voxelSlice"},
    {"voxelSliceAxis", "debug.voxelSliceAxis"},
    {"voxelMip", "debug.voxelMip"},
    {"voxelChannel", "debug.voxelChannel"},
    {"exposure", "output.exposureEv"},  // linear, from before exposure stops: log2 of it
}};
// Keys that are no longer render settings: the GI mode's parts (gi.mode replaces them) and what
// only the editor uses (its own settings keep them).
constexpr std::array<std::pair<std::string_view, std::string_view>, 5> kRetiredKeys{{
    {"anisotropicVoxels", "gi.mode"},
    {"diffuseFromVoxelIrradiance", "gi.mode"},
    {"interactiveFpsTarget", "the editor's own settings (editor.interactiveFpsTarget)"},
    {"voxelIrradianceVoxelsPerFrame", "the editor's GI budget (editor.giUpdateVoxelsPerFrame)"},
    {"voxelIrradianceRefineVoxelsPerFrame", "the editor's GI budget (editor.giRefineVoxelsPerFrame)"},
}};

// Reads `value` into `field`; throws naming `key` when its type does not fit.
template <typename T>
void readField(const nlohmann::json& value, T& field, const std::string& key) {
    if constexpr (std::is_enum_v<T>) {
        const auto parsed = value.is_string() ? parseEnum(value.template get<std::string>(), &field) : std::nullopt;
        if (!parsed) throw std::runtime_error("render settings: '" + key + "' is not a known name");
        field = *parsed;
    } else if constexpr (kIsFloatArray<T>) {
        if (!value.is_array() || value.size() != field.size() ||
            !std::all_of(value.begin(), value.end(), [](const nlohmann::json& e) { return e.is_number(); }))
            throw std::runtime_error("render settings: '" + key + "' expects " + std::to_string(field.size()) +
                                     " numbers");
        field = value.template get<T>();
    } else if constexpr (std::is_same_v<T, std::string>) {
        if (!value.is_string()) throw std::runtime_error("render settings: '" + key + "' expects a string");
        field = value.template get<std::string>();
    } else {
        const bool ok = std::is_same_v<T, bool> ? value.is_boolean()
                        : std::is_integral_v<T> ? value.is_number_integer()
                                                : value.is_number();
        if (!ok) throw std::runtime_error("render settings: '" + key + "' has the wrong type");
        field = value.template get<T>();
    }
}

// Sets the field called `key` ("group.field") from `value`; false when no field has that key.
// Errors name `shown` (the key as the file or the user wrote it) when given.
bool readByKey(RenderSettings& s, std::string_view key, const nlohmann::json& value, std::string_view shown = {}) {
    bool found = false;
    visitFields(s, [&](std::string_view group, std::string_view name, auto& field) {
        if (found || key.size() != group.size() + 1 + name.size() || !key.starts_with(group) ||
            key[group.size()] != '.' || !key.ends_with(name))
            return;
        readField(value, field, std::string(shown.empty() ? key : shown));
        found = true;
    });
    return found;
}

void warn(std::vector<std::string>* warnings, std::string text) {
    if (warnings) warnings->push_back(std::move(text));
}

// Reads one key of an older flat file; false when `key` is no such key.
bool readFlatKey(RenderSettings& s, const std::string& key, const nlohmann::json& value,
                 std::vector<std::string>* warnings) {
    for (const auto& [old, now] : kFlatKeys) {
        if (key != old) continue;
        if (key == "exposure") {
            if (!value.is_number() || value.get<double>() <= 0.0)
                throw std::runtime_error(
                    "render settings: 'exposure' (linear, from older files) must be a positive number");
            s.output.exposureEv = static_cast<float>(std::log2(value.get<double>()));
            warn(warnings,
                 "render settings: 'exposure' (a linear multiplier) is deprecated; read as output.exposureEv "
                 "(stops) " +
                     std::to_string(s.output.exposureEv));
            return true;
        }
        readByKey(s, now, value, key);
        warn(warnings, "render settings: '" + key + "' is deprecated; read as " + std::string(now));
        return true;
    }
    return false;
}
}  // namespace

std::string_view toString(View view) { return nameOf(kViewNames, view); }
std::optional<View> parseView(std::string_view text) { return valueOf(kViewNames, text); }
std::string_view toString(VoxelChannel channel) { return nameOf(kVoxelChannelNames, channel); }
std::optional<VoxelChannel> parseVoxelChannel(std::string_view text) { return valueOf(kVoxelChannelNames, text); }
std::string_view toString(SkyMode mode) { return nameOf(kSkyModeNames, mode); }
std::optional<SkyMode> parseSkyMode(std::string_view text) { return valueOf(kSkyModeNames, text); }
std::string_view toString(GiMode mode) { return nameOf(kGiModeNames, mode); }
std::optional<GiMode> parseGiMode(std::string_view text) { return valueOf(kGiModeNames, text); }

std::string toJson(const RenderSettings& settings) {
    nlohmann::ordered_json j;
    RenderSettings copy = settings;
    visitFields(copy, [&](const char* group, const char* name, auto& value) {
        if constexpr (std::is_enum_v<std::decay_t<decltype(value)>>)
            j[group][name] = std::string(toString(value));
        else
            j[group][name] = value;
    });
    return j.dump(2);
}

RenderSettings renderSettingsFromJson(std::string_view text, const RenderSettings& defaults,
                                      std::vector<std::string>* warnings) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::runtime_error(std::string("render settings: not valid JSON: ") + e.what());
    }
    if (!j.is_object()) throw std::runtime_error("render settings: expected a JSON object");
    RenderSettings s = defaults;
    // Older flat keys first, so that a file with both takes the grouped value.
    for (const auto& [key, value] : j.items())
        if (!value.is_object()) readFlatKey(s, key, value, warnings);
    // The GI mode was three fields: the cached mode read the voxel irradiance, the accurate mode
    // had directional voxels without it, the fast mode neither.
    const auto flag = [&](const char* key) -> std::optional<bool> {
        const auto it = j.find(key);
        if (it == j.end()) return std::nullopt;
        if (!it->is_boolean())
            throw std::runtime_error(std::string("render settings: '") + key + "' has the wrong type");
        return it->get<bool>();
    };
    const std::optional<bool> anisotropic = flag("anisotropicVoxels");
    const std::optional<bool> irradiance = flag("diffuseFromVoxelIrradiance");
    if (anisotropic || irradiance) {
        s.gi.mode = irradiance.value_or(true)    ? GiMode::Cached
                    : anisotropic.value_or(true) ? GiMode::Accurate
                                                 : GiMode::Fast;
        warn(warnings,
             "render settings: 'anisotropicVoxels' and 'diffuseFromVoxelIrradiance' are deprecated; read as "
             "gi.mode \"" +
                 std::string(toString(s.gi.mode)) + "\"");
    }
    for (const auto& [key, now] : kRetiredKeys)
        if (j.contains(key) && now != "gi.mode")
            warn(warnings, "render settings: '" + std::string(key) + "' is no longer a render setting; it is " +
                               std::string(now));
    visitFields(s, [&](const char* group, const char* name, auto& value) {
        const auto g = j.find(group);
        if (g == j.end() || !g->is_object()) return;
        const auto it = g->find(name);
        if (it == g->end()) return;
        readField(*it, value, std::string(group) + "." + name);
    });
    return s;
}

std::vector<std::string> renderSettingKeys() {
    std::vector<std::string> keys;
    RenderSettings s;
    visitFields(s,
                [&](const char* group, const char* name, auto&) { keys.push_back(std::string(group) + "." + name); });
    return keys;
}

void setRenderSetting(RenderSettings& settings, std::string_view key, std::string_view value,
                      std::vector<std::string>* warnings) {
    nlohmann::json parsed = nlohmann::json::parse(value, nullptr, /*allow_exceptions=*/false);
    if (parsed.is_discarded() || parsed.is_object()) parsed = std::string(value);
    RenderSettings updated = settings;
    const std::string name(key);
    if (!readByKey(updated, name, parsed)) {
        if (name == "anisotropicVoxels" || name == "diffuseFromVoxelIrradiance") {
            updated = renderSettingsFromJson(nlohmann::json{{name, parsed}}.dump(), settings, warnings);
        } else if (!readFlatKey(updated, name, parsed, warnings)) {
            throw std::runtime_error("unknown render setting '" + name + "'");
        }
    }
    settings = updated;
}

}  // namespace lit
