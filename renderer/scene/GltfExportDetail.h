#pragma once
// Internal to the glTF export (scene/GltfWriter.cpp and the files it runs: GltfExport,
// GltfExportKept, GltfFileLayout): the builder of the tinygltf model a save writes. Nothing here
// is part of Lit's API.
//
// One class, its members in three files by concern: scene/GltfExport.cpp writes what Lit draws
// (Scene → glTF: nodes, materials, textures, images, lights, cameras), scene/GltfExportMeshes.cpp
// its meshes (vertices and indices in the file's layout), and scene/GltfExportKept.cpp what the
// import kept without drawing (extra attributes, morph targets, sparse accessors, skins,
// animations, and the names, extras, extensions and min/max the file's accessors, buffer views
// and buffers had).

#include "scene/GltfWriter.h"
#include "scene/Scene.h"

#include <tiny_gltf.h>

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lit::gltfexport {

constexpr int kArrayBuffer = 34962;         // GL_ARRAY_BUFFER: vertex attributes
constexpr int kElementArrayBuffer = 34963;  // GL_ELEMENT_ARRAY_BUFFER: indices

// "node 3 ('hip')" for messages.
inline std::string named(const std::string& kind, std::size_t index, const std::string& name) {
    return kind + " " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')");
}

// A drawn vertex attribute of lit::Vertex as a primitive writes it.
struct PrimitiveAttribute {
    const char* name;
    std::size_t offset;  // in lit::Vertex
    std::size_t bytes;
    int type;
};

class ModelBuilder {
public:
    // `replacedAnimation`: the name of a kept animation not to write (the caller writes its own).
    ModelBuilder(const Scene& scene, const std::filesystem::path& file, std::string replacedAnimation)
        : scene_(scene), file_(file), replacedAnimation_(std::move(replacedAnimation)) {}

    tinygltf::Model build();
    std::vector<std::pair<std::string, std::string>> takeJsonPatches() { return std::move(jsonPatches_); }
    // The written indices of Scene::keptNodes (valid after build()).
    const std::vector<int>& keptNodeIndices() const { return keptNodeIndex_; }

private:
    // ---- Scene → glTF (scene/GltfExport.cpp)
    [[noreturn]] void fail(const std::string& problem) const { throw SceneSaveError(file_.string() + ": " + problem); }
    void checkIndex(int index, std::size_t count, const std::string& what, const char* kind) const;
    void checkFinite(float value, const std::string& what) const;
    template <int N>
    void checkFinite(const glm::vec<N, float>& value, const std::string& what) const {
        for (int i = 0; i < N; ++i) checkFinite(value[i], what);
    }
    void checkScene() const;
    std::vector<int> reachableNodes() const;

    int addBufferView(const void* data, std::size_t bytes, int target, std::size_t stride);
    int addAccessor(int view, std::size_t byteOffset, int componentType, int type, std::size_t count);
    void orderNodes();
    // The written index of a node reference (scene/Scene.h: keptNodeRef), -1 when not written.
    int writtenNode(int reference) const;
    std::optional<std::string> relativeUri(const Image& image) const;
    void addImages();
    void addTextures();
    void addMaterials();
    void addLights();
    void addCameras();
    void addNodes();
    void useExtension(const std::string& name);
    // Writes what the loader kept back into an object, declaring the extensions it brings.
    void restore(const KeptGltf& kept, tinygltf::Value& extras, tinygltf::ExtensionMap& extensions);
    void restoreTextureInfo(const std::string& keptExtras, const std::string& keptExtensions, tinygltf::Value& extras,
                            tinygltf::ExtensionMap& extensions);

    // ---- Meshes (scene/GltfExportMeshes.cpp)
    void addMeshes();
    tinygltf::Primitive addPrimitive(const Primitive& primitive);
    void addAttributeView(const std::vector<PrimitiveAttribute>& group, const std::vector<Vertex>& vertices,
                          const Primitive& primitive, tinygltf::Primitive& p);
    void setPositionBounds(int accessor, const Primitive& primitive);
    int sharedAccessor(int file, int componentType, int type, bool normalized, const unsigned char* bytes,
                       std::size_t count) const;

    // ---- What the import kept without drawing (scene/GltfExportKept.cpp)
    void checkKeptNodes() const;
    // A kept accessor (scene/Scene.h); vertex data (`target` kArrayBuffer) gets a stride that is
    // a multiple of 4 bytes, as glTF requires.
    int addKeptAccessor(const KeptAccessor& kept, int target);
    // Attribute name → accessor, for kept attributes whose count is `vertexCount` (others are
    // dropped: the geometry was rebuilt). False when one was dropped.
    bool addKeptAttributes(const KeptAttributes& kept, std::size_t vertexCount, std::map<std::string, int>& attributes);
    void addTargets(const std::vector<KeptAttributes>& targets, std::size_t vertexCount,
                    tinygltf::Primitive& primitive);
    // The skins (in order) up to the first whose inverse bind matrices came after the file's
    // accessor `beforeFileAccessor`, so they are written in the file's accessor order.
    void addSkins(int beforeFileAccessor);
    void addAnimations();
    int addAnimationOutput(const Animation::Sampler& sampler, int type);
    // Names, extras and extensions of the file's objects Lit lays out itself (scene/Scene.h).
    void keepView(int view, const KeptObject& kept);
    void keepAccessor(int accessor, const KeptAccessorInfo& info);
    std::pair<std::vector<double>, std::vector<double>> minMaxOf(int accessor) const;
    void keepMinMax(int accessor, const KeptAccessorInfo& info);
    template <class Object>
    void keepNameAndExtras(Object& out, const char* array, int index, const std::string& name, const KeptGltf& kept);
    void keepBuffers();
    void keepMaterialFields(const Material& material, const tinygltf::Material& out, std::size_t index);

    const Scene& scene_;
    const std::filesystem::path& file_;
    tinygltf::Model model_;
    std::string replacedAnimation_;
    std::vector<int> meshIndex_;                              // scene mesh → glTF mesh, -1 when left out
    std::vector<int> nodeIndex_;                              // scene node → glTF node, -1 when not written
    std::vector<int> keptNodeIndex_;                          // Scene::keptNodes → glTF node
    std::vector<int> skinIndex_;                              // scene skin → glTF skin, -1 when not written
    std::size_t nextSkin_ = 0;                                // the next skin addSkins looks at
    std::vector<std::pair<const Node*, bool>> writtenNodes_;  // in written order; true: a kept node
    std::vector<int> imageIndex_;  // scene image → glTF image, -1 when not written (generated)
    // JSON the tinygltf serialiser cannot write (a sampler's name and extensions): JSON pointer →
    // value text, set into the document by writeGltfModel.
    std::vector<std::pair<std::string, std::string>> jsonPatches_;
    // Animation accessors written so far, by the file's accessor index (Animation::Sampler).
    std::map<int, std::pair<int, const std::vector<float>*>> writtenInputs_;
    std::map<int, std::pair<int, const Animation::Sampler*>> writtenOutputs_;
    std::map<int, int> writtenByFile_;  // the file's accessor → its written copy (sharedAccessor)
    bool wroteKeptVertexData_ = false;  // kept attributes or morph targets (KHR_mesh_quantization)
};

}  // namespace lit::gltfexport
