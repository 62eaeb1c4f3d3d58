// KHR_materials_ior / _specular / _sheen / _clearcoat / _transmission / _volume factors in and out (scene/GltfMaterialLayers.h).

#include "scene/GltfMaterialLayers.h"

#include "scene/GltfKeep.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace lit::gltfkeep {

namespace {

// The number `key` of an extension object, if it is one (non-numbers are reported).
std::optional<double> numberIn(const tinygltf::Value& object, const char* key, const std::string& where,
                               const std::function<void(const std::string&)>& warn) {
    if (!object.Has(key)) return std::nullopt;
    const tinygltf::Value& value = object.Get(key);
    if (!value.IsNumber()) {
        warn(where + " " + key + " is not a number; Lit uses the default");
        return std::nullopt;
    }
    const double number = value.GetNumberAsDouble();
    if (!std::isfinite(number)) {
        warn(where + " " + key + " is not finite; Lit uses the default");
        return std::nullopt;
    }
    return number;
}

// A factor in [lo, hi], clamped with a warning; `fallback` when absent.
float factorIn(const tinygltf::Value& object, const char* key, float fallback, double lo, double hi,
               const std::string& where, const std::function<void(const std::string&)>& warn) {
    const std::optional<double> number = numberIn(object, key, where, warn);
    if (!number) return fallback;
    const double clamped = std::clamp(*number, lo, hi);
    if (clamped != *number)
        warn(where + " " + key + " " + std::to_string(*number) + " is outside its range; Lit uses " +
             std::to_string(clamped));
    return static_cast<float>(clamped);
}

// A colour of three numbers in [0, hi], clamped with a warning; `fallback` when absent or not
// three finite numbers (with a warning).
glm::vec3 colorIn(const tinygltf::Value& object, const char* key, const glm::vec3& fallback, double hi,
                  const std::string& where, const std::function<void(const std::string&)>& warn) {
    if (!object.Has(key)) return fallback;
    const tinygltf::Value& color = object.Get(key);
    glm::vec3 out = fallback;
    bool valid = color.IsArray() && color.ArrayLen() == 3;
    bool clamped = false;
    for (int i = 0; valid && i < 3; ++i) {
        const tinygltf::Value& e = color.Get(i);
        valid = e.IsNumber() && std::isfinite(e.GetNumberAsDouble());
        if (!valid) break;
        const double value = std::clamp(e.GetNumberAsDouble(), 0.0, hi);
        clamped = clamped || value != e.GetNumberAsDouble();
        out[i] = static_cast<float>(value);
    }
    if (!valid) {
        warn(where + " " + key + " is not three finite numbers; Lit uses [" + std::to_string(fallback.x) + ", " +
             std::to_string(fallback.y) + ", " + std::to_string(fallback.z) + "]");
        return fallback;
    }
    if (clamped) warn(where + " " + key + " has a value outside its range; Lit clamps it");
    return out;
}

// The extension object the file had for `name` (Material::kept), if any.
std::optional<nlohmann::json> keptObject(const nlohmann::json& kept, const char* name) {
    if (!kept.is_object()) return std::nullopt;
    const auto found = kept.find(name);
    if (found == kept.end() || !found->is_object()) return std::nullopt;
    return *found;
}

// Sets `object[key]` to `value` unless the file's number there already rounds to it, or the key
// is absent and `value` is the extension's default.
void setFactor(nlohmann::json& object, const char* key, float value, float defaultValue) {
    const auto found = object.find(key);
    if (found != object.end() && found->is_number() && static_cast<float>(found->get<double>()) == value) return;
    if (found == object.end() && value == defaultValue) return;
    object[key] = static_cast<double>(value);
}

void setColor(nlohmann::json& object, const char* key, const glm::vec3& value, const glm::vec3& defaultValue) {
    const auto found = object.find(key);
    if (found != object.end() && found->is_array() && found->size() == 3) {
        bool same = true;
        for (int c = 0; c < 3; ++c)
            same = same && (*found)[static_cast<std::size_t>(c)].is_number() &&
                   static_cast<float>((*found)[static_cast<std::size_t>(c)].get<double>()) == value[c];
        if (same) return;
    }
    if (found == object.end() && value == defaultValue) return;
    object[key] = nlohmann::json::array({static_cast<double>(value.x), static_cast<double>(value.y),
                                         static_cast<double>(value.z)});
}

}  // namespace

void readMaterialLayers(const tinygltf::ExtensionMap& extensions, Material& material,
                        const std::function<void(const std::string&)>& warn) {
    const auto object = [&](const char* name) -> const tinygltf::Value* {
        const auto it = extensions.find(name);
        if (it == extensions.end()) return nullptr;
        if (!it->second.IsObject()) {
            warn(std::string(name) + " is not an object; ignored");
            return nullptr;
        }
        return &it->second;
    };
    if (const tinygltf::Value* ior = object(kIorExtension)) {
        const std::string where = kIorExtension;
        // The schema allows 0 (a perfect mirror) or at least 1.
        if (const std::optional<double> value = numberIn(*ior, "ior", where, warn)) {
            double used = *value;
            if (used != 0.0 && used < 1.0) used = 1.0;
            if (used != *value)
                warn(where + " ior " + std::to_string(*value) + " is below 1; Lit uses " + std::to_string(used));
            material.ior = static_cast<float>(used);
        }
    }
    if (const tinygltf::Value* specular = object(kSpecularExtension)) {
        const std::string where = kSpecularExtension;
        material.specularFactor = factorIn(*specular, "specularFactor", 1.0f, 0.0, 1.0, where, warn);
        material.specularColorFactor =
            colorIn(*specular, "specularColorFactor", glm::vec3(1.0f), std::numeric_limits<double>::max(), where, warn);
    }
    if (const tinygltf::Value* sheen = object(kSheenExtension)) {
        const std::string where = kSheenExtension;
        material.sheenColorFactor = colorIn(*sheen, "sheenColorFactor", glm::vec3(0.0f), 1.0, where, warn);
        material.sheenRoughness = factorIn(*sheen, "sheenRoughnessFactor", 0.0f, 0.0, 1.0, where, warn);
    }
    if (const tinygltf::Value* clearcoat = object(kClearcoatExtension)) {
        const std::string where = kClearcoatExtension;
        material.clearcoatFactor = factorIn(*clearcoat, "clearcoatFactor", 0.0f, 0.0, 1.0, where, warn);
        material.clearcoatRoughness = factorIn(*clearcoat, "clearcoatRoughnessFactor", 0.0f, 0.0, 1.0, where, warn);
    }
    if (const tinygltf::Value* transmission = object(kTransmissionExtension)) {
        const std::string where = kTransmissionExtension;
        material.transmission = factorIn(*transmission, "transmissionFactor", 0.0f, 0.0, 1.0, where, warn);
    }
    if (const tinygltf::Value* volume = object(kVolumeExtension)) {
        const std::string where = kVolumeExtension;
        material.thickness =
            factorIn(*volume, "thicknessFactor", 0.0f, 0.0, std::numeric_limits<float>::max(), where, warn);
        // The schema's default is +∞ (no absorption), which JSON cannot write: 0 stands for it here.
        if (const std::optional<double> distance = numberIn(*volume, "attenuationDistance", where, warn)) {
            if (*distance > 0.0 && *distance <= std::numeric_limits<float>::max())
                material.attenuationDistance = static_cast<float>(*distance);
            else
                warn(where + " attenuationDistance " + std::to_string(*distance) +
                     " is not a positive distance; Lit uses infinity (no absorption)");
        }
        material.attenuationColor = colorIn(*volume, "attenuationColor", glm::vec3(1.0f), 1.0, where, warn);
    }
}

void writeMaterialLayers(const Material& material, tinygltf::ExtensionMap& extensions,
                         const std::function<void(const std::string&)>& use) {
    const nlohmann::json kept = material.kept.extensions.empty()
                                    ? nlohmann::json::object()
                                    : nlohmann::json::parse(material.kept.extensions, nullptr, false);
    const auto write = [&](const char* name, const auto& setFactors) {
        const std::optional<nlohmann::json> file = keptObject(kept, name);
        nlohmann::json object = file.value_or(nlohmann::json::object());
        setFactors(object);
        if (object.empty() && !file) return;
        extensions[name] = toValue(object);
        use(name);
    };
    write(kIorExtension, [&](nlohmann::json& o) { setFactor(o, "ior", material.ior, 1.5f); });
    write(kSpecularExtension, [&](nlohmann::json& o) {
        setFactor(o, "specularFactor", material.specularFactor, 1.0f);
        setColor(o, "specularColorFactor", material.specularColorFactor, glm::vec3(1.0f));
    });
    write(kSheenExtension, [&](nlohmann::json& o) {
        setColor(o, "sheenColorFactor", material.sheenColorFactor, glm::vec3(0.0f));
        setFactor(o, "sheenRoughnessFactor", material.sheenRoughness, 0.0f);
    });
    write(kClearcoatExtension, [&](nlohmann::json& o) {
        setFactor(o, "clearcoatFactor", material.clearcoatFactor, 0.0f);
        setFactor(o, "clearcoatRoughnessFactor", material.clearcoatRoughness, 0.0f);
    });
    write(kTransmissionExtension,
          [&](nlohmann::json& o) { setFactor(o, "transmissionFactor", material.transmission, 0.0f); });
    write(kVolumeExtension, [&](nlohmann::json& o) {
        setFactor(o, "thicknessFactor", material.thickness, 0.0f);
        setFactor(o, "attenuationDistance", material.attenuationDistance, 0.0f);
        setColor(o, "attenuationColor", material.attenuationColor, glm::vec3(1.0f));
    });
}

}  // namespace lit::gltfkeep
