#pragma once
// The GPU copy of a Scene: one vertex and one index buffer for all primitives, one GL texture per
// image that a texture uses (sRGB or linear by use, mipmapped), one GL sampler object per distinct
// wrap/filter combination, and the material table as an SSBO. A glTF texture is an (image,
// sampler) pair and costs no texture memory of its own: a file whose 100,000 textures share one
// image uploads one image. Passes draw through it; they never touch the CPU Scene's vectors
// directly.

#include <shared.h>

#include <array>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "gl/Objects.h"
#include "scene/Aabb.h"
#include "scene/TriangleChunks.h"

namespace lit {

struct Scene;
class Log;
namespace gl {
class Program;
}

// One primitive of one node instance, or one chunk of a large primitive (TriangleChunks.h): the
// chunks of a primitive share its node and material and split its index range.
struct DrawItem {
    int node = -1;
    int material = -1;         // -1: the default material (last entry of the material table)
    GLint baseVertex = 0;
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    Aabb localBounds;          // of this item's triangles (a chunk's own box), object space
    int primitive = 0;         // the primitive of the node's mesh the item draws (a chunk of it)
};

// Chooses the items one view draws: fills `visibleItems` with indices into GpuScene::items() of
// the items that may be visible under `viewProjection` (world → clip), ascending. Passes that
// render several views (shadow maps) call it once per view; an empty function means "draw all".
using ItemCuller = std::function<void(const glm::mat4& viewProjection, std::vector<std::uint32_t>& visibleItems)>;

struct DrawCounters {
    int drawCalls = 0;
    std::size_t triangles = 0;
};

// The texture unit of each material slot (LIT_MATERIAL_SLOT_* → LIT_TEX_*).
inline constexpr std::array<GLuint, LIT_MATERIAL_SLOTS> kMaterialTextureUnits = {
    LIT_TEX_BASE_COLOR,       LIT_TEX_METALLIC_ROUGHNESS, LIT_TEX_NORMAL,      LIT_TEX_EMISSIVE,
    LIT_TEX_OCCLUSION,        LIT_TEX_TRANSMISSION,       LIT_TEX_CLEARCOAT,   LIT_TEX_CLEARCOAT_ROUGHNESS,
    LIT_TEX_SPECULAR,         LIT_TEX_SPECULAR_COLOR,     LIT_TEX_SHEEN_COLOR, LIT_TEX_SHEEN_ROUGHNESS,
    LIT_TEX_CLEARCOAT_NORMAL, LIT_TEX_THICKNESS};

class GpuScene {
public:
    // A material's KHR_texture_transform rows, two per texture reference, the first's w its UV
    // set (material.glsl's uUvTransforms, set per draw).
    using UvTransforms = std::array<glm::vec4, 2 * LIT_MATERIAL_SLOTS>;

    GpuScene() = default;
    // Primitives of more than `maxChunkTriangles` triangles are split into chunks of at most that
    // many (their indices reordered on the GPU, the Scene unchanged), one draw item each, so
    // culling can drop the parts out of view; 0 keeps one item per primitive.
    GpuScene(const Scene& scene, Log& log, std::uint32_t maxChunkTriangles = kDefaultChunkTriangles);

    // Re-uploads the material table (after material edits).
    void updateMaterials(const Scene& scene);

    // Which material state a draw needs bound.
    enum class Bind { Everything, AlphaOnly };

    // Draws every item (optionally filtered) with `program` bound by the caller. Sets the
    // uniforms uModel, uNormalMatrix, uMaterialIndex and binds the material's textures and their
    // samplers; the samplers are unbound again at the end (unbindMaterialSamplers).
    template <typename Filter>
    void draw(const Scene& scene, const gl::Program& program, Bind bind, DrawCounters& counters, Filter&& keep) const;
    void draw(const Scene& scene, const gl::Program& program, Bind bind, DrawCounters& counters) const {
        draw(scene, program, bind, counters, [](const DrawItem&) { return true; });
    }

    // Draws the items whose indices into items() are listed, in the order listed (a culling
    // result: see Bvh::cull). Same bindings and uniforms as draw().
    void drawList(const Scene& scene, const gl::Program& program, Bind bind, DrawCounters& counters,
                  std::span<const std::uint32_t> itemIndices) const;

    const std::vector<DrawItem>& items() const { return items_; }
    // Whether the item's material is a transmissive sheet (scene/Sheets.h drawnAsSheet): SheetPass
    // draws it over the lit image; the G-buffer, the shadow maps and the voxels leave it out
    // (material_table.glsl).
    bool isSheet(const DrawItem& item) const;
    bool hasSheets() const { return hasSheets_; }
    // Whether some sheet is a volume's face that bends the light (scene/Sheets.h refractiveIndexOfVolume).
    bool hasRefractingSheets() const { return hasRefractingSheets_; }
    // The sheets among `candidates` (item indices; nullptr: every item), in their order, into `out`.
    void sheetItems(const std::vector<std::uint32_t>* candidates, std::vector<std::uint32_t>& out) const;
    bool empty() const { return items_.empty(); }
    const gl::Buffer& materials() const { return materials_; }
    // Whether a material has KHR_materials_ior / _specular / _sheen / _clearcoat values other than the
    // defaults, or a layer texture (the lighting passes' MaterialLayersVariant).
    bool hasMaterialLayers() const { return materialLayers_; }
    // Whether a material has a layer texture (KHR_materials_specular, _sheen, _clearcoat) or a coat
    // normal of its own: the G-buffer then stores their texels (GBufferPass's layers target).
    bool hasLayerTextures() const { return layerTextures_; }

    // The textures `item`'s material samples, as LIT_MATERIAL_TEXTURES bits (material.glsl): the
    // ones that loaded, which the material table's flags also say.
    unsigned materialTextureMask(const DrawItem& item) const;

    // Binds the vertex array (call once before a batch of draws).
    void bindGeometry() const { vertexArray_.bind(); }
    // Issues one draw with per-draw uniforms, textures and samplers. A caller that draws items
    // itself calls unbindMaterialSamplers() after its last one, so that a texture bound later to
    // the material units samples with its own parameters.
    void drawItem(const Scene& scene, const DrawItem& item, const gl::Program& program, Bind bind,
                  DrawCounters& counters) const;

    // Unbinds the sampler objects of the material texture units (kMaterialTextureUnits).
    static void unbindMaterialSamplers();

    // What the upload made: GL textures (one per image a texture uses), sampler objects (one per
    // distinct wrap/filter combination) and the bytes of the textures' mip chains.
    std::size_t imageTextureCount() const;
    std::size_t samplerCount() const { return samplers_.size(); }
    std::uint64_t textureBytes() const { return textureBytes_; }

private:
    void bindMaterialTextures(int material, Bind bind) const;
    // The material table's row `item` draws with (the default material, last, for none or a bad index).
    int materialRow(const DrawItem& item) const;

    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::VertexArray vertexArray_;
    gl::Buffer materials_;
    bool materialLayers_ = false;
    bool layerTextures_ = false;
    std::vector<gl::Texture> images_;      // per Scene::images entry; empty where no texture uses it or it is unusable
    std::vector<gl::Sampler> samplers_;    // one per distinct wrap/filter combination
    // Per Scene::textures entry: its GL texture (0: unusable, the material falls back) and sampler.
    struct TextureBinding {
        GLuint texture = 0;
        GLuint sampler = 0;
    };
    std::vector<TextureBinding> textures_;
    std::uint64_t textureBytes_ = 0;
    gl::Texture whiteTexture_;             // bound where a material has no texture
    std::vector<DrawItem> items_;
    std::vector<bool> sheetMaterials_;     // per material, + default at the end: drawnAsSheet
    bool hasSheets_ = false;               // some material is a sheet
    bool hasRefractingSheets_ = false;     // some sheet material is a refracting volume
    // Per material slot (LIT_MATERIAL_SLOT_*).
    using MaterialTextures = std::array<TextureBinding, LIT_MATERIAL_SLOTS>;
    std::vector<MaterialTextures> materialTextures_;  // per material, + default at the end
    std::vector<int> materialLayerBits_;              // GpuMaterial::layerTextures.x, same rows
    std::vector<UvTransforms> materialUvTransforms_;  // per material, + default at the end
};

template <typename Filter>
void GpuScene::draw(const Scene& scene, const gl::Program& program, Bind bind, DrawCounters& counters,
                    Filter&& keep) const {
    if (items_.empty()) return;
    bindGeometry();
    for (const DrawItem& item : items_)
        if (keep(item)) drawItem(scene, item, program, bind, counters);
    unbindMaterialSamplers();
}

}  // namespace lit
