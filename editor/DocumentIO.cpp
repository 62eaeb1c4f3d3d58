#include "DocumentIO.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

#include "Log.h"
#include "animation/CameraPathIO.h"
#include "io/AtomicFile.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"
#include "scene/SceneBuilder.h"

namespace lit::editor {

namespace fs = std::filesystem;

namespace {

// 1: the copy was always "autosave.glb"; 2: the marker names it ("scene").
constexpr int kMarkerVersion = 2;
constexpr const char* kCopyNames[] = {"autosave-1.glb", "autosave-2.glb"};

std::optional<std::string> readTextFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return std::nullopt;
    return text.str();
}

// The scene and its camera path, as openDocument and recovery read them.
Document loadScene(const fs::path& sceneFile, const fs::path& documentFile, Log& log,
                   const std::function<void(const LoadProgress&)>& progress = {}, const GltfLimits& limits = {}) {
    GltfLoadOptions options;
    options.progress = progress;
    options.limits = limits;
    Scene scene = loadGltf(sceneFile, log, options);  // logs the summary line
    addDefaultCamera(scene, log, DefaultCameraPlacement::InsideLargestSpace);
    CameraPath path;
    std::vector<std::string> names;
    std::string pathName = kDefaultCameraAnimation;
    try {
        names = cameraAnimationNames(sceneFile);
        // The editor's own path when the file has one, else the file's first camera animation
        // (a Blender "fly"), edited and saved under its own name.
        if (std::find(names.begin(), names.end(), kDefaultCameraAnimation) == names.end() && !names.empty())
            pathName = names.front();
        if (std::find(names.begin(), names.end(), pathName) != names.end()) {
            path = loadCameraPathFromGltf(sceneFile, pathName);
            log.info("camera path: " + std::to_string(path.keys().size()) + " keys of '" + pathName + "' from " +
                     sceneFile.filename().string());
        }
    } catch (const std::exception& error) {
        // The scene is still worth editing; the path starts empty (saving replaces the bad one).
        log.warning(std::string("camera path not loaded: ") + error.what());
        path = CameraPath();
    }
    Document doc(std::move(scene), std::move(path), documentFile);
    doc.cameraPathName = pathName;
    doc.cameraAnimations = names;
    doc.markSaved();
    return doc;
}

std::string localTimeText(std::time_t seconds) {
    std::tm local{};
    localtime_r(&seconds, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", &local);
    return text;
}

// The pid in a lock file, or 0 when it holds none.
long lockOwner(const fs::path& lock) {
    const std::optional<std::string> text = readTextFile(lock);
    if (!text) return 0;
    char* end = nullptr;
    const long pid = std::strtol(text->c_str(), &end, 10);
    return pid > 0 && end != text->c_str() ? pid : 0;
}

bool processAlive(long pid) {
    if (pid <= 0) return false;
    // EPERM: the process exists but belongs to someone else.
    return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

// The scene and camera path as saveDocument and the autosave write them (saveGltf leaves an
// empty path out).
void saveScene(const Document& doc, const fs::path& file,
               std::vector<std::pair<fs::path, std::string>> alsoWrite = {}) {
    GltfSaveOptions options;
    options.cameraPath = &doc.cameraPath;
    options.cameraPathName = doc.cameraPathName.empty() ? std::string(kDefaultCameraAnimation) : doc.cameraPathName;
    options.alsoWrite = std::move(alsoWrite);
    saveGltf(doc.scene, file, options);
}

void removeQuietly(const fs::path& file) {
    std::error_code error;
    fs::remove(file, error);
}

}  // namespace

fs::path settingsSidecarPath(const fs::path& sceneFile) {
    fs::path sidecar = sceneFile;
    sidecar += ".lit.json";
    return sidecar;
}

Document openDocument(const fs::path& file, Log& log, const std::function<void(const LoadProgress&)>& progress,
                      const GltfLimits& limits) {
    // A save of this document that a crash interrupted is finished (past its commit point) or
    // undone before the file is read, and its temporaries removed.
    for (const std::string& line : recoverInterruptedSaves(file.has_parent_path() ? file.parent_path() : fs::path(".")))
        log.info(line);
    Document doc = loadScene(file, file, log, progress, limits);
    const fs::path sidecar = settingsSidecarPath(file);
    std::error_code error;
    if (fs::exists(sidecar, error)) {
        const std::optional<std::string> text = readTextFile(sidecar);
        try {
            if (!text) throw std::runtime_error("cannot read the file");
            std::vector<std::string> deprecated;
            doc.settings = renderSettingsFromJson(*text, {}, &deprecated);
            log.info("render settings from " + sidecar.filename().string());
            // An older sidecar loads; saving writes the new keys.
            for (const std::string& message : deprecated) log.warning(sidecar.filename().string() + ": " + message);
        } catch (const std::exception& e) {
            log.warning(sidecar.string() + ": " + e.what() + "; using the default render settings");
            doc.settings = RenderSettings{};
        }
    }
    doc.markSaved();  // the settings just read are the saved ones
    return doc;
}

std::string chooseCameraAnimation(Document& doc, const std::string& name) {
    if (name == doc.cameraPathName) return "";
    const bool inFile = std::find(doc.cameraAnimations.begin(), doc.cameraAnimations.end(), name) !=
                        doc.cameraAnimations.end();
    CameraPath path;
    if (inFile) {
        if (doc.file.empty()) return "the document has no file to read '" + name + "' from";
        try {
            path = loadCameraPathFromGltf(doc.file, name);
        } catch (const std::exception& error) {
            return "cannot read camera animation '" + name + "': " + error.what();
        }
    }
    try {
        doc.edit("Edit Animation " + name, Change::CameraPath, [&](Scene&) {
            doc.cameraPath = std::move(path);
            doc.cameraPathName = name;
        });
    } catch (const std::exception& error) {
        return error.what();
    }
    if (!inFile) doc.cameraAnimations.push_back(name);
    doc.selectedKey = -1;
    return "";
}

void saveDocument(Document& doc, const fs::path& file) {
    // The scene, its buffer and the settings sidecar have one commit point (io/AtomicFile.h).
    saveScene(doc, file, {{settingsSidecarPath(file), toJson(doc.settings) + "\n"}});
    doc.file = file;
    doc.markSaved();
}

// ---- Autosave ----------------------------------------------------------------------------------

fs::path Autosave::defaultFolder() {
    if (const char* state = std::getenv("XDG_STATE_HOME"); state != nullptr && fs::path(state).is_absolute())
        return fs::path(state) / "lit";
    if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
        return fs::path(home) / ".local" / "state" / "lit";
    std::error_code error;
    return fs::temp_directory_path(error) / "lit";
}

Autosave::Autosave() : Autosave(defaultFolder()) {}

Autosave::Autosave(fs::path folder, double intervalSeconds) : folder_(std::move(folder)), interval_(intervalSeconds) {
    std::error_code error;
    fs::create_directories(folder_, error);
    if (error) {
        lastError_ = "autosave disabled: cannot create " + folder_.string() + ": " + error.message();
        return;
    }
    const long owner = lockOwner(lockFile());
    const long self = static_cast<long>(::getpid());
    if (owner != 0 && owner != self && processAlive(owner)) {
        lastError_ = "autosave disabled: another editor (pid " + std::to_string(owner) + ") uses " + folder_.string();
        return;
    }
    // An autosave interrupted by a crash: finish or undo its file replacements first.
    (void)recoverInterruptedSaves(folder_);
    // The copy the marker names; version 1 markers named no copy: it was autosave.glb.
    if (const std::optional<std::string> text = readTextFile(markerFile())) {
        const nlohmann::json marker = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
        const int version = marker.is_object() ? marker.value("version", 0) : 0;
        if (version == 1) copyName_ = "autosave.glb";
        if (version == kMarkerVersion) {
            const std::string name = marker.value("scene", std::string());
            if (std::find(std::begin(kCopyNames), std::end(kCopyNames), name) != std::end(kCopyNames)) copyName_ = name;
        }
        // A lock left behind by a session that is gone: its copy, if complete, is offered.
        if (!copyName_.empty() && fs::exists(lockFile(), error) && fs::exists(autosaveFile(), error)) {
            const std::string document = marker.value("document", std::string());
            const auto savedAt = static_cast<std::time_t>(marker.value("savedAt", std::int64_t{0}));
            recoverable_ = AutosaveInfo{autosaveFile(), fs::path(document), localTimeText(savedAt)};
        }
    }
    // Copies the marker does not name are the leftovers of an autosave that did not finish.
    for (const char* name : {kCopyNames[0], kCopyNames[1], "autosave.glb"})
        if (name != copyName_) removeQuietly(folder_ / name);
    try {
        writeFileAtomically(lockFile(), std::to_string(self) + "\n");
        active_ = true;
    } catch (const std::exception& e) {
        lastError_ = std::string("autosave disabled: ") + e.what();
    }
}

void Autosave::maybeSave(const Document& doc, std::chrono::system_clock::time_point now) {
    maybeSave(doc, std::chrono::duration<double>(now.time_since_epoch()).count());
}

void Autosave::maybeSave(const Document& doc, double nowSeconds) {
    // A crash's copy waits for the user's answer; writing now would overwrite it.
    if (!active_ || recoverable_) return;
    if (!lastWrite_) {
        lastWrite_ = nowSeconds;
        return;
    }
    if (nowSeconds - *lastWrite_ < interval_) return;
    lastWrite_ = nowSeconds;
    if (!doc.dirty()) {
        // Saved since: the copy is older than the file and must not be offered after a crash.
        if (written_) discard();
        return;
    }
    if (written_ && *written_ == copyOf(doc)) return;
    try {
        saveNow(doc);
        lastError_.clear();
    } catch (const std::exception& e) {
        lastError_ = std::string("autosave failed: ") + e.what();
    }
}

void Autosave::saveNow(const Document& doc) {
    // Never overwrite the copy the marker names: write the other one, then switch the marker.
    const std::string next = copyName_ == kCopyNames[0] ? kCopyNames[1] : kCopyNames[0];
    saveScene(doc, folder_ / next);
    const nlohmann::json marker = {
        {"version", kMarkerVersion},
        {"scene", next},
        {"document", doc.file.string()},
        {"savedAt", static_cast<std::int64_t>(std::time(nullptr))},
        {"settings", nlohmann::json::parse(toJson(doc.settings))},
    };
    writeFileAtomically(markerFile(), marker.dump(2) + "\n");  // the commit point
    const std::string previous = copyName_;
    copyName_ = next;
    if (!previous.empty() && previous != next) removeQuietly(folder_ / previous);
    written_ = copyOf(doc);
}

std::optional<AutosaveInfo> Autosave::recoverable() const { return recoverable_; }

Document Autosave::recover(Log& log) {
    if (!recoverable_) throw std::runtime_error("there is no autosave to recover");
    const std::optional<std::string> text = readTextFile(markerFile());
    if (!text) throw std::runtime_error("cannot read " + markerFile().string());
    const nlohmann::json marker = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
    if (!marker.is_object()) throw std::runtime_error(markerFile().string() + " is not a JSON object");

    Document doc = loadScene(autosaveFile(), recoverable_->documentFile, log);
    if (auto settings = marker.find("settings"); settings != marker.end()) {
        try {
            std::vector<std::string> deprecated;
            doc.settings = renderSettingsFromJson(settings->dump(), {}, &deprecated);
            for (const std::string& message : deprecated)
                log.warning(markerFile().filename().string() + ": " + message);
        } catch (const std::exception& e) {
            log.warning(markerFile().string() + ": " + e.what() + "; using the default render settings");
        }
    }
    doc.markUnsaved();
    // This session's copies may be written from now on (the recovered one is theirs to replace).
    recoverable_.reset();
    written_ = copyOf(doc);
    return doc;
}

void Autosave::discard() {
    recoverable_.reset();
    written_.reset();
    if (!active_) return;  // the files, if any, are another editor's
    removeQuietly(markerFile());  // first: without it, no copy is offered
    for (const char* name : {kCopyNames[0], kCopyNames[1], "autosave.glb"}) removeQuietly(folder_ / name);
    copyName_.clear();
}

void Autosave::cleanExit() {
    if (!active_) return;  // the lock, if any, is another editor's
    // A crash's copy the user neither recovered nor discarded stays on offer: the lock (now
    // naming this process, which is ending) keeps marking it as left by a crash.
    if (!recoverable_) {
        discard();
        removeQuietly(lockFile());
    }
    active_ = false;
}

}  // namespace lit::editor
