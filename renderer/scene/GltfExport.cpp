// Scene → glTF: what Lit draws, as a tinygltf model (scene/GltfExportDetail.h; meshes are
// scene/GltfExportMeshes.cpp, the kept parts scene/GltfExportKept.cpp).
//
// Decisions worth knowing:
// - All geometry and embedded images go into one buffer: "<stem>.bin" beside a .gltf, the BIN
//   chunk of a .glb (laid out as the file had it: scene/GltfFileLayout.h).
// - Nodes are written in the file's order (Node::fileIndex), nodes Lit made after them: an
//   unedited file keeps its node indices. A node's `matrix` is written back while its transform
//   is unedited and no written animation moves it. Primitives without triangles are left out
//   (the loader skips them), and so are meshes left with none.
// - Min/max the file had on an accessor are recomputed from the written values (the file's exact
//   numbers where their floats agree).
// - asset.generator is "Lit": glTF means the tool that wrote the file, and importers use it to
//   work around that tool's quirks. The file's own generator goes to the asset's extras as
//   "litSourceGenerator" (a file Lit wrote keeps the one it already has there).
// - An image that came from a file which still exists is referenced by a URI relative to the new
//   file's folder (not copied, not re-encoded: JPEGs stay JPEGs); an image embedded in the source
//   is written with its own bytes and MIME type (Image::encoded: 16-bit PNGs and KTX2 stay as
//   they were); any other image (generated, or from a file that is gone) is encoded as PNG into
//   the buffer. The loader's white stand-in (Image::generated) is not written.
// - A WebP image (EXT_texture_webp) keeps its bytes and goes back into the extension's `source`,
//   with the file's fallback image (if any) as the texture's `source`. Once its pixels are
//   edited it is written as a PNG through the plain `source`.
// - KHR_texture_transform is written from Material::textureTransforms (the fields that differ
//   from the identity) on every texture reference that had it or was given one.
// - Every glTF scene of the source is written, in its order (Scene::otherScenes around the
//   shown one, which keeps its index as `scene`).
// - Light intensities are written in glTF's photometric units: Scene's W/sr and W/m² times
//   683 lm/W (scene/LightUnits.h), or the file's own number for a light that was not edited.
// - Light::castsShadow has no glTF equivalent; false is written to the light's extras as
//   {"litCastsShadow": false}, which the loader reads back.
// - A camera's zfar of 0 (fitted to the scene) is written as no zfar, which glTF reads as an
//   infinite far plane.

#include "image/ImageIO.h"
#include "io/GltfFile.h"
#include "scene/GltfExportDetail.h"
#include "scene/GltfKeep.h"
#include "scene/GltfMaterialLayers.h"
#include "scene/GltfTextureTransform.h"
#include "scene/LightUnits.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <tuple>

namespace lit::gltfexport {

namespace {

namespace fs = std::filesystem;

constexpr const char* kLightsExtension = "KHR_lights_punctual";
constexpr const char* kEmissiveStrengthExtension = "KHR_materials_emissive_strength";
constexpr const char* kWebpExtension = "EXT_texture_webp";
constexpr const char* kCastsShadowKey = "litCastsShadow";
constexpr const char* kGenerator = "Lit";
constexpr const char* kSourceGeneratorKey = "litSourceGenerator";

// The file's exact number of a field while its float still equals it, else the float
// (scene/Scene.h: FileNumbers).
double fileOr(const FileNumbers& numbers, const std::string& key, float value) {
    const auto it = numbers.find(key);
    return it != numbers.end() && static_cast<float>(it->second) == value ? it->second : static_cast<double>(value);
}

template <int N>
std::vector<double> fileOr(const FileNumbers& numbers, const char* prefix, const glm::vec<N, float>& v) {
    std::vector<double> out(N);
    for (int i = 0; i < N; ++i) out[static_cast<std::size_t>(i)] = fileOr(numbers, prefix + std::to_string(i), v[i]);
    return out;
}

// Whether the written image `out` (of scene image `image`) holds WebP: the source's own bytes,
// or a file by URI (addImages re-encodes anything else as PNG).
bool writtenAsWebp(const tinygltf::Image& out, const Image& image) {
    if (out.bufferView >= 0) return out.mimeType == "image/webp";
    return !out.uri.empty() && (image.mimeType == "image/webp" || out.uri.ends_with(".webp"));
}

// A node's translation, rotation and scale, only what differs from the glTF defaults (as other
// exporters write them), with the file's exact numbers while they still hold.
void addTrs(const Node& node, tinygltf::Node& out) {
    if (node.translation != glm::vec3(0.0f)) out.translation = fileOr(node.fileNumbers, "t", node.translation);
    if (node.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
        // A rotation already unit within float rounding is written as it is (the file's
        // numbers after a load), others normalized.
        const float length = glm::length(node.rotation);
        const glm::quat q = std::abs(length - 1.0f) <= 1e-6f ? node.rotation : node.rotation / length;
        out.rotation = fileOr(node.fileNumbers, "r", glm::vec4(q.x, q.y, q.z, q.w));  // glTF order
    }
    if (node.scale != glm::vec3(1.0f)) out.scale = fileOr(node.fileNumbers, "s", node.scale);
}

}  // namespace

void ModelBuilder::restore(const KeptGltf& kept, tinygltf::Value& extras, tinygltf::ExtensionMap& extensions) {
    gltfkeep::restore(kept, extras, extensions);
    for (const auto& [name, value] : extensions) useExtension(name);
}

void ModelBuilder::restoreTextureInfo(const std::string& keptExtras, const std::string& keptExtensions,
                                      tinygltf::Value& extras, tinygltf::ExtensionMap& extensions) {
    restore(KeptGltf{keptExtras, keptExtensions}, extras, extensions);
}

int ModelBuilder::writtenNode(int reference) const {
    if (reference >= 0)
        return static_cast<std::size_t>(reference) < nodeIndex_.size() ? nodeIndex_[static_cast<std::size_t>(reference)]
                                                                       : -1;
    const int kept = keptNodeIndex(reference);
    return reference <= -2 && static_cast<std::size_t>(kept) < keptNodeIndex_.size()
               ? keptNodeIndex_[static_cast<std::size_t>(kept)]
               : -1;
}

void ModelBuilder::checkIndex(int index, std::size_t count, const std::string& what, const char* kind) const {
    if (index < -1 || index >= static_cast<int>(count))
        fail(what + " refers to " + kind + " " + std::to_string(index) + ", which does not exist (the scene has " +
             std::to_string(count) + ")");
}

void ModelBuilder::checkFinite(float value, const std::string& what) const {
    if (!std::isfinite(value)) fail(what + " is not a finite number");
}

// Everything the file will refer to must exist, and every number must be writable as JSON.
void ModelBuilder::checkScene() const {
    for (std::size_t i = 0; i < scene_.nodes.size(); ++i) {
        const Node& node = scene_.nodes[i];
        const std::string what = named("node", i, node.name);
        for (int child : node.children)
            if (child < 0 || child >= static_cast<int>(scene_.nodes.size()))
                fail(what + " has child " + std::to_string(child) + ", which does not exist (the scene has " +
                     std::to_string(scene_.nodes.size()) + " nodes)");
        checkIndex(node.mesh, scene_.meshes.size(), what, "mesh");
        checkIndex(node.light, scene_.lights.size(), what, "light");
        checkIndex(node.camera, scene_.cameras.size(), what, "camera");
        checkIndex(node.skin, scene_.skins.size(), what, "skin");
        checkFinite(node.translation, what + "'s translation");
        checkFinite(glm::vec4(node.rotation.x, node.rotation.y, node.rotation.z, node.rotation.w),
                    what + "'s rotation");
        checkFinite(node.scale, what + "'s scale");
        if (glm::length(node.rotation) < 1e-6f) fail(what + "'s rotation is a zero quaternion");
    }
    checkKeptNodes();
    for (int root : scene_.roots)
        if (root < 0 || root >= static_cast<int>(scene_.nodes.size()))
            fail("root " + std::to_string(root) + " does not exist (the scene has " +
                 std::to_string(scene_.nodes.size()) + " nodes)");
    for (std::size_t m = 0; m < scene_.meshes.size(); ++m)
        for (std::size_t p = 0; p < scene_.meshes[m].primitives.size(); ++p) {
            const Primitive& primitive = scene_.meshes[m].primitives[p];
            const std::string what = "mesh '" + scene_.meshes[m].name + "' primitive " + std::to_string(p);
            checkIndex(primitive.material, scene_.materials.size(), what, "material");
            if (primitive.indices.size() % 3 != 0)
                fail(what + " has " + std::to_string(primitive.indices.size()) + " indices, not a multiple of 3");
            for (std::uint32_t index : primitive.indices)
                if (index >= primitive.vertices.size())
                    fail(what + " has the index " + std::to_string(index) + ", which is out of range (" +
                         std::to_string(primitive.vertices.size()) + " vertices)");
            for (const Vertex& v : primitive.vertices) {
                checkFinite(v.position, what + ": a vertex position");
                checkFinite(v.normal, what + ": a vertex normal");
                checkFinite(v.uv, what + ": a vertex texture coordinate");
                checkFinite(v.tangent, what + ": a vertex tangent");
            }
        }
    for (std::size_t m = 0; m < scene_.materials.size(); ++m) {
        const Material& material = scene_.materials[m];
        const std::string what = named("material", m, material.name);
        for (int texture : {material.baseColorTexture, material.metallicRoughnessTexture, material.normalTexture,
                            material.emissiveTexture, material.occlusionTexture})
            checkIndex(texture, scene_.textures.size(), what, "texture");
        checkFinite(material.baseColorFactor, what + "'s baseColorFactor");
        checkFinite(material.metallic, what + "'s metallic factor");
        checkFinite(material.roughness, what + "'s roughness factor");
        checkFinite(material.normalScale, what + "'s normalScale");
        checkFinite(material.emissiveFactor, what + "'s emissiveFactor");
        checkFinite(material.emissiveStrength, what + "'s emissiveStrength");
        checkFinite(material.occlusionStrength, what + "'s occlusionStrength");
        checkFinite(material.alphaCutoff, what + "'s alphaCutoff");
    }
    for (std::size_t t = 0; t < scene_.textures.size(); ++t)
        checkIndex(scene_.textures[t].image, scene_.images.size(), "texture " + std::to_string(t), "image");
    for (std::size_t l = 0; l < scene_.lights.size(); ++l) {
        const Light& light = scene_.lights[l];
        const std::string what = named("light", l, light.name);
        checkFinite(light.color, what + "'s colour");
        checkFinite(light.intensity, what + "'s intensity");
        checkFinite(light.range, what + "'s range");
        checkFinite(light.innerConeAngle, what + "'s innerConeAngle");
        checkFinite(light.outerConeAngle, what + "'s outerConeAngle");
    }
    for (std::size_t c = 0; c < scene_.cameras.size(); ++c) {
        const Camera& camera = scene_.cameras[c];
        const std::string what = named("camera", c, camera.name);
        checkFinite(camera.aspectRatio, what + "'s aspectRatio");
        checkFinite(camera.zfar, what + "'s zfar");
        if (!(camera.yfov > 0.0f && std::isfinite(camera.yfov)))
            fail(what + " has yfov " + std::to_string(camera.yfov) + "; glTF needs a positive field of view");
        if (!(camera.znear > 0.0f && std::isfinite(camera.znear)))
            fail(what + " has znear " + std::to_string(camera.znear) + "; glTF needs a positive near plane");
    }
}

// The nodes reachable from the roots, in index order. A node reached twice (a cycle, or two
// parents) cannot be written as a glTF tree.
std::vector<int> ModelBuilder::reachableNodes() const {
    std::vector<std::uint8_t> reached(scene_.nodes.size(), 0);
    std::vector<int> stack;
    for (int root : scene_.roots)
        if (std::find(stack.begin(), stack.end(), root) == stack.end()) stack.push_back(root);
    while (!stack.empty()) {
        const int index = stack.back();
        stack.pop_back();
        if (reached[static_cast<std::size_t>(index)])
            fail(named("node", static_cast<std::size_t>(index), scene_.nodes[static_cast<std::size_t>(index)].name) +
                 " is reached twice from the roots (a cycle, or a node with two parents)");
        reached[static_cast<std::size_t>(index)] = 1;
        for (int child : scene_.nodes[static_cast<std::size_t>(index)].children) stack.push_back(child);
    }
    std::vector<int> out;
    for (std::size_t i = 0; i < reached.size(); ++i)
        if (reached[i]) out.push_back(static_cast<int>(i));
    return out;
}

int ModelBuilder::addBufferView(const void* data, std::size_t bytes, int target, std::size_t stride) {
    if (model_.buffers.empty()) model_.buffers.emplace_back();
    std::vector<unsigned char>& bin = model_.buffers[0].data;
    bin.resize((bin.size() + 3) & ~std::size_t(3), 0);  // every view starts 4-byte aligned
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = bin.size();
    view.byteLength = bytes;
    view.byteStride = stride;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    bin.insert(bin.end(), p, p + bytes);
    model_.bufferViews.push_back(std::move(view));
    return static_cast<int>(model_.bufferViews.size()) - 1;
}

int ModelBuilder::addAccessor(int view, std::size_t byteOffset, int componentType, int type, std::size_t count) {
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.byteOffset = byteOffset;
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    model_.accessors.push_back(std::move(accessor));
    return static_cast<int>(model_.accessors.size()) - 1;
}

// The image's file as seen from the new file's folder, when the image came from a file that
// still exists.
std::optional<std::string> ModelBuilder::relativeUri(const Image& image) const {
    if (image.uri.empty() || isDataUri(image.uri) || scene_.sourcePath.empty()) return std::nullopt;
    std::error_code ec;
    const fs::path source = fs::absolute(scene_.sourcePath.parent_path() / percentDecode(image.uri), ec);
    if (ec || !fs::is_regular_file(source, ec)) return std::nullopt;
    const fs::path from = fs::weakly_canonical(fs::absolute(file_, ec).parent_path(), ec);
    if (ec) return std::nullopt;
    const fs::path to = fs::weakly_canonical(source, ec);
    if (ec) return std::nullopt;
    const fs::path relative = to.lexically_relative(from);
    if (relative.empty()) return std::nullopt;
    return percentEncodePath(relative.generic_string());
}

void ModelBuilder::addImages() {
    imageIndex_.assign(scene_.images.size(), -1);
    for (std::size_t i = 0; i < scene_.images.size(); ++i) {
        const Image& image = scene_.images[i];
        if (image.generated) continue;
        tinygltf::Image out;
        out.name = image.name;
        if (const std::optional<std::string> uri = relativeUri(image)) {
            out.uri = *uri;
            // tinygltf writes no mimeType beside a uri; the file's optional one goes back.
            if (!image.mimeType.empty())
                jsonPatches_.emplace_back("/images/" + std::to_string(model_.images.size()) + "/mimeType",
                                          nlohmann::json(image.mimeType).dump());
        } else if (!image.encoded.empty()) {  // the file's own bytes: not re-encoded (16-bit PNG, KTX2, JPEG)
            out.bufferView = addBufferView(image.encoded.data(), image.encoded.size(), 0, 0);
            out.mimeType = image.mimeType.empty() ? "application/octet-stream" : image.mimeType;
        } else {
            std::vector<std::uint8_t> png;
            try {
                png = encodePng(image.width, image.height, image.rgba, /*flipVertically=*/false);  // rows are top-down
            } catch (const std::exception& e) {
                fail(named("image", i, image.name) + " cannot be embedded: " + e.what());
            }
            out.bufferView = addBufferView(png.data(), png.size(), 0, 0);
            out.mimeType = "image/png";
        }
        keepView(out.bufferView, image.view);
        restore(image.kept, out.extras, out.extensions);
        imageIndex_[i] = static_cast<int>(model_.images.size());
        model_.images.push_back(std::move(out));
    }
}

void ModelBuilder::addTextures() {
    // One glTF sampler per distinct setting (name, extras, extensions and the fields written
    // included).
    using SamplerKey = std::tuple<std::array<int, 4>, std::array<bool, 4>, std::string, std::string, std::string>;
    std::map<SamplerKey, int> samplers;
    // Lit's values for what a file left out (scene/Scene.h: Texture).
    const std::array<int, 4> defaults = {10497, 10497, 9987, 9729};
    for (const Texture& texture : scene_.textures) {
        const std::array<int, 4> values = {texture.wrapS, texture.wrapT, texture.minFilter, texture.magFilter};
        // A field is written where the file had it or where it no longer holds Lit's default.
        std::array<bool, 4> written{};
        for (std::size_t f = 0; f < 4; ++f)
            written[f] = (texture.hasSampler && texture.samplerFields[f]) || values[f] != defaults[f];
        const bool anySampler = texture.hasSampler || std::find(written.begin(), written.end(), true) != written.end();
        int samplerIndex = -1;
        if (anySampler) {
            const SamplerKey key = {values, written, texture.samplerName, texture.samplerKept.extras,
                                    texture.samplerKept.extensions};
            auto [it, added] = samplers.emplace(key, static_cast<int>(model_.samplers.size()));
            if (added) {
                tinygltf::Sampler sampler;
                sampler.wrapS = texture.wrapS;
                sampler.wrapT = texture.wrapT;
                sampler.minFilter = written[2] ? texture.minFilter : -1;  // -1: not written by tinygltf
                sampler.magFilter = written[3] ? texture.magFilter : -1;
                tinygltf::ExtensionMap extensions;
                restore(texture.samplerKept, sampler.extras, extensions);
                // tinygltf 2.7 writes neither a sampler's name nor its extensions: set them in the
                // JSON; it always writes wrapS and wrapT: removed where the file had none.
                const std::string at = "/samplers/" + std::to_string(model_.samplers.size());
                if (!texture.samplerName.empty())
                    jsonPatches_.emplace_back(at + "/name", nlohmann::json(texture.samplerName).dump());
                if (!texture.samplerKept.extensions.empty())
                    jsonPatches_.emplace_back(at + "/extensions", texture.samplerKept.extensions);
                if (!written[0]) jsonPatches_.emplace_back(at + "/wrapS", "");
                if (!written[1]) jsonPatches_.emplace_back(at + "/wrapT", "");
                model_.samplers.push_back(sampler);
            }
            samplerIndex = it->second;
        }
        tinygltf::Texture out;
        out.name = texture.name;
        // The file's own image where the loader shared an identical earlier one (Texture::fileImage).
        int image = texture.image;
        if (texture.fileImage >= 0 && static_cast<std::size_t>(texture.fileImage) < scene_.images.size() &&
            texture.image >= 0 && scene_.images[static_cast<std::size_t>(texture.fileImage)].sameAs == texture.image)
            image = texture.fileImage;
        const auto writtenImage = [&](int i) {
            return i >= 0 && static_cast<std::size_t>(i) < imageIndex_.size() ? imageIndex_[static_cast<std::size_t>(i)]
                                                                              : -1;
        };
        out.source = writtenImage(image);
        // A WebP image goes back into EXT_texture_webp (with the file's fallback as `source`)
        // while it is still the file's WebP bytes; one re-encoded as PNG is a plain source.
        if (texture.webp && out.source >= 0 && writtenAsWebp(model_.images[static_cast<std::size_t>(out.source)],
                                                              scene_.images[static_cast<std::size_t>(image)])) {
            tinygltf::Value::Object webp;
            webp["source"] = tinygltf::Value(out.source);
            out.extensions[kWebpExtension] = tinygltf::Value(std::move(webp));
            useExtension(kWebpExtension);
            out.source = writtenImage(texture.fallbackImage);
        }
        out.sampler = samplerIndex;
        restore(texture.kept, out.extras, out.extensions);
        model_.textures.push_back(std::move(out));
    }
}

void ModelBuilder::addMaterials() {
    for (const Material& material : scene_.materials) {
        const FileNumbers& n = material.fileNumbers;
        tinygltf::Material out;
        out.name = material.name;
        tinygltf::PbrMetallicRoughness& pbr = out.pbrMetallicRoughness;
        pbr.baseColorFactor = fileOr(n, "baseColorFactor", material.baseColorFactor);
        pbr.baseColorTexture.index = material.baseColorTexture;
        pbr.baseColorTexture.texCoord = material.textureTexCoord[0];
        pbr.metallicFactor = fileOr(n, "metallicFactor", material.metallic);
        pbr.roughnessFactor = fileOr(n, "roughnessFactor", material.roughness);
        pbr.metallicRoughnessTexture.index = material.metallicRoughnessTexture;
        pbr.metallicRoughnessTexture.texCoord = material.textureTexCoord[1];
        out.normalTexture.texCoord = material.textureTexCoord[2];
        out.emissiveTexture.texCoord = material.textureTexCoord[3];
        out.occlusionTexture.texCoord = material.textureTexCoord[4];
        out.normalTexture.index = material.normalTexture;
        out.normalTexture.scale = fileOr(n, "normalScale", material.normalScale);
        out.occlusionTexture.index = material.occlusionTexture;
        out.occlusionTexture.strength = fileOr(n, "occlusionStrength", material.occlusionStrength);
        out.emissiveTexture.index = material.emissiveTexture;
        out.emissiveFactor = fileOr(n, "emissiveFactor", material.emissiveFactor);
        if (material.emissiveStrength != 1.0f || n.count("emissiveStrength")) {
            tinygltf::Value::Object extension;
            extension["emissiveStrength"] = tinygltf::Value(fileOr(n, "emissiveStrength", material.emissiveStrength));
            out.extensions[kEmissiveStrengthExtension] = tinygltf::Value(std::move(extension));
            useExtension(kEmissiveStrengthExtension);
        }
        switch (material.alphaMode) {
            case AlphaMode::Opaque:
                out.alphaMode = "OPAQUE";
                break;
            case AlphaMode::Mask:
                out.alphaMode = "MASK";
                break;
            case AlphaMode::Blend:
                out.alphaMode = "BLEND";
                break;
        }
        out.alphaCutoff = fileOr(n, "alphaCutoff", material.alphaCutoff);
        out.doubleSided = material.doubleSided;
        keepMaterialFields(material, out, model_.materials.size());
        // Before restore(): the layer extensions are written from the file's objects in `kept`.
        gltfkeep::writeMaterialLayers(material, out.extensions, [&](const std::string& name) { useExtension(name); });
        restore(material.kept, out.extras, out.extensions);
        const auto& extras = material.textureExtras;
        const auto& extensions = material.textureExtensions;
        // KHR_texture_transform first: restore() keeps an extension already present.
        const std::array<tinygltf::ExtensionMap*, 5> referenceExtensions = {
            &pbr.baseColorTexture.extensions, &pbr.metallicRoughnessTexture.extensions, &out.normalTexture.extensions,
            &out.emissiveTexture.extensions, &out.occlusionTexture.extensions};
        const std::array<int, 5> textures = {material.baseColorTexture, material.metallicRoughnessTexture,
                                             material.normalTexture, material.emissiveTexture,
                                             material.occlusionTexture};
        for (std::size_t slot = 0; slot < 5; ++slot) {
            if (textures[slot] < 0 || !material.textureTransforms[slot].present) continue;
            (*referenceExtensions[slot])[gltfkeep::kTextureTransformExtension] =
                gltfkeep::textureTransformValue(material.textureTransforms[slot]);
            useExtension(gltfkeep::kTextureTransformExtension);
        }
        restoreTextureInfo(extras[0], extensions[0], pbr.baseColorTexture.extras, pbr.baseColorTexture.extensions);
        restoreTextureInfo(extras[1], extensions[1], pbr.metallicRoughnessTexture.extras,
                           pbr.metallicRoughnessTexture.extensions);
        restoreTextureInfo(extras[2], extensions[2], out.normalTexture.extras, out.normalTexture.extensions);
        restoreTextureInfo(extras[3], extensions[3], out.emissiveTexture.extras, out.emissiveTexture.extensions);
        restoreTextureInfo(extras[4], extensions[4], out.occlusionTexture.extras, out.occlusionTexture.extensions);
        restore(material.pbrKept, pbr.extras, pbr.extensions);
        model_.materials.push_back(std::move(out));
    }
}

void ModelBuilder::addLights() {
    for (const Light& light : scene_.lights) {
        tinygltf::Light out;
        out.name = light.name;
        out.color = fileOr(light.fileNumbers, "color", light.color);
        // Back to the file's photometric units (cd, lx); an unedited light keeps its exact number.
        out.intensity = light.intensity == light.fileIntensityAsLoaded ? light.fileIntensity
                                                                       : photometricFromRadiometric(light.intensity);
        out.range =
            fileOr(light.fileNumbers, "range", std::max(light.range, 0.0f));  // written only when > 0 (0 = infinite)
        switch (light.type) {
            case LightType::Directional:
                out.type = "directional";
                break;
            case LightType::Point:
                out.type = "point";
                break;
            case LightType::Spot:
                out.type = "spot";
                out.spot.innerConeAngle = fileOr(light.fileNumbers, "innerConeAngle", light.innerConeAngle);
                out.spot.outerConeAngle = fileOr(light.fileNumbers, "outerConeAngle", light.outerConeAngle);
                break;
        }
        if (!light.castsShadow) {
            tinygltf::Value::Object extras;
            extras[kCastsShadowKey] = tinygltf::Value(false);
            out.extras = tinygltf::Value(std::move(extras));
        }
        restore(light.kept, out.extras, out.extensions);
        model_.lights.push_back(std::move(out));
    }
    if (!model_.lights.empty()) useExtension(kLightsExtension);
}

void ModelBuilder::addCameras() {
    for (const Camera& camera : scene_.cameras) {
        tinygltf::Camera out;
        out.name = camera.name;
        if (camera.orthographic && camera.xmag != 0.0f && camera.ymag != 0.0f && camera.zfar > camera.znear) {
            out.type = "orthographic";  // as the file had it (Lit draws it in perspective)
            const FileNumbers& n = camera.fileNumbers;
            out.orthographic.xmag = fileOr(n, "xmag", camera.xmag);
            out.orthographic.ymag = fileOr(n, "ymag", camera.ymag);
            out.orthographic.znear = fileOr(n, "znear", camera.znear);
            out.orthographic.zfar = fileOr(n, "zfar", camera.zfar);
        } else {
            out.type = "perspective";
            const FileNumbers& n = camera.fileNumbers;
            out.perspective.yfov = fileOr(n, "yfov", camera.yfov);
            out.perspective.znear = fileOr(n, "znear", camera.znear);
            out.perspective.zfar = fileOr(n, "zfar", std::max(camera.zfar, 0.0f));  // 0: left out by writeGltfModel
            out.perspective.aspectRatio = fileOr(n, "aspectRatio", std::max(camera.aspectRatio, 0.0f));  // 0: left out
        }
        restore(camera.kept, out.extras, out.extensions);
        model_.cameras.push_back(std::move(out));
    }
}

void ModelBuilder::orderNodes() {
    // The written nodes (the shown ones reachable from the roots, then the kept ones) in the
    // file's order (Node::fileIndex), those Lit made after them in their own order: an unedited
    // file keeps its node indices, an edited one its nodes' order. A file index seen twice (a
    // copied node) counts once.
    struct Written {
        const Node* node;
        bool kept;
        int index;  // in Scene::nodes or Scene::keptNodes
        long long order;
    };
    std::vector<Written> written;
    for (int index : reachableNodes())
        written.push_back({&scene_.nodes[static_cast<std::size_t>(index)], false, index, 0});
    for (std::size_t k = 0; k < scene_.keptNodes.size(); ++k)
        written.push_back({&scene_.keptNodes[k], true, static_cast<int>(k), 0});
    {
        std::vector<std::uint8_t> seen;
        constexpr long long kMade = 1LL << 40;  // after every file index
        for (std::size_t i = 0; i < written.size(); ++i) {
            const int file = written[i].node->fileIndex;
            const bool first =
                file >= 0 && (static_cast<std::size_t>(file) >= seen.size() || !seen[static_cast<std::size_t>(file)]);
            if (first) {
                if (static_cast<std::size_t>(file) >= seen.size()) seen.resize(static_cast<std::size_t>(file) + 1, 0);
                seen[static_cast<std::size_t>(file)] = 1;
            }
            written[i].order = first ? file : kMade + static_cast<long long>(i);
        }
        std::stable_sort(written.begin(), written.end(),
                         [](const Written& a, const Written& b) { return a.order < b.order; });
    }
    nodeIndex_.assign(scene_.nodes.size(), -1);
    keptNodeIndex_.assign(scene_.keptNodes.size(), -1);
    for (std::size_t i = 0; i < written.size(); ++i)
        (written[i].kept ? keptNodeIndex_ : nodeIndex_)[static_cast<std::size_t>(written[i].index)] =
            static_cast<int>(i);
    for (const Written& w : written) writtenNodes_.emplace_back(w.node, w.kept);
    skinIndex_.assign(scene_.skins.size(), -1);
}

void ModelBuilder::addNodes() {
    addSkins(std::numeric_limits<int>::max());
    // Nodes a written animation moves: glTF forbids a matrix on them (§5.25).
    std::vector<const Node*> animated;
    for (const Animation& animation : scene_.animations) {
        if (!replacedAnimation_.empty() && animation.name == replacedAnimation_) continue;
        for (const Animation::Channel& channel : animation.channels) {
            if (channel.path == "weights") continue;
            if (channel.node >= 0 && static_cast<std::size_t>(channel.node) < scene_.nodes.size())
                animated.push_back(&scene_.nodes[static_cast<std::size_t>(channel.node)]);
            else if (channel.node <= -2 &&
                     static_cast<std::size_t>(keptNodeIndex(channel.node)) < scene_.keptNodes.size())
                animated.push_back(&scene_.keptNodes[static_cast<std::size_t>(keptNodeIndex(channel.node))]);
        }
    }
    const auto addNode = [&](const Node& node, const std::vector<int>& childIndex) {
        tinygltf::Node out;
        out.name = node.name;
        for (int child : node.children) out.children.push_back(childIndex[static_cast<std::size_t>(child)]);
        // The file's matrix while the transform is the one it gave (an edit writes TRS).
        const bool fileMatrix = node.fileMatrix.size() == 16 && node.translation == node.matrixTranslation &&
                                node.rotation == node.matrixRotation && node.scale == node.matrixScale &&
                                std::find(animated.begin(), animated.end(), &node) == animated.end();
        if (fileMatrix) {
            out.matrix = node.fileMatrix;
        } else {
            addTrs(node, out);
        }

        out.mesh = node.mesh >= 0 ? meshIndex_[static_cast<std::size_t>(node.mesh)] : -1;
        out.camera = node.camera;
        out.skin = node.skin >= 0 ? skinIndex_[static_cast<std::size_t>(node.skin)] : -1;
        out.weights = node.weights;
        if (node.light >= 0) {
            tinygltf::Value::Object extension;
            extension["light"] = tinygltf::Value(node.light);
            out.extensions[kLightsExtension] = tinygltf::Value(std::move(extension));
        }
        restore(node.kept, out.extras, out.extensions);
        model_.nodes.push_back(std::move(out));
    };
    for (const auto& [node, kept] : writtenNodes_) addNode(*node, kept ? keptNodeIndex_ : nodeIndex_);
    const auto sceneOf = [&](const std::string& name, const std::vector<int>& roots, const KeptGltf& kept) {
        tinygltf::Scene out;
        out.name = name;
        for (int reference : roots) {
            const int mapped = writtenNode(reference);
            if (mapped < 0) continue;
            // A node another scene shares may have been deleted or re-parented under a node.
            const Node& node = reference >= 0 ? scene_.nodes[static_cast<std::size_t>(reference)]
                                              : scene_.keptNodes[static_cast<std::size_t>(keptNodeIndex(reference))];
            if (node.parent >= 0) continue;
            if (std::find(out.nodes.begin(), out.nodes.end(), mapped) == out.nodes.end()) out.nodes.push_back(mapped);
        }
        restore(kept, out.extras, out.extensions);
        return out;
    };
    // The file's scenes in their order, the shown one where it was (without a name while it still
    // has the one the loader gave an unnamed scene).
    const std::string shownName =
        !scene_.fileSceneNamed && scene_.name == scene_.sourcePath.stem().string() ? std::string() : scene_.name;
    const std::size_t shown =
        std::min(static_cast<std::size_t>(std::max(scene_.sceneIndex, 0)), scene_.otherScenes.size());
    for (std::size_t i = 0; i < scene_.otherScenes.size(); ++i) {
        if (i == shown) model_.scenes.push_back(sceneOf(shownName, scene_.roots, scene_.kept));
        const Scene::OtherScene& other = scene_.otherScenes[i];
        model_.scenes.push_back(sceneOf(other.name, other.roots, other.kept));
    }
    if (shown == scene_.otherScenes.size()) model_.scenes.push_back(sceneOf(shownName, scene_.roots, scene_.kept));
    model_.defaultScene = static_cast<int>(shown);
}

void ModelBuilder::useExtension(const std::string& name) {
    if (std::find(model_.extensionsUsed.begin(), model_.extensionsUsed.end(), name) == model_.extensionsUsed.end())
        model_.extensionsUsed.push_back(name);
}

tinygltf::Model ModelBuilder::build() {
    checkScene();
    model_.asset.version = "2.0";
    model_.asset.generator = kGenerator;
    addImages();
    addTextures();
    addMaterials();
    orderNodes();
    addMeshes();
    addLights();
    addCameras();
    addNodes();
    addAnimations();
    keepBuffers();
    model_.asset.copyright = scene_.copyright;
    {
        tinygltf::Value extras;
        if (!scene_.generator.empty() && scene_.generator != kGenerator) {
            tinygltf::Value::Object source;
            source[kSourceGeneratorKey] = tinygltf::Value(scene_.generator);
            extras = tinygltf::Value(std::move(source));
        }
        restore(scene_.assetKept, extras, model_.asset.extensions);
        // tinygltf writes asset extras only when they are an object (glTF's extras usually are).
        model_.asset.extras = std::move(extras);
    }
    restore(scene_.fileKept, model_.extras, model_.extensions);
    // Kept vertex data may be quantized (KHR_mesh_quantization's types); the extension is then
    // required, as its specification says.
    const bool quantized = std::find(scene_.unknownExtensionsUsed.begin(), scene_.unknownExtensionsUsed.end(),
                                     "KHR_mesh_quantization") != scene_.unknownExtensionsUsed.end();
    if (quantized && wroteKeptVertexData_) {
        useExtension("KHR_mesh_quantization");
        model_.extensionsRequired.push_back("KHR_mesh_quantization");
    }
    // What the file required stays required while the saved file uses it (Blender requires
    // KHR_lights_punctual of a file with lights).
    for (const std::string& e : scene_.extensionsRequired)
        if (std::find(model_.extensionsUsed.begin(), model_.extensionsUsed.end(), e) != model_.extensionsUsed.end() &&
            std::find(model_.extensionsRequired.begin(), model_.extensionsRequired.end(), e) ==
                model_.extensionsRequired.end())
            model_.extensionsRequired.push_back(e);
    // Extensions the source declared that no kept data uses any more are not declared again
    // (the validator reports unused ones); those still used were declared by restore().
    return std::move(model_);
}

}  // namespace lit::gltfexport
