// A saving process for the kill tests (save_kill.sh): it saves a large generated document, the
// test SIGKILLs it at a chosen moment, then checks what is on disk with this program's other
// modes, which do what the next editor start does (recovery) and print what they find.
//
//   lit_save_kill_helper save FILE VARIANT       saveDocument(FILE) of document VARIANT (0 or 1);
//                                                 prints "ready" before, "saved in N ms" (stderr) after
//   lit_save_kill_helper autosave FOLDER VARIANT  Autosave(FOLDER).saveNow of document VARIANT (same)
//   lit_save_kill_helper check FILE               openDocument(FILE) (recovers interrupted saves
//                                                 first); prints "variant N" or fails (exit 1)
//   lit_save_kill_helper recover FOLDER           the next editor start: Autosave(FOLDER), recover
//                                                 the crash's copy; prints "variant N" or "none"
//
// The variants differ in every file of the save (triangle count, so a .bin of one never fits
// the .gltf of the other, vertex positions and the render settings), so a mix of old and new is
// either unloadable or detected.

#include "DocumentIO.h"
#include "Log.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using lit::editor::Document;

// A grid of (side-1)^2 quads, about 6.6 MB (variant 0) and 7.5 MB (variant 1) on disk.
Document makeDocument(int variant) {
    const int side = variant == 0 ? 300 : 320;
    lit::Primitive primitive;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            lit::Vertex v;
            v.position = {static_cast<float>(x), static_cast<float>(variant), static_cast<float>(y)};
            primitive.vertices.push_back(v);
        }
    for (int y = 0; y + 1 < side; ++y)
        for (int x = 0; x + 1 < side; ++x) {
            const auto i = static_cast<std::uint32_t>(y * side + x);
            const auto s = static_cast<std::uint32_t>(side);
            primitive.indices.insert(primitive.indices.end(), {i, i + s, i + 1, i + 1, i + s, i + s + 1});
        }
    primitive.bounds.extend(glm::vec3(0.0f));
    primitive.bounds.extend(glm::vec3(static_cast<float>(side), static_cast<float>(variant), static_cast<float>(side)));
    lit::Scene scene;
    scene.meshes.push_back({"grid", {std::move(primitive)}});
    lit::Node node;
    node.name = "grid";
    node.mesh = 0;
    scene.nodes.push_back(node);
    scene.roots = {0};
    scene.updateWorldTransforms();
    Document doc(std::move(scene), lit::CameraPath(), {});
    doc.settings.shadows.mapSize = variant == 0 ? 1024 : 2048;
    return doc;
}

// Which variant a loaded document is, or -1 when it is neither (a mix).
int variantOf(const Document& doc) {
    if (doc.scene.meshes.empty() || doc.scene.meshes[0].primitives.empty()) return -1;
    const lit::Primitive& p = doc.scene.meshes[0].primitives[0];
    for (int variant : {0, 1}) {
        const std::size_t side = variant == 0 ? 300 : 320;
        if (p.vertices.size() == side * side && p.vertices.back().position.y == static_cast<float>(variant) &&
            doc.settings.shadows.mapSize == (variant == 0 ? 1024 : 2048))
            return variant;
    }
    return -1;
}

// "saved in N ms": from "ready" to the end of the save, for spreading the kills over it.
void printSaveTime(std::chrono::steady_clock::time_point start) {
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start);
    // On stderr: stdout is the test's "ready" pipe, whose reader is gone by now.
    std::fprintf(stderr, "saved in %lld ms\n", static_cast<long long>(ms.count()));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: lit_save_kill_helper save|autosave|check|recover PATH [VARIANT]\n");
        return 2;
    }
    const std::string mode = argv[1];
    const std::filesystem::path path = argv[2];
    lit::Log log;
    log.setSink([](const lit::LogMessage&) {});
    try {
        if (mode == "save" && argc == 4) {
            Document doc = makeDocument(std::atoi(argv[3]));
            std::printf("ready\n");
            std::fflush(stdout);
            const auto start = std::chrono::steady_clock::now();
            lit::editor::saveDocument(doc, path);
            printSaveTime(start);
            return 0;
        }
        if (mode == "autosave" && argc == 4) {
            Document doc = makeDocument(std::atoi(argv[3]));
            doc.file = "grid.gltf";
            lit::editor::Autosave autosave(path, 60.0);
            std::printf("ready\n");
            std::fflush(stdout);
            const auto start = std::chrono::steady_clock::now();
            autosave.saveNow(doc);
            printSaveTime(start);
            return 0;
        }
        if (mode == "check") {
            const Document doc = lit::editor::openDocument(path, log);
            const int variant = variantOf(doc);
            std::printf("variant %d\n", variant);
            return variant >= 0 ? 0 : 1;
        }
        if (mode == "recover") {
            lit::editor::Autosave autosave(path, 60.0);
            if (!autosave.recoverable()) {
                std::printf("none\n");
                return 0;
            }
            const Document doc = autosave.recover(log);
            const int variant = variantOf(doc);
            std::printf("variant %d\n", variant);
            return variant >= 0 ? 0 : 1;  // no cleanExit: the test inspects the folder
        }
    } catch (const std::exception& e) {
        std::printf("error: %s\n", e.what());
        return 1;
    }
    std::fprintf(stderr, "lit_save_kill_helper: bad arguments\n");
    return 2;
}
