// Kept glTF data as JSON text and back (scene/GltfKeep.h).

#include "scene/GltfKeep.h"

#include <limits>
#include <utility>

namespace lit::gltfkeep {

nlohmann::json toJson(const tinygltf::Value& value) {
    switch (value.Type()) {
        case tinygltf::NULL_TYPE:
            return nullptr;
        case tinygltf::BOOL_TYPE:
            return value.Get<bool>();
        case tinygltf::INT_TYPE:
            return value.Get<int>();
        case tinygltf::REAL_TYPE:
            return value.Get<double>();
        case tinygltf::STRING_TYPE:
            return value.Get<std::string>();
        case tinygltf::BINARY_TYPE:
            return nullptr;  // not produced by JSON parsing
        case tinygltf::ARRAY_TYPE: {
            nlohmann::json out = nlohmann::json::array();
            for (std::size_t i = 0; i < value.ArrayLen(); ++i) out.push_back(toJson(value.Get(static_cast<int>(i))));
            return out;
        }
        case tinygltf::OBJECT_TYPE: {
            nlohmann::json out = nlohmann::json::object();
            for (const std::string& key : value.Keys()) out[key] = toJson(value.Get(key));
            return out;
        }
    }
    return nullptr;
}

tinygltf::Value toValue(const nlohmann::json& j) {
    if (j.is_boolean()) return tinygltf::Value(j.get<bool>());
    if (j.is_number_integer()) {
        const auto n = j.get<long long>();
        if (n >= std::numeric_limits<int>::min() && n <= std::numeric_limits<int>::max())
            return tinygltf::Value(static_cast<int>(n));
        return tinygltf::Value(static_cast<double>(n));
    }
    if (j.is_number()) return tinygltf::Value(j.get<double>());
    if (j.is_string()) return tinygltf::Value(j.get<std::string>());
    if (j.is_array()) {
        tinygltf::Value::Array out;
        for (const nlohmann::json& e : j) out.push_back(toValue(e));
        return tinygltf::Value(std::move(out));
    }
    if (j.is_object()) {
        tinygltf::Value::Object out;
        for (auto it = j.begin(); it != j.end(); ++it) out[it.key()] = toValue(it.value());
        return tinygltf::Value(std::move(out));
    }
    return tinygltf::Value();
}

// Extras as JSON text ("" when absent).
std::string extrasText(const tinygltf::Value& extras) {
    return extras.Type() == tinygltf::NULL_TYPE ? std::string() : toJson(extras).dump();
}

// The extensions except those Lit reads and writes itself (`known`), as a JSON object text.
std::string extensionsText(const tinygltf::ExtensionMap& extensions, std::initializer_list<const char*> known) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [name, value] : extensions) {
        bool isKnown = false;
        for (const char* k : known) isKnown |= name == k;
        if (!isKnown) out[name] = toJson(value);
    }
    return out.empty() ? std::string() : out.dump();
}

KeptGltf keep(const tinygltf::Value& extras, const tinygltf::ExtensionMap& extensions,
              std::initializer_list<const char*> known) {
    return KeptGltf{extrasText(extras), extensionsText(extensions, known)};
}

// Writes kept extras/extensions back; extensions already present (Lit's own) win.
void restore(const KeptGltf& kept, tinygltf::Value& extras, tinygltf::ExtensionMap& extensions) {
    if (!kept.extras.empty()) {
        const nlohmann::json j = nlohmann::json::parse(kept.extras, nullptr, false);
        if (!j.is_discarded()) {
            if (extras.IsObject() && j.is_object()) {  // Lit's own keys (litCastsShadow) stay
                tinygltf::Value::Object merged = extras.Get<tinygltf::Value::Object>();
                for (auto it = j.begin(); it != j.end(); ++it) merged.emplace(it.key(), toValue(it.value()));
                extras = tinygltf::Value(std::move(merged));
            } else {
                extras = toValue(j);
            }
        }
    }
    if (!kept.extensions.empty()) {
        const nlohmann::json j = nlohmann::json::parse(kept.extensions, nullptr, false);
        if (j.is_object())
            for (auto it = j.begin(); it != j.end(); ++it) extensions.emplace(it.key(), toValue(it.value()));
    }
}

// Extras and extensions of a JSON object the parser does not read (sparse accessor parts).
KeptGltf keepFromJson(const nlohmann::json& object) {
    KeptGltf out;
    if (!object.is_object()) return out;
    if (const auto extras = object.find("extras"); extras != object.end()) out.extras = extras->dump();
    if (const auto extensions = object.find("extensions");
        extensions != object.end() && extensions->is_object() && !extensions->empty())
        out.extensions = extensions->dump();
    return out;
}

}  // namespace lit::gltfkeep
