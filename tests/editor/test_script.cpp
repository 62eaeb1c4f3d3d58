#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "Script.h"

namespace {

using namespace lit::editor;

std::string errorOf(const std::string& text) {
    try {
        parseScript(text, "s.txt");
    } catch (const ScriptError& error) {
        return error.what();
    }
    return "";
}

TEST(Script, ParsesEveryCommand) {
    const std::string text =
        "# a comment\n"
        "\n"
        "select Big Box   \n"
        "select -\n"
        "set node.name  A name with spaces  # trailing comment\n"
        "set light.color 1 0.5 0\n"
        "setting gi false\n"
        "setting exposure 1.5\n"
        "setting view albedo\n"
        "view direct-diffuse\n"
        "panel timeline off\n"
        "pick 10 20.5\n"
        "screenshot out/a.png\n"
        "screenshot out/b.png noui\r\n"
        "save\n"
        "save other.glb\n"
        "open scene.gltf\n"
        "undo\n"
        "redo\n"
        "wait 3\n"
        "wait gi\n"
        "key add\n"
        "key delete 0\n"
        "key select 1\n"
        "key time 1 2.5\n"
        "key update 1\n"
        "play\n"
        "pause\n"
        "time 1.25\n"
        "quit";
    const std::vector<ScriptCommand> commands = parseScript(text, "s.txt");
    ASSERT_EQ(commands.size(), 28u);
    EXPECT_EQ(commands[0].line, 3);
    EXPECT_EQ(commands[0].name, "select");
    EXPECT_EQ(commands[0].args, std::vector<std::string>{"Big Box"});
    EXPECT_EQ(commands[1].args, std::vector<std::string>{"-"});
    EXPECT_EQ(commands[2].args, (std::vector<std::string>{"node.name", "A name with spaces"}));
    EXPECT_EQ(commands[3].args, (std::vector<std::string>{"light.color", "1 0.5 0"}));
    EXPECT_EQ(commands[4].args, (std::vector<std::string>{"gi", "false"}));
    EXPECT_EQ(commands[11].args, (std::vector<std::string>{"out/b.png", "noui"}));  // \r dropped
    EXPECT_TRUE(commands[12].args.empty());
    EXPECT_EQ(commands[18].args, std::vector<std::string>{"gi"});
    EXPECT_EQ(commands[22].name, "key");
    EXPECT_EQ(commands[22].args, (std::vector<std::string>{"time", "1", "2.5"}));
    EXPECT_EQ(commands[27].name, "quit");
    EXPECT_EQ(commands[27].line, 30);
}

TEST(Script, EmptyAndCommentOnlyScriptsHaveNoCommands) {
    EXPECT_TRUE(parseScript("", "s.txt").empty());
    EXPECT_TRUE(parseScript("# nothing\n\n   \n", "s.txt").empty());
}

TEST(Script, ErrorsNameTheFileAndLine) {
    EXPECT_EQ(errorOf("wait 1\n\nselec Box\n"), "s.txt:3: unknown command 'selec'");
    EXPECT_EQ(errorOf("select\n"), "s.txt:1: select: expected a node name (or - for none), got 0 arguments");
    EXPECT_EQ(errorOf("undo now\n"), "s.txt:1: undo: expected no arguments, got 1 argument");
    EXPECT_EQ(errorOf("\nwait\n"), "s.txt:2: wait: expected a number of frames, seconds, gi, refined or play, got 0 arguments");
    EXPECT_EQ(errorOf("wait 1.5x\n"), "s.txt:1: wait: expected a whole number of frames (1 or more), seconds (0 < N ≤ 3600, as 2.5s), gi, refined or play, got '1.5x'");
    EXPECT_EQ(errorOf("wait 0\n"), "s.txt:1: wait: expected a whole number of frames (1 or more), seconds (0 < N ≤ 3600, as 2.5s), gi, refined or play, got '0'");
    EXPECT_EQ(errorOf("wait refine\n"),
              "s.txt:1: wait: expected a whole number of frames (1 or more), seconds (0 < N ≤ 3600, as 2.5s), gi, refined or play, got 'refine'");
    EXPECT_EQ(parseScript("wait refined\n", "s.txt").at(0).args, std::vector<std::string>{"refined"});
    EXPECT_EQ(parseScript("wait 2.5s\n", "s.txt").at(0).args, std::vector<std::string>{"2.5s"});
    EXPECT_EQ(waitSeconds("2.5s"), 2.5);
    EXPECT_FALSE(waitSeconds("0s"));
    EXPECT_FALSE(waitSeconds("s"));
    EXPECT_FALSE(waitSeconds("2.5"));
    EXPECT_EQ(errorOf("wait -1s\n"),
              "s.txt:1: wait: expected a whole number of frames (1 or more), seconds (0 < N ≤ 3600, as 2.5s), gi, refined or play, got '-1s'");
    EXPECT_EQ(errorOf("wait GI\n"), "s.txt:1: wait: expected a whole number of frames (1 or more), seconds (0 < N ≤ 3600, as 2.5s), gi, refined or play, got 'GI'");
    EXPECT_EQ(errorOf("set light.intensity\n"), "s.txt:1: set: expected a property and a value");
    EXPECT_EQ(errorOf("set light.intensity 1.5x\n"), "s.txt:1: light.intensity: expected 1 number, got '1.5x'");
    EXPECT_EQ(errorOf("set light.colour 1 1 1\n"), "s.txt:1: unknown property 'light.colour'");
    EXPECT_EQ(errorOf("set light.shadow maybe\n"), "s.txt:1: light.shadow: expected on or off, got 'maybe'");
    EXPECT_EQ(errorOf("setting voxelRes 64\n"), "s.txt:1: unknown render setting 'voxelRes'");
    EXPECT_EQ(errorOf("setting gi\n"), "s.txt:1: setting: expected a setting name and a value, got 1 argument");
    EXPECT_NE(errorOf("setting gi 3\n").find("s.txt:1: "), std::string::npos);
    EXPECT_NE(errorOf("setting gi 3\n").find("'gi'"), std::string::npos);
    EXPECT_EQ(errorOf("view shiny\n"), "s.txt:1: unknown view 'shiny'");
    EXPECT_EQ(errorOf("panel sidebar on\n"),
              "s.txt:1: unknown panel 'sidebar' (hierarchy, inspector, settings, stats, stats-details, camera, log, timeline, legend)");
    EXPECT_EQ(errorOf("panel log maybe\n"), "s.txt:1: panel: expected on or off, got 'maybe'");
    EXPECT_EQ(errorOf("pick 10\n"), "s.txt:1: pick: expected X and Y window pixels, got 1 argument");
    EXPECT_EQ(errorOf("pick 10 -2\n"), "s.txt:1: pick: expected a pixel position, got '-2'");
    EXPECT_EQ(errorOf("screenshot a.png both\n"), "s.txt:1: screenshot: expected ui or noui, got 'both'");
    EXPECT_EQ(errorOf("save a b\n"), "s.txt:1: save: expected at most a file, got 2 arguments");
    EXPECT_EQ(errorOf("open\n"), "s.txt:1: open: expected a file, got 0 arguments");
    EXPECT_EQ(errorOf("key\n"), "s.txt:1: key: expected add, delete I, select I, time I T or update I");
    EXPECT_EQ(errorOf("key remove 1\n"), "s.txt:1: unknown key action 'remove' (add, delete, select, time, update)");
    EXPECT_EQ(errorOf("key add 1\n"), "s.txt:1: key add: expected no values, got 1");
    EXPECT_EQ(errorOf("key select x\n"), "s.txt:1: key select: expected a key index, got 'x'");
    EXPECT_EQ(errorOf("key time 1\n"), "s.txt:1: key time: expected 2 values, got 1");
    EXPECT_EQ(errorOf("key time 1 soon\n"), "s.txt:1: key time: expected seconds, got 'soon'");
    EXPECT_EQ(errorOf("time\n"), "s.txt:1: time: expected a time in seconds, got 0 arguments");
    EXPECT_EQ(errorOf("time 1s\n"), "s.txt:1: time: expected seconds, got '1s'");
    EXPECT_EQ(errorOf("play 9\n"), "s.txt:1: play: expected a speed 0.1..4, got '9'");
    EXPECT_EQ(errorOf("play 1 2\n"), "s.txt:1: play: expected at most a speed, got 2 arguments");
    EXPECT_EQ(errorOf("duration 0\n"), "s.txt:1: duration: expected seconds > 0, got '0'");
    EXPECT_EQ(errorOf("wait playing\n"),
              "s.txt:1: wait: expected a whole number of frames (1 or more), seconds (0 < N ≤ 3600, as 2.5s), gi, refined or play, got 'playing'");
    EXPECT_EQ(errorOf("play 0.5\nwait play\nduration 3\n"), "");
}

TEST(Script, ErrorAtNamesTheCommandsLine) {
    ScriptCommand command;
    command.line = 7;
    EXPECT_EQ(scriptErrorAt(command, "script.txt", "no node called 'X'"), "script.txt:7: no node called 'X'");
}

TEST(Script, LoadScriptReadsAFileAndNamesItInErrors) {
    const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / "lit_script_test";
    std::filesystem::create_directories(folder);
    const std::filesystem::path good = folder / "good.txt";
    std::ofstream(good) << "wait 2\nquit\n";
    const std::vector<ScriptCommand> commands = loadScript(good);
    ASSERT_EQ(commands.size(), 2u);
    EXPECT_EQ(commands[1].name, "quit");

    const std::filesystem::path bad = folder / "bad.txt";
    std::ofstream(bad) << "wait 2\njump\n";
    try {
        loadScript(bad);
        FAIL() << "no error";
    } catch (const ScriptError& error) {
        EXPECT_EQ(std::string(error.what()), bad.string() + ":2: unknown command 'jump'");
    }
    EXPECT_THROW(loadScript(folder / "missing.txt"), ScriptError);
}

}  // namespace

namespace {

using namespace lit::editor;

TEST(Script, CameraAndConeDirectionsCommands) {
    const std::vector<ScriptCommand> commands =
        parseScript("camera 3 2.5 7 0 1 2.5\nview cone-directions\npick 10 20\n", "s.txt");
    ASSERT_EQ(commands.size(), 3u);
    EXPECT_EQ(commands[0].name, "camera");
    EXPECT_EQ(commands[0].args.size(), 6u);
    EXPECT_EQ(commands[1].args[0], kConeDirectionsView);
    EXPECT_THROW(parseScript("camera 1 2 3\n", "s.txt"), ScriptError);
    EXPECT_THROW(parseScript("camera 1 2 3 4 5 six\n", "s.txt"), ScriptError);
}

// "interactive on|off": the interactive render scale in a script (frame-rate measurements).
TEST(Script, InteractiveCommand) {
    const std::vector<ScriptCommand> commands = parseScript("interactive on\ninteractive off\n", "s.txt");
    ASSERT_EQ(commands.size(), 2u);
    EXPECT_EQ(commands[0].name, "interactive");
    EXPECT_EQ(commands[0].args[0], "on");
    EXPECT_EQ(commands[1].args[0], "off");
    EXPECT_EQ(errorOf("interactive yes\n"), "s.txt:1: interactive: expected on or off, got 'yes'");
    EXPECT_THROW(parseScript("interactive\n", "s.txt"), ScriptError);
}

// "memory" logs what the process holds and "loop" starts the script over (for the soak test).
TEST(Script, MemoryAndLoopCommands) {
    const std::vector<ScriptCommand> commands = parseScript("memory\nloop\n", "s.txt");
    ASSERT_EQ(commands.size(), 2u);
    EXPECT_EQ(commands[0].name, "memory");
    EXPECT_EQ(commands[1].name, "loop");
    EXPECT_EQ(errorOf("wait 1\nmemory now\n"), "s.txt:2: memory: expected no arguments, got 1 argument");
    EXPECT_EQ(errorOf("loop 3\n"), "s.txt:1: loop: expected no arguments, got 1 argument");
    EXPECT_EQ(errorOf("layout now\n"), "s.txt:1: layout: expected no arguments, got 1 argument");
}

}  // namespace

namespace {

using namespace lit::editor;

TEST(Script, ParsesTheAuthoringCommands) {
    const std::string text =
        "add box\n"
        "add spot 1 2 3.5\n"
        "select+ Big Box\n"
        "delete\n"
        "duplicate\n"
        "parent The Parent\n"
        "parent -\n"
        "material unique\n"
        "primitive 1\n"
        "gizmo rotate\n"
        "space local\n"
        "snap on\n"
        "snap 0.5 15 0.25\n"
        "drag 10 20 30.5 40\n"
        "frame\n"
        "orbit -20 5\n"
        "animation my fly\n";
    const std::vector<ScriptCommand> commands = parseScript(text, "s.txt");
    ASSERT_EQ(commands.size(), 17u);
    EXPECT_EQ(commands[1].args, (std::vector<std::string>{"spot", "1", "2", "3.5"}));
    EXPECT_EQ(commands[2].args, std::vector<std::string>{"Big Box"});
    EXPECT_EQ(commands[5].args, std::vector<std::string>{"The Parent"});
    EXPECT_EQ(commands[16].args, std::vector<std::string>{"my fly"});
}

TEST(Script, RejectsBadAuthoringCommands) {
    auto errorOf = [](const std::string& text) -> std::string {
        try {
            parseScript(text, "s.txt");
        } catch (const ScriptError& error) {
            return error.what();
        }
        return "";
    };
    EXPECT_EQ(errorOf("add cone\n"), "s.txt:1: unknown kind 'cone' (empty, directional, point, spot, camera, box, plane, sphere)");
    EXPECT_NE(errorOf("add box 1 2\n"), "");
    EXPECT_NE(errorOf("gizmo spin\n"), "");
    EXPECT_NE(errorOf("space global\n"), "");
    EXPECT_NE(errorOf("snap 0 15 0.1\n"), "");  // a zero step
    EXPECT_NE(errorOf("snap maybe\n"), "");
    EXPECT_NE(errorOf("drag 1 2 3\n"), "");
    EXPECT_NE(errorOf("delete now\n"), "");
    EXPECT_NE(errorOf("material shared\n"), "");
    EXPECT_NE(errorOf("primitive -1\n"), "");
    EXPECT_NE(errorOf("select+\n"), "");
}

}  // namespace

namespace {

using namespace lit::editor;

// The command table gives each command its own verb, and every verb has a command (the runner
// switches over the verbs).
TEST(Script, EachCommandHasItsOwnVerb) {
    const std::vector<ScriptCommand> commands = parseScript(
        "select A\nselect+ A\nadd box\ndelete\nduplicate\nparent -\nmaterial unique\nprimitive 0\n"
        "gizmo rotate\nspace local\nsnap on\ndrag 1 2 3 4\nframe\norbit 1 2\nanimation a\nset node.name A\n"
        "setting gi false\nview final\npanel log on\npick 1 2\nscreenshot a.png\nsave\nopen a.gltf\n"
        "camera 0 0 0 1 1 1\nundo\nredo\ninteractive on\nwait 1\nkey add\nplay\npause\ntime 1\nduration 2\nquit\nloop\n"
        "memory\nlayout\n",
        "s.txt");
    std::set<ScriptVerb> verbs;
    for (const ScriptCommand& command : commands) verbs.insert(command.verb);
    EXPECT_EQ(verbs.size(), commands.size());
    EXPECT_EQ(commands.size(), static_cast<std::size_t>(ScriptVerb::Layout) + 1);
    EXPECT_EQ(commands[0].verb, ScriptVerb::Select);
    EXPECT_EQ(commands[1].verb, ScriptVerb::SelectToggle);
    EXPECT_EQ(commands.back().verb, ScriptVerb::Layout);
}

// Positions, pixels and steps are used as floats: a number beyond a float's range is refused
// when the script is read, not when the command runs.
TEST(Script, NumbersUsedAsFloatsMustFitOne) {
    EXPECT_EQ(errorOf("add box 1e300 0 0\n"), "s.txt:1: add: expected a number, got '1e300'");
    EXPECT_EQ(errorOf("orbit 1e300 0\n"), "s.txt:1: orbit: expected a number, got '1e300'");
    EXPECT_EQ(errorOf("wait 3000000000\n"),
              "s.txt:1: wait: expected a whole number of frames (1 or more), seconds (0 < N ≤ 3600, as 2.5s), gi, refined or play, got '3000000000'");
}

}  // namespace
