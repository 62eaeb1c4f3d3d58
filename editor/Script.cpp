#include "Script.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "EditorState.h"
#include "PathEditing.h"
#include "Properties.h"
#include "RenderSettings.h"
#include "SceneEdits.h"
#include "SettingCommand.h"
#include "TransformGizmo.h"
#include "TextParse.h"

namespace lit::editor {

namespace {

// The first word of `text` and the (trimmed) rest.
std::pair<std::string_view, std::string_view> firstWord(std::string_view text) {
    text = trim(text);
    std::size_t end = 0;
    while (end < text.size() && !isSpace(text[end])) ++end;
    return {text.substr(0, end), trim(text.substr(end))};
}

bool isNumber(const std::string& text) { return parseNumber<double>(text).has_value(); }
// Positions, pixels and steps: the runner uses them as floats, so they must parse as one.
bool isFloat(const std::string& text) { return parseNumber<float>(text).has_value(); }

bool isCount(const std::string& text, long minimum) {
    const auto value = parseNumber<long>(text);
    return value && *value >= minimum;
}

std::string plural(std::size_t n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// "" when the command has between `minimum` and `maximum` arguments, else the message.
std::string expectCount(const ScriptCommand& c, std::size_t minimum, std::size_t maximum, const char* usage) {
    if (c.args.size() >= minimum && c.args.size() <= maximum) return "";
    return c.name + ": expected " + usage + ", got " + plural(c.args.size(), "argument");
}

// "" when every argument is a number, else the message.
std::string expectNumbers(const ScriptCommand& c) {
    for (const std::string& v : c.args)
        if (!isFloat(v)) return c.name + ": expected a number, got '" + v + "'";
    return "";
}

std::string expectOnOff(const ScriptCommand& c, const std::string& value) {
    return value == "on" || value == "off" ? "" : c.name + ": expected on or off, got '" + value + "'";
}

std::string checkNoArguments(const ScriptCommand& c) { return expectCount(c, 0, 0, "no arguments"); }

std::string checkAdd(const ScriptCommand& c) {
    constexpr const char* kKinds = "(empty, directional, point, spot, camera, box, plane, sphere)";
    const std::vector<std::string>& a = c.args;
    if (a.empty() || (a.size() != 1 && a.size() != 4))
        return std::string("add: expected a kind ") + kKinds + " and optionally X Y Z";
    if (!parseNodeKind(a[0])) return "unknown kind '" + a[0] + "' " + kKinds;
    for (std::size_t i = 1; i < a.size(); ++i)
        if (!isFloat(a[i])) return "add: expected a number, got '" + a[i] + "'";
    return "";
}

std::string checkGizmo(const ScriptCommand& c) {
    if (auto e = expectCount(c, 1, 1, "translate, rotate or scale"); !e.empty()) return e;
    return parseGizmoMode(c.args[0]) ? "" : "gizmo: expected translate, rotate or scale, got '" + c.args[0] + "'";
}

std::string checkSpace(const ScriptCommand& c) {
    if (auto e = expectCount(c, 1, 1, "world or local"); !e.empty()) return e;
    const std::string& a = c.args[0];
    return a == "world" || a == "local" ? "" : "space: expected world or local, got '" + a + "'";
}

std::string checkSnap(const ScriptCommand& c) {
    const std::vector<std::string>& a = c.args;
    if (a.size() == 1)
        return a[0] == "on" || a[0] == "off" ? "" : "snap: expected on, off or M DEG FACTOR, got '" + a[0] + "'";
    if (a.size() != 3) return "snap: expected on, off or three steps (metres, degrees, scale factor)";
    for (const std::string& v : a)
        if (!isFloat(v) || *parseNumber<float>(v) <= 0.0f) return "snap: expected a positive step, got '" + v + "'";
    return "";
}

std::string checkDrag(const ScriptCommand& c) {
    if (auto e = expectCount(c, 4, 4, "X0 Y0 X1 Y1 window pixels"); !e.empty()) return e;
    return expectNumbers(c);
}

std::string checkOrbit(const ScriptCommand& c) {
    if (auto e = expectCount(c, 2, 2, "DX DY pixels"); !e.empty()) return e;
    return expectNumbers(c);
}

std::string checkMaterial(const ScriptCommand& c) {
    if (auto e = expectCount(c, 1, 1, "unique"); !e.empty()) return e;
    return c.args[0] == "unique" ? "" : "material: expected unique, got '" + c.args[0] + "'";
}

std::string checkPrimitive(const ScriptCommand& c) {
    if (auto e = expectCount(c, 1, 1, "a primitive index"); !e.empty()) return e;
    return isCount(c.args[0], 0) ? "" : "primitive: expected a primitive index, got '" + c.args[0] + "'";
}

std::string checkSet(const ScriptCommand& c) {
    if (c.args.size() < 2) return "set: expected a property and a value";
    return checkPropertyValue(c.args[0], c.args[1]);
}

// Applied to default settings: the same setters the runner uses, so both accept the same keys
// and values.
std::string checkSetting(const ScriptCommand& c) {
    if (auto e = expectCount(c, 2, 2, "a setting name and a value"); !e.empty()) return e;
    ViewportSettings viewport;
    if (std::optional<std::string> editor = applyEditorSetting(viewport, c.args[0], c.args[1])) return *editor;
    RenderSettings settings;
    return applySetting(settings, c.args[0], c.args[1]);
}

std::string checkView(const ScriptCommand& c) {
    if (auto e = expectCount(c, 1, 1, "a view name"); !e.empty()) return e;
    // "cone-directions" is the editor's own view (cones drawn over the final image).
    return parseView(c.args[0]) || c.args[0] == kConeDirectionsView ? "" : "unknown view '" + c.args[0] + "'";
}

std::string checkPanel(const ScriptCommand& c) {
    if (auto e = expectCount(c, 2, 2, "a panel name and on|off"); !e.empty()) return e;
    // The names the runner resolves with panelFlag.
    if (PanelVisibility probe; panelFlag(probe, c.args[0]) == nullptr)
        return "unknown panel '" + c.args[0] +
               "' (hierarchy, inspector, settings, stats, stats-details, camera, log, timeline, legend)";
    return expectOnOff(c, c.args[1]);
}

std::string checkPick(const ScriptCommand& c) {
    if (auto e = expectCount(c, 2, 2, "X and Y window pixels"); !e.empty()) return e;
    for (const std::string& v : c.args)
        if (!isFloat(v) || v.front() == '-') return "pick: expected a pixel position, got '" + v + "'";
    return "";
}

std::string checkScreenshot(const ScriptCommand& c) {
    if (auto e = expectCount(c, 1, 2, "a file and optionally ui|noui"); !e.empty()) return e;
    const std::vector<std::string>& a = c.args;
    return a.size() == 1 || a[1] == "ui" || a[1] == "noui" ? "" : "screenshot: expected ui or noui, got '" + a[1] + "'";
}

std::string checkCamera(const ScriptCommand& c) {
    if (auto e = expectCount(c, 6, 6, "a position X Y Z and a point to look at X Y Z"); !e.empty()) return e;
    return expectNumbers(c);
}

std::string checkInteractive(const ScriptCommand& c) {
    if (auto e = expectCount(c, 1, 1, "on or off"); !e.empty()) return e;
    return expectOnOff(c, c.args[0]);
}

std::string checkWait(const ScriptCommand& c) {
    if (auto e = expectCount(c, 1, 1, "a number of frames, seconds, gi, refined or play"); !e.empty()) return e;
    const std::string& a = c.args[0];
    // A frame count is an int (the runner counts frames in one).
    const std::optional<int> frames = parseNumber<int>(a);
    return a == "gi" || a == "refined" || a == "play" || (frames && *frames >= 1) || waitSeconds(a)
               ? ""
               : "wait: expected a whole number of frames (1 or more), seconds (0 < N ≤ 3600, as 2.5s), gi, "
                 "refined or play, got '" + a + "'";
}

std::string checkTime(const ScriptCommand& c) {
    if (auto e = expectCount(c, 1, 1, "a time in seconds"); !e.empty()) return e;
    return isNumber(c.args[0]) ? "" : "time: expected seconds, got '" + c.args[0] + "'";
}

std::string checkPlay(const ScriptCommand& c) {
    if (auto e = expectCount(c, 0, 1, "at most a speed"); !e.empty()) return e;
    if (c.args.empty()) return "";
    const std::optional<float> speed = parseNumber<float>(c.args[0]);
    return speed && *speed >= kMinPlaybackSpeed && *speed <= kMaxPlaybackSpeed
               ? ""
               : "play: expected a speed 0.1..4, got '" + c.args[0] + "'";
}

std::string checkDuration(const ScriptCommand& c) {
    if (auto e = expectCount(c, 1, 1, "a duration in seconds"); !e.empty()) return e;
    const std::optional<float> seconds = parseNumber<float>(c.args[0]);
    return seconds && *seconds > 0.0f ? "" : "duration: expected seconds > 0, got '" + c.args[0] + "'";
}

std::string checkKey(const ScriptCommand& c) {
    const std::vector<std::string>& a = c.args;
    if (a.empty()) return "key: expected add, delete I, select I, time I T or update I";
    const std::string& action = a[0];
    std::size_t values = 0;
    if (action == "add")
        values = 0;
    else if (action == "delete" || action == "select" || action == "update")
        values = 1;
    else if (action == "time")
        values = 2;
    else
        return "unknown key action '" + action + "' (add, delete, select, time, update)";
    if (a.size() != values + 1)
        return "key " + action + ": expected " + (values == 0 ? std::string("no values") : plural(values, "value")) +
               ", got " + std::to_string(a.size() - 1);
    if (values >= 1 && !isCount(a[1], 0)) return "key " + action + ": expected a key index, got '" + a[1] + "'";
    if (values == 2 && !isNumber(a[2])) return "key time: expected seconds, got '" + a[2] + "'";
    return "";
}

// How the rest of a command's line becomes its arguments.
enum class Arguments {
    Words,             // split on whitespace
    RestOfLine,        // one argument, the whole rest (node and animation names may hold spaces)
    PropertyAndValue,  // the first word, then the rest (set node.name A name with spaces)
};

// The script language: each command's name, verb, arguments and the checks that need no scene
// (argument counts, numbers, on|off, view and panel names). The runner does the rest.
struct CommandSpec {
    std::string_view name;
    ScriptVerb verb;
    Arguments arguments;
    std::string (*check)(const ScriptCommand&);
};

constexpr CommandSpec kCommands[] = {
    {"select", ScriptVerb::Select, Arguments::RestOfLine,
     [](const ScriptCommand& c) { return expectCount(c, 1, 1, "a node name (or - for none)"); }},
    {"select+", ScriptVerb::SelectToggle, Arguments::RestOfLine,
     [](const ScriptCommand& c) { return expectCount(c, 1, 1, "a node name"); }},
    {"add", ScriptVerb::Add, Arguments::Words, checkAdd},
    {"delete", ScriptVerb::Delete, Arguments::Words, checkNoArguments},
    {"duplicate", ScriptVerb::Duplicate, Arguments::Words, checkNoArguments},
    {"parent", ScriptVerb::Parent, Arguments::RestOfLine,
     [](const ScriptCommand& c) { return expectCount(c, 1, 1, "a parent node name (or - for the scene root)"); }},
    {"material", ScriptVerb::Material, Arguments::Words, checkMaterial},
    {"primitive", ScriptVerb::Primitive, Arguments::Words, checkPrimitive},
    {"gizmo", ScriptVerb::Gizmo, Arguments::Words, checkGizmo},
    {"space", ScriptVerb::Space, Arguments::Words, checkSpace},
    {"snap", ScriptVerb::Snap, Arguments::Words, checkSnap},
    {"drag", ScriptVerb::Drag, Arguments::Words, checkDrag},
    {"frame", ScriptVerb::Frame, Arguments::Words, checkNoArguments},
    {"orbit", ScriptVerb::Orbit, Arguments::Words, checkOrbit},
    {"animation", ScriptVerb::Animation, Arguments::RestOfLine,
     [](const ScriptCommand& c) { return expectCount(c, 1, 1, "a camera animation name"); }},
    {"set", ScriptVerb::Set, Arguments::PropertyAndValue, checkSet},
    {"setting", ScriptVerb::Setting, Arguments::Words, checkSetting},
    {"view", ScriptVerb::View, Arguments::Words, checkView},
    {"panel", ScriptVerb::Panel, Arguments::Words, checkPanel},
    {"pick", ScriptVerb::Pick, Arguments::Words, checkPick},
    {"screenshot", ScriptVerb::Screenshot, Arguments::Words, checkScreenshot},
    {"save", ScriptVerb::Save, Arguments::Words,
     [](const ScriptCommand& c) { return expectCount(c, 0, 1, "at most a file"); }},
    {"open", ScriptVerb::Open, Arguments::Words, [](const ScriptCommand& c) { return expectCount(c, 1, 1, "a file"); }},
    {"camera", ScriptVerb::Camera, Arguments::Words, checkCamera},
    {"undo", ScriptVerb::Undo, Arguments::Words, checkNoArguments},
    {"redo", ScriptVerb::Redo, Arguments::Words, checkNoArguments},
    {"interactive", ScriptVerb::Interactive, Arguments::Words, checkInteractive},
    {"wait", ScriptVerb::Wait, Arguments::Words, checkWait},
    {"key", ScriptVerb::Key, Arguments::Words, checkKey},
    {"play", ScriptVerb::Play, Arguments::Words, checkPlay},
    {"pause", ScriptVerb::Pause, Arguments::Words, checkNoArguments},
    {"time", ScriptVerb::Time, Arguments::Words, checkTime},
    {"duration", ScriptVerb::Duration, Arguments::Words, checkDuration},
    {"quit", ScriptVerb::Quit, Arguments::Words, checkNoArguments},
    {"loop", ScriptVerb::Loop, Arguments::Words, checkNoArguments},
    {"memory", ScriptVerb::Memory, Arguments::Words, checkNoArguments},
    {"layout", ScriptVerb::Layout, Arguments::Words, checkNoArguments},
};

const CommandSpec* findCommand(std::string_view name) {
    for (const CommandSpec& spec : kCommands)
        if (spec.name == name) return &spec;
    return nullptr;
}

}  // namespace

std::string scriptErrorAt(const ScriptCommand& command, const std::string& source, const std::string& message) {
    return source + ":" + std::to_string(command.line) + ": " + message;
}

std::vector<ScriptCommand> parseScript(std::string_view text, const std::string& source) {
    std::vector<ScriptCommand> commands;
    int lineNumber = 0;
    for (std::size_t pos = 0; pos <= text.size();) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++lineNumber;
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        const auto [name, rest] = firstWord(line);
        if (name.empty()) continue;
        ScriptCommand command;
        command.line = lineNumber;
        command.name = std::string(name);
        const CommandSpec* spec = findCommand(name);
        if (spec == nullptr)
            throw ScriptError(scriptErrorAt(command, source, "unknown command '" + command.name + "'"));
        command.verb = spec->verb;
        switch (spec->arguments) {
            case Arguments::Words:
                for (const std::string_view word : splitWords(rest)) command.args.emplace_back(word);
                break;
            case Arguments::RestOfLine:
                if (!rest.empty()) command.args.emplace_back(rest);
                break;
            case Arguments::PropertyAndValue: {
                const auto [property, value] = firstWord(rest);
                if (!property.empty()) command.args.emplace_back(property);
                if (!value.empty()) command.args.emplace_back(value);
                break;
            }
        }
        if (const std::string error = spec->check(command); !error.empty())
            throw ScriptError(scriptErrorAt(command, source, error));
        commands.push_back(std::move(command));
    }
    return commands;
}

std::vector<ScriptCommand> loadScript(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw ScriptError(file.string() + ": cannot open the script");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw ScriptError(file.string() + ": cannot read the script");
    return parseScript(text.str(), file.string());
}

std::optional<double> waitSeconds(const std::string& word) {
    if (word.size() < 2 || word.back() != 's') return std::nullopt;
    const std::optional<double> seconds = parseNumber<double>(word.substr(0, word.size() - 1));
    return seconds && *seconds > 0.0 && *seconds <= 3600.0 ? seconds : std::nullopt;
}

}  // namespace lit::editor
