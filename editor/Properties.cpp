#include "Properties.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>

#include "TextParse.h"

namespace lit::editor {

namespace {

constexpr float kDegPerRad = 57.29577951308232f;

// An edit of one property: parses `value` into a copy of the target object so that a bad value
// changes nothing. Returns "" or the message (without the property-name prefix).
class Parser {
public:
    Parser(std::string_view name, std::string_view value) : name_(name), value_(value) {}

    // Exactly `count` numbers (or, with `orCount`, that many instead).
    std::optional<std::vector<float>> numbers(std::size_t count, std::size_t orCount = 0) {
        const auto words = splitWords(value_);
        std::vector<float> values;
        bool ok = words.size() == count || (orCount != 0 && words.size() == orCount);
        for (std::string_view w : words) {
            if (!ok) break;
            const auto v = parseNumber<float>(w);
            if (!v) ok = false;
            else values.push_back(*v);
        }
        if (ok) return values;
        std::string expected = "expected " + std::to_string(count);
        if (orCount != 0) expected += " or " + std::to_string(orCount);
        expected += (count == 1 && orCount == 0) ? " number" : " numbers";
        fail(expected + ", got '" + std::string(trim(value_)) + "'");
        return std::nullopt;
    }
    std::optional<float> number() {
        const auto v = numbers(1);
        return v ? std::optional<float>((*v)[0]) : std::nullopt;
    }
    std::optional<glm::vec3> vec3() {
        const auto v = numbers(3);
        return v ? std::optional<glm::vec3>(glm::vec3((*v)[0], (*v)[1], (*v)[2])) : std::nullopt;
    }
    std::optional<bool> onOff() {
        const std::string_view word = trim(value_);
        if (word == "on") return true;
        if (word == "off") return false;
        fail("expected on or off, got '" + std::string(word) + "'");
        return std::nullopt;
    }
    // Checks a parsed value; `rule` says what is required ("must be in [0, 1]").
    bool require(bool condition, const std::string& rule) {
        if (!condition) fail(rule + ", got '" + std::string(trim(value_)) + "'");
        return condition;
    }
    void fail(const std::string& message) {
        if (error_.empty()) error_ = std::string(name_) + ": " + message;
    }
    std::string_view value() const { return value_; }
    const std::string& error() const { return error_; }

private:
    std::string_view name_;
    std::string_view value_;
    std::string error_;
};

// "11.4592" rather than std::to_string's "11.459156".
std::string degreesText(float radians) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(radians * kDegPerRad));
    return text;
}

bool allIn(const glm::vec3& v, float lo, float hi) {
    return v.x >= lo && v.y >= lo && v.z >= lo && v.x <= hi && v.y <= hi && v.z <= hi;
}

void setNode(Parser& p, std::string_view name, Node& node) {
    if (name == "node.translation") {
        if (auto v = p.vec3()) node.translation = *v;
    } else if (name == "node.rotation") {
        // XYZ Euler: X applied first, then Y, then Z (glm's quat(vec3), which the inspector uses).
        if (auto v = p.vec3()) node.rotation = glm::normalize(glm::quat(*v / kDegPerRad));
    } else if (name == "node.scale") {
        // A zero scale collapses the node and its normals; a negative one mirrors (allowed).
        if (auto v = p.vec3(); v && p.require(v->x != 0.0f && v->y != 0.0f && v->z != 0.0f, "scale must not be 0"))
            node.scale = *v;
    } else if (name == "node.name") {
        const std::string_view text = trim(p.value());
        if (p.require(!text.empty(), "expected a name")) node.name = std::string(text);
    }
}

void setMaterial(Parser& p, std::string_view name, Material& m, int rememberedTexture) {
    if (name == "material.albedo") {
        if (auto v = p.numbers(3, 4); v && p.require(allIn(glm::vec3((*v)[0], (*v)[1], (*v)[2]), 0.0f, 1.0f) &&
                                                         (v->size() == 3 || ((*v)[3] >= 0.0f && (*v)[3] <= 1.0f)),
                                                     "values must be in [0, 1]"))
            m.baseColorFactor = glm::vec4((*v)[0], (*v)[1], (*v)[2], v->size() == 4 ? (*v)[3] : m.baseColorFactor.a);
    } else if (name == "material.albedoTexture") {
        if (auto on = p.onOff()) {
            if (!*on) m.baseColorTexture = -1;
            else if (rememberedTexture < 0) p.fail("material '" + m.name + "' has no albedo texture");
            else m.baseColorTexture = rememberedTexture;
        }
    } else if (name == "material.roughness") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f && *v <= 1.0f, "must be in [0, 1]")) m.roughness = *v;
    } else if (name == "material.metalness") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f && *v <= 1.0f, "must be in [0, 1]")) m.metallic = *v;
    } else if (name == "material.emissive") {
        if (auto v = p.vec3(); v && p.require(allIn(*v, 0.0f, 1.0f), "values must be in [0, 1]")) m.emissiveFactor = *v;
    } else if (name == "material.emissiveStrength") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f, "must not be negative")) m.emissiveStrength = *v;
    } else if (name == "material.ior") {
        if (auto v = p.number(); v && p.require(*v == 0.0f || *v >= 1.0f, "must be at least 1 (or 0, a mirror)"))
            m.ior = *v;
    } else if (name == "material.specular") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f && *v <= 1.0f, "must be in [0, 1]")) m.specularFactor = *v;
    } else if (name == "material.specularTint") {
        if (auto v = p.vec3(); v && p.require(allIn(*v, 0.0f, std::numeric_limits<float>::max()), "values must not be negative"))
            m.specularColorFactor = *v;
    } else if (name == "material.sheen") {
        if (auto v = p.vec3(); v && p.require(allIn(*v, 0.0f, 1.0f), "values must be in [0, 1]")) m.sheenColorFactor = *v;
    } else if (name == "material.sheenRoughness") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f && *v <= 1.0f, "must be in [0, 1]")) m.sheenRoughness = *v;
    } else if (name == "material.clearcoat") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f && *v <= 1.0f, "must be in [0, 1]")) m.clearcoatFactor = *v;
    } else if (name == "material.clearcoatRoughness") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f && *v <= 1.0f, "must be in [0, 1]"))
            m.clearcoatRoughness = *v;
    } else if (name == "material.transmission") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f && *v <= 1.0f, "must be in [0, 1]")) m.transmission = *v;
    } else if (name == "material.thickness") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f, "must not be negative")) m.thickness = *v;
    } else if (name == "material.attenuationDistance") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f, "must not be negative (0: infinite)"))
            m.attenuationDistance = *v;
    } else if (name == "material.attenuationColor") {
        if (auto v = p.vec3(); v && p.require(allIn(*v, 0.0f, 1.0f), "values must be in [0, 1]"))
            m.attenuationColor = *v;
    }
}

void setLight(Parser& p, std::string_view name, Light& l) {
    if (name == "light.type") {
        const std::string_view word = trim(p.value());
        if (word == "directional") l.type = LightType::Directional;
        else if (word == "point") l.type = LightType::Point;
        else if (word == "spot") l.type = LightType::Spot;
        else p.fail("expected directional, point or spot, got '" + std::string(word) + "'");
    } else if (name == "light.color") {
        if (auto v = p.vec3(); v && p.require(allIn(*v, 0.0f, std::numeric_limits<float>::max()), "values must not be negative")) l.color = *v;
    } else if (name == "light.intensity") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f, "must not be negative")) l.intensity = *v;
    } else if (name == "light.range") {
        if (auto v = p.number(); v && p.require(*v >= 0.0f, "must not be negative (0 = infinite)")) l.range = *v;
    } else if (name == "light.inner") {
        // glTF: 0 <= inner < outer <= 90°.
        const std::string rule =
            "must be at least 0 and less than light.outer (" + degreesText(l.outerConeAngle) + "°)";
        if (auto v = p.number(); v && p.require(*v >= 0.0f && *v / kDegPerRad < l.outerConeAngle, rule))
            l.innerConeAngle = *v / kDegPerRad;
    } else if (name == "light.outer") {
        const std::string rule =
            "must be more than light.inner (" + degreesText(l.innerConeAngle) + "°) and at most 90";
        if (auto v = p.number(); v && p.require(*v / kDegPerRad > l.innerConeAngle && *v <= 90.0f, rule))
            l.outerConeAngle = *v / kDegPerRad;
    } else if (name == "light.shadow") {
        if (auto on = p.onOff()) l.castsShadow = *on;
    }
}

void setCamera(Parser& p, std::string_view name, Camera& c) {
    if (name == "camera.fov") {
        if (auto v = p.number(); v && p.require(*v > 0.0f && *v < 180.0f, "must be between 0 and 180 (exclusive)"))
            c.yfov = *v / kDegPerRad;
    } else if (name == "camera.near") {
        if (auto v = p.number(); v && p.require(*v > 0.0f && (c.zfar <= 0.0f || *v < c.zfar),
                                                "must be more than 0 and less than camera.far"))
            c.znear = *v;
    } else if (name == "camera.far") {
        if (auto v = p.number(); v && p.require(*v == 0.0f || *v > c.znear, "must be 0 (fitted) or more than camera.near"))
            c.zfar = *v;
    }
}

bool startsWith(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

bool isPropertyName(std::string_view name) {
    const auto& names = propertyNames();
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

const std::vector<std::string>& propertyNames() {
    static const std::vector<std::string> names{
        "node.translation",
        "node.rotation",
        "node.scale",
        "node.name",
        "material.albedo",
        "material.albedoTexture",
        "material.roughness",
        "material.metalness",
        "material.emissive",
        "material.emissiveStrength",
        "material.ior",
        "material.specular",
        "material.specularTint",
        "material.sheen",
        "material.sheenRoughness",
        "material.clearcoat",
        "material.clearcoatRoughness",
        "material.transmission",
        "material.thickness",
        "material.attenuationDistance",
        "material.attenuationColor",
        "light.type",
        "light.color",
        "light.intensity",
        "light.range",
        "light.inner",
        "light.outer",
        "light.shadow",
        "camera.fov",
        "camera.near",
        "camera.far",
    };
    return names;
}

int findNode(const Scene& scene, std::string_view name) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].name == name) return static_cast<int>(i);
    return -1;
}

std::string checkPropertyValue(std::string_view name, std::string_view value) {
    if (!isPropertyName(name)) return "unknown property '" + std::string(name) + "'";
    // The setters on stand-ins whose current values allow every value a real object might: a
    // spot cone of 0..90° (light.inner/outer), no far plane (camera.near), a near plane at 0
    // (camera.far), and an albedo texture to turn on.
    Parser parser(name, value);
    Node node;
    Material material;
    Light light;
    light.innerConeAngle = 0.0f;
    light.outerConeAngle = 90.0f / kDegPerRad;
    Camera camera;
    camera.znear = 0.0f;
    camera.zfar = 0.0f;
    if (startsWith(name, "node.")) setNode(parser, name, node);
    else if (startsWith(name, "material.")) setMaterial(parser, name, material, 0);
    else if (startsWith(name, "light.")) setLight(parser, name, light);
    else setCamera(parser, name, camera);
    return parser.error();
}

std::string setProperty(Document& doc, std::string_view name, std::string_view value) {
    if (!isPropertyName(name)) return "unknown property '" + std::string(name) + "'";
    Scene& scene = doc.scene;
    if (doc.selectedNode < 0) return "no node is selected";
    if (doc.selectedNode >= static_cast<int>(scene.nodes.size()))
        return "the selected node " + std::to_string(doc.selectedNode) + " does not exist";
    const int nodeIndex = doc.selectedNode;
    const Node& node = scene.nodes[nodeIndex];
    const std::string nodeLabel = "node '" + node.name + "'";
    const std::string label(name);

    Parser parser(name, value);
    if (startsWith(name, "node.")) {
        Node changed = node;
        setNode(parser, name, changed);
        if (!parser.error().empty()) return parser.error();
        // A name is nothing the renderer uses: Change::Camera bumps no revision counter.
        doc.edit(label, name == "node.name" ? Change::Camera : Change::Transform,
                 [&](Scene& s) { s.nodes[nodeIndex] = std::move(changed); });
    } else if (startsWith(name, "material.")) {
        if (node.mesh < 0 || node.mesh >= static_cast<int>(scene.meshes.size())) return nodeLabel + " holds no mesh";
        const Mesh& mesh = scene.meshes[node.mesh];
        // The primitive chosen in the inspector (Document::selectedPrimitive), else the first.
        const std::size_t primitive =
            doc.selectedPrimitive > 0 && doc.selectedPrimitive < static_cast<int>(mesh.primitives.size())
                ? static_cast<std::size_t>(doc.selectedPrimitive)
                : 0;
        const int material = mesh.primitives.empty() ? -1 : mesh.primitives[primitive].material;
        if (material < 0 || material >= static_cast<int>(scene.materials.size()))
            return nodeLabel + " has no material of its own (its mesh uses the default material)";
        Material changed = scene.materials[material];
        setMaterial(parser, name, changed, doc.rememberedAlbedoTexture(material));
        if (!parser.error().empty()) return parser.error();
        doc.edit(label, Change::Material, [&](Scene& s) { s.materials[material] = std::move(changed); });
    } else if (startsWith(name, "light.")) {
        if (node.light < 0 || node.light >= static_cast<int>(scene.lights.size())) return nodeLabel + " holds no light";
        const int light = node.light;
        Light changed = scene.lights[light];
        setLight(parser, name, changed);
        if (!parser.error().empty()) return parser.error();
        doc.edit(label, Change::Light, [&](Scene& s) { s.lights[light] = std::move(changed); });
    } else {
        if (node.camera < 0 || node.camera >= static_cast<int>(scene.cameras.size())) return nodeLabel + " holds no camera";
        const int camera = node.camera;
        Camera changed = scene.cameras[camera];
        setCamera(parser, name, changed);
        if (!parser.error().empty()) return parser.error();
        doc.edit(label, Change::Camera, [&](Scene& s) { s.cameras[camera] = std::move(changed); });
    }
    return "";
}

}  // namespace lit::editor
