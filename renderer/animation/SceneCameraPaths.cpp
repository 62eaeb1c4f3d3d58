#include "animation/SceneCameraPaths.h"

#include "animation/CameraPathIO.h"
#include "scene/GltfKeep.h"
#include "scene/Scene.h"

#include <tiny_gltf.h>

#include <cstring>

namespace lit {

namespace {

// A tinygltf model with what CameraPathIO reads of an animation: the node tree with poses and
// cameras, and the animation itself with its data in one buffer.
tinygltf::Model modelForAnimation(const Scene& scene, const Animation& animation) {
    tinygltf::Model model;
    for (const Camera& camera : scene.cameras) {
        tinygltf::Camera out;
        out.type = "perspective";
        out.name = camera.name;
        out.perspective.yfov = camera.yfov;
        out.perspective.znear = camera.znear;
        model.cameras.push_back(out);
    }
    for (const Node& node : scene.nodes) {
        tinygltf::Node out;
        out.name = node.name;
        out.children = node.children;
        out.camera = node.camera;
        out.translation = {node.translation.x, node.translation.y, node.translation.z};
        out.rotation = {node.rotation.x, node.rotation.y, node.rotation.z, node.rotation.w};
        out.scale = {node.scale.x, node.scale.y, node.scale.z};
        model.nodes.push_back(out);
    }
    tinygltf::Scene root;
    root.nodes = scene.roots;
    model.scenes.push_back(root);
    model.defaultScene = 0;

    model.buffers.emplace_back();
    std::vector<unsigned char>& bytes = model.buffers[0].data;
    const auto addFloats = [&](const std::vector<float>& values, int type, std::size_t count) {
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = bytes.size();
        view.byteLength = values.size() * sizeof(float);
        bytes.resize(bytes.size() + view.byteLength);
        if (!values.empty()) std::memcpy(bytes.data() + view.byteOffset, values.data(), view.byteLength);
        model.bufferViews.push_back(view);
        tinygltf::Accessor accessor;
        accessor.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.type = type;
        accessor.count = count;
        model.accessors.push_back(accessor);
        return static_cast<int>(model.accessors.size()) - 1;
    };
    tinygltf::Animation out;
    out.name = animation.name;
    for (const Animation::Sampler& sampler : animation.samplers) {
        const int types[] = {0, TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC2, TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4};
        const int components = sampler.components >= 1 && sampler.components <= 4 ? sampler.components : 1;
        tinygltf::AnimationSampler s;
        s.input = addFloats(sampler.input, TINYGLTF_TYPE_SCALAR, sampler.input.size());
        s.output = addFloats(sampler.output, types[components], sampler.output.size() / static_cast<std::size_t>(components));
        s.interpolation = sampler.interpolation;
        out.samplers.push_back(s);
    }
    for (const Animation::Channel& channel : animation.channels) {
        tinygltf::AnimationChannel c;
        c.sampler = channel.sampler;
        c.target_node = channel.node;
        c.target_path = channel.path;
        out.channels.push_back(c);
    }
    tinygltf::ExtensionMap noExtensions;
    gltfkeep::restore(KeptGltf{animation.kept.extras, ""}, out.extras, noExtensions);
    model.animations.push_back(out);
    return model;
}

}  // namespace

CameraPath loadCameraPath(const Scene& scene, const std::string& name) {
    for (const Animation& animation : scene.animations)
        if (animation.name == name) return readCameraPathAnimation(modelForAnimation(scene, animation), name);
    std::string message = "no camera animation named '" + name + "'; ";
    if (scene.cameraAnimationNames.empty()) throw CameraPathError(message + "the scene has none");
    message += "the scene's camera animations are:";
    for (std::size_t i = 0; i < scene.cameraAnimationNames.size(); ++i)
        message += (i ? ", '" : " '") + scene.cameraAnimationNames[i] + "'";
    throw CameraPathError(message);
}

}  // namespace lit
