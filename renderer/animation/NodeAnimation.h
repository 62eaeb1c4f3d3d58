#pragma once
// Node animations of a Scene: the translation, rotation and scale channels of Scene::animations
// that move the scene's mesh, light and empty nodes, played together on one clock (every
// animation starts at 0 s, as Blender's actions and three.js's clips do when all are played).
//
//   applyNodeAnimations(scene, 1.5);  // every animated node posed as at 1.5 s
//
// The pose goes into Node::pose, never into the rest transform (Node::translation, rotation,
// scale): edits change the rest transform and a save writes it, so a scene saved at any time
// reloads the same. Channels not played: those of camera nodes (a camera's animation is a camera
// path: animation/SceneCameraPaths.h), morph "weights", kept nodes' (not drawn), and channels
// whose sampler is malformed (listed by nodeAnimationProblems).

#include <string>
#include <vector>

namespace lit {

struct Scene;

// What the played channels cover: how many channels and nodes, and the last key time, seconds
// (0 when nothing is played).
struct NodeAnimationSummary {
    int channels = 0;
    int nodes = 0;
    double endTime = 0.0;
};
NodeAnimationSummary summarizeNodeAnimations(const Scene& scene);

// Sets Node::pose of every node the played channels drive to its pose at `seconds` (clamped to
// each channel's keys) and clears it on every other node. When a pose changed it recomputes the
// world transforms and bumps Scene::geometryRevision (the renderer redoes bounds, shadows and
// voxels, as after a gizmo move), and lightRevision when a light's node moved. Returns whether
// anything changed.
bool applyNodeAnimations(Scene& scene, double seconds);

// The channels left out because their data cannot be played, one line each ("animation 'x'
// channel 2: ..."), for a warning at load.
std::vector<std::string> nodeAnimationProblems(const Scene& scene);

}  // namespace lit
