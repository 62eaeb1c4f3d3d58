#include "FileActions.h"

#include <algorithm>
#include <cctype>
#include <exception>
#include <utility>

#include "RenderSettings.h"
#include "SaveAsName.h"
#include "animation/NodeAnimation.h"
#include "panels/LoadingWindow.h"
#include "scene/GltfWriter.h"
#include "scene/SceneMemory.h"

namespace lit::editor {

namespace {

bool isSceneFile(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".gltf" || extension == ".glb";
}

std::string displayName(const std::filesystem::path& file) {
    return file.empty() ? std::string("untitled") : file.filename().string();
}

// What a scene opened in this run may make the loader read (--allow-external-uris), and the
// memory it may need with the default render settings (its sidecar's come with it), under the
// limit lit-render uses ($LIT_MAX_RENDER_MB or the default): checked before decoding.
GltfLimits loadLimits(const EditorOptions& options) {
    GltfLimits limits;
    limits.allowExternalUris = options.allowExternalUris;
    const MemoryLimit memory = renderMemoryLimit();
    limits.memoryBudgetBytes = memory.bytes;
    limits.memoryBudgetSource = memory.source;
    limits.render = RenderFootprint::of(RenderSettings{});
    return limits;
}

std::filesystem::path initialScene(const EditorOptions& options) { return options.scene.value_or(defaultScenePath()); }

}  // namespace

Document loadInitialDocument(const EditorOptions& options, Log& log) {
    if (options.interactive()) return Document{};
    const std::filesystem::path path = initialScene(options);
    Document doc = openDocument(path, log, {}, loadLimits(options));
    log.info("opened scene " + path.string());
    for (const std::string& problem : nodeAnimationProblems(doc.scene)) log.warning(problem);
    return doc;
}

FileActions::FileActions(FileContext context)
    : options_(context.options),
      doc_(context.doc),
      log_(context.log),
      sceneError_(context.sceneError),
      recent_(context.recent),
      menu_(context.menu),
      upload_(context.upload),
      exitCode_(context.exitCode),
      documentReplaced_(std::move(context.documentReplaced)) {}

void FileActions::start() {
    if (!options_.interactive()) {
        recent_.add(initialScene(options_));
        return;
    }
    autosave_.emplace();
    recoveryAfterLoad_ = true;
    startLoading(initialScene(options_));
}

void FileActions::showError(std::string message) {
    sceneError_ = std::move(message);
    log_.error(sceneError_);
}

// ---- open and quit, asking first -----------------------------------------------------------

void FileActions::requestOpen(const std::filesystem::path& path) {
    if (options_.scriptMode() || !doc_.dirty()) {
        open(path);
        return;
    }
    askAboutUnsavedChanges({PendingAction::Kind::Open, path});
}

void FileActions::requestQuit() {
    if (options_.scriptMode() || !doc_.dirty()) {
        exitCode_ = 0;
        return;
    }
    askAboutUnsavedChanges({PendingAction::Kind::Quit, {}});
}

void FileActions::askAboutUnsavedChanges(PendingAction action) {
    pending_ = std::move(action);
    const std::string name = displayName(doc_.file);
    const std::string before = pending_.kind == PendingAction::Kind::Quit
                                   ? "before quitting"
                                   : "before opening " + pending_.file.filename().string();
    unsavedQuestion_.ask({"Unsaved changes", name + " has unsaved changes. Save them " + before + "?", "Save",
                          "Discard", /*cancellable=*/true});
}

void FileActions::answerUnsavedChanges(Answer answer) {
    switch (answer) {
        case Answer::None:
            return;
        case Answer::Cancel:
            pending_ = {};
            return;
        case Answer::No:
            carryOut(std::exchange(pending_, {}));
            return;
        case Answer::Yes:
            if (doc_.file.empty()) {
                // No file yet: the Save As dialog finishes the job (or its Cancel drops it).
                saveAsForPending_ = true;
                menu_.askSaveAs(suggestSaveAsName(doc_.file));
                return;
            }
            // A failed save loses nothing: the error is shown and the action is dropped.
            if (saveTo(doc_.file).empty())
                carryOut(std::exchange(pending_, {}));
            else
                pending_ = {};
            return;
    }
}

void FileActions::carryOut(PendingAction action) {
    switch (action.kind) {
        case PendingAction::Kind::None:
            break;
        case PendingAction::Kind::Quit:
            exitCode_ = 0;
            break;
        case PendingAction::Kind::Open:
            open(action.file);
            break;
    }
}

void FileActions::openDropped(const std::vector<std::filesystem::path>& paths) {
    bool opened = false;
    for (const std::filesystem::path& path : paths) {
        if (!isSceneFile(path)) {
            log_.error("cannot open dropped file '" + path.string() +
                       "': only glTF scenes (.gltf, .glb) can be opened");
        } else if (opened) {
            log_.warning("dropped several scenes; opened the first, ignored '" + path.string() + "'");
        } else {
            opened = true;
            requestOpen(path);
        }
    }
}

// ---- loading -----------------------------------------------------------------------------------

std::string FileActions::open(const std::filesystem::path& path) {
    if (options_.interactive()) {
        startLoading(path);
        return "";
    }
    Document loaded;
    try {
        loaded = openDocument(path, log_, {}, loadLimits(options_));
    } catch (const std::exception& error) {
        showError(error.what());
        return sceneError_;  // the current document stays
    }
    return adoptDocument(std::move(loaded), path);
}

void FileActions::startLoading(const std::filesystem::path& path) {
    if (loading_) {
        log_.warning("still loading " + loading_->file.filename().string() + "; open " + path.filename().string() +
                     " when it is done");
        return;
    }
    Loading loading;
    loading.file = path;
    loading.status = std::make_shared<LoadStatus>();
    loading.start = std::chrono::steady_clock::now();
    // The worker gets its own copies: the path, the status it reports into, and the log, which
    // is thread-safe. The Document comes back through the future (or its exception does).
    loading.result =
        std::async(std::launch::async, [path, status = loading.status, &log = log_, limits = loadLimits(options_)] {
            return openDocument(
                path, log,
                [status](const LoadProgress& progress) {
                    const std::lock_guard lock(status->mutex);
                    status->progress = progress;
                },
                limits);
        });
    loading_ = std::move(loading);
    log_.info("loading " + path.string());
}

void FileActions::finishLoading() {
    if (!loading_ || loading_->result.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    if (!loading_->uploading) {
        // The upload (Renderer::setScene) blocks this thread: show its stage for one frame first.
        loading_->uploading = true;
        const std::lock_guard lock(loading_->status->mutex);
        loading_->status->progress = {"upload", 0, 1};
        return;
    }
    Loading loading = std::move(*loading_);
    loading_.reset();
    try {
        adoptDocument(loading.result.get(), loading.file);
    } catch (const std::exception& error) {
        showError(error.what());  // the current document stays
    }
    if (std::exchange(recoveryAfterLoad_, false)) offerRecovery();
}

void FileActions::drawLoadingWindow() {
    if (!loading_) return;
    LoadProgress progress;
    {
        const std::lock_guard lock(loading_->status->mutex);
        progress = loading_->status->progress;
    }
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - loading_->start;
    lit::editor::drawLoadingWindow(loading_->file, progress, elapsed.count());
}

std::string FileActions::adoptDocument(Document loaded, const std::filesystem::path& path) {
    // The settings come with the file (its sidecar), else they are the defaults.
    doc_ = std::move(loaded);
    try {
        upload_.upload(doc_.scene);
    } catch (const std::exception& error) {
        // The file parsed but the GPU copy failed (e.g. a texture over the driver's limits):
        // fall back to an empty scene rather than render a half-uploaded one.
        showError("cannot upload scene '" + path.string() + "': " + error.what());
        doc_ = Document{};
        upload_.upload(doc_.scene);
        documentReplaced_();
        return sceneError_;
    }
    if (!path.empty()) recent_.add(path);  // a recovered untitled document has no file
    sceneError_.clear();
    log_.info("opened scene " + (path.empty() ? std::string("(untitled)") : path.string()));
    for (const std::string& problem : nodeAnimationProblems(doc_.scene)) log_.warning(problem);
    documentReplaced_();
    return "";
}

// ---- saving ------------------------------------------------------------------------------------

std::string FileActions::saveTo(const std::filesystem::path& target) {
    // A copy: `target` may be doc_.file itself, which saving updates.
    const std::filesystem::path path = target;
    try {
        saveDocument(doc_, path);
    } catch (const std::exception& error) {
        showError(std::string("Not saved: ") + error.what());
        return error.what();
    }
    recent_.add(path);
    const std::string note = uncompressedSaveNote(doc_.scene);
    log_.info("saved " + path.string() + (note.empty() ? "" : " (" + note + ")"));
    return "";
}

void FileActions::saveOrAskForName() {
    if (doc_.file.empty())
        menu_.askSaveAs(suggestSaveAsName(doc_.file));
    else
        saveTo(doc_.file);
}

void FileActions::saveAs(const std::filesystem::path& path) {
    const bool saved = saveTo(path).empty();
    if (!std::exchange(saveAsForPending_, false)) return;
    if (saved)
        carryOut(std::exchange(pending_, {}));
    else
        pending_ = {};
}

void FileActions::saveAsCancelled() {
    if (std::exchange(saveAsForPending_, false)) pending_ = {};
}

// ---- autosave and recovery ---------------------------------------------------------------------

void FileActions::autosave(double nowSeconds) {
    if (!autosave_) return;
    autosave_->maybeSave(doc_, nowSeconds);
    // Say once per new problem why there is no autosave copy (another editor holds the folder, a
    // full disk...).
    if (autosave_->lastError() != lastAutosaveError_) {
        lastAutosaveError_ = autosave_->lastError();
        if (!lastAutosaveError_.empty()) log_.warning(lastAutosaveError_);
    }
}

void FileActions::exiting(int exitCode) {
    if (autosave_ && exitCode == 0) autosave_->cleanExit();
}

void FileActions::offerRecovery() {
    const std::optional<AutosaveInfo> info = autosave_->recoverable();
    if (!info) return;
    recoverQuestion_.ask({"Recover autosave",
                          "The editor did not exit cleanly. Recover the autosave from " + info->timeText + " of " +
                              displayName(info->documentFile) + "?",
                          "Recover", "Discard", /*cancellable=*/false});
}

void FileActions::answerRecovery(Answer answer) {
    switch (answer) {
        case Answer::None:
        case Answer::Cancel:
            return;  // left as it is: offered again next start
        case Answer::No:
            autosave_->discard();
            return;
        case Answer::Yes: {
            try {
                Document recovered = autosave_->recover(log_);
                const std::filesystem::path file = recovered.file;
                if (adoptDocument(std::move(recovered), file).empty())
                    log_.info("recovered the autosave of " + displayName(doc_.file));
            } catch (const std::exception& error) {
                showError(std::string("cannot recover the autosave: ") + error.what());
            }
            return;
        }
    }
}

void FileActions::drawQuestions() {
    answerUnsavedChanges(unsavedQuestion_.draw());
    answerRecovery(recoverQuestion_.draw());
}

}  // namespace lit::editor
