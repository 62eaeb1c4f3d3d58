#include "animation/NodeAnimation.h"

#include "animation/AnimationSampler.h"
#include "scene/Scene.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace lit {

namespace {

enum class Target { Translation, Rotation, Scale };

std::optional<Target> targetOf(const std::string& path) {
    if (path == "translation") return Target::Translation;
    if (path == "rotation") return Target::Rotation;
    if (path == "scale") return Target::Scale;
    return std::nullopt;
}

// A channel that can be played, with its sampler ready; or the reason it cannot ("" when it is
// not a node-transform channel at all: weights, camera nodes, kept nodes).
struct PlayableChannel {
    int node = -1;
    Target target = Target::Translation;
    std::optional<AnimationSampler> sampler;
    std::string problem;
};

PlayableChannel playable(const Scene& scene, const Animation& animation, const Animation::Channel& channel) {
    PlayableChannel out;
    const std::optional<Target> target = targetOf(channel.path);
    if (!target || channel.node < 0 || channel.node >= static_cast<int>(scene.nodes.size())) return out;
    if (scene.nodes[static_cast<std::size_t>(channel.node)].camera >= 0) return out;
    if (channel.sampler < 0 || channel.sampler >= static_cast<int>(animation.samplers.size())) {
        out.problem = "no sampler " + std::to_string(channel.sampler);
        return out;
    }
    const Animation::Sampler& sampler = animation.samplers[static_cast<std::size_t>(channel.sampler)];
    const int components = *target == Target::Rotation ? 4 : 3;
    if (sampler.components != components) {
        out.problem = channel.path + " needs " + std::to_string(components) + " components, the sampler has " +
                      std::to_string(sampler.components);
        return out;
    }
    const std::optional<Interpolation> interpolation = parseInterpolation(sampler.interpolation);
    if (!interpolation) {
        out.problem = "unknown interpolation '" + sampler.interpolation + "'";
        return out;
    }
    try {
        out.sampler.emplace(sampler.input, sampler.output, components, *interpolation);
    } catch (const std::invalid_argument& e) {
        out.problem = e.what();
        return out;
    }
    out.node = channel.node;
    out.target = *target;
    return out;
}

template <typename Visit>
void forEachChannel(const Scene& scene, Visit&& visit) {
    for (const Animation& animation : scene.animations)
        for (std::size_t c = 0; c < animation.channels.size(); ++c)
            visit(animation, c, playable(scene, animation, animation.channels[c]));
}

}  // namespace

NodeAnimationSummary summarizeNodeAnimations(const Scene& scene) {
    NodeAnimationSummary summary;
    std::vector<bool> animated(scene.nodes.size(), false);
    forEachChannel(scene, [&](const Animation&, std::size_t, const PlayableChannel& channel) {
        if (!channel.sampler) return;
        ++summary.channels;
        animated[static_cast<std::size_t>(channel.node)] = true;
        summary.endTime = std::max(summary.endTime, static_cast<double>(channel.sampler->endTime()));
    });
    summary.nodes = static_cast<int>(std::count(animated.begin(), animated.end(), true));
    return summary;
}

bool applyNodeAnimations(Scene& scene, double seconds) {
    std::vector<Node::AnimatedPose> poses(scene.nodes.size());
    // Animations in file order: where two drive the same channel of a node, the later one wins.
    forEachChannel(scene, [&](const Animation&, std::size_t, const PlayableChannel& channel) {
        if (!channel.sampler) return;
        Node::AnimatedPose& pose = poses[static_cast<std::size_t>(channel.node)];
        switch (channel.target) {
        case Target::Translation: pose.translation = glm::vec3(channel.sampler->sample(seconds)); break;
        case Target::Rotation: pose.rotation = channel.sampler->sampleRotation(seconds); break;
        case Target::Scale: pose.scale = glm::vec3(channel.sampler->sample(seconds)); break;
        }
    });
    bool moved = false, lightMoved = false;
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        Node& node = scene.nodes[i];
        if (node.pose == poses[i]) continue;
        node.pose = poses[i];
        moved = true;
        // A light below a moved node moves too; any light node in the scene is cheap to redo.
        lightMoved = lightMoved || node.light >= 0 || !node.children.empty();
    }
    if (!moved) return false;
    scene.updateWorldTransforms();
    ++scene.geometryRevision;
    if (lightMoved) ++scene.lightRevision;
    return true;
}

std::vector<std::string> nodeAnimationProblems(const Scene& scene) {
    std::vector<std::string> problems;
    forEachChannel(scene, [&](const Animation& animation, std::size_t c, const PlayableChannel& channel) {
        if (channel.problem.empty()) return;
        problems.push_back("animation '" + animation.name + "' channel " + std::to_string(c) + ": " + channel.problem +
                           " (not played)");
    });
    return problems;
}

}  // namespace lit
