// lit_check_saved_scene FILE.gltf CHECK...
// Loads a glTF file the editor saved and checks values in it; the editor's round-trip test uses
// it to find every edit in the file. Each CHECK is NODE.PROPERTY=V[,V...]:
//   translation, scale           the node's (metres / factor)
//   roughness, metalness, albedo  the material of the node's mesh (first primitive); albedo RGB
//   emissive, emissiveStrength
//   light.color, light.intensity, light.range   the light the node holds
//   rotation                     the node's quaternion x, y, z, w
//   worldPosition                the node's world-space origin (metres)
//   holds                        1/0 each: holds a mesh, a light, a camera
//   parent                       the parent node's name, "-" for a root (compared as text)
//   distinctMaterial             NODE.distinctMaterial=1:OTHER (or 0:OTHER): whether the two
//                                nodes' first primitives use different materials
// "*.nodes=N" checks the node count. NODE is the longest node name the check starts with
// followed by a dot, so names may hold dots ("Box.001.translation=...").
// Prints one line per check; exits 0 when all hold, 1 when one does not, 2 on bad usage.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "Log.h"
#include "scene/GltfLoader.h"
#include "scene/Scene.h"

namespace {

// Saved as JSON text: float → decimal → float round-trips exactly with enough digits; this
// allows for a writer that prints fewer (7 significant digits).
constexpr float kTolerance = 1e-5f;

std::vector<float> parseValues(const std::string& text) {
    std::vector<float> values;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        std::size_t used = 0;
        values.push_back(std::stof(item, &used));
        if (used != item.size()) throw std::invalid_argument("'" + item + "' is not a number");
    }
    return values;
}

const lit::Material* materialOf(const lit::Scene& scene, const lit::Node& node) {
    if (node.mesh < 0 || scene.meshes[node.mesh].primitives.empty()) return nullptr;
    const int index = scene.meshes[node.mesh].primitives.front().material;
    return index < 0 ? nullptr : &scene.materials[index];
}

// The actual value of `property`, or an empty vector with `why` set.
std::vector<float> actualValue(const lit::Scene& scene, const lit::Node& node, const std::string& property,
                               std::string& why) {
    const lit::Material* material = materialOf(scene, node);
    const lit::Light* light = node.light >= 0 ? &scene.lights[node.light] : nullptr;
    auto vec3 = [](const glm::vec3& v) { return std::vector<float>{v.x, v.y, v.z}; };
    if (property == "translation") return vec3(node.translation);
    if (property == "rotation") return {node.rotation.x, node.rotation.y, node.rotation.z, node.rotation.w};
    if (property == "worldPosition") return vec3(glm::vec3(node.world[3]));
    if (property == "holds")
        return {node.mesh >= 0 ? 1.0f : 0.0f, node.light >= 0 ? 1.0f : 0.0f, node.camera >= 0 ? 1.0f : 0.0f};
    if (property == "scale") return vec3(node.scale);
    if (property.starts_with("light.")) {
        if (light == nullptr) {
            why = "the node holds no light";
            return {};
        }
        if (property == "light.color") return vec3(light->color);
        if (property == "light.intensity") return {light->intensity};
        if (property == "light.range") return {light->range};
    } else if (property == "roughness" || property == "metalness" || property == "albedo" || property == "emissive" ||
               property == "emissiveStrength") {
        if (material == nullptr) {
            why = "the node has no mesh with a material";
            return {};
        }
        if (property == "roughness") return {material->roughness};
        if (property == "metalness") return {material->metallic};
        if (property == "albedo") return vec3(glm::vec3(material->baseColorFactor));
        if (property == "emissive") return vec3(material->emissiveFactor);
        if (property == "emissiveStrength") return {material->emissiveStrength};
    }
    why = "unknown property '" + property + "'";
    return {};
}

std::string join(const std::vector<float>& values) {
    // Appended piece by piece: `"," + std::to_string(v)` (operator+ on a temporary) made GCC 12 at
    // -O3 report a false -Wrestrict, an error in a -Werror Release build.
    std::string text;
    for (const float v : values) {
        if (!text.empty()) text += ',';
        text += std::to_string(v);
    }
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: lit_check_saved_scene FILE.gltf NODE.PROPERTY=V[,V...]...\n");
        return 2;
    }
    lit::Log log;
    lit::Scene scene;
    try {
        scene = lit::loadGltf(argv[1], log);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "lit_check_saved_scene: cannot load %s: %s\n", argv[1], error.what());
        return 1;
    }
    bool allHold = true;
    for (int i = 2; i < argc; ++i) {
        const std::string check = argv[i];
        const std::size_t equals = check.rfind('=');
        // The node: the longest name followed by a dot that the check starts with.
        const lit::Node* node = nullptr;
        for (const lit::Node& candidate : scene.nodes)
            if (check.size() > candidate.name.size() && check.compare(0, candidate.name.size(), candidate.name) == 0 &&
                check[candidate.name.size()] == '.' && (node == nullptr || candidate.name.size() > node->name.size()))
                node = &candidate;
        const std::size_t dot = node != nullptr ? node->name.size() : check.find('.');
        if (dot == std::string::npos || equals == std::string::npos || equals < dot) {
            std::fprintf(stderr, "lit_check_saved_scene: '%s' is not NODE.PROPERTY=VALUES\n", check.c_str());
            return 2;
        }
        const std::string nodeName = check.substr(0, dot);
        const std::string property = check.substr(dot + 1, equals - dot - 1);
        const std::string value = check.substr(equals + 1);
        // Text-valued checks.
        if (property == "parent" || property == "distinctMaterial" || (nodeName == "*" && property == "nodes")) {
            std::string found;
            if (nodeName == "*") {
                found = std::to_string(scene.nodes.size());
            } else if (node == nullptr) {
                found = "(no node called '" + nodeName + "')";
            } else if (property == "parent") {
                found = node->parent < 0 ? "-" : scene.nodes[static_cast<std::size_t>(node->parent)].name;
            } else {
                const lit::Node* other = nullptr;
                for (const lit::Node& candidate : scene.nodes)
                    if (candidate.name == value.substr(value.find(':') == std::string::npos ? 0 : value.find(':') + 1))
                        other = &candidate;
                found = other == nullptr ? "(no such node)" : materialOf(scene, *node) != materialOf(scene, *other) ? "1" : "0";
            }
            const std::string wanted = property == "distinctMaterial" ? value.substr(0, value.find(':')) : value;
            const bool holds = found == wanted;
            std::printf("%s %s%s%s\n", holds ? "ok  " : "FAIL", check.c_str(), holds ? "" : ": found ", holds ? "" : found.c_str());
            allHold &= holds;
            continue;
        }
        std::vector<float> expected;
        try {
            expected = parseValues(value);
        } catch (const std::exception&) {
            std::fprintf(stderr, "lit_check_saved_scene: '%s': the values are not numbers\n", check.c_str());
            return 2;
        }
        std::string why;
        std::vector<float> actual;
        if (node == nullptr)
            why = "no node called '" + nodeName + "'";
        else
            actual = actualValue(scene, *node, property, why);
        bool holds = why.empty() && actual.size() == expected.size();
        for (std::size_t c = 0; holds && c < actual.size(); ++c)
            holds = std::fabs(actual[c] - expected[c]) <= kTolerance * std::max(1.0f, std::fabs(expected[c]));
        if (why.empty() && !holds) why = "found " + join(actual);
        std::printf("%s %s%s%s\n", holds ? "ok  " : "FAIL", check.c_str(), why.empty() ? "" : ": ", why.c_str());
        allHold &= holds;
    }
    return allHold ? 0 : 1;
}
