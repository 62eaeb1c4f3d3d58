#pragma once
// The voxel-levels view's colour per volume (VoxelDebugPass::executeLevels); the editor's legend
// shows the same. No GL here.

#include <algorithm>
#include <array>
#include <cstddef>
#include <glm/glm.hpp>

namespace lit {

// Near level `nearLevel` (1 the finest), or the scene's volume (0): warm to cool from the finest
// level out, the scene's volume blue.
inline glm::vec3 voxelLevelColor(int nearLevel) {
    constexpr std::array<glm::vec3, 5> kNear{glm::vec3(1.0f, 0.55f, 0.15f), glm::vec3(0.4f, 0.85f, 0.3f),
                                             glm::vec3(0.75f, 0.45f, 0.95f), glm::vec3(0.95f, 0.35f, 0.45f),
                                             glm::vec3(0.3f, 0.85f, 0.8f)};
    if (nearLevel <= 0) return {0.3f, 0.6f, 1.0f};
    return kNear[static_cast<std::size_t>(std::min(nearLevel, static_cast<int>(kNear.size())) - 1)];
}

}  // namespace lit
