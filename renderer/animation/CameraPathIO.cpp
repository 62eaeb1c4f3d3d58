#include "animation/CameraPathIO.h"

#include "io/AtomicFile.h"
#include "io/GltfFile.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace lit {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

// ---------------------------------------------------------------------------------------------
// JSON

// The shortest decimal that reads back as the same float, as a double: 0.69f is written "0.69",
// not "0.6899999976158142".
double shortestDecimal(float value) {
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    double result = value;
    if (ec == std::errc()) std::from_chars(text, end, result);
    return result;
}

// 6 significant digits, no trailing zeros: "0.05", "3", "1e+39".
std::string number(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

std::string brief(const Json& value) {
    std::string text = value.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return text;
}

OrderedJson pathToJsonValue(const CameraPath& path) {
    OrderedJson root;
    root["version"] = kCameraPathVersion;
    root["loop"] = path.options().loop;
    root["constantSpeed"] = path.options().constantSpeed;
    root["easeInOut"] = path.options().easeInOut;
    OrderedJson keys = OrderedJson::array();
    for (const CameraKey& key : path.keys()) {
        const glm::quat& q = key.rotation;
        keys.push_back(
            {{"time", shortestDecimal(key.time)},
             {"position",
              {shortestDecimal(key.position.x), shortestDecimal(key.position.y), shortestDecimal(key.position.z)}},
             {"rotation", {shortestDecimal(q.x), shortestDecimal(q.y), shortestDecimal(q.z), shortestDecimal(q.w)}},
             {"yfov", shortestDecimal(key.yfov)}});
    }
    root["keys"] = std::move(keys);
    return root;
}

void rejectUnknownFields(const Json& object, std::initializer_list<const char*> known, const std::string& prefix) {
    for (const auto& item : object.items()) {
        const bool isKnown = std::any_of(known.begin(), known.end(), [&](const char* k) { return item.key() == k; });
        if (!isKnown) throw CameraPathError(prefix + "unknown field '" + item.key() + "'");
    }
}

const Json& requireField(const Json& object, const char* name, const std::string& prefix) {
    const auto it = object.find(name);
    if (it == object.end()) throw CameraPathError(prefix + "missing field '" + name + "'");
    return *it;
}

float readNumber(const Json& value, const std::string& what, const std::string& prefix) {
    if (!value.is_number()) throw CameraPathError(prefix + what + " must be a number, got " + brief(value));
    const double number = value.get<double>();
    if (!std::isfinite(number)) throw CameraPathError(prefix + what + " is not a finite number");
    if (std::abs(number) > FLT_MAX) throw CameraPathError(prefix + what + " is too large for a float: " + brief(value));
    return static_cast<float>(number);
}

template <int N>
glm::vec<N, float> readVector(const Json& value, const char* name, const std::string& prefix) {
    if (!value.is_array() || value.size() != N ||
        !std::all_of(value.begin(), value.end(), [](const Json& v) { return v.is_number(); }))
        throw CameraPathError(prefix + "'" + name + "' must be an array of " + std::to_string(N) + " numbers, got " +
                              brief(value));
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i) {
        const double number = value[static_cast<std::size_t>(i)].get<double>();
        if (!std::isfinite(number)) throw CameraPathError(prefix + name + " has a value that is not a finite number");
        if (std::abs(number) > FLT_MAX)
            throw CameraPathError(prefix + name +
                                  " has a value too large for a float: " + brief(value[static_cast<std::size_t>(i)]));
        out[i] = static_cast<float>(number);
    }
    return out;
}

CameraPath pathFromJsonValue(const Json& root) {
    if (!root.is_object()) throw CameraPathError("not a camera path: the JSON is not an object");
    rejectUnknownFields(root, {"version", "loop", "constantSpeed", "easeInOut", "keys"}, "");
    const Json& version = requireField(root, "version", "");
    if (!version.is_number_integer()) throw CameraPathError("'version' must be an integer, got " + brief(version));
    if (version.get<long long>() != kCameraPathVersion)
        throw CameraPathError("unknown version " + version.dump() + " (this build of Lit reads version " +
                              std::to_string(kCameraPathVersion) + ")");

    CameraPathOptions options;
    const auto readFlag = [&](const char* name, bool& flag) {
        const auto it = root.find(name);
        if (it == root.end()) return;
        if (!it->is_boolean())
            throw CameraPathError(std::string("'") + name + "' must be true or false, got " + brief(*it));
        flag = it->get<bool>();
    };
    readFlag("loop", options.loop);
    readFlag("constantSpeed", options.constantSpeed);
    readFlag("easeInOut", options.easeInOut);

    const Json& keysJson = requireField(root, "keys", "");
    if (!keysJson.is_array()) throw CameraPathError("'keys' must be an array, got " + brief(keysJson));
    std::vector<CameraKey> keys;
    keys.reserve(keysJson.size());
    for (std::size_t i = 0; i < keysJson.size(); ++i) {
        const std::string prefix = "key " + std::to_string(i) + ": ";
        const Json& k = keysJson[i];
        if (!k.is_object()) throw CameraPathError(prefix + "must be an object, got " + brief(k));
        rejectUnknownFields(k, {"time", "position", "rotation", "yfov"}, prefix);
        CameraKey key;
        key.time = readNumber(requireField(k, "time", prefix), "'time'", prefix);
        key.position = readVector<3>(requireField(k, "position", prefix), "position", prefix);
        const glm::vec4 q = readVector<4>(requireField(k, "rotation", prefix), "rotation", prefix);
        key.rotation = glm::quat(q.w, q.x, q.y, q.z);  // the file is in glTF order: x, y, z, w
        key.yfov = readNumber(requireField(k, "yfov", prefix), "'yfov'", prefix);
        keys.push_back(key);
    }
    return CameraPath(std::move(keys), options);  // validates order, quaternion lengths, fov range
}

std::string readTextFile(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw CameraPathError(file.string() + ": no such file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw CameraPathError(file.string() + ": cannot open the file for reading");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw CameraPathError(file.string() + ": cannot read the file");
    return text.str();
}

// ---------------------------------------------------------------------------------------------
// tinygltf values ↔ JSON

Json toJson(const tinygltf::Value& value) {
    if (value.IsBool()) return value.Get<bool>();
    if (value.IsInt()) return value.Get<int>();
    if (value.IsReal()) return value.Get<double>();
    if (value.IsString()) return value.Get<std::string>();
    if (value.IsArray()) {
        Json array = Json::array();
        for (std::size_t i = 0; i < value.ArrayLen(); ++i) array.push_back(toJson(value.Get(static_cast<int>(i))));
        return array;
    }
    if (value.IsObject()) {
        Json object = Json::object();
        for (const std::string& key : value.Keys()) object[key] = toJson(value.Get(key));
        return object;
    }
    return nullptr;
}

tinygltf::Value toValue(const OrderedJson& json) {
    if (json.is_boolean()) return tinygltf::Value(json.get<bool>());
    if (json.is_number_integer()) {
        const long long n = json.get<long long>();
        if (n >= INT32_MIN && n <= INT32_MAX) return tinygltf::Value(static_cast<int>(n));
        return tinygltf::Value(static_cast<double>(n));
    }
    if (json.is_number()) return tinygltf::Value(json.get<double>());
    if (json.is_string()) return tinygltf::Value(json.get<std::string>());
    if (json.is_array()) {
        tinygltf::Value::Array array;
        for (const OrderedJson& item : json) array.push_back(toValue(item));
        return tinygltf::Value(std::move(array));
    }
    if (json.is_object()) {
        tinygltf::Value::Object object;
        for (const auto& item : json.items()) object[item.key()] = toValue(item.value());
        return tinygltf::Value(std::move(object));
    }
    return tinygltf::Value();
}

// ---------------------------------------------------------------------------------------------
// glTF nodes

std::string inQuotes(const std::string& name) { return "'" + name + "'"; }

glm::dmat4 localMatrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glTF
    glm::dvec3 t(0.0), s(1.0);
    glm::dquat r(1.0, 0.0, 0.0, 0.0);
    if (node.translation.size() == 3) t = glm::make_vec3(node.translation.data());
    if (node.rotation.size() == 4)
        r = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    if (node.scale.size() == 3) s = glm::make_vec3(node.scale.data());
    return glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(glm::normalize(r)) * glm::scale(glm::dmat4(1.0), s);
}

// World matrix of the parent of `node` (identity for a root). The node hierarchy is assumed to be
// still: a path animates the camera node only.
glm::dmat4 parentWorld(const tinygltf::Model& model, int node) {
    std::vector<int> parent(model.nodes.size(), -1);
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        for (const int child : model.nodes[i].children)
            if (child >= 0 && static_cast<std::size_t>(child) < parent.size())
                parent[static_cast<std::size_t>(child)] = static_cast<int>(i);
    glm::dmat4 world(1.0);
    int current = parent[static_cast<std::size_t>(node)];
    for (std::size_t steps = 0; current >= 0; ++steps) {
        if (steps > model.nodes.size())
            throw CameraPathError("the node hierarchy has a cycle above node " + std::to_string(node));
        world = localMatrix(model.nodes[static_cast<std::size_t>(current)]) * world;
        current = parent[static_cast<std::size_t>(current)];
    }
    return world;
}

// Rotation and translation of a rigid-ish matrix (scale removed from the columns).
void splitRigid(const glm::dmat4& m, glm::dvec3& translation, glm::dquat& rotation) {
    translation = glm::dvec3(m[3]);
    glm::dmat3 r(m);
    for (int c = 0; c < 3; ++c) {
        const double length = glm::length(r[c]);
        if (length > 0.0) r[c] /= length;
    }
    rotation = glm::normalize(glm::quat_cast(r));
}

bool holdsCamera(const tinygltf::Model& model, int node) {
    return node >= 0 && static_cast<std::size_t>(node) < model.nodes.size() &&
           model.nodes[static_cast<std::size_t>(node)].camera >= 0 &&
           static_cast<std::size_t>(model.nodes[static_cast<std::size_t>(node)].camera) < model.cameras.size();
}

int findAnimation(const tinygltf::Model& model, const std::string& name) {
    for (std::size_t i = 0; i < model.animations.size(); ++i)
        if (model.animations[i].name == name) return static_cast<int>(i);
    return -1;
}

bool hasLitExtras(const tinygltf::Animation& animation) {
    return animation.extras.IsObject() && animation.extras.Has(kCameraPathExtrasKey);
}

// The first node holding a camera that a translation or rotation channel of `animation` targets.
int animatedCameraNode(const tinygltf::Model& model, const tinygltf::Animation& animation) {
    for (const tinygltf::AnimationChannel& channel : animation.channels)
        if ((channel.target_path == "translation" || channel.target_path == "rotation") &&
            holdsCamera(model, channel.target_node))
            return channel.target_node;
    return -1;
}

std::string listCameraAnimations(const tinygltf::Model& model) {
    const std::vector<std::string> names = cameraAnimationNames(model);
    if (names.empty()) return "the file has no camera animations";
    std::string text = "its camera animations are:";
    for (std::size_t i = 0; i < names.size(); ++i) text += (i ? ", " : " ") + inQuotes(names[i]);
    return text;
}

// ---------------------------------------------------------------------------------------------
// Writing an animation

// Accessors, buffer views and the buffer of an animation Lit wrote, when nothing else uses them.
struct Slots {
    int timeAccessor = -1, translationAccessor = -1, rotationAccessor = -1;
    int timeView = -1, translationView = -1, rotationView = -1;
    int buffer = -1;
};

std::optional<Slots> reusableSlots(const tinygltf::Model& model, int animationIndex) {
    const tinygltf::Animation& animation = model.animations[static_cast<std::size_t>(animationIndex)];
    if (!hasLitExtras(animation) || animation.samplers.size() != 2 || animation.channels.size() != 2)
        return std::nullopt;
    Slots s;
    s.timeAccessor = animation.samplers[0].input;
    if (animation.samplers[1].input != s.timeAccessor) return std::nullopt;
    for (const tinygltf::AnimationChannel& channel : animation.channels) {
        if (channel.sampler < 0 || channel.sampler > 1) return std::nullopt;
        const int output = animation.samplers[static_cast<std::size_t>(channel.sampler)].output;
        if (channel.target_path == "translation")
            s.translationAccessor = output;
        else if (channel.target_path == "rotation")
            s.rotationAccessor = output;
    }
    const std::set<int> accessors = {s.timeAccessor, s.translationAccessor, s.rotationAccessor};
    if (accessors.size() != 3) return std::nullopt;
    std::vector<int> views;
    for (const int a : {s.timeAccessor, s.translationAccessor, s.rotationAccessor}) {
        if (a < 0 || static_cast<std::size_t>(a) >= model.accessors.size()) return std::nullopt;
        const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(a)];
        if (accessor.sparse.isSparse || accessor.bufferView < 0 ||
            static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size())
            return std::nullopt;
        views.push_back(accessor.bufferView);
    }
    s.timeView = views[0];
    s.translationView = views[1];
    s.rotationView = views[2];
    if (std::set<int>(views.begin(), views.end()).size() != 3) return std::nullopt;
    s.buffer = model.bufferViews[static_cast<std::size_t>(s.timeView)].buffer;
    for (const int v : views)
        if (model.bufferViews[static_cast<std::size_t>(v)].buffer != s.buffer) return std::nullopt;
    if (s.buffer < 0 || static_cast<std::size_t>(s.buffer) >= model.buffers.size()) return std::nullopt;

    // Nothing else may refer to them.
    const auto ownAccessor = [&](int a) { return accessors.count(a) > 0; };
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& primitive : mesh.primitives) {
            if (ownAccessor(primitive.indices)) return std::nullopt;
            for (const auto& [semantic, a] : primitive.attributes)
                if (ownAccessor(a)) return std::nullopt;
            for (const auto& target : primitive.targets)
                for (const auto& [semantic, a] : target)
                    if (ownAccessor(a)) return std::nullopt;
        }
    for (const tinygltf::Skin& skin : model.skins)
        if (ownAccessor(skin.inverseBindMatrices)) return std::nullopt;
    for (std::size_t i = 0; i < model.animations.size(); ++i) {
        if (static_cast<int>(i) == animationIndex) continue;
        for (const tinygltf::AnimationSampler& sampler : model.animations[i].samplers)
            if (ownAccessor(sampler.input) || ownAccessor(sampler.output)) return std::nullopt;
    }
    const std::set<int> ownViews(views.begin(), views.end());
    for (std::size_t a = 0; a < model.accessors.size(); ++a) {
        const tinygltf::Accessor& accessor = model.accessors[a];
        if (!ownAccessor(static_cast<int>(a)) && ownViews.count(accessor.bufferView)) return std::nullopt;
        if (accessor.sparse.isSparse &&
            (ownViews.count(accessor.sparse.indices.bufferView) || ownViews.count(accessor.sparse.values.bufferView)))
            return std::nullopt;
    }
    for (const tinygltf::Image& image : model.images)
        if (ownViews.count(image.bufferView)) return std::nullopt;
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v)
        if (!ownViews.count(static_cast<int>(v)) && model.bufferViews[v].buffer == s.buffer) return std::nullopt;
    return s;
}

template <typename T>
void appendBytes(std::vector<unsigned char>& bytes, const std::vector<T>& values) {
    const std::size_t offset = bytes.size();
    bytes.resize(offset + values.size() * sizeof(T));
    if (!values.empty()) std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
}

// The camera node the animation will target (creating a camera when the scene has none).
int chooseCameraNode(tinygltf::Model& model, const CameraPath& path, const std::string& name, int existing,
                     int cameraNode) {
    if (cameraNode >= 0) {
        if (static_cast<std::size_t>(cameraNode) >= model.nodes.size())
            throw CameraPathError("node " + std::to_string(cameraNode) + " does not exist (the file has " +
                                  std::to_string(model.nodes.size()) + " nodes)");
        if (!holdsCamera(model, cameraNode))
            throw CameraPathError("node " + std::to_string(cameraNode) + " " +
                                  inQuotes(model.nodes[static_cast<std::size_t>(cameraNode)].name) +
                                  " holds no camera");
        return cameraNode;
    }
    if (existing >= 0) {
        const int node = animatedCameraNode(model, model.animations[static_cast<std::size_t>(existing)]);
        if (node >= 0) return node;
    }
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        if (holdsCamera(model, static_cast<int>(i))) return static_cast<int>(i);

    // No camera at all: add one, posed at the path's start, to the default scene.
    const CameraPose start = *path.evaluate(path.startTime());
    tinygltf::Camera camera;
    camera.type = "perspective";
    camera.name = name;
    camera.perspective.yfov = start.yfov;
    camera.perspective.znear = 0.05;       // metres, as Lit's default camera
    camera.perspective.zfar = 1000.0;      // metres; glTF's "infinite" (no zfar) is not writable by tinygltf 2.7
    camera.perspective.aspectRatio = 0.0;  // left out: the output's aspect
    model.cameras.push_back(camera);
    tinygltf::Node node;
    node.name = name;
    node.camera = static_cast<int>(model.cameras.size()) - 1;
    node.translation = {start.position.x, start.position.y, start.position.z};
    node.rotation = {start.rotation.x, start.rotation.y, start.rotation.z, start.rotation.w};
    model.nodes.push_back(node);
    const int nodeIndex = static_cast<int>(model.nodes.size()) - 1;
    if (model.scenes.empty()) {
        model.scenes.emplace_back();
        model.defaultScene = 0;
    }
    const std::size_t scene =
        model.defaultScene >= 0 && static_cast<std::size_t>(model.defaultScene) < model.scenes.size()
            ? static_cast<std::size_t>(model.defaultScene)
            : 0;
    model.scenes[scene].nodes.push_back(nodeIndex);
    return nodeIndex;
}

// ---------------------------------------------------------------------------------------------
// Reading an animation from its channels

std::vector<float> readFloats(const tinygltf::Model& model, int index, int components, const std::string& what) {
    const std::string name = what + ": accessor " + std::to_string(index);
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        throw CameraPathError(name + " does not exist");
    const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
    if (accessor.sparse.isSparse) throw CameraPathError(name + " is sparse, which camera paths do not read");
    if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        throw CameraPathError(name + " has component type " + std::to_string(accessor.componentType) +
                              "; camera paths read FLOAT (5126)");
    if (tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)) != components)
        throw CameraPathError(
            name + " has " +
            std::to_string(tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type))) +
            " components per element, expected " + std::to_string(components));
    if (accessor.count == 0) throw CameraPathError(name + " is empty");
    if (accessor.bufferView < 0 || static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size())
        throw CameraPathError(name + " has no valid buffer view");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        throw CameraPathError(name + ": buffer view " + std::to_string(accessor.bufferView) + " has no valid buffer");
    const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t element = sizeof(float) * static_cast<std::size_t>(components);
    const std::size_t stride = view.byteStride > 0 ? view.byteStride : element;
    // Written to avoid overflow: the last element must end inside the view, the view inside the buffer.
    const std::size_t viewLength = view.byteLength;
    if (stride < element || view.byteOffset > data.size() || viewLength > data.size() - view.byteOffset ||
        accessor.byteOffset > viewLength || element > viewLength - accessor.byteOffset ||
        accessor.count - 1 > (viewLength - accessor.byteOffset - element) / stride)
        throw CameraPathError(name + " reads past the end of its buffer view or buffer");
    std::vector<float> out(accessor.count * static_cast<std::size_t>(components));
    const unsigned char* base = data.data() + view.byteOffset + accessor.byteOffset;
    for (std::size_t i = 0; i < accessor.count; ++i)
        std::memcpy(out.data() + i * static_cast<std::size_t>(components), base + i * stride, element);
    return out;
}

// One animation channel's sampler, read and checked, evaluable at any time.
class ChannelSampler {
public:
    ChannelSampler(const tinygltf::Model& model, const tinygltf::Animation& animation, int samplerIndex, bool rotation,
                   const std::string& label)
        : rotation_(rotation) {
        const std::string what = label + ": sampler " + std::to_string(samplerIndex);
        if (samplerIndex < 0 || static_cast<std::size_t>(samplerIndex) >= animation.samplers.size())
            throw CameraPathError(what + " does not exist");
        const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<std::size_t>(samplerIndex)];
        interpolation_ = sampler.interpolation.empty() ? "LINEAR" : sampler.interpolation;
        if (interpolation_ != "LINEAR" && interpolation_ != "STEP" && interpolation_ != "CUBICSPLINE")
            throw CameraPathError(what + ": interpolation '" + interpolation_ + "' is not LINEAR, STEP or CUBICSPLINE");
        times_ = readFloats(model, sampler.input, 1, what + " input");
        components_ = rotation ? 4 : 3;
        values_ = readFloats(model, sampler.output, components_, what + " output");
        for (std::size_t i = 0; i < times_.size(); ++i) {
            if (!std::isfinite(times_[i]))
                throw CameraPathError(what + ": keyframe time " + std::to_string(i) + " is not a finite number");
            if (i > 0 && !(times_[i] > times_[i - 1]))
                throw CameraPathError(what + ": keyframe time " + std::to_string(i) + " (" + number(times_[i]) +
                                      " s) is not after keyframe " + std::to_string(i - 1) + " (" +
                                      number(times_[i - 1]) + " s)");
        }
        const std::size_t perKey = interpolation_ == "CUBICSPLINE" ? 3 : 1;
        if (values_.size() != times_.size() * perKey * static_cast<std::size_t>(components_))
            throw CameraPathError(what + ": " + std::to_string(values_.size() / static_cast<std::size_t>(components_)) +
                                  " output values for " + std::to_string(times_.size()) + " keyframes (" +
                                  interpolation_ + " needs " + std::to_string(times_.size() * perKey) + ")");
        for (std::size_t i = 0; i < values_.size(); ++i)
            if (!std::isfinite(values_[i]))
                throw CameraPathError(what + ": output value " +
                                      std::to_string(i / static_cast<std::size_t>(components_)) +
                                      " is not a finite number");
        if (rotation)
            for (std::size_t k = 0; k < times_.size(); ++k) {
                const glm::dvec4 q = value(k);
                const double length = glm::length(q);
                if (std::abs(length - 1.0) > kQuaternionLengthTolerance)
                    throw CameraPathError(what + ": rotation keyframe " + std::to_string(k) +
                                          " is not a unit quaternion (length " + number(length) + ")");
            }
    }

    const std::vector<float>& times() const { return times_; }

    // Translation (xyz) or rotation (xyzw) at time t, the way the glTF spec interpolates it.
    glm::dvec4 at(double t) const {
        if (t <= times_.front()) return value(0);
        if (t >= times_.back()) return value(times_.size() - 1);
        const std::size_t k =
            static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), static_cast<float>(t)) -
                                     times_.begin()) -
            1;
        const double t0 = times_[k], t1 = times_[std::min(k + 1, times_.size() - 1)];
        if (k + 1 >= times_.size() || interpolation_ == "STEP") return value(k);
        const double dt = t1 - t0;
        const double s = std::clamp((t - t0) / dt, 0.0, 1.0);
        if (interpolation_ == "CUBICSPLINE") {
            const double s2 = s * s, s3 = s2 * s;
            const glm::dvec4 out = (2 * s3 - 3 * s2 + 1) * value(k) + (s3 - 2 * s2 + s) * dt * tangent(k, 2) +
                                   (-2 * s3 + 3 * s2) * value(k + 1) + (s3 - s2) * dt * tangent(k + 1, 0);
            return rotation_ ? glm::normalize(out) : out;
        }
        if (!rotation_) return glm::mix(value(k), value(k + 1), s);
        const glm::dvec4 a = value(k), b = value(k + 1);
        const glm::dquat q = glm::slerp(glm::dquat(a.w, a.x, a.y, a.z), glm::dquat(b.w, b.x, b.y, b.z), s);
        return {q.x, q.y, q.z, q.w};
    }

private:
    // Keyframe k's value; with CUBICSPLINE the elements are (in-tangent, value, out-tangent).
    glm::dvec4 element(std::size_t index) const {
        glm::dvec4 v(0.0);
        for (int c = 0; c < components_; ++c)
            v[c] = values_[index * static_cast<std::size_t>(components_) + static_cast<std::size_t>(c)];
        return v;
    }
    glm::dvec4 value(std::size_t k) const { return element(interpolation_ == "CUBICSPLINE" ? 3 * k + 1 : k); }
    glm::dvec4 tangent(std::size_t k, std::size_t which) const { return element(3 * k + which); }

    bool rotation_;
    int components_ = 3;
    std::string interpolation_;
    std::vector<float> times_;
    std::vector<float> values_;
};

CameraPath pathFromChannels(const tinygltf::Model& model, const tinygltf::Animation& animation,
                            const std::string& label) {
    const int node = animatedCameraNode(model, animation);
    if (node < 0)
        throw CameraPathError(label +
                              " does not animate a camera: no translation or rotation channel targets a node "
                              "with a camera");
    std::optional<ChannelSampler> translation, rotation;
    for (const tinygltf::AnimationChannel& channel : animation.channels) {
        if (channel.target_node != node) continue;
        if (channel.target_path == "translation" && !translation)
            translation.emplace(model, animation, channel.sampler, false, label);
        else if (channel.target_path == "rotation" && !rotation)
            rotation.emplace(model, animation, channel.sampler, true, label);
    }

    // One key at every keyframe time of either channel (times closer than 1 µs are one key).
    std::vector<double> times;
    if (translation) times.insert(times.end(), translation->times().begin(), translation->times().end());
    if (rotation) times.insert(times.end(), rotation->times().begin(), rotation->times().end());
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end(), [](double a, double b) { return b - a < 1e-6; }), times.end());

    const tinygltf::Node& cameraNode = model.nodes[static_cast<std::size_t>(node)];
    const tinygltf::Camera& camera = model.cameras[static_cast<std::size_t>(cameraNode.camera)];
    if (camera.type != "perspective")
        throw CameraPathError(label + ": camera " + std::to_string(cameraNode.camera) + " " + inQuotes(camera.name) +
                              " is " + camera.type + "; camera paths need a perspective camera");
    const glm::dmat4 parent = parentWorld(model, node);
    glm::dvec3 restTranslation;
    glm::dquat restRotation;
    splitRigid(localMatrix(cameraNode), restTranslation, restRotation);

    std::vector<CameraKey> keys;
    for (const double t : times) {
        const glm::dvec3 localTranslation = translation ? glm::dvec3(translation->at(t)) : restTranslation;
        glm::dquat localRotation = restRotation;
        if (rotation) {
            const glm::dvec4 q = rotation->at(t);
            localRotation = glm::normalize(glm::dquat(q.w, q.x, q.y, q.z));
        }
        const glm::dmat4 world =
            parent * glm::translate(glm::dmat4(1.0), localTranslation) * glm::mat4_cast(localRotation);
        glm::dvec3 position;
        glm::dquat orientation;
        splitRigid(world, position, orientation);
        keys.push_back({static_cast<float>(t), glm::vec3(position), glm::quat(orientation),
                        static_cast<float>(camera.perspective.yfov)});
    }
    try {
        return CameraPath(std::move(keys));
    } catch (const CameraPathError& e) {
        throw CameraPathError(label + ": " + e.what());
    }
}

// ---------------------------------------------------------------------------------------------
// Files

bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    // Images are written back as they came. Only embedded (data URI) ones need their bytes, to
    // embed them again; buffer-view images stay in their buffer (and tinygltf 2.7 does not
    // check their bounds before handing over the pointer, so it is not read).
    if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

std::string lowerExtension(const fs::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

struct LoadedModel {
    tinygltf::Model model;
    bool binary = false;
};

LoadedModel loadModel(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw CameraPathError(file.string() + ": no such file");
    LoadedModel loaded;
    loaded.binary = lowerExtension(file) == ".glb";
    tinygltf::TinyGLTF parser;
    parser.SetImageLoader(&keepEncodedImage, nullptr);
    std::string err, warn;
    bool ok = false;
    try {
        ok = loaded.binary ? parser.LoadBinaryFromFile(&loaded.model, &err, &warn, file.string())
                           : parser.LoadASCIIFromFile(&loaded.model, &err, &warn, file.string());
    } catch (const std::exception& e) {
        throw CameraPathError(file.string() + ": cannot load the glTF file: " + e.what());
    }
    if (!ok) {
        while (!err.empty() && std::isspace(static_cast<unsigned char>(err.back()))) err.pop_back();
        throw CameraPathError(file.string() + ": cannot load the glTF file: " + (err.empty() ? "unknown error" : err));
    }
    return loaded;
}

std::string slug(const std::string& name) {
    std::string out;
    for (const unsigned char c : name) {
        if (std::isalnum(c))
            out += static_cast<char>(std::tolower(c));
        else if (!out.empty() && out.back() != '_')
            out += '_';
    }
    while (!out.empty() && out.back() == '_') out.pop_back();
    return out.empty() ? "camera_path" : out;
}

}  // namespace

// ---- JSON ------------------------------------------------------------------------------------

std::string cameraPathToJson(const CameraPath& path) { return pathToJsonValue(path).dump(2) + "\n"; }

CameraPath cameraPathFromJson(std::string_view text) {
    Json root;
    try {
        root = Json::parse(text.begin(), text.end());
    } catch (const Json::exception& e) {
        std::string reason = e.what();
        // "[json.exception.parse_error.101] parse error at line 2, column 5: ..." → from "parse error";
        // numbers beyond double range ("1e999") come as out_of_range.406.
        if (const std::size_t at = reason.find("] "); at != std::string::npos) reason.erase(0, at + 2);
        throw CameraPathError("not valid JSON: " + reason);
    }
    return pathFromJsonValue(root);
}

void saveCameraPathJson(const fs::path& file, const CameraPath& path) {
    try {
        writeFileAtomically(file, cameraPathToJson(path));
    } catch (const std::runtime_error& e) {
        throw CameraPathError(e.what());  // starts with the file name
    }
}

CameraPath loadCameraPathJson(const fs::path& file) {
    const std::string text = readTextFile(file);
    try {
        return cameraPathFromJson(text);
    } catch (const CameraPathError& e) {
        throw CameraPathError(file.string() + ": " + e.what());
    }
}

// ---- glTF, in memory -------------------------------------------------------------------------

void writeCameraPathAnimation(tinygltf::Model& model, const CameraPath& path, const std::string& name, int cameraNode) {
    if (path.empty()) throw CameraPathError("cannot save a camera path with no keys as a glTF animation");
    if (name.empty()) throw CameraPathError("a camera path animation needs a name");
    const int existing = findAnimation(model, name);
    const int node = chooseCameraNode(model, path, name, existing, cameraNode);

    // Animated nodes must use TRS, not a matrix (glTF 2.0, 5.25): convert a matrix once.
    tinygltf::Node& target = model.nodes[static_cast<std::size_t>(node)];
    if (target.matrix.size() == 16) {
        const glm::dmat4 m = glm::make_mat4(target.matrix.data());
        glm::dvec3 t;
        glm::dquat r;
        splitRigid(m, t, r);
        target.translation = {t.x, t.y, t.z};
        target.rotation = {r.x, r.y, r.z, r.w};
        target.scale = {glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])), glm::length(glm::dvec3(m[2]))};
        target.matrix.clear();
    }

    // Sample the path at kGltfSampleRate over [start, end], the end included so a player that
    // loops the animation closes the loop too.
    std::vector<double> times;
    const double start = path.startTime(), end = path.endTime();
    for (std::size_t i = 0;; ++i) {
        const double t = start + static_cast<double>(i) / kGltfSampleRate;
        if (t > end - 1e-6) break;
        times.push_back(t);
    }
    if (times.empty() || end - times.back() > 1e-6) times.push_back(end);

    const glm::dmat4 toParent = glm::inverse(parentWorld(model, node));
    std::vector<float> timeData, translationData, rotationData;
    glm::dquat previous(1.0, 0.0, 0.0, 0.0);
    for (std::size_t i = 0; i < times.size(); ++i) {
        const CameraPose pose = *path.evaluate(times[i]);
        const glm::dmat4 world =
            glm::translate(glm::dmat4(1.0), glm::dvec3(pose.position)) * glm::mat4_cast(glm::dquat(pose.rotation));
        glm::dvec3 t;
        glm::dquat r;
        splitRigid(toParent * world, t, r);
        if (i > 0 && glm::dot(previous, r) < 0.0) r = -r;  // LINEAR slerps between neighbours: keep them close
        previous = r;
        timeData.push_back(static_cast<float>(times[i]));
        translationData.insert(translationData.end(),
                               {static_cast<float>(t.x), static_cast<float>(t.y), static_cast<float>(t.z)});
        rotationData.insert(rotationData.end(), {static_cast<float>(r.x), static_cast<float>(r.y),
                                                 static_cast<float>(r.z), static_cast<float>(r.w)});
    }
    std::vector<unsigned char> bytes;
    appendBytes(bytes, timeData);
    appendBytes(bytes, translationData);
    appendBytes(bytes, rotationData);

    Slots slots;
    if (const std::optional<Slots> reuse = existing >= 0 ? reusableSlots(model, existing) : std::nullopt) {
        slots = *reuse;
    } else {
        model.buffers.emplace_back();
        slots.buffer = static_cast<int>(model.buffers.size()) - 1;
        for (int* view : {&slots.timeView, &slots.translationView, &slots.rotationView}) {
            model.bufferViews.emplace_back();
            *view = static_cast<int>(model.bufferViews.size()) - 1;
        }
        for (int* accessor : {&slots.timeAccessor, &slots.translationAccessor, &slots.rotationAccessor}) {
            model.accessors.emplace_back();
            *accessor = static_cast<int>(model.accessors.size()) - 1;
        }
    }

    tinygltf::Buffer& buffer = model.buffers[static_cast<std::size_t>(slots.buffer)];
    buffer.data = std::move(bytes);
    buffer.name = name;
    const std::size_t counts[3] = {timeData.size(), translationData.size() / 3, rotationData.size() / 4};
    const std::size_t sizes[3] = {timeData.size() * 4, translationData.size() * 4, rotationData.size() * 4};
    const int views[3] = {slots.timeView, slots.translationView, slots.rotationView};
    const int accessors[3] = {slots.timeAccessor, slots.translationAccessor, slots.rotationAccessor};
    const int types[3] = {TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4};
    const char* names[3] = {"time", "translation", "rotation"};
    std::size_t offset = 0;
    for (int i = 0; i < 3; ++i) {
        tinygltf::BufferView view;
        view.name = name + " " + names[i];
        view.buffer = slots.buffer;
        view.byteOffset = offset;
        view.byteLength = sizes[i];
        model.bufferViews[static_cast<std::size_t>(views[i])] = view;
        offset += sizes[i];

        tinygltf::Accessor accessor;
        accessor.name = view.name;
        accessor.bufferView = views[i];
        accessor.byteOffset = 0;
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.type = types[i];
        accessor.count = counts[i];
        if (i == 0) {  // required on animation inputs
            accessor.minValues = {timeData.front()};
            accessor.maxValues = {timeData.back()};
        }
        model.accessors[static_cast<std::size_t>(accessors[i])] = accessor;
    }

    tinygltf::Animation animation;
    animation.name = name;
    for (const int output : {slots.translationAccessor, slots.rotationAccessor}) {
        tinygltf::AnimationSampler sampler;
        sampler.input = slots.timeAccessor;
        sampler.output = output;
        sampler.interpolation = "LINEAR";
        animation.samplers.push_back(sampler);
    }
    for (int i = 0; i < 2; ++i) {
        tinygltf::AnimationChannel channel;
        channel.sampler = i;
        channel.target_node = node;
        channel.target_path = i == 0 ? "translation" : "rotation";
        animation.channels.push_back(channel);
    }
    // Keep whatever else the old animation's extras held; replace the path.
    tinygltf::Value::Object extras;
    if (existing >= 0 && model.animations[static_cast<std::size_t>(existing)].extras.IsObject())
        extras = model.animations[static_cast<std::size_t>(existing)].extras.Get<tinygltf::Value::Object>();
    extras[kCameraPathExtrasKey] = toValue(pathToJsonValue(path));
    animation.extras = tinygltf::Value(std::move(extras));
    if (existing >= 0)
        model.animations[static_cast<std::size_t>(existing)] = std::move(animation);
    else
        model.animations.push_back(std::move(animation));
}

CameraPath readCameraPathAnimation(const tinygltf::Model& model, const std::string& name) {
    const int index = findAnimation(model, name);
    if (index < 0) throw CameraPathError("no animation named " + inQuotes(name) + "; " + listCameraAnimations(model));
    const tinygltf::Animation& animation = model.animations[static_cast<std::size_t>(index)];
    const std::string label = "animation " + inQuotes(name);
    if (hasLitExtras(animation)) {
        try {
            return pathFromJsonValue(toJson(animation.extras.Get(kCameraPathExtrasKey)));
        } catch (const CameraPathError& e) {
            throw CameraPathError(label + ": extras." + kCameraPathExtrasKey + ": " + e.what());
        }
    }
    return pathFromChannels(model, animation, label);
}

std::vector<std::string> cameraAnimationNames(const tinygltf::Model& model) {
    std::vector<std::string> names;
    for (const tinygltf::Animation& animation : model.animations)
        if (!animation.name.empty() && (hasLitExtras(animation) || animatedCameraNode(model, animation) >= 0))
            names.push_back(animation.name);
    return names;
}

// ---- glTF, files -----------------------------------------------------------------------------

void saveCameraPathToGltf(const fs::path& scene, const CameraPath& path, const std::string& name, int cameraNode) {
    LoadedModel loaded = loadModel(scene);
    tinygltf::Model& model = loaded.model;
    const bool allEmbedded =
        !model.buffers.empty() && std::all_of(model.buffers.begin(), model.buffers.end(),
                                              [](const tinygltf::Buffer& b) { return isDataUri(b.uri); });
    try {
        writeCameraPathAnimation(model, path, name, cameraNode);
    } catch (const CameraPathError& e) {
        throw CameraPathError(scene.string() + ": " + e.what());
    }

    // A .glb keeps everything in one file (buffer 0 is its BIN chunk, the rest embedded); an
    // embedded .gltf stays embedded; otherwise buffers live in files next to the scene.
    const bool embedBuffers = loaded.binary || allEmbedded;
    if (!embedBuffers) {
        std::set<std::string> used;
        for (const tinygltf::Buffer& b : model.buffers)
            if (!b.uri.empty()) used.insert(b.uri);
        for (tinygltf::Buffer& b : model.buffers) {
            if (!b.uri.empty() && !isDataUri(b.uri)) continue;
            // Ours (no uri yet) or an embedded buffer in a mixed file: give it a file of its own.
            std::string base = scene.stem().string() + "_" + slug(b.name.empty() ? name : b.name);
            std::string uri = base + ".bin";
            for (int n = 2; used.count(uri); ++n) uri = base + "_" + std::to_string(n) + ".bin";
            used.insert(uri);
            b.uri = uri;
        }
        for (std::size_t i = 0; i < model.buffers.size(); ++i)
            if (!staysInFolder(model.buffers[i].uri))
                throw CameraPathError(scene.string() + ": buffer " + std::to_string(i) + "'s uri '" +
                                      model.buffers[i].uri +
                                      "' points outside the scene's folder; Lit does not rewrite files there");
    }
    for (tinygltf::Image& image : model.images) {
        // Embedded images lost their data URI in tinygltf; put it back.
        if (!image.uri.empty() || image.bufferView >= 0 || image.image.empty()) continue;
        std::string mime = image.mimeType;
        if (mime.empty()) mime = image.image.size() > 3 && image.image[0] == 0x89 ? "image/png" : "image/jpeg";
        image.uri = "data:" + mime + ";base64," + base64Encode(image.image);
    }

    // A .glb's extra buffers and an embedded .gltf's buffers are embedded (no uri): see writeGltfModel.
    if (embedBuffers)
        for (tinygltf::Buffer& b : model.buffers) b.uri.clear();
    try {
        writeGltfModel(std::move(model), scene, loaded.binary);
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        throw CameraPathError(what.starts_with(scene.string() + ": ") ? what : scene.string() + ": " + what);
    }
}

CameraPath loadCameraPathFromGltf(const fs::path& scene, const std::string& name) {
    const LoadedModel loaded = loadModel(scene);
    try {
        return readCameraPathAnimation(loaded.model, name);
    } catch (const CameraPathError& e) {
        throw CameraPathError(scene.string() + ": " + e.what());
    }
}

std::vector<std::string> cameraAnimationNames(const fs::path& scene) {
    return cameraAnimationNames(loadModel(scene).model);
}

}  // namespace lit
