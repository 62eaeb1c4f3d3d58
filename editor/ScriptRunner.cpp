#include "ScriptRunner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "DocumentIO.h"
#include "FlyController.h"
#include "ProcessMemory.h"
#include "Properties.h"
#include "SceneEdits.h"
#include "SettingCommand.h"
#include "TextParse.h"
#include "ViewportOverlay.h"
#include "passes/TemporalAntialiasPass.h"

namespace lit::editor {

namespace {

// A number argument: parseScript has checked that it parses as the float it is used as.
float number(const std::string& text) { return parseNumber<float>(text).value_or(0.0f); }

}  // namespace

ScriptRunner::ScriptRunner(std::vector<ScriptCommand> commands, std::string source, ScriptTarget target)
    : commands_(std::move(commands)), source_(std::move(source)), target_(target) {}

void ScriptRunner::step() {
    if (waitFrames_ > 0) {
        --waitFrames_;
        return;
    }
    if (waitUntil_) {
        if (std::chrono::steady_clock::now() < *waitUntil_) return;
        waitUntil_.reset();
    }
    if (waitForGi_ > 0) {
        // The frame just rendered tells how far the update is (renderer stats of the last frame).
        const FrameStats& stats = target_.renderer.stats();
        // The converged image also holds a full anti-aliasing history, which starts once the
        // refinement stops changing the light.
        const RenderSettings& settings = target_.doc.settings;
        const bool antialiasing = waitForRefinement_ && TemporalAntialiasPass::applies(settings) &&
                                  stats.antialiasFrames < TemporalAntialiasPass::frames(settings);
        const bool busy = stats.giUpdateDone < 1.0f || (waitForRefinement_ && stats.giRefining) || antialiasing;
        if (busy) {
            if (--waitForGi_ == 0) {
                fail(commands_[next_ - 1], waitForRefinement_ ? "wait refined: the GI refinement did not finish in " +
                                                                    std::to_string(kRefineWaitFrames) + " frames"
                                                              : "wait gi: the GI update did not finish in " +
                                                                    std::to_string(kGiWaitFrames) + " frames");
            }
            return;
        }
        waitForGi_ = 0;
    }
    if (waitForPlayback_ > 0) {
        if (target_.playback.playing) {
            if (--waitForPlayback_ == 0)
                fail(commands_[next_ - 1],
                     "wait play: the playback did not end in " + std::to_string(kPlaybackWaitFrames) + " frames");
            return;
        }
        waitForPlayback_ = 0;
    }
    if (next_ >= commands_.size()) {
        target_.exitCode = 0;  // the end of the script: like quit
        return;
    }
    const ScriptCommand& command = commands_[next_++];
    const std::string error = run(command);
    if (!error.empty()) fail(command, error);
}

void ScriptRunner::fail(const ScriptCommand& command, const std::string& message) {
    std::fprintf(stderr, "lit-editor: %s\n", scriptErrorAt(command, source_, message).c_str());
    target_.exitCode = 1;
}

std::string ScriptRunner::run(const ScriptCommand& command) {
    Document& doc = target_.doc;
    const std::vector<std::string>& args = command.args;
    switch (command.verb) {
        case ScriptVerb::Select:
        case ScriptVerb::SelectToggle:
            return select(command);
        case ScriptVerb::Add:
            return add(command);
        case ScriptVerb::Delete:
            return deleteSelection(doc);
        case ScriptVerb::Duplicate:
            return duplicateSelection(doc, target_.camera.right());
        case ScriptVerb::Parent: {
            int parent = -1;
            if (args[0] != "-") {
                parent = findNode(doc.scene, args[0]);
                if (parent < 0) return "no node called '" + args[0] + "'";
            }
            return reparentSelection(doc, parent);
        }
        case ScriptVerb::Material:
            if (doc.selectedNode < 0) return "no node is selected";
            return makeMaterialUnique(doc, doc.selectedNode, doc.selectedPrimitive);
        case ScriptVerb::Primitive:
            return primitive(command);
        case ScriptVerb::Gizmo:
            target_.gizmo.mode = parseGizmoMode(args[0]).value_or(GizmoMode::Translate);
            return "";
        case ScriptVerb::Space:
            target_.gizmo.space = args[0] == "local" ? GizmoSpace::Local : GizmoSpace::World;
            return "";
        case ScriptVerb::Snap:
            return snap(command);
        case ScriptVerb::Drag:
            return drag(command);
        case ScriptVerb::Frame:
            if (doc.selection().empty()) return "frame: no node is selected";
            target_.input.frameSelection();
            return "";
        case ScriptVerb::Orbit:
            return orbit(command);
        case ScriptVerb::Animation:
            return chooseCameraAnimation(doc, args[0]);
        case ScriptVerb::Set:
            return setProperty(doc, args[0], args[1]);
        case ScriptVerb::Setting:
            return setting(command);
        case ScriptVerb::View:
            return target_.input.setView(args[0]);
        case ScriptVerb::Panel:
            if (bool* shown = panelFlag(target_.panels, args[0])) *shown = args[1] == "on";
            return "";
        case ScriptVerb::Pick:
            return target_.input.pickAt({number(args[0]), number(args[1])});
        case ScriptVerb::Screenshot:
            target_.screenshots.request({args[0], args.size() == 1 || args[1] == "ui", 0, command});
            return "";
        case ScriptVerb::Save: {
            const std::filesystem::path file = args.empty() ? doc.file : std::filesystem::path(args[0]);
            if (file.empty()) return "the document has no file yet: give one (save PATH)";
            return target_.files.saveTo(file);
        }
        case ScriptVerb::Open:
            return target_.files.open(args[0]);
        case ScriptVerb::Camera:
            return camera(command);
        case ScriptVerb::Undo:
            return doc.undo() ? "" : "nothing to undo";
        case ScriptVerb::Redo:
            return doc.redo() ? "" : "nothing to redo";
        case ScriptVerb::Interactive:
            interactive_ = args[0] == "on";
            return "";
        case ScriptVerb::Wait:
            return wait(command);
        // The timeline's actions (PathEditing.h).
        case ScriptVerb::Key:
        case ScriptVerb::Play:
        case ScriptVerb::Pause:
        case ScriptVerb::Time:
        case ScriptVerb::Duration:
            return runPathCommand(doc, target_.playback, target_.camera, command.name, args);
        case ScriptVerb::Quit:
            target_.exitCode = 0;
            return "";
        case ScriptVerb::Loop:
            next_ = 0;  // the next frame runs the first command again
            return "";
        case ScriptVerb::Memory:
            // After the release the editor does every 5 s anyway: the figures are what it holds, not
            // what happens to wait for the next release (up to a freed voxel volume or two).
            ProcessMemory::releaseFreeHeap();
            target_.log.info(ProcessMemory::query().describe());
            return "";
        case ScriptVerb::Layout: {
            const ViewportUiReport& ui = target_.ui;
            auto rect = [](const char* name, glm::vec4 r) {
                char text[96];
                std::snprintf(text, sizeof text, "%s %.0f %.0f %.0f %.0f", name, static_cast<double>(r.x),
                              static_cast<double>(r.y), static_cast<double>(r.z), static_cast<double>(r.w));
                return std::string(text);
            };
            target_.log.info("layout: " + rect("area", ui.area) + "; " + rect("legend", ui.legend) + "; " +
                             rect("stats", ui.stats) + "; legend text: " + ui.legendText);
            return "";
        }
    }
    return "unknown command '" + command.name + "'";
}

std::string ScriptRunner::select(const ScriptCommand& command) {
    Document& doc = target_.doc;
    const std::string& name = command.args[0];
    if (command.verb == ScriptVerb::Select && name == "-") {
        doc.select(-1);
        return "";
    }
    const int node = findNode(doc.scene, name);
    if (node < 0) return "no node called '" + name + "'";
    doc.select(node, command.verb == ScriptVerb::SelectToggle);
    return "";
}

std::string ScriptRunner::add(const ScriptCommand& command) {
    const std::vector<std::string>& args = command.args;
    const NodeKind kind = parseNodeKind(args[0]).value_or(NodeKind::Empty);
    const FlyCamera& camera = target_.camera;
    if (args.size() == 4) {
        const glm::vec3 position(number(args[1]), number(args[2]), number(args[3]));
        addNode(target_.doc, kind, position,
                kind == NodeKind::DirectionalLight ? glm::vec3(0.3f, -1.0f, -0.2f) : camera.forward(),
                glm::distance(camera.position, position));
    } else {
        addNodeInFront(target_.doc, kind, camera.position, camera.forward());
    }
    return "";
}

std::string ScriptRunner::primitive(const ScriptCommand& command) {
    const Document& doc = target_.doc;
    if (doc.selectedNode < 0) return "no node is selected";
    const int mesh = doc.scene.nodes[static_cast<std::size_t>(doc.selectedNode)].mesh;
    const int count =
        mesh >= 0 ? static_cast<int>(doc.scene.meshes[static_cast<std::size_t>(mesh)].primitives.size()) : 0;
    const int index = parseNumber<int>(command.args[0]).value_or(-1);
    if (index < 0 || index >= count)
        return "primitive: the selected node has " + std::to_string(count) + " primitives, not " + command.args[0];
    target_.doc.selectedPrimitive = index;
    target_.doc.primitivePicked = true;
    return "";
}

std::string ScriptRunner::snap(const ScriptCommand& command) {
    const std::vector<std::string>& args = command.args;
    GizmoSnap& snap = target_.gizmo.snap;
    if (args.size() == 1) {
        snap.enabled = args[0] == "on";
        return "";
    }
    snap.translateStep = number(args[0]);
    snap.rotateStepDegrees = number(args[1]);
    snap.scaleStep = number(args[2]);
    snap.enabled = true;
    return "";
}

std::string ScriptRunner::drag(const ScriptCommand& command) {
    const std::vector<std::string>& args = command.args;
    if (target_.doc.selectedNode < 0) return "drag: no node is selected";
    const glm::vec2 from(number(args[0]), number(args[1]));
    const glm::vec2 to(number(args[2]), number(args[3]));
    if (!target_.input.dragGizmo(target_.input.currentView(), from, to))
        return "drag: no " + std::string(gizmoModeName(target_.gizmo.mode)) + " gizmo handle at (" + args[0] + ", " +
               args[1] + ")";
    return "";
}

std::string ScriptRunner::orbit(const ScriptCommand& command) {
    const Document& doc = target_.doc;
    FlyCamera& camera = target_.camera;
    const Aabb bounds = doc.scene.worldBounds();
    const glm::vec3 pivot = doc.selectedNode >= 0 ? nodeWorldPosition(doc.scene, doc.selectedNode)
                            : bounds.empty()      ? camera.position + camera.forward() * 2.0f
                                                  : bounds.center();
    orbitAround(camera, pivot, {number(command.args[0]), number(command.args[1])});
    return "";
}

std::string ScriptRunner::setting(const ScriptCommand& command) {
    const std::string& key = command.args[0];
    const std::string& value = command.args[1];
    std::vector<std::string> deprecated;
    std::optional<std::string> result = applyEditorSetting(target_.viewport, key, value, &deprecated);
    if (!result) result = applySetting(target_.doc.settings, key, value, &deprecated);
    for (const std::string& message : deprecated) target_.log.warning(message);
    return *result;
}

std::string ScriptRunner::camera(const ScriptCommand& command) {
    const std::vector<std::string>& args = command.args;
    const glm::vec3 position(number(args[0]), number(args[1]), number(args[2]));
    const glm::vec3 target(number(args[3]), number(args[4]), number(args[5]));
    if (glm::length(target - position) < 1e-6f) return "camera: the target is the camera's own position";
    const glm::vec3 d = glm::normalize(target - position);
    // Inverse of FlyCamera::forward(): (−sin yaw · cos pitch, sin pitch, −cos yaw · cos pitch).
    FlyCamera& camera = target_.camera;
    camera.position = position;
    camera.pitch = std::asin(std::clamp(d.y, -1.0f, 1.0f));
    camera.yaw = std::atan2(-d.x, -d.z);
    return "";
}

std::string ScriptRunner::wait(const ScriptCommand& command) {
    const std::string& what = command.args[0];
    if (what == "play") {
        waitForPlayback_ = kPlaybackWaitFrames;
        return "";
    }
    if (what == "gi" || what == "refined") {
        waitForRefinement_ = what == "refined";
        waitForGi_ = waitForRefinement_ ? kRefineWaitFrames : kGiWaitFrames;
        return "";
    }
    if (const std::optional<double> seconds = waitSeconds(what)) {
        waitUntil_ = std::chrono::steady_clock::now() +
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(*seconds));
        return "";
    }
    waitFrames_ = parseNumber<int>(what).value_or(1) - 1;  // this frame is the first
    return "";
}

}  // namespace lit::editor
