// glTF 2.0 export, the public entry point: Scene → tinygltf::Model (scene/GltfExport.cpp, and
// scene/GltfExportKept.cpp for what the import kept without drawing), the camera path as an
// animation, one buffer laid out as the file had it (scene/GltfFileLayout.cpp), then the files,
// written atomically (io/GltfFile.h).

#include "scene/GltfWriter.h"

#include "animation/CameraPathIO.h"
#include "io/GltfFile.h"
#include "scene/GltfExportDetail.h"
#include "scene/GltfFileLayout.h"
#include "scene/Scene.h"

#include <algorithm>
#include <cctype>
#include <utility>

namespace lit {

namespace {

namespace fs = std::filesystem;

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

}  // namespace

void saveGltf(const Scene& scene, const fs::path& file, const GltfSaveOptions& options) {
    const std::string extension = lowercase(file.extension().string());
    if (extension != ".gltf" && extension != ".glb")
        throw SceneSaveError(file.string() + ": cannot save as '" + file.extension().string() +
                             "'; the file name must end in .gltf or .glb");
    const bool binary = extension == ".glb";

    const bool ownPath = options.cameraPath && !options.cameraPath->empty();
    gltfexport::ModelBuilder builder(scene, file, ownPath ? options.cameraPathName : std::string());
    tinygltf::Model model = builder.build();
    const std::vector<std::pair<std::string, std::string>> jsonPatches = builder.takeJsonPatches();
    if (options.cameraPath && !options.cameraPath->empty()) {
        try {
            // The path animates a camera of the shown scene: the kept nodes are hidden from
            // writeCameraPathAnimation's search for a camera node, so without a shown camera it
            // adds one rather than animate a node Lit does not show.
            const std::vector<int>& keptNodes = builder.keptNodeIndices();
            std::vector<int> keptCameras;
            for (int i : keptNodes)
                keptCameras.push_back(std::exchange(model.nodes[static_cast<std::size_t>(i)].camera, -1));
            writeCameraPathAnimation(model, *options.cameraPath, options.cameraPathName);
            for (std::size_t i = 0; i < keptCameras.size(); ++i)
                model.nodes[static_cast<std::size_t>(keptNodes[i])].camera = keptCameras[i];
        } catch (const CameraPathError& e) {
            throw SceneSaveError(file.string() + ": cannot write the camera path: " + e.what());
        }
    }
    gltfexport::mergeBuffers(model);
    gltfexport::keepFileLayout(model, scene);
    if (!binary && !model.buffers.empty()) model.buffers[0].uri = percentEncodePath(file.stem().string() + ".bin");

    try {
        writeGltfModel(std::move(model), file, binary, options.alsoWrite, jsonPatches);
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        throw SceneSaveError(what.starts_with(file.string() + ": ") ? what : file.string() + ": " + what);
    }
}

std::string uncompressedSaveNote(const Scene& scene) {
    if (scene.decodedCompression.empty()) return {};
    std::string names;
    for (std::size_t i = 0; i < scene.decodedCompression.size(); ++i)
        names += (i == 0 ? "" : " and ") + scene.decodedCompression[i];
    return "written uncompressed: the source used " + names + ", which Lit reads but does not write";
}

}  // namespace lit
