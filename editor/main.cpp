// lit-editor: interactive viewer/editor for Lit scenes. See EditorOptions.h for the command line.

#include <cstdio>
#include <exception>
#include <string_view>
#include <vector>

#include "App.h"
#include "EditorOptions.h"

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
    try {
        App app(options);
        return app.run();
    } catch (const std::exception& error) {
        std::fprintf(stderr, "lit-editor: %s\n", error.what());
        return 1;
    }
}
