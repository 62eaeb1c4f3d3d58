// lit-editor: interactive viewer/editor for Lit scenes. See EditorOptions.h for the command line.

#include <cstdio>
#include <exception>
#include <string_view>
#include <utility>
#include <vector>

#include "App.h"
#include "EditorOptions.h"
#include "Script.h"

int main(int argc, char** argv) {
    using namespace lit::editor;
    const std::vector<std::string_view> args(argv + 1, argv + argc);
    EditorOptions options;
    try {
        options = parseEditorOptions(args);
    } catch (const OptionsError& error) {
        std::fprintf(stderr, "lit-editor: %s\n%s", error.what(), editorUsage().c_str());
        return 2;
    }
    if (options.help) {
        std::fputs(editorUsage().c_str(), stdout);
        return 0;
    }
    // The whole script is checked before a window opens: a typo on line 40 must not cost the
    // 39 lines of rendering before it.
    std::vector<ScriptCommand> script;
    if (options.script) {
        try {
            script = loadScript(*options.script);
        } catch (const ScriptError& error) {
            std::fprintf(stderr, "lit-editor: %s\n", error.what());
            return 2;
        }
    }
    try {
        App app(options, std::move(script));
        return app.run();
    } catch (const std::exception& error) {
        std::fprintf(stderr, "lit-editor: %s\n", error.what());
        return 1;
    }
}
