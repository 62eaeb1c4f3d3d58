#pragma once
// The editor's files: opening a scene (on a worker thread behind a progress window when someone
// is at the window, at once for scripts and screenshots), save and save as, quitting, files
// dropped onto the window, and the autosave copy with the offer to recover it after a crash.
// With unsaved changes, open and quit ask first (not in a script); a failed open or save loses
// nothing: the error is shown and the document stays as it was.

#include <chrono>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "Document.h"
#include "DocumentIO.h"
#include "EditorOptions.h"
#include "Log.h"
#include "RecentFiles.h"
#include "SceneUpload.h"
#include "panels/Dialogs.h"
#include "panels/MainMenu.h"

namespace lit::editor {

// The scene the editor starts with, before its window opens. For scripts and screenshots the
// file given (or the Cornell box), and a scene that cannot be loaded throws: those runs exist to
// check a scene. Interactively an empty document; FileActions::start loads the file behind a
// progress bar.
Document loadInitialDocument(const EditorOptions& options, Log& log);

// What the file actions read and change.
struct FileContext {
    const EditorOptions& options;
    Document& doc;
    Log& log;
    std::string& sceneError;  // shown in the UI until dismissed
    RecentFiles& recent;
    MainMenu& menu;                // its Save As dialog names a file that has none
    SceneUpload& upload;           // the renderer's copy of a document opened
    std::optional<int>& exitCode;  // 0 once quitting is confirmed
    // After the document was replaced (opened, recovered, or emptied after a failed upload): the
    // camera goes to the new scene.
    std::function<void()> documentReplaced;
};

class FileActions {
public:
    explicit FileActions(FileContext context);
    // Interactively: starts the autosave and loads the initial scene (the recovery offer comes
    // once it is in, so a recovered copy is not replaced by it); otherwise adds the scene
    // loadInitialDocument opened to the recent files.
    void start();

    // Open and quit as the user asks: with unsaved changes (and not in a script) ask first.
    void requestOpen(const std::filesystem::path& path);
    void requestQuit();
    // Opens without asking. Returns "" or the error, which is also shown and logged; on error
    // the current document stays. Interactively the file loads in the background and this
    // returns at once.
    std::string open(const std::filesystem::path& path);
    // Saves to `path` (the document's file, or Save As). Returns "" or the error, which is also
    // shown and logged; a failed save changes nothing on disk or in the document.
    std::string saveTo(const std::filesystem::path& path);
    // Save (Ctrl+S, File > Save): to the document's file, or through the Save As dialog.
    void saveOrAskForName();
    // The Save As dialog's outcome: saves, and finishes an action waiting for it.
    void saveAs(const std::filesystem::path& path);
    void saveAsCancelled();
    // Files dropped onto the window: opens the first glTF scene, says why the rest are not.
    void openDropped(const std::vector<std::filesystem::path>& paths);

    // Once a frame, before the UI: adopts a scene the worker has finished loading.
    void finishLoading();
    // In the UI: the loading progress and the questions, acting on their answers.
    void drawLoadingWindow();
    void drawQuestions();
    // A scene is loading on the worker: its progress window wants frames while nothing else does.
    bool loading() const { return loading_.has_value(); }
    bool asking() const { return unsavedQuestion_.asking() || recoverQuestion_.asking(); }
    // Once a frame: writes the autosave copy when it is due. `nowSeconds`: a steady clock.
    void autosave(double nowSeconds);
    // The editor ends with `exitCode`: after a normal quit the autosave copy is not needed at the
    // next start.
    void exiting(int exitCode);

private:
    // An action that waits for the answer to "save changes?".
    struct PendingAction {
        enum class Kind { None, Quit, Open } kind = Kind::None;
        std::filesystem::path file;  // Open: the scene to open
    };
    // A scene loading on a worker thread; its progress is written there and read by the UI.
    struct LoadStatus {
        std::mutex mutex;
        LoadProgress progress;
    };
    struct Loading {
        std::filesystem::path file;
        std::shared_ptr<LoadStatus> status;
        std::future<Document> result;
        std::chrono::steady_clock::time_point start;
        bool uploading = false;  // the worker is done; the GPU upload runs after one more frame
    };

    void askAboutUnsavedChanges(PendingAction action);
    void answerUnsavedChanges(Answer answer);
    void carryOut(PendingAction action);
    void startLoading(const std::filesystem::path& path);
    // Makes `loaded` the document and uploads it (an empty one when that fails).
    std::string adoptDocument(Document loaded, const std::filesystem::path& path);
    void offerRecovery();
    void answerRecovery(Answer answer);
    void showError(std::string message);  // sceneError and the log

    const EditorOptions& options_;
    Document& doc_;
    Log& log_;
    std::string& sceneError_;
    RecentFiles& recent_;
    MainMenu& menu_;
    SceneUpload& upload_;
    std::optional<int>& exitCode_;
    std::function<void()> documentReplaced_;
    QuestionDialog unsavedQuestion_;
    QuestionDialog recoverQuestion_;
    PendingAction pending_;
    bool saveAsForPending_ = false;  // the Save As dialog was opened by "Save" in the question
    std::optional<Loading> loading_;
    bool recoveryAfterLoad_ = false;  // offer the autosave once the initial scene is in
    // Periodic copies of the document, offered after a crash. Only interactively: a script must
    // neither be interrupted by an old crash's offer nor leave copies behind.
    std::optional<Autosave> autosave_;
    std::string lastAutosaveError_;  // logged once when it changes
};

}  // namespace lit::editor
