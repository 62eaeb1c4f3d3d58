// make-gi-suite OUTDIR — writes the GI accuracy suite's generated scenes to OUTDIR (assets/gi/):
//   glossy_floor.gltf  a Cornell room whose floor is a glossy metal that reflects the coloured walls
//   thin_walls.gltf    a Cornell room whose walls are one voxel thick at 128³, with a strong sun
//                      shining on its roof from outside (any sunlight inside is a leak)
//   sealed_room.gltf   a closed room on a sunlit ground; nothing inside is lit but by leaks
//   city.gltf          640 m of box buildings between 14 m streets under a low sun, seen from
//                      street level: a scene far larger than one voxel volume resolves
//   cornell_room.gltf  the Cornell box built with this file's room (the control for the two below)
//   cornell_mirrored.gltf  the Cornell box mirrored in x (red wall and tall block at +x): an error that
//                      moves with the scene is the scene's, one that stays on a side is the tracer's
//   cornell_swapped.gltf   the Cornell box with the red and green walls' colours swapped (geometry
//                      unchanged): an error that follows the colour is the colour's, else the geometry's
// Each is built with SceneBuilder and written with saveGltf (atomic). The Cornell box itself is
// assets/cornell_box.gltf (tools/make_cornell_box.cpp). tools/gi-accuracy.sh renders the suite;
// docs/tables/gi-accuracy.md has the tables. Conventions as assets/README.md: metres, +Y up, the camera looks −Z.

#include "scene/GltfWriter.h"
#include "scene/SceneBuilder.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

namespace fs = std::filesystem;
using namespace lit;

constexpr float kPi = 3.14159265358979323846f;

struct RoomMaterials {
    int white, red, green, floor;
};

// Variants of the Cornell room for telling a tracer's defect from a scene's property (the
// red-wall nook's shadow): x mirrored (every x negated, so the turns about y too), or the two coloured
// walls' materials swapped. Node names stay with the colour (the accuracy regions find the red
// wall by name and take the floor on its side).
struct RoomVariant {
    bool mirrorX = false;
    bool swapColours = false;
};

// The Cornell box's materials (assets/README.md); the floor is `floor` (white unless given).
RoomMaterials addRoomMaterials(Scene& scene) {
    RoomMaterials m{};
    m.white = addMaterial(scene, glm::vec3(0.73f), 0.9f, 0.0f, "white");
    m.red = addMaterial(scene, glm::vec3(0.63f, 0.065f, 0.05f), 0.9f, 0.0f, "red");
    m.green = addMaterial(scene, glm::vec3(0.14f, 0.45f, 0.091f), 0.9f, 0.0f, "green");
    m.floor = m.white;
    return m;
}

void name(Scene& scene, int node, const char* text) { scene.nodes[static_cast<std::size_t>(node)].name = text; }

// A camera node (and camera) named `text` with a square image: field of view `yfov` (rad), near
// and far planes (m), at `position` looking at `target`.
void addSquareCamera(Scene& scene, const char* text, float yfov, float znear, float zfar, glm::vec3 position,
                     glm::vec3 target) {
    Camera camera;
    camera.name = text;
    camera.yfov = yfov;
    camera.aspectRatio = 1.0f;
    camera.znear = znear;
    camera.zfar = zfar;
    name(scene, addCameraNode(scene, camera, position, target), text);
}

// The Cornell room: interior x ∈ [−1, 1], y ∈ [0, 2], z ∈ [−1, 1], open at z = +1, with the node
// names of assets/cornell_box.gltf (the accuracy regions find walls by name). thickness 0: single-
// sided walls (planes facing in); otherwise closed slabs of that thickness (metres) outside the
// interior. Two blocks and the down-pointing spot of the Cornell box (20 W/sr = 13 660 cd).
void addCornellRoom(Scene& scene, const RoomMaterials& m, float thickness, RoomVariant variant = {}) {
    const float t = thickness;
    // x of the mirrored room; the blocks' turns about y change sign with it.
    const float sx = variant.mirrorX ? -1.0f : 1.0f;
    // The wall at −x (before mirroring) is the red one unless the colours are swapped.
    const bool redAtLeft = !variant.swapColours;
    const int leftMaterial = redAtLeft ? m.red : m.green, rightMaterial = redAtLeft ? m.green : m.red;
    const char* leftName = redAtLeft ? "left_wall_red" : "right_wall_green";
    const char* rightName = redAtLeft ? "right_wall_green" : "left_wall_red";
    if (t <= 0.0f) {
        const auto plane = [&](const char* n, int material, glm::vec3 at, glm::quat rotation) {
            name(scene, addMeshNode(scene, makePlaneMesh(n, 2.0f, material, 8), at, rotation), n);
        };
        plane("floor", m.floor, {0, 0, 0}, glm::quat(1, 0, 0, 0));
        plane("ceiling", m.white, {0, 2, 0}, glm::angleAxis(kPi, glm::vec3(1, 0, 0)));
        plane("back_wall", m.white, {0, 1, -1}, glm::angleAxis(kPi / 2, glm::vec3(1, 0, 0)));
        // The planes face +y before turning: −90° about z faces +x (the wall at −x), +90° faces −x.
        plane(leftName, leftMaterial, {-sx, 1, 0}, glm::angleAxis(-sx * kPi / 2, glm::vec3(0, 0, 1)));
        plane(rightName, rightMaterial, {sx, 1, 0}, glm::angleAxis(sx * kPi / 2, glm::vec3(0, 0, 1)));
    } else {
        if (variant.mirrorX || variant.swapColours) throw std::logic_error("room variants are made with single-sided walls only");
        const float outer = 2.0f + 2.0f * t, depth = 2.0f + t;  // walls reach from the back slab to z = +1
        const auto slab = [&](const char* n, int material, glm::vec3 size, glm::vec3 at) {
            name(scene, addMeshNode(scene, makeBoxMesh(n, size, material), at), n);
        };
        slab("floor", m.floor, {outer, t, depth}, {0, -0.5f * t, -0.5f * t});
        slab("ceiling", m.white, {outer, t, depth}, {0, 2.0f + 0.5f * t, -0.5f * t});
        slab("back_wall", m.white, {outer, outer, t}, {0, 1, -1.0f - 0.5f * t});
        slab("left_wall_red", m.red, {t, outer, depth}, {-1.0f - 0.5f * t, 1, -0.5f * t});
        slab("right_wall_green", m.green, {t, outer, depth}, {1.0f + 0.5f * t, 1, -0.5f * t});
    }
    const float turn = 17.0f * kPi / 180.0f;
    name(scene, addMeshNode(scene, makeBoxMesh("tall_box", {0.6f, 1.2f, 0.6f}, m.white), {-0.33f * sx, 0.6f, -0.3f},
                            glm::angleAxis(sx * turn, glm::vec3(0, 1, 0))),
         "tall_box");
    name(scene, addMeshNode(scene, makeBoxMesh("short_box", {0.6f, 0.6f, 0.6f}, m.white), {0.35f * sx, 0.3f, 0.35f},
                            glm::angleAxis(-sx * turn, glm::vec3(0, 1, 0))),
         "short_box");
    Light spot;
    spot.name = "ceiling_spot";
    spot.type = LightType::Spot;
    spot.intensity = 20.0f;
    spot.innerConeAngle = 0.6f;
    spot.outerConeAngle = 1.05f;
    name(scene, addLightNode(scene, spot, {0, 1.9f, 0}, {0, -1, 0}), "ceiling_spot");
    addSquareCamera(scene, "camera", 0.69f, 0.05f, 20.0f, {0, 1, 3.4f}, {0, 1, 0});
}

Scene glossyFloor() {
    Scene scene;
    scene.name = "glossy_floor";
    RoomMaterials m = addRoomMaterials(scene);
    // A polished white metal: its indirect specular term shows the red and green walls.
    m.floor = addMaterial(scene, glm::vec3(0.9f), 0.2f, 1.0f, "glossy metal");
    addCornellRoom(scene, m, 0.0f);
    return scene;
}

Scene thinWalls() {
    Scene scene;
    scene.name = "thin_walls";
    const RoomMaterials m = addRoomMaterials(scene);
    // VoxelVolume spans the largest extent (2 + 2t) over N − 4 voxels: t = 2 / (128 − 6) makes
    // t exactly one voxel at 128³ (two at 64³, half a voxel at 256³).
    addCornellRoom(scene, m, 2.0f / 122.0f);
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    // W/m² (13 660 lx; Light::intensity is radiometric): ~3.6× the spot's illuminance on the floor;
    // all of it must stay outside.
    sun.intensity = 20.0f;
    // Down and slightly towards +z: it falls on the roof and never through the open front.
    name(scene, addLightNode(scene, sun, {0, 4, 0}, glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f))), "sun");
    return scene;
}

// The Cornell box (assets/cornell_box.gltf built with the suite's room) mirrored in x or with the
// wall colours swapped.
Scene cornellVariant(const char* sceneName, RoomVariant variant) {
    Scene scene;
    scene.name = sceneName;
    const RoomMaterials m = addRoomMaterials(scene);
    addCornellRoom(scene, m, 0.0f, variant);
    return scene;
}

Scene sealedRoom() {
    Scene scene;
    scene.name = "sealed_room";
    const int ground = addMaterial(scene, glm::vec3(0.5f), 0.9f, 0.0f, "ground");
    const int wall = addMaterial(scene, glm::vec3(0.73f), 0.9f, 0.0f, "white");
    name(scene, addMeshNode(scene, makePlaneMesh("ground", 16.0f, ground, 8), {0, 0, 0}), "ground");
    // A closed room, interior 4 × 3 × 4 m, walls 0.2 m thick, standing on the ground.
    constexpr float t = 0.2f, w = 4.0f, h = 3.0f;
    const auto slab = [&](const char* n, glm::vec3 size, glm::vec3 at) {
        name(scene, addMeshNode(scene, makeBoxMesh(n, size, wall), at), n);
    };
    slab("room_floor", {w + 2 * t, t, w + 2 * t}, {0, 0.5f * t, 0});
    slab("room_roof", {w + 2 * t, t, w + 2 * t}, {0, t + h + 0.5f * t, 0});
    slab("room_wall_back", {w + 2 * t, h, t}, {0, t + 0.5f * h, -0.5f * w - 0.5f * t});
    slab("room_wall_front", {w + 2 * t, h, t}, {0, t + 0.5f * h, 0.5f * w + 0.5f * t});
    slab("room_wall_left", {t, h, w}, {-0.5f * w - 0.5f * t, t + 0.5f * h, 0});
    slab("room_wall_right", {t, h, w}, {0.5f * w + 0.5f * t, t + 0.5f * h, 0});
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    // W/m² (34 150 lx), from high up and to the side: it lights the roof, two walls and the ground.
    sun.intensity = 50.0f;
    name(scene, addLightNode(scene, sun, {0, 8, 0}, glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f))), "sun");
    addSquareCamera(scene, "inside", 1.2f, 0.05f, 30.0f, {1.2f, 1.6f, 1.6f}, {-1.0f, 1.4f, -1.5f});
    return scene;
}

// A city of 10 × 10 blocks, 50 m square with 14 m streets between them (640 m across), one box
// building per block, 8–44 m tall, on a ground of asphalt. The sun stands 30° high, 60° off the
// streets' axis, so one side of each street is sunlit and the other lit only by bounced light.
// The camera stands on the central street at eye height, looking down it. Heights come from a
// fixed integer sequence, so the file is the same on every machine.
Scene city() {
    Scene scene;
    scene.name = "city";
    const int ground = addMaterial(scene, glm::vec3(0.25f), 0.95f, 0.0f, "ground");
    const int facades[3] = {addMaterial(scene, glm::vec3(0.70f, 0.67f, 0.60f), 0.9f, 0.0f, "stone"),
                            addMaterial(scene, glm::vec3(0.55f, 0.30f, 0.22f), 0.9f, 0.0f, "brick"),
                            addMaterial(scene, glm::vec3(0.45f, 0.47f, 0.50f), 0.9f, 0.0f, "concrete")};
    constexpr int kBlocks = 10;
    constexpr float kBlock = 50.0f, kStreet = 14.0f, kPitch = kBlock + kStreet;
    name(scene, addMeshNode(scene, makePlaneMesh("ground", kBlocks * kPitch + 60.0f, ground, 16), {0, 0, 0}), "ground");
    std::uint32_t state = 12345u;
    const auto next = [&state] {
        state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG: the same on every platform
        return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
    };
    for (int i = 0; i < kBlocks; ++i)
        for (int j = 0; j < kBlocks; ++j) {
            const float height = 8.0f + 36.0f * next();
            const int material = facades[static_cast<int>(3.0f * next()) % 3];
            const std::string n = "building_" + std::to_string(i) + "_" + std::to_string(j);
            const glm::vec3 at{(static_cast<float>(i) - 4.5f) * kPitch, 0.5f * height, (static_cast<float>(j) - 4.5f) * kPitch};
            name(scene, addMeshNode(scene, makeBoxMesh(n, {kBlock, height, kBlock}, material), at), n.c_str());
        }
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.intensity = 50.0f;  // W/m² (34 150 lx)
    const float elevation = 30.0f * kPi / 180.0f, azimuth = 60.0f * kPi / 180.0f;
    const glm::vec3 toSun{std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
    name(scene, addLightNode(scene, sun, {0, 100, 0}, -toSun), "sun");
    // The street between block columns 4 and 5 runs along z at x = 0.
    addSquareCamera(scene, "street", 1.0f, 0.1f, 1000.0f, {0, 1.7f, 290.0f}, {0, 6.0f, 0});
    return scene;
}

}  // namespace

int main(int argc, char** argv) {
    // An option is never taken for the output folder (`make-gi-suite --help` made a folder "--help").
    const bool help = argc == 2 && (std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "-h");
    if (argc != 2 || help || std::string_view(argv[1]).starts_with("-")) {
        std::fprintf(stderr, "usage: make-gi-suite OUTDIR\n  writes the GI accuracy suite's scenes (OUTDIR/*.gltf and .bin; "
                             "the committed copies are assets/gi)\n");
        return help ? 0 : 2;
    }
    try {
        const fs::path out = argv[1];
        fs::create_directories(out);
        for (Scene scene : {glossyFloor(), thinWalls(), sealedRoom(), city(), cornellVariant("cornell_room", {}),
                            cornellVariant("cornell_mirrored", {.mirrorX = true}),
                            cornellVariant("cornell_swapped", {.swapColours = true})}) {
            scene.updateWorldTransforms();
            const fs::path file = out / (scene.name + ".gltf");
            saveGltf(scene, file);
            std::printf("wrote %s (%zu triangles)\n", file.string().c_str(), scene.triangleCount());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make-gi-suite: %s\n", e.what());
        return 1;
    }
    return 0;
}
