#include "Script.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "EditorState.h"
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

bool isCount(const std::string& text, long minimum) {
    const auto value = parseNumber<long>(text);
    return value && *value >= minimum;
}

std::string plural(std::size_t n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// Checks one command; returns "" or the message.
std::string check(const ScriptCommand& c) {
    const std::string& name = c.name;
    const std::vector<std::string>& a = c.args;
    auto count = [&](std::size_t minimum, std::size_t maximum, const char* usage) -> std::string {
        if (a.size() >= minimum && a.size() <= maximum) return "";
        return name + ": expected " + usage + ", got " + plural(a.size(), "argument");
    };
    if (name == "select") return count(1, 1, "a node name (or - for none)");
    if (name == "select+") return count(1, 1, "a node name");
    if (name == "parent") return count(1, 1, "a parent node name (or - for the scene root)");
    if (name == "animation") return count(1, 1, "a camera animation name");
    if (name == "add") {
        if (a.empty() || (a.size() != 1 && a.size() != 4))
            return "add: expected a kind (empty, directional, point, spot, camera, box, plane, sphere) and optionally X Y Z";
        if (!parseNodeKind(a[0]))
            return "unknown kind '" + a[0] + "' (empty, directional, point, spot, camera, box, plane, sphere)";
        for (std::size_t i = 1; i < a.size(); ++i)
            if (!isNumber(a[i])) return "add: expected a number, got '" + a[i] + "'";
        return "";
    }
    if (name == "delete" || name == "duplicate" || name == "frame") return count(0, 0, "no arguments");
    if (name == "gizmo") {
        if (auto e = count(1, 1, "translate, rotate or scale"); !e.empty()) return e;
        return parseGizmoMode(a[0]) ? "" : "gizmo: expected translate, rotate or scale, got '" + a[0] + "'";
    }
    if (name == "space") {
        if (auto e = count(1, 1, "world or local"); !e.empty()) return e;
        return a[0] == "world" || a[0] == "local" ? "" : "space: expected world or local, got '" + a[0] + "'";
    }
    if (name == "snap") {
        if (a.size() == 1) return a[0] == "on" || a[0] == "off" ? "" : "snap: expected on, off or M DEG FACTOR, got '" + a[0] + "'";
        if (a.size() != 3) return "snap: expected on, off or three steps (metres, degrees, scale factor)";
        for (const std::string& v : a)
            if (!isNumber(v) || *parseNumber<double>(v) <= 0.0) return "snap: expected a positive step, got '" + v + "'";
        return "";
    }
    if (name == "drag" || name == "orbit") {
        const std::size_t n = name == "drag" ? 4 : 2;
        if (auto e = count(n, n, name == "drag" ? "X0 Y0 X1 Y1 window pixels" : "DX DY pixels"); !e.empty()) return e;
        for (const std::string& v : a)
            if (!isNumber(v)) return name + ": expected a number, got '" + v + "'";
        return "";
    }
    if (name == "material") {
        if (auto e = count(1, 1, "unique"); !e.empty()) return e;
        return a[0] == "unique" ? "" : "material: expected unique, got '" + a[0] + "'";
    }
    if (name == "primitive") {
        if (auto e = count(1, 1, "a primitive index"); !e.empty()) return e;
        return isCount(a[0], 0) ? "" : "primitive: expected a primitive index, got '" + a[0] + "'";
    }
    if (name == "set") {
        if (a.size() < 2) return "set: expected a property and a value";
        return checkPropertyValue(a[0], a[1]);
    }
    if (name == "setting") {
        if (auto e = count(2, 2, "a setting name and a value"); !e.empty()) return e;
        ViewportSettings viewport;
        if (std::optional<std::string> editor = applyEditorSetting(viewport, a[0], a[1])) return *editor;
        RenderSettings settings;
        return applySetting(settings, a[0], a[1]);
    }
    if (name == "view") {
        if (auto e = count(1, 1, "a view name"); !e.empty()) return e;
        // "cone-directions" is the editor's own view (cones drawn over the final image).
        return parseView(a[0]) || a[0] == kConeDirectionsView ? "" : "unknown view '" + a[0] + "'";
    }
    if (name == "panel") {
        if (auto e = count(2, 2, "a panel name and on|off"); !e.empty()) return e;
        // The names the App resolves with panelFlag when the command runs.
        if (PanelVisibility probe; panelFlag(probe, a[0]) == nullptr)
            return "unknown panel '" + a[0] + "' (hierarchy, inspector, settings, stats, camera, log, timeline)";
        return a[1] == "on" || a[1] == "off" ? "" : "panel: expected on or off, got '" + a[1] + "'";
    }
    if (name == "pick") {
        if (auto e = count(2, 2, "X and Y window pixels"); !e.empty()) return e;
        for (const std::string& v : a)
            if (!isNumber(v) || v.front() == '-') return "pick: expected a pixel position, got '" + v + "'";
        return "";
    }
    if (name == "screenshot") {
        if (auto e = count(1, 2, "a file and optionally ui|noui"); !e.empty()) return e;
        return a.size() == 1 || a[1] == "ui" || a[1] == "noui" ? "" : "screenshot: expected ui or noui, got '" + a[1] + "'";
    }
    if (name == "save") return count(0, 1, "at most a file");
    if (name == "camera") {
        if (auto e = count(6, 6, "a position X Y Z and a point to look at X Y Z"); !e.empty()) return e;
        for (const std::string& v : a)
            if (!isNumber(v)) return "camera: expected a number, got '" + v + "'";
        return "";
    }
    if (name == "open") return count(1, 1, "a file");
    if (name == "undo" || name == "redo" || name == "play" || name == "pause" || name == "quit" || name == "memory" ||
        name == "loop")
        return count(0, 0, "no arguments");
    if (name == "interactive") {
        if (auto e = count(1, 1, "on or off"); !e.empty()) return e;
        return a[0] == "on" || a[0] == "off" ? "" : "interactive: expected on or off, got '" + a[0] + "'";
    }
    if (name == "wait") {
        if (auto e = count(1, 1, "a number of frames, gi or refined"); !e.empty()) return e;
        return a[0] == "gi" || a[0] == "refined" || isCount(a[0], 1)
                   ? ""
                   : "wait: expected a whole number of frames (1 or more), gi or refined, got '" + a[0] + "'";
    }
    if (name == "time") {
        if (auto e = count(1, 1, "a time in seconds"); !e.empty()) return e;
        return isNumber(a[0]) ? "" : "time: expected seconds, got '" + a[0] + "'";
    }
    if (name == "key") {
        if (a.empty()) return "key: expected add, delete I, select I, time I T or update I";
        const std::string& action = a[0];
        std::size_t values = 0;
        if (action == "add") values = 0;
        else if (action == "delete" || action == "select" || action == "update") values = 1;
        else if (action == "time") values = 2;
        else return "unknown key action '" + action + "' (add, delete, select, time, update)";
        if (a.size() != values + 1)
            return "key " + action + ": expected " + (values == 0 ? std::string("no values") : plural(values, "value")) +
                   ", got " + std::to_string(a.size() - 1);
        if (values >= 1 && !isCount(a[1], 0)) return "key " + action + ": expected a key index, got '" + a[1] + "'";
        if (values == 2 && !isNumber(a[2])) return "key time: expected seconds, got '" + a[2] + "'";
        return "";
    }
    return "unknown command '" + name + "'";
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
        if (name == "set") {
            // The value is the rest of the line (node.name may hold spaces).
            const auto [property, value] = firstWord(rest);
            if (!property.empty()) command.args.emplace_back(property);
            if (!value.empty()) command.args.emplace_back(value);
        } else if (name == "select" || name == "select+" || name == "parent" || name == "animation") {
            if (!rest.empty()) command.args.emplace_back(rest);  // node names may hold spaces
        } else {
            for (const std::string_view word : splitWords(rest)) command.args.emplace_back(word);
        }
        if (const std::string error = check(command); !error.empty())
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

}  // namespace lit::editor
