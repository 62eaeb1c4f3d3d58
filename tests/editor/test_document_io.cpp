#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>

#include "DocumentIO.h"
#include "EditorFixtures.h"
#include "Log.h"
#include "Properties.h"
#include "Renderer.h"
#include "ScreenshotNames.h"
#include "animation/CameraPathIO.h"
#include "scene/GltfLoader.h"
#include "scene/GltfWriter.h"

namespace {

using namespace lit;
using namespace lit::editor;
using lit::editor::testing::fixtureDocument;
using lit::editor::testing::fixturePath;
namespace fs = std::filesystem;

// A fresh, empty folder per test.
fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::path(::testing::TempDir()) / ("lit_docio_" + std::to_string(::getpid())) / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

void quiet(Log& log) { log.setSink([](const LogMessage&) {}); }

bool logged(const Log& log, LogLevel level, const std::string& part) {
    for (const LogMessage& m : log.recent())
        if (m.level == level && m.text.find(part) != std::string::npos) return true;
    return false;
}

std::string readText(const fs::path& file) {
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// ---- screenshot names ------------------------------------------------------------------------

std::chrono::system_clock::time_point utc(int year, int month, int day, int hour, int minute, int second) {
    std::tm t{};
    t.tm_year = year - 1900;
    t.tm_mon = month - 1;
    t.tm_mday = day;
    t.tm_hour = hour;
    t.tm_min = minute;
    t.tm_sec = second;
    return std::chrono::system_clock::from_time_t(timegm(&t));
}

class ScreenshotNames : public ::testing::Test {
protected:
    void SetUp() override {
        if (const char* tz = std::getenv("TZ")) oldTz_ = tz;
        ::setenv("TZ", "UTC", 1);
        ::tzset();
    }
    void TearDown() override {
        if (oldTz_) ::setenv("TZ", oldTz_->c_str(), 1);
        else ::unsetenv("TZ");
        ::tzset();
    }
    std::optional<std::string> oldTz_;
};

TEST_F(ScreenshotNames, NamedByLocalTimeWithUiSuffix) {
    const fs::path folder = freshFolder("shots");
    const auto time = utc(2026, 12, 1, 16, 5, 9) + std::chrono::milliseconds(700);
    EXPECT_EQ(timestampedScreenshotPath(folder, false, time), folder / "lit_2026-12-01_16-05-09.png");
    EXPECT_EQ(timestampedScreenshotPath(folder, true, time), folder / "lit_2026-12-01_16-05-09_ui.png");
    EXPECT_EQ(timestampedScreenshotPath("screenshots", false, utc(2027, 1, 2, 3, 4, 5)),
              fs::path("screenshots") / "lit_2027-01-02_03-04-05.png");
}

TEST_F(ScreenshotNames, NeverNamesAnExistingFile) {
    const fs::path folder = freshFolder("shots_taken");
    const auto time = utc(2026, 12, 1, 16, 5, 9);
    std::ofstream(folder / "lit_2026-12-01_16-05-09.png") << "x";
    EXPECT_EQ(timestampedScreenshotPath(folder, false, time), folder / "lit_2026-12-01_16-05-09_2.png");
    std::ofstream(folder / "lit_2026-12-01_16-05-09_2.png") << "x";
    EXPECT_EQ(timestampedScreenshotPath(folder, false, time), folder / "lit_2026-12-01_16-05-09_3.png");
    // The UI variant is a different name.
    EXPECT_EQ(timestampedScreenshotPath(folder, true, time), folder / "lit_2026-12-01_16-05-09_ui.png");
}

// ---- open / save -----------------------------------------------------------------------------

void expectNear(const glm::vec3& a, const glm::vec3& b, const std::string& what) {
    EXPECT_LT(glm::length(a - b), 1e-5f) << what;
}

TEST(DocumentIO, SidecarNameAppendsLitJson) {
    EXPECT_EQ(settingsSidecarPath("a/scene.gltf"), fs::path("a/scene.gltf.lit.json"));
    EXPECT_EQ(settingsSidecarPath("scene.glb"), fs::path("scene.glb.lit.json"));
}

TEST(DocumentIO, OpenMissingFileThrows) {
    Log log;
    quiet(log);
    EXPECT_THROW(openDocument(freshFolder("missing") / "nope.gltf", log), SceneLoadError);
}

// A buffer outside the scene's folder (here "../cornell_box.bin") is refused unless the session
// allows external URIs (lit-editor --allow-external-uris).
TEST(DocumentIO, ExternalBufferIsRefusedUnlessAllowed) {
    const fs::path folder = freshFolder("external");
    fs::create_directories(folder / "inner");
    fs::copy_file(fs::path(defaultScenePath()).replace_extension(".bin"), folder / "cornell_box.bin");
    std::string text = readText(defaultScenePath());
    const std::string uri = "\"uri\": \"cornell_box.bin\"";
    const std::size_t at = text.find(uri);
    ASSERT_NE(at, std::string::npos) << "the Cornell box no longer names cornell_box.bin";
    text.replace(at, uri.size(), "\"uri\": \"../cornell_box.bin\"");
    const fs::path scene = folder / "inner" / "outside.gltf";
    std::ofstream(scene) << text;
    Log log;
    quiet(log);
    try {
        openDocument(scene, log);
        ADD_FAILURE() << "a buffer outside the scene's folder was read";
    } catch (const SceneLoadError& error) {
        EXPECT_NE(std::string(error.what()).find("--allow-external-uris"), std::string::npos) << error.what();
    }
    GltfLimits limits;
    limits.allowExternalUris = true;
    const Document doc = openDocument(scene, log, {}, limits);
    EXPECT_FALSE(doc.scene.meshes.empty());
}

// A scene without lights gets no light node (the renderer lights it with its default sun and
// sky, which a save does not write); a scene without cameras gets a camera.
TEST(DocumentIO, OpenGivesASceneWithoutLightsAndCamerasDefaults) {
    const fs::path folder = freshFolder("defaults");
    Scene scene;
    addMeshNode(scene, makeBoxMesh("Box", glm::vec3(1.0f), addMaterial(scene, glm::vec3(0.5f))), glm::vec3(0.0f));
    scene.updateWorldTransforms();
    saveGltf(scene, folder / "bare.gltf");
    Log log;
    quiet(log);
    const Document doc = openDocument(folder / "bare.gltf", log);
    EXPECT_EQ(doc.scene.lights.size(), 0u);
    EXPECT_EQ(doc.scene.cameras.size(), 1u);
    EXPECT_TRUE(doc.cameraPath.empty());
    // The render settings' defaults, the same for every front end.
    EXPECT_EQ(doc.settings, RenderSettings{});
    EXPECT_EQ(doc.file, folder / "bare.gltf");
    EXPECT_FALSE(doc.dirty());
    EXPECT_TRUE(logged(log, LogLevel::Info, "no cameras"));
}

TEST(DocumentIO, ABadSidecarIsAWarning) {
    const fs::path folder = freshFolder("bad_sidecar");
    Document doc = fixtureDocument();
    saveDocument(doc, folder / "s.gltf");
    std::ofstream(settingsSidecarPath(folder / "s.gltf")) << "{ \"gi\": 3 ";  // not JSON
    Log log;
    quiet(log);
    const Document reopened = openDocument(folder / "s.gltf", log);
    EXPECT_EQ(reopened.settings, RenderSettings{});
    EXPECT_TRUE(logged(log, LogLevel::Warning, "s.gltf.lit.json"));
}

TEST(DocumentIO, SaveAndOpenKeepEveryEdit) {
    const fs::path folder = freshFolder("round_trip");
    Log log;
    quiet(log);
    Document doc = openDocument(defaultScenePath(), log);
    ASSERT_FALSE(doc.dirty());

    auto set = [&](const char* node, const char* name, const char* value) {
        doc.selectedNode = findNode(doc.scene, node);
        ASSERT_GE(doc.selectedNode, 0) << node;
        ASSERT_EQ(setProperty(doc, name, value), "") << name;
    };
    set("tall_box", "node.translation", "0.1 0.2 -0.3");
    set("tall_box", "node.rotation", "0 30 0");
    set("tall_box", "node.scale", "1 1.5 1");
    set("short_box", "node.name", "small box");
    set("left_wall_red", "material.albedo", "0.7 0.05 0.1");
    set("left_wall_red", "material.roughness", "0.35");
    set("left_wall_red", "material.metalness", "0.25");
    set("left_wall_red", "material.emissive", "0.5 0.25 0");
    set("left_wall_red", "material.emissiveStrength", "4");
    set("ceiling_spot", "light.color", "1 0.9 0.8");
    set("ceiling_spot", "light.intensity", "42");
    set("ceiling_spot", "light.range", "8");
    set("ceiling_spot", "light.outer", "50");
    set("ceiling_spot", "light.inner", "20");
    set("camera", "camera.fov", "50");
    set("camera", "camera.near", "0.1");
    CameraPathOptions options;
    options.constantSpeed = true;
    const CameraPath path(fixturePath().keys(), options);
    doc.edit("Path", Change::CameraPath, [&](Scene&) { doc.cameraPath = path; });
    doc.settings.gi.enabled = false;
    doc.settings.output.exposureEv = 1.5f;
    doc.settings.debug.view = View::Albedo;
    doc.settings.gi.voxelResolution = 64;
    ASSERT_TRUE(doc.dirty());

    const fs::path file = folder / "edited.gltf";
    saveDocument(doc, file);
    EXPECT_EQ(doc.file, file);
    EXPECT_FALSE(doc.dirty());
    EXPECT_TRUE(fs::exists(settingsSidecarPath(file)));

    Log log2;
    quiet(log2);
    const Document back = openDocument(file, log2);
    EXPECT_EQ(log2.countAtLeast(LogLevel::Warning), 0u);
    EXPECT_FALSE(back.dirty());
    EXPECT_EQ(back.settings, doc.settings);
    EXPECT_EQ(back.cameraPath.options(), options);
    ASSERT_EQ(back.cameraPath.keys().size(), path.keys().size());
    for (std::size_t i = 0; i < path.keys().size(); ++i) {
        EXPECT_FLOAT_EQ(back.cameraPath.keys()[i].time, path.keys()[i].time);
        expectNear(back.cameraPath.keys()[i].position, path.keys()[i].position, "key position");
        EXPECT_NEAR(std::abs(glm::dot(back.cameraPath.keys()[i].rotation, path.keys()[i].rotation)), 1.0f, 1e-6f);
        EXPECT_FLOAT_EQ(back.cameraPath.keys()[i].yfov, path.keys()[i].yfov);
    }

    const int tall = findNode(back.scene, "tall_box");
    ASSERT_GE(tall, 0);
    const Node& original = doc.scene.nodes[findNode(doc.scene, "tall_box")];
    expectNear(back.scene.nodes[tall].translation, original.translation, "translation");
    expectNear(back.scene.nodes[tall].scale, original.scale, "scale");
    EXPECT_NEAR(std::abs(glm::dot(back.scene.nodes[tall].rotation, original.rotation)), 1.0f, 1e-6f);
    EXPECT_GE(findNode(back.scene, "small box"), 0);
    EXPECT_EQ(findNode(back.scene, "short_box"), -1);

    const Node& wall = back.scene.nodes[findNode(back.scene, "left_wall_red")];
    const Material& red = back.scene.materials.at(back.scene.meshes.at(wall.mesh).primitives.at(0).material);
    EXPECT_LT(glm::length(red.baseColorFactor - glm::vec4(0.7f, 0.05f, 0.1f, 1.0f)), 1e-5f);
    EXPECT_NEAR(red.roughness, 0.35f, 1e-6f);
    EXPECT_NEAR(red.metallic, 0.25f, 1e-6f);
    expectNear(red.emissiveFactor, {0.5f, 0.25f, 0.0f}, "emissive");
    EXPECT_NEAR(red.emissiveStrength, 4.0f, 1e-6f);

    const Light& spot = back.scene.lights.at(back.scene.nodes[findNode(back.scene, "ceiling_spot")].light);
    expectNear(spot.color, {1.0f, 0.9f, 0.8f}, "light colour");
    EXPECT_NEAR(spot.intensity, 42.0f, 1e-4f);
    EXPECT_NEAR(spot.range, 8.0f, 1e-6f);
    EXPECT_NEAR(spot.outerConeAngle, glm::radians(50.0f), 1e-6f);
    EXPECT_NEAR(spot.innerConeAngle, glm::radians(20.0f), 1e-6f);

    const Camera& camera = back.scene.cameras.at(back.scene.nodes[findNode(back.scene, "camera")].camera);
    EXPECT_NEAR(camera.yfov, glm::radians(50.0f), 1e-6f);
    EXPECT_NEAR(camera.znear, 0.1f, 1e-7f);
}

// ---- autosave --------------------------------------------------------------------------------

void moveBox(Document& doc, float x) {
    doc.edit("Move", Change::Transform, [x](Scene& s) { s.nodes[0].translation.x = x; });
}

// What a crashed session leaves in `folder`: a copy of `doc` with its box moved to x = 1, and
// the lock (the Autosave is destroyed without cleanExit()).
void leaveCrashedCopy(const fs::path& folder, Document& doc) {
    Autosave crashed(folder, 1.0);
    moveBox(doc, 1.0f);
    crashed.saveNow(doc);
}

TEST(Autosave, DefaultFolderFollowsXdgStateHome) {
    const char* old = std::getenv("XDG_STATE_HOME");
    const std::optional<std::string> saved = old ? std::optional<std::string>(old) : std::nullopt;
    ::setenv("XDG_STATE_HOME", "/some/state", 1);
    EXPECT_EQ(Autosave::defaultFolder(), fs::path("/some/state/lit"));
    ::setenv("XDG_STATE_HOME", "relative/ignored", 1);
    if (const char* home = std::getenv("HOME")) {
        EXPECT_EQ(Autosave::defaultFolder(), fs::path(home) / ".local/state/lit");
    }
    if (saved) ::setenv("XDG_STATE_HOME", saved->c_str(), 1);
    else ::unsetenv("XDG_STATE_HOME");
}

TEST(Autosave, WritesAfterTheIntervalOnlyWhenDirty) {
    const fs::path folder = freshFolder("autosave_interval");
    Document doc = fixtureDocument();
    Autosave autosave(folder, 60.0);
    ASSERT_TRUE(autosave.active()) << autosave.lastError();
    EXPECT_TRUE(fs::exists(autosave.lockFile()));
    EXPECT_FALSE(autosave.recoverable());

    autosave.maybeSave(doc, 1000.0);  // the clock starts
    autosave.maybeSave(doc, 1100.0);  // clean: nothing to write
    EXPECT_FALSE(fs::exists(autosave.autosaveFile()));

    moveBox(doc, 2.0f);
    autosave.maybeSave(doc, 1130.0);  // 30 s since the last check
    EXPECT_FALSE(fs::exists(autosave.autosaveFile()));
    autosave.maybeSave(doc, 1161.0);
    ASSERT_TRUE(fs::exists(autosave.autosaveFile())) << autosave.lastError();
    ASSERT_TRUE(fs::exists(autosave.markerFile()));
    EXPECT_NE(readText(autosave.markerFile()).find("fixture.gltf"), std::string::npos);

    // Saved since: the copy goes at the next interval.
    doc.markSaved();
    autosave.maybeSave(doc, 1200.0);
    EXPECT_TRUE(fs::exists(autosave.autosaveFile()));
    autosave.maybeSave(doc, 1230.0);
    EXPECT_FALSE(fs::exists(autosave.autosaveFile()));
    EXPECT_FALSE(fs::exists(autosave.markerFile()));
    autosave.cleanExit();
    EXPECT_FALSE(fs::exists(autosave.lockFile()));
}

TEST(Autosave, ACrashLeavesARecoverableCopy) {
    const fs::path folder = freshFolder("autosave_crash");
    Document doc = fixtureDocument();
    doc.settings.output.exposureEv = 3.0f;
    {
        Autosave crashed(folder, 60.0);
        moveBox(doc, 4.0f);
        crashed.maybeSave(doc, 0.0);
        crashed.maybeSave(doc, 60.0);
        ASSERT_TRUE(fs::exists(crashed.autosaveFile())) << crashed.lastError();
        // Destroyed without cleanExit(): the lock stays, as after a crash.
    }
    Autosave next(folder, 60.0);
    const std::optional<AutosaveInfo> info = next.recoverable();
    ASSERT_TRUE(info.has_value());
    EXPECT_EQ(info->documentFile, fs::path("fixture.gltf"));
    EXPECT_EQ(info->autosaveFile.parent_path(), folder);
    EXPECT_TRUE(fs::exists(info->autosaveFile)) << info->autosaveFile;
    EXPECT_EQ(info->timeText.size(), std::string("2026-12-01 16:05").size());

    // Until the user answers, this session does not overwrite the copy.
    Document other = fixtureDocument();
    moveBox(other, -9.0f);
    next.maybeSave(other, 0.0);
    next.maybeSave(other, 500.0);
    Log log;
    quiet(log);
    const Document recovered = next.recover(log);
    EXPECT_EQ(recovered.scene.nodes[0].translation.x, 4.0f);
    EXPECT_EQ(recovered.file, fs::path("fixture.gltf"));
    EXPECT_EQ(recovered.settings.output.exposureEv, 3.0f);
    EXPECT_EQ(recovered.cameraPath.keys().size(), 2u);
    EXPECT_TRUE(recovered.dirty());
    EXPECT_FALSE(next.recoverable());
    next.cleanExit();

    Autosave afterClean(folder, 60.0);
    EXPECT_FALSE(afterClean.recoverable());
    EXPECT_FALSE(fs::exists(afterClean.autosaveFile()));
    afterClean.cleanExit();
}

TEST(Autosave, NothingToRecoverAfterACleanExit) {
    const fs::path folder = freshFolder("autosave_clean");
    Document doc = fixtureDocument();
    {
        Autosave session(folder, 10.0);
        moveBox(doc, 1.0f);
        session.maybeSave(doc, 0.0);
        session.maybeSave(doc, 10.0);
        ASSERT_TRUE(fs::exists(session.autosaveFile()));
        session.cleanExit();
        EXPECT_FALSE(fs::exists(session.lockFile()));
        EXPECT_FALSE(fs::exists(session.autosaveFile()));
    }
    Autosave next(folder, 10.0);
    EXPECT_FALSE(next.recoverable());
    next.cleanExit();
}

TEST(Autosave, AnUnansweredCopyIsOfferedAgain) {
    const fs::path folder = freshFolder("autosave_unanswered");
    Document doc = fixtureDocument();
    leaveCrashedCopy(folder, doc);
    {
        Autosave next(folder, 1.0);
        ASSERT_TRUE(next.recoverable());
        next.cleanExit();  // quit without answering
        EXPECT_TRUE(fs::exists(next.autosaveFile()));
    }
    Autosave third(folder, 1.0);
    EXPECT_TRUE(third.recoverable());
    third.discard();
    third.cleanExit();
    EXPECT_FALSE(fs::exists(third.lockFile()));
    EXPECT_FALSE(fs::exists(third.autosaveFile()));
}

TEST(Autosave, DiscardDropsTheCopy) {
    const fs::path folder = freshFolder("autosave_discard");
    Document doc = fixtureDocument();
    leaveCrashedCopy(folder, doc);
    Autosave next(folder, 1.0);
    ASSERT_TRUE(next.recoverable());
    next.discard();
    EXPECT_FALSE(next.recoverable());
    EXPECT_FALSE(fs::exists(next.autosaveFile()));
    // Now this session's own copies are written.
    next.maybeSave(doc, 0.0);
    next.maybeSave(doc, 1.0);
    EXPECT_TRUE(fs::exists(next.autosaveFile()));
    next.cleanExit();
}

TEST(Autosave, ALockOfALiveEditorIsLeftAlone) {
    const fs::path folder = freshFolder("autosave_live");
    Document doc = fixtureDocument();
    leaveCrashedCopy(folder, doc);
    // The parent process (the test runner's shell or ctest) is alive and not us.
    std::ofstream(folder / "session.lock") << ::getppid() << "\n";
    Autosave second(folder, 1.0);
    EXPECT_FALSE(second.active());
    EXPECT_FALSE(second.recoverable());
    EXPECT_NE(second.lastError().find("another editor"), std::string::npos);
    second.cleanExit();  // not ours: stays
    EXPECT_TRUE(fs::exists(folder / "session.lock"));
    EXPECT_TRUE(fs::exists(folder / "autosave-1.glb"));  // the crashed copy (the first autosave writes copy 1)

    // A lock of a process that is gone is a crash.
    std::ofstream(folder / "session.lock") << 999999999 << "\n";
    Autosave third(folder, 1.0);
    EXPECT_TRUE(third.active());
    EXPECT_TRUE(third.recoverable());
    third.cleanExit();
}

}  // namespace

namespace {

using namespace lit;
using namespace lit::editor;

TEST(DocumentIO, EveryCameraAnimationIsListedAndCanBeChosenUndoneAndSaved) {
    const fs::path folder = fs::path(::testing::TempDir()) / ("lit_docio_anim_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    const fs::path file = folder / "anim.gltf";
    // A file whose only camera animation is Blender-style "fly" (3 keys).
    Document made = lit::editor::testing::fixtureDocument();
    made.cameraPath = CameraPath();
    saveDocument(made, file);
    std::vector<CameraKey> keys(3);
    for (int i = 0; i < 3; ++i) {
        keys[static_cast<std::size_t>(i)].time = static_cast<float>(i);
        keys[static_cast<std::size_t>(i)].position = {static_cast<float>(i), 1.0f, 4.0f};
    }
    saveCameraPathToGltf(file, CameraPath(keys), "fly");

    Log log;
    log.setSink([](const LogMessage&) {});
    Document doc = openDocument(file, log);
    EXPECT_EQ(doc.cameraAnimations, std::vector<std::string>{"fly"});
    EXPECT_EQ(doc.cameraPathName, "fly");  // no "camera path": the file's own animation is edited
    ASSERT_EQ(doc.cameraPath.keys().size(), 3u);

    // A new path under the editor's name, then back: one undo step each.
    ASSERT_EQ(chooseCameraAnimation(doc, "camera path"), "");
    EXPECT_TRUE(doc.cameraPath.empty());
    EXPECT_EQ(doc.undoLabel(), "Edit Animation camera path");
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.cameraPathName, "fly");
    EXPECT_EQ(doc.cameraPath.keys().size(), 3u);
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.cameraPathName, "camera path");
    ASSERT_EQ(chooseCameraAnimation(doc, "fly"), "");
    EXPECT_EQ(doc.cameraPath.keys().size(), 3u);

    // Edit "fly", save, reopen: the edit is in "fly".
    CameraPath edited = doc.cameraPath;
    std::vector<CameraKey> changed = edited.keys();
    changed[1].position.y = 2.5f;
    doc.edit("key", Change::CameraPath, [&](Scene&) { doc.cameraPath = CameraPath(changed, edited.options()); });
    saveDocument(doc, file);
    const Document back = openDocument(file, log);
    EXPECT_EQ(back.cameraPathName, "fly");
    ASSERT_EQ(back.cameraPath.keys().size(), 3u);
    EXPECT_FLOAT_EQ(back.cameraPath.keys()[1].position.y, 2.5f);
}

}  // namespace
