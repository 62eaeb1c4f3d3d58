#include "scene/GpuScene.h"

#include <shared.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <stdexcept>
#include <string>

#include "Log.h"
#include "gl/Shader.h"
#include "scene/Scene.h"
#include "scene/SceneMemory.h"
#include "scene/Sheets.h"

namespace lit {

namespace {

gl::Texture uploadImage(const Image& image, const std::string& label) {
    const int levels = gl::Texture::mipCount(image.width, image.height);
    gl::Texture texture(label, {GL_TEXTURE_2D, image.srgb ? GLenum(GL_SRGB8_ALPHA8) : GLenum(GL_RGBA8), image.width,
                                image.height, 1, levels});
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.rgba.data());
    glGenerateTextureMipmap(texture.id());
    return texture;
}

// The GL sampler state of a glTF sampler, as GpuScene sets it: always trilinear when
// minification asks for mipmaps (or leaves it to the renderer), the file's choice otherwise.
struct SamplerState {
    GLint wrapS = GL_REPEAT, wrapT = GL_REPEAT;
    GLint minFilter = GL_LINEAR_MIPMAP_LINEAR, magFilter = GL_LINEAR;
    auto operator<=>(const SamplerState&) const = default;
};

GLint glWrap(int wrap) {
    return wrap == GL_CLAMP_TO_EDGE || wrap == GL_MIRRORED_REPEAT ? GLint(wrap) : GLint(GL_REPEAT);
}

SamplerState samplerStateOf(const Texture& texture) {
    const int min = texture.minFilter;
    const bool mipFilter = min == GL_NEAREST_MIPMAP_NEAREST || min == GL_LINEAR_MIPMAP_NEAREST ||
                           min == GL_NEAREST_MIPMAP_LINEAR || min == GL_LINEAR_MIPMAP_LINEAR;
    SamplerState state;
    state.wrapS = glWrap(texture.wrapS);
    state.wrapT = glWrap(texture.wrapT);
    state.minFilter = mipFilter || (min != GL_NEAREST && min != GL_LINEAR) ? GLint(GL_LINEAR_MIPMAP_LINEAR) : GLint(min);
    state.magFilter = texture.magFilter == GL_NEAREST ? GL_NEAREST : GL_LINEAR;
    return state;
}

gl::Sampler makeSampler(const SamplerState& state, std::size_t index) {
    gl::Sampler sampler("material sampler " + std::to_string(index));
    sampler.set(GL_TEXTURE_WRAP_S, state.wrapS);
    sampler.set(GL_TEXTURE_WRAP_T, state.wrapT);
    sampler.set(GL_TEXTURE_MIN_FILTER, state.minFilter);
    sampler.set(GL_TEXTURE_MAG_FILTER, state.magFilter);
    // Only for filtered samplers: a file that asks for nearest texels (pixel art, lookup tables)
    // gets them, and llvmpipe's anisotropic filter blends texels even under GL_NEAREST.
    if (state.magFilter == GL_LINEAR && state.minFilter == GL_LINEAR_MIPMAP_LINEAR &&
        epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic"))
        glSamplerParameterf(sampler.id(), GL_TEXTURE_MAX_ANISOTROPY_EXT, 8.0f);
    return sampler;
}

// The material's texture transforms and UV sets as material.glsl's uUvTransforms wants them.
GpuScene::UvTransforms uvTransformsOf(const Material& m) {
    static_assert(2 * LIT_MATERIAL_SLOTS == std::tuple_size_v<GpuScene::UvTransforms>);
    static_assert(LIT_MATERIAL_SLOT_TRANSMISSION == std::tuple_size_v<decltype(m.textureTransforms)>);
    static_assert(LIT_MATERIAL_SLOTS == LIT_MATERIAL_SLOT_TRANSMISSION + kExtensionTextureSlots.size());
    GpuScene::UvTransforms out{};
    const auto put = [&out](std::size_t slot, const TextureTransform& transform, int uvSet) {
        const std::array<glm::vec3, 2> rows = uvTransformRows(transform);
        out[2 * slot] = glm::vec4(rows[0], static_cast<float>(uvSet));
        out[2 * slot + 1] = glm::vec4(rows[1], 0.0f);
    };
    for (std::size_t slot = 0; slot < m.textureTransforms.size(); ++slot)
        put(slot, m.textureTransforms[slot], drawnTexCoord(m, slot));
    for (std::size_t k = 0; k < kExtensionTextureSlots.size(); ++k) {
        const ExtensionTexture& t = m.*kExtensionTextureSlots[k].member;
        put(LIT_MATERIAL_SLOT_TRANSMISSION + k, t.transform, drawnTexCoord(t));
    }
    return out;
}

gpu::GpuMaterial toGpu(const Material& m) {
    gpu::GpuMaterial g{};
    g.baseColorFactor = m.baseColorFactor;
    g.emissive = glm::vec4(m.emissiveFactor * m.emissiveStrength, 0.0f);
    g.params = glm::vec4(m.metallic, m.roughness, m.normalScale, m.occlusionStrength);
    g.textures = glm::ivec4(m.baseColorTexture >= 0, m.metallicRoughnessTexture >= 0, m.normalTexture >= 0,
                            m.emissiveTexture >= 0);
    const int alphaMode = m.alphaMode == AlphaMode::Mask    ? LIT_ALPHA_MASK
                          : m.alphaMode == AlphaMode::Blend ? LIT_ALPHA_BLEND
                                                            : LIT_ALPHA_OPAQUE;
    g.modes = glm::ivec4(m.occlusionTexture >= 0, alphaMode, m.doubleSided ? 1 : 0, 0);
    g.alpha = glm::vec4(m.alphaCutoff, std::clamp(m.transmission, 0.0f, 1.0f), refractiveIndexOfVolume(m), 0.0f);
    // docs/MATERIALS.md: F0 = min(((η − 1)/(η + 1))² · k, 1) · s, F90 = s. The table holds the
    // product before the clamp, ((η − 1)/(η + 1))² · k · s, which the shaders clamp to s after a
    // specular-colour texel has scaled it (material_table.glsl materialDielectricF0).
    const float reflectance = (m.ior - 1.0f) / (m.ior + 1.0f);  // η = 0 (a mirror) gives 1
    const float f0FromIor = reflectance * reflectance;
    g.specular = glm::vec4(glm::vec3(f0FromIor) * m.specularColorFactor * m.specularFactor, m.specularFactor);
    g.clearcoat = glm::vec4(m.clearcoatFactor, m.clearcoatRoughness, m.clearcoatNormalTexture.scale, 0.0f);
    g.volume = glm::vec4(volumeAbsorption(m), m.thickness);
    g.sheen = glm::vec4(m.sheenColorFactor, m.sheenRoughness);
    return g;
}

}  // namespace

GpuScene::GpuScene(const Scene& scene, Log& log, std::uint32_t maxChunkTriangles) {
    // Geometry: every primitive once, instanced by the nodes that reference its mesh.
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    struct Range {
        GLint baseVertex;
        std::uint32_t firstIndex, indexCount;
        Aabb bounds;
    };
    // Per mesh, per primitive: its chunks (one range when it was not split).
    std::vector<std::vector<std::vector<Range>>> meshRanges(scene.meshes.size());
    std::size_t splitPrimitives = 0, chunkCount = 0;
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        for (const Primitive& p : scene.meshes[m].primitives) {
            const auto baseVertex = static_cast<GLint>(vertices.size());
            const auto firstIndex = static_cast<std::uint32_t>(indices.size());
            vertices.insert(vertices.end(), p.vertices.begin(), p.vertices.end());
            indices.insert(indices.end(), p.indices.begin(), p.indices.end());
            const std::span<std::uint32_t> own(indices.data() + firstIndex, p.indices.size());
            std::vector<Range>& ranges = meshRanges[m].emplace_back();
            try {
                for (const TriangleChunk& c : splitIntoChunks(p.vertices, own, maxChunkTriangles))
                    ranges.push_back({baseVertex, firstIndex + c.firstIndex, c.indexCount, c.bounds});
            } catch (const std::invalid_argument& e) {
                throw std::invalid_argument("mesh " + std::to_string(m) + " \"" + scene.meshes[m].name + "\": " + e.what());
            }
            // An unsplit primitive keeps the box the Scene computed for it.
            if (ranges.size() == 1) ranges.front().bounds = p.bounds;
            if (ranges.size() > 1) {
                ++splitPrimitives;
                chunkCount += ranges.size();
            }
        }
    }
    if (splitPrimitives > 0)
        log.info("split " + std::to_string(splitPrimitives) + " large primitives into " + std::to_string(chunkCount) +
                 " chunks of at most " + std::to_string(maxChunkTriangles) + " triangles for culling");
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        const Node& node = scene.nodes[n];
        if (node.mesh < 0) continue;
        const Mesh& mesh = scene.meshes[static_cast<std::size_t>(node.mesh)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            for (const Range& r : meshRanges[static_cast<std::size_t>(node.mesh)][p]) {
                if (r.indexCount == 0) continue;
                items_.push_back({static_cast<int>(n), mesh.primitives[p].material, r.baseVertex, r.firstIndex,
                                  r.indexCount, r.bounds, static_cast<int>(p)});
            }
        }
    }
    vertices_ = gl::Buffer::fromSpan<Vertex>("scene vertices", vertices);
    indices_ = gl::Buffer::fromSpan<std::uint32_t>("scene indices", indices);
    vertexArray_ = gl::VertexArray("scene geometry");
    const GLuint vao = vertexArray_.id();
    glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, indices_.id());
    const auto attribute = [vao](GLuint location, GLint size, std::size_t offset) {
        glEnableVertexArrayAttrib(vao, location);
        glVertexArrayAttribFormat(vao, location, size, GL_FLOAT, GL_FALSE, static_cast<GLuint>(offset));
        glVertexArrayAttribBinding(vao, location, 0);
    };
    attribute(0, 3, offsetof(Vertex, position));
    attribute(1, 3, offsetof(Vertex, normal));
    attribute(2, 2, offsetof(Vertex, uv));
    attribute(3, 4, offsetof(Vertex, tangent));
    attribute(4, 2, offsetof(Vertex, uv1));

    // Textures: each image once, however many textures use it; each distinct sampler once.
    whiteTexture_ = gl::Texture("white 1x1", {GL_TEXTURE_2D, GL_RGBA8, 1, 1, 1, 1});
    const std::uint8_t white[4] = {255, 255, 255, 255};
    glTextureSubImage2D(whiteTexture_.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
    // An image wider or taller than the driver's limit cannot be a texture (glTextureStorage2D
    // fails with GL_INVALID_VALUE): checked here, before the upload, so that it is one warning
    // naming the image instead of a GL error.
    GLint maxTextureSide = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSide);
    images_.resize(scene.images.size());
    std::vector<std::uint8_t> imageTried(scene.images.size(), 0);
    std::map<SamplerState, GLuint> samplerIds;
    textures_.reserve(scene.textures.size());
    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        const Texture& tex = scene.textures[t];
        const bool valid = tex.image >= 0 && static_cast<std::size_t>(tex.image) < scene.images.size() &&
                           scene.images[static_cast<std::size_t>(tex.image)].width > 0;
        if (!valid) {
            log.warning("texture " + std::to_string(t) + " has no usable image; using a neutral texture");
            textures_.emplace_back();
            continue;
        }
        const auto imageIndex = static_cast<std::size_t>(tex.image);
        const Image& image = scene.images[imageIndex];
        if (!imageTried[imageIndex]) {
            imageTried[imageIndex] = 1;
            if (image.width > maxTextureSide || image.height > maxTextureSide) {
                log.warning("image " + std::to_string(tex.image) + (image.name.empty() ? "" : " ('" + image.name + "')") +
                            " is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                            ", larger than this GL's limit of " + std::to_string(maxTextureSide) +
                            " pixels a side; its textures use a neutral texture");
            } else {
                images_[imageIndex] =
                    uploadImage(image, image.name.empty() ? "image " + std::to_string(imageIndex) : image.name);
                textureBytes_ += textureBytesWithMips(image.width, image.height);
            }
        }
        if (!images_[imageIndex]) {
            textures_.emplace_back();
            continue;
        }
        const SamplerState state = samplerStateOf(tex);
        auto found = samplerIds.find(state);
        if (found == samplerIds.end()) {
            samplers_.push_back(makeSampler(state, samplers_.size()));
            found = samplerIds.emplace(state, samplers_.back().id()).first;
        }
        textures_.push_back({images_[imageIndex].id(), found->second});
    }
    if (!scene.textures.empty())
        log.info("uploaded " + std::to_string(imageTextureCount()) + " images for " +
                 std::to_string(scene.textures.size()) + " textures with " + std::to_string(samplers_.size()) +
                 " samplers (" + std::to_string(textureBytes_ / (1024 * 1024)) + " MB with mipmaps)");
    updateMaterials(scene);
}

void GpuScene::updateMaterials(const Scene& scene) {
    std::vector<gpu::GpuMaterial> table;
    table.reserve(scene.materials.size() + 1);
    materialTextures_.clear();
    materialLayerBits_.clear();
    materialUvTransforms_.clear();
    sheetMaterials_.clear();
    materialLayers_ = std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
        return m.ior != 1.5f || m.specularFactor != 1.0f || m.specularColorFactor != glm::vec3(1.0f) ||
               m.clearcoatFactor != 0.0f || m.sheenColorFactor != glm::vec3(0.0f);
    });
    layerTextures_ = false;
    hasRefractingSheets_ = false;
    const auto textureId = [this](int index) -> TextureBinding {
        if (index < 0 || static_cast<std::size_t>(index) >= textures_.size()) return {};
        return textures_[static_cast<std::size_t>(index)];
    };
    for (const Material& m : scene.materials) {
        gpu::GpuMaterial g = toGpu(m);
        MaterialTextures t{};
        t[LIT_MATERIAL_SLOT_BASE_COLOR] = textureId(m.baseColorTexture);
        t[LIT_MATERIAL_SLOT_METALLIC_ROUGHNESS] = textureId(m.metallicRoughnessTexture);
        t[LIT_MATERIAL_SLOT_NORMAL] = textureId(m.normalTexture);
        t[LIT_MATERIAL_SLOT_EMISSIVE] = textureId(m.emissiveTexture);
        t[LIT_MATERIAL_SLOT_OCCLUSION] = textureId(m.occlusionTexture);
        for (std::size_t k = 0; k < kExtensionTextureSlots.size(); ++k)
            t[LIT_MATERIAL_SLOT_TRANSMISSION + k] = textureId((m.*kExtensionTextureSlots[k].member).texture);
        // A texture that failed to load must not be sampled as if present.
        const auto present = [&t](int slot) { return t[static_cast<std::size_t>(slot)].texture != 0; };
        g.textures = glm::ivec4(present(LIT_MATERIAL_SLOT_BASE_COLOR), present(LIT_MATERIAL_SLOT_METALLIC_ROUGHNESS),
                                present(LIT_MATERIAL_SLOT_NORMAL), present(LIT_MATERIAL_SLOT_EMISSIVE));
        g.modes.x = present(LIT_MATERIAL_SLOT_OCCLUSION);
        g.modes.w = present(LIT_MATERIAL_SLOT_TRANSMISSION);
        // LIT_LAYER_TEXTURE_* bit k is layer slot LIT_MATERIAL_SLOT_CLEARCOAT + k.
        for (int k = 0; LIT_MATERIAL_SLOT_CLEARCOAT + k <= LIT_MATERIAL_SLOT_CLEARCOAT_NORMAL; ++k)
            if (present(LIT_MATERIAL_SLOT_CLEARCOAT + k)) g.layerTextures.x |= 1 << k;
        // A coat over a normal-mapped base keeps the interpolated normal (KHR_materials_clearcoat),
        // which the G-buffer then stores beside the base's.
        if (m.clearcoatFactor > 0.0f &&
            (present(LIT_MATERIAL_SLOT_CLEARCOAT_NORMAL) || present(LIT_MATERIAL_SLOT_NORMAL)))
            g.layerTextures.x |= LIT_LAYER_COAT_NORMAL_STORED;
        g.layerTextures.y = present(LIT_MATERIAL_SLOT_THICKNESS);
        layerTextures_ = layerTextures_ || g.layerTextures.x != 0;
        hasRefractingSheets_ = hasRefractingSheets_ || g.alpha.z > 0.0f;  // refractiveIndexOfVolume
        materialLayerBits_.push_back(g.layerTextures.x);
        table.push_back(g);
        sheetMaterials_.push_back(drawnAsSheet(m));
        materialTextures_.push_back(t);
        materialUvTransforms_.push_back(uvTransformsOf(m));
    }
    // The default material (glTF spec: white, metallic 1, roughness 1; we use metallic 0 so
    // untextured test geometry is visible as diffuse white).
    Material fallback;
    fallback.metallic = 0.0f;
    table.push_back(toGpu(fallback));
    sheetMaterials_.push_back(false);
    hasSheets_ = std::find(sheetMaterials_.begin(), sheetMaterials_.end(), true) != sheetMaterials_.end();
    materialTextures_.push_back({});
    materialLayerBits_.push_back(0);
    // A specular texture under the default factors still needs the layers read per pixel.
    materialLayers_ = materialLayers_ || layerTextures_;
    materialUvTransforms_.push_back(uvTransformsOf(fallback));
    materials_ = gl::Buffer::fromSpan<gpu::GpuMaterial>("materials", table);
}

void GpuScene::bindMaterialTextures(int material, Bind bind) const {
    const MaterialTextures& t = materialTextures_[static_cast<std::size_t>(material)];
    const GLuint white = whiteTexture_.id();
    // Sampler 0 leaves the white texture's own parameters in force.
    const auto bindSlot = [white, &t](int slot) {
        const TextureBinding& binding = t[static_cast<std::size_t>(slot)];
        const GLuint unit = kMaterialTextureUnits[static_cast<std::size_t>(slot)];
        glBindTextureUnit(unit, binding.texture ? binding.texture : white);
        glBindSampler(unit, binding.texture ? binding.sampler : 0);
    };
    bindSlot(LIT_MATERIAL_SLOT_BASE_COLOR);
    if (bind == Bind::AlphaOnly) return;
    for (int slot = LIT_MATERIAL_SLOT_METALLIC_ROUGHNESS; slot <= LIT_MATERIAL_SLOT_OCCLUSION; ++slot) bindSlot(slot);
    // The extensions' textures are sampled only where the material has them (material.glsl's flags):
    // a draw without leaves whatever is bound there.
    for (int slot = LIT_MATERIAL_SLOT_TRANSMISSION; slot < LIT_MATERIAL_SLOTS; ++slot)
        if (t[static_cast<std::size_t>(slot)].texture) bindSlot(slot);
}

void GpuScene::unbindMaterialSamplers() {
    for (const GLuint unit : kMaterialTextureUnits) glBindSampler(unit, 0);
}

std::size_t GpuScene::imageTextureCount() const {
    return static_cast<std::size_t>(
        std::count_if(images_.begin(), images_.end(), [](const gl::Texture& t) { return static_cast<bool>(t); }));
}

void GpuScene::drawList(const Scene& scene, const gl::Program& program, Bind bind, DrawCounters& counters,
                        std::span<const std::uint32_t> itemIndices) const {
    if (itemIndices.empty()) return;
    bindGeometry();
    for (const std::uint32_t index : itemIndices) {
        assert(index < items_.size() && "drawList: item index out of range (a culling result of another scene?)");
        if (index < items_.size()) drawItem(scene, items_[index], program, bind, counters);
    }
    unbindMaterialSamplers();
}

int GpuScene::materialRow(const DrawItem& item) const {
    return (item.material >= 0 && static_cast<std::size_t>(item.material) + 1 < materialTextures_.size())
               ? item.material
               : static_cast<int>(materialTextures_.size()) - 1;
}

bool GpuScene::isSheet(const DrawItem& item) const {
    const auto row = static_cast<std::size_t>(materialRow(item));
    return row < sheetMaterials_.size() && sheetMaterials_[row];
}

void GpuScene::sheetItems(const std::vector<std::uint32_t>* candidates, std::vector<std::uint32_t>& out) const {
    out.clear();
    if (!hasSheets_) return;
    const auto consider = [&](std::uint32_t index) {
        if (index < items_.size() && isSheet(items_[index])) out.push_back(index);
    };
    if (candidates) {
        for (const std::uint32_t index : *candidates) consider(index);
    } else {
        for (std::uint32_t i = 0; i < items_.size(); ++i) consider(i);
    }
}

unsigned GpuScene::materialTextureMask(const DrawItem& item) const {
    if (materialTextures_.empty()) return 0;
    const auto row = static_cast<std::size_t>(materialRow(item));
    const MaterialTextures& t = materialTextures_[row];
    const auto present = [&t](int slot) { return t[static_cast<std::size_t>(slot)].texture != 0; };
    const bool layers = materialLayerBits_[row] != 0;
    return (present(LIT_MATERIAL_SLOT_BASE_COLOR) ? LIT_MATERIAL_TEXTURE_BASE_COLOR : 0u) |
           (present(LIT_MATERIAL_SLOT_METALLIC_ROUGHNESS) ? LIT_MATERIAL_TEXTURE_METALLIC_ROUGHNESS : 0u) |
           (present(LIT_MATERIAL_SLOT_NORMAL) ? LIT_MATERIAL_TEXTURE_NORMAL : 0u) |
           (present(LIT_MATERIAL_SLOT_EMISSIVE) ? LIT_MATERIAL_TEXTURE_EMISSIVE : 0u) |
           (present(LIT_MATERIAL_SLOT_OCCLUSION) ? LIT_MATERIAL_TEXTURE_OCCLUSION : 0u) |
           (layers ? LIT_MATERIAL_TEXTURE_LAYERS : 0u);
}

void GpuScene::drawItem(const Scene& scene, const DrawItem& item, const gl::Program& program, Bind bind,
                        DrawCounters& counters) const {
    const glm::mat4& model = scene.nodes[static_cast<std::size_t>(item.node)].world;
    const glm::mat4 normalMatrix = glm::transpose(glm::inverse(model));
    glProgramUniformMatrix4fv(program.id(), LIT_LOC_MODEL, 1, GL_FALSE, glm::value_ptr(model));
    glProgramUniformMatrix4fv(program.id(), LIT_LOC_NORMAL_MATRIX, 1, GL_FALSE, glm::value_ptr(normalMatrix));
    const int material = materialRow(item);
    glProgramUniform1i(program.id(), LIT_LOC_MATERIAL, material);
    glProgramUniform4fv(program.id(), LIT_LOC_UV_TRANSFORMS, 2 * LIT_MATERIAL_SLOTS,
                        glm::value_ptr(materialUvTransforms_[static_cast<std::size_t>(material)][0]));
    bindMaterialTextures(material, bind);
    glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(item.indexCount), GL_UNSIGNED_INT,
                             reinterpret_cast<const void*>(static_cast<std::uintptr_t>(item.firstIndex) * 4u),
                             item.baseVertex);
    ++counters.drawCalls;
    counters.triangles += item.indexCount / 3;
}

}  // namespace lit
