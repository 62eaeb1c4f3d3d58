#include <gtest/gtest.h>

#include <string_view>
#include <vector>

#include "EditorOptions.h"

namespace {

using lit::editor::EditorOptions;
using lit::editor::OptionsError;
using lit::editor::parseEditorOptions;

EditorOptions parse(std::vector<std::string_view> args) { return parseEditorOptions(args); }

// The message names the offending argument, so a test can tell one mistake from another.
std::string errorOf(std::vector<std::string_view> args) {
    try {
        parseEditorOptions(args);
    } catch (const OptionsError& error) {
        return error.what();
    }
    return "no error";
}

TEST(EditorOptions, DefaultsOpenTheBuiltInSceneInA1280x720Window) {
    const EditorOptions options = parse({});
    EXPECT_FALSE(options.scene);
    EXPECT_FALSE(options.screenshot);
    EXPECT_EQ(options.width, 1280);
    EXPECT_EQ(options.height, 720);
    EXPECT_FALSE(options.help);
}

TEST(EditorOptions, FrameLog) {
    EXPECT_FALSE(parse({}).frameLog);
    const EditorOptions options = parse({"--script", "s.lit", "--frame-log", "frames.csv"});
    ASSERT_TRUE(options.frameLog);
    EXPECT_EQ(*options.frameLog, "frames.csv");
    EXPECT_EQ(errorOf({"--frame-log"}), "--frame-log needs a value");
    EXPECT_EQ(errorOf({"--frame-log", ""}), "--frame-log needs a file name");
}

TEST(EditorOptions, ParsesSceneScreenshotFramesAndSize) {
    const EditorOptions options =
        parse({"scene.gltf", "--screenshot", "out.png", "--frames", "5", "--size", "640x360"});
    ASSERT_TRUE(options.scene);
    EXPECT_EQ(*options.scene, "scene.gltf");
    ASSERT_TRUE(options.screenshot);
    EXPECT_EQ(*options.screenshot, "out.png");
    EXPECT_EQ(options.frames, 5);
    EXPECT_EQ(options.width, 640);
    EXPECT_EQ(options.height, 360);
}

TEST(EditorOptions, OptionsMayComeBeforeTheScene) {
    const EditorOptions options = parse({"--size", "800x600", "box.glb"});
    ASSERT_TRUE(options.scene);
    EXPECT_EQ(*options.scene, "box.glb");
    EXPECT_EQ(options.width, 800);
}

TEST(EditorOptions, ScreenshotDefaultsToEnoughFramesForGpuTimings) {
    // The profiler's timings arrive kFramesInFlight (4) frames late.
    EXPECT_GT(parse({"--screenshot", "a.png"}).frames, 4);
}

TEST(EditorOptions, Help) {
    EXPECT_TRUE(parse({"--help"}).help);
    EXPECT_TRUE(parse({"-h"}).help);
}

// As lit-render's flag: off unless given, so a scene from elsewhere cannot read other files.
TEST(EditorOptions, AllowExternalUrisIsOffUnlessGiven) {
    EXPECT_FALSE(parse({"scene.gltf"}).allowExternalUris);
    const EditorOptions options = parse({"--allow-external-uris", "scene.gltf"});
    EXPECT_TRUE(options.allowExternalUris);
    ASSERT_TRUE(options.scene);
    EXPECT_EQ(*options.scene, "scene.gltf");
    EXPECT_NE(lit::editor::editorUsage().find("--allow-external-uris"), std::string::npos);
}

// The help names where the layout is kept and how to move it.
TEST(EditorOptions, UsageNamesTheLayoutFile) {
    EXPECT_NE(lit::editor::editorUsage().find("~/.config/lit/imgui.ini"), std::string::npos);
    EXPECT_NE(lit::editor::editorUsage().find("LIT_EDITOR_LAYOUT"), std::string::npos);
}

TEST(EditorOptions, RejectsBadInputWithMessagesNamingTheProblem) {
    EXPECT_NE(errorOf({"--size", "640"}).find("WIDTHxHEIGHT"), std::string::npos);
    EXPECT_NE(errorOf({"--size", "0x360"}).find("--size"), std::string::npos);
    EXPECT_NE(errorOf({"--size", "640xabc"}).find("--size height"), std::string::npos);
    EXPECT_NE(errorOf({"--frames", "0", "--screenshot", "a.png"}).find("--frames"), std::string::npos);
    EXPECT_NE(errorOf({"--frames", "3"}).find("only applies with --screenshot"), std::string::npos);
    EXPECT_NE(errorOf({"--screenshot"}).find("needs a value"), std::string::npos);
    EXPECT_NE(errorOf({"--bogus"}).find("unknown option '--bogus'"), std::string::npos);
    EXPECT_NE(errorOf({"a.gltf", "b.gltf"}).find("more than one scene"), std::string::npos);
}

}  // namespace

namespace {

TEST(EditorOptions, ParsesScript) {
    const EditorOptions options = lit::editor::parseEditorOptions(
        std::vector<std::string_view>{"scene.gltf", "--script", "walk.txt", "--size", "640x360"});
    ASSERT_TRUE(options.script);
    EXPECT_EQ(*options.script, "walk.txt");
    EXPECT_FALSE(options.screenshot);
}

TEST(EditorOptions, ScriptNeedsAFileAndExcludesScreenshotMode) {
    EXPECT_NE(errorOf({"--script"}).find("needs a value"), std::string::npos);
    EXPECT_NE(errorOf({"--script", ""}).find("--script needs a file name"), std::string::npos);
    EXPECT_NE(errorOf({"--script", "a.txt", "--screenshot", "a.png"}).find("cannot be combined"), std::string::npos);
}

}  // namespace
