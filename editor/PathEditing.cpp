#include "PathEditing.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "TextParse.h"
#include "animation/NodeAnimation.h"

namespace lit::editor {

namespace {

bool parseIndex(const std::string& text, std::size_t count, std::size_t& index, std::string& error) {
    const std::optional<std::size_t> parsed = parseNumber<std::size_t>(text);
    if (!parsed) {
        error = "expected a key index, got '" + text + "'";
        return false;
    }
    index = *parsed;
    if (index >= count) {
        error = "no key " + text + " (the path has " + std::to_string(count) + (count == 1 ? " key)" : " keys)");
        return false;
    }
    return true;
}

}  // namespace

CameraKey keyFromCamera(const FlyCamera& camera, float time) {
    const CameraView view = camera.view(1.0f, 0.1f, 10.0f);
    const glm::mat4 world = glm::inverse(view.view);
    CameraKey key;
    key.time = time;
    key.position = camera.position;
    key.rotation = glm::normalize(glm::quat_cast(glm::mat3(world)));
    key.yfov = camera.yfov;
    return key;
}

void applyPoseToCamera(const CameraPose& pose, FlyCamera& camera) {
    CameraView view;
    view.view = glm::inverse(pose.world());
    view.position = pose.position;
    view.yfov = pose.yfov;
    camera.setFromView(view);
    camera.position = pose.position;
    camera.yfov = pose.yfov;
}

void lookThroughPath(const CameraPath& path, double time, FlyCamera& camera) {
    if (const auto pose = path.evaluate(time)) applyPoseToCamera(*pose, camera);
}

std::size_t addKey(Document& doc, CameraKey key) {
    // Move past every key the new one would collide with (keys are sorted by time).
    for (const CameraKey& existing : doc.cameraPath.keys())
        if (std::abs(existing.time - key.time) < kMinKeySpacing) key.time = existing.time + kMinKeySpacing;
    std::size_t index = 0;
    // Document::edit cancels the edit if insertKey throws (a key with a bad value).
    doc.edit("Add Key", Change::CameraPath, [&](Scene&) { index = doc.cameraPath.insertKey(key); });
    doc.selectedKey = static_cast<int>(index);
    return index;
}

float nextKeyTime(const CameraPath& path, double playhead) {
    const std::vector<CameraKey>& keys = path.keys();
    if (keys.empty()) return static_cast<float>(playhead);
    const auto onKey = std::any_of(keys.begin(), keys.end(), [&](const CameraKey& key) {
        return std::abs(static_cast<double>(key.time) - playhead) < kMinKeySpacing;
    });
    if (!onKey && playhead > keys.front().time) return static_cast<float>(playhead);
    const float meanSpacing =
        keys.size() < 2 ? kDefaultKeyInterval
                        : std::max((keys.back().time - keys.front().time) / static_cast<float>(keys.size() - 1),
                                   kMinAddedKeyInterval);
    return keys.back().time + meanSpacing;
}

std::size_t addKeyFromView(Document& doc, PathPlayback& playback, const FlyCamera& camera) {
    const std::size_t index = addKey(doc, keyFromCamera(camera, nextKeyTime(doc.cameraPath, playback.time)));
    playback.playing = false;
    playback.time = doc.cameraPath.keys()[index].time;
    return index;
}

TimeSpan scrubSpan(const CameraPath& path, double animationEnd) {
    if (!hasTimeline(path, animationEnd)) return {};
    const TimeSpan span = playSpan(path, animationEnd);
    const double start = std::min(0.0, span.start);
    return {start, span.end + std::max(0.25 * (span.end - start), static_cast<double>(kDefaultKeyInterval))};
}

TimeSpan playSpan(const CameraPath& path, double animationEnd) {
    const bool animated = animationEnd > 0.0;
    if (path.empty()) return {0.0, animated ? animationEnd : 0.0};
    const double start = path.startTime(), end = path.endTime();
    if (!animated) return {start, end};
    return {std::min(start, 0.0), std::max(end, animationEnd)};
}

bool scalePathDuration(Document& doc, float seconds) {
    const std::vector<CameraKey>& keys = doc.cameraPath.keys();
    if (keys.size() < 2 || !std::isfinite(seconds) || seconds <= 0.0f) return false;
    const float first = keys.front().time;
    const float duration = keys.back().time - first;
    float smallestGap = duration;
    for (std::size_t i = 1; i < keys.size(); ++i) smallestGap = std::min(smallestGap, keys[i].time - keys[i - 1].time);
    // The shortest gap must stay a key spacing apart (a little more, for the float rounding).
    const float factor = std::max(seconds / duration, 1.01f * kMinKeySpacing / smallestGap);
    std::vector<CameraKey> scaled = keys;
    for (CameraKey& key : scaled) key.time = first + (key.time - first) * factor;
    try {
        doc.cameraPath.setKeys(std::move(scaled));
    } catch (const CameraPathError&) {
        return false;
    }
    doc.touched(Change::CameraPath);
    return true;
}

bool setPathDuration(Document& doc, float seconds) {
    if (doc.cameraPath.keys().size() < 2) return false;
    doc.beginEdit("Path Duration");
    const bool ok = scalePathDuration(doc, seconds);
    doc.endEdit();
    return ok;
}

int keyNear(const CameraPath& path, double time, double tolerance) {
    int best = -1;
    double bestDistance = tolerance;
    const std::vector<CameraKey>& keys = path.keys();
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const double distance = std::abs(static_cast<double>(keys[i].time) - time);
        if (distance <= bestDistance) {
            best = static_cast<int>(i);
            bestDistance = distance;
        }
    }
    return best;
}

bool deleteKey(Document& doc, std::size_t index) {
    if (index >= doc.cameraPath.keys().size()) return false;
    doc.edit("Delete Key", Change::CameraPath, [&](Scene&) { doc.cameraPath.removeKey(index); });
    const int remaining = static_cast<int>(doc.cameraPath.keys().size());
    doc.selectedKey = remaining == 0 ? -1 : std::min(static_cast<int>(index), remaining - 1);
    return true;
}

float clampKeyTime(const CameraPath& path, std::size_t index, float time) {
    const std::vector<CameraKey>& keys = path.keys();
    if (index >= keys.size() || !std::isfinite(time)) return index < keys.size() ? keys[index].time : 0.0f;
    float lo = -1e30f, hi = 1e30f;
    if (index > 0) lo = keys[index - 1].time + kMinKeySpacing;
    if (index + 1 < keys.size()) hi = keys[index + 1].time - kMinKeySpacing;
    if (lo > hi) return keys[index].time;  // no room: keep it where it is
    return std::clamp(time, lo, hi);
}

bool setKeyValues(Document& doc, std::size_t index, CameraKey key) {
    if (index >= doc.cameraPath.keys().size()) return false;
    key.time = clampKeyTime(doc.cameraPath, index, key.time);
    key.yfov = std::clamp(key.yfov, 0.01f, 3.1f);
    if (glm::length(key.rotation) < 1e-6f) key.rotation = doc.cameraPath.keys()[index].rotation;
    key.rotation = glm::normalize(key.rotation);
    try {
        doc.cameraPath.setKey(index, key);
    } catch (const CameraPathError&) {
        return false;  // e.g. a non-finite position typed in: the key stays as it was
    }
    doc.touched(Change::CameraPath);
    return true;
}

bool retimeKey(Document& doc, std::size_t index, float time) {
    if (index >= doc.cameraPath.keys().size()) return false;
    CameraKey key = doc.cameraPath.keys()[index];
    key.time = time;
    doc.beginEdit("Retime Key");
    const bool ok = setKeyValues(doc, index, key);
    doc.endEdit();
    return ok;
}

bool updateKeyFromCamera(Document& doc, std::size_t index, const FlyCamera& camera) {
    if (index >= doc.cameraPath.keys().size()) return false;
    doc.beginEdit("Update Key");
    const bool ok = setKeyValues(doc, index, keyFromCamera(camera, doc.cameraPath.keys()[index].time));
    doc.endEdit();
    return ok;
}

void setPathOptions(Document& doc, const CameraPathOptions& options) {
    doc.edit("Path Options", Change::CameraPath, [&](Scene&) { doc.cameraPath.setOptions(options); });
}

void PathPlayback::advance(const CameraPath& path, double dtSeconds, double animationEnd) {
    if (!playing) return;
    if (!hasTimeline(path, animationEnd)) {
        playing = false;
        return;
    }
    time += dtSeconds * static_cast<double>(speed);
    const auto [start, end] = playSpan(path, animationEnd);
    if (path.options().loop && end > start) {
        time = start + std::fmod(std::fmod(time - start, end - start) + (end - start), end - start);
    } else if (time >= end) {
        time = end;
        playing = false;
    } else if (time < start) {
        time = start;
        playing = false;
    }
}

void PathPlayback::play(const CameraPath& path, double animationEnd) {
    if (!hasTimeline(path, animationEnd)) return;
    const TimeSpan span = playSpan(path, animationEnd);
    if (time < span.start || (!path.options().loop && time >= span.end)) time = span.start;
    playing = true;
}

std::string runPathCommand(Document& doc, PathPlayback& playback, FlyCamera& camera, const std::string& name,
                           const std::vector<std::string>& args) {
    const std::size_t count = doc.cameraPath.keys().size();
    std::string error;
    std::size_t index = 0;
    if (name == "play") {
        const double animationEnd = summarizeNodeAnimations(doc.scene).endTime;
        if (!hasTimeline(doc.cameraPath, animationEnd)) return "the camera path has no keys and no node is animated";
        if (!args.empty()) {
            const std::optional<float> speed = parseNumber<float>(args[0]);
            if (!speed || *speed < kMinPlaybackSpeed || *speed > kMaxPlaybackSpeed) return "play: expected a speed 0.1..4";
            playback.speed = *speed;
        }
        playback.play(doc.cameraPath, animationEnd);
        return "";
    }
    if (name == "duration") {
        const std::optional<float> seconds = args.size() == 1 ? parseNumber<float>(args[0]) : std::nullopt;
        if (!seconds || *seconds <= 0.0f) return "duration: expected seconds > 0";
        if (count < 2) return "duration: the camera path needs two keys to have a duration";
        setPathDuration(doc, *seconds);
        return "";
    }
    if (name == "pause") {
        playback.playing = false;
        return "";
    }
    if (name == "time") {
        const std::optional<double> seconds = args.size() == 1 ? parseNumber<double>(args[0]) : std::nullopt;
        if (!seconds) return "time: expected seconds";
        playback.time = *seconds;
        lookThroughPath(doc.cameraPath, playback.time, camera);
        return "";
    }
    if (name != "key" || args.empty()) return "unknown camera path command '" + name + "'";
    const std::string& action = args[0];
    if (action == "add") {
        if (args.size() != 1) return "key add takes no values";
        addKeyFromView(doc, playback, camera);
        return "";
    }
    if (args.size() < 2) return "key " + action + ": expected a key index";
    if (!parseIndex(args[1], count, index, error)) return "key " + action + ": " + error;
    if (action == "delete") {
        deleteKey(doc, index);
        return "";
    }
    if (action == "select") {
        doc.selectedKey = static_cast<int>(index);
        playback.time = doc.cameraPath.keys()[index].time;
        lookThroughPath(doc.cameraPath, playback.time, camera);
        return "";
    }
    if (action == "update") {
        updateKeyFromCamera(doc, index, camera);
        return "";
    }
    if (action == "time") {
        const std::optional<float> seconds = args.size() == 3 ? parseNumber<float>(args[2]) : std::nullopt;
        if (!seconds) return "key time: expected an index and seconds";
        retimeKey(doc, index, *seconds);
        return "";
    }
    return "unknown key action '" + action + "' (add, delete, select, time, update)";
}

}  // namespace lit::editor
