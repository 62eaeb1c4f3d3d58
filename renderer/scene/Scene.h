#pragma once
// Scene data on the CPU: what a glTF file describes, in the units and conventions of
// docs/CONVENTIONS.md (metres, +Y up, right-handed, cameras look down −Z, linear colours).
// The Renderer uploads it; the editor edits it and bumps the revision counters so the renderer
// knows what to redo (geometry → re-voxelize, lights → re-inject).

#include "scene/Aabb.h"
#include "scene/TextureTransform.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lit {

// What a glTF object held that Lit does not use: its "extras" and the extensions Lit does not
// read, as JSON text ("" = none). Kept so that saving a file loses nothing (scene/GltfWriter.cpp);
// objects Lit creates have none.
struct KeptGltf {
    std::string extras;      // the object's "extras" value
    std::string extensions;  // a JSON object: extension name → value (Lit's own extensions left out)
    bool operator==(const KeptGltf&) const = default;
};

// The file's numbers of fields Lit holds as float, by field name ("yfov", "t0".."t2",
// "r0".."r3", "s0".."s2", ...), only those a float cannot hold exactly (JSON numbers are doubles:
// Blender writes a camera's yfov as 0.39959652046304894). A save writes the file's number for a
// field whose float still equals it rounded, so an unedited value comes back exactly.
using FileNumbers = std::map<std::string, double>;

// A glTF buffer or buffer view's name, extras and extensions Lit does not use. Lit lays out its own
// buffer views (and writes one buffer); these go on the view (buffer) that holds the same data
// again, so a save loses none of them.
struct KeptObject {
    std::string name;
    KeptGltf kept{};
    bool empty() const { return name.empty() && kept.extras.empty() && kept.extensions.empty(); }
    bool operator==(const KeptObject&) const = default;
};

// What an accessor held besides its elements: its name, extras and extensions, and its buffer
// view's (a sparse accessor without a base: none).
struct KeptAccessorInfo {
    std::string name;
    KeptGltf kept{};
    KeptObject view{};
    // The file's min and max (empty when it had none): a save writes them again, recomputed from
    // the written elements, with the file's exact numbers where they still hold (a JSON double
    // such as Blender's 3.0416666666666665 for a float key time of 3.0416667).
    std::vector<double> min{};
    std::vector<double> max{};
    // The accessor's index in the file (-1: none): accessors the file shared between primitives
    // (Blender shares identical ones) are written once again while their elements agree.
    int file = -1;
    // Its buffer view's byteStride in the file (0: none): written again where the elements are
    // still that far apart.
    std::size_t viewStride = 0;
    // Its buffer view's index in the file (-1: none) and its byteOffset in that view: the drawn
    // attributes a file kept in one view (two attributes one after the other, or interleaved) are
    // written in one view again (Primitive::fileViews).
    int fileView = -1;
    std::size_t byteOffset = 0;
    // Whether it carries a name, extras or extensions (its own or its view's).
    bool hasNameOrExtras() const { return !name.empty() || !(kept == KeptGltf{}) || !view.empty(); }
    bool operator==(const KeptAccessorInfo&) const = default;
};

// An accessor's elements as the file had them, for data Lit carries without using it (extra
// vertex attributes, morph targets, skin matrices), so that a save writes them back unchanged:
// tightly packed little-endian components, sparse accessors already expanded.
struct KeptAccessor {
    std::string type = "SCALAR";  // glTF accessor type: SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4
    int componentType = 5126;     // glTF (GL) enum: 5120 BYTE, 5121 UNSIGNED_BYTE, ... 5126 FLOAT
    bool normalized = false;
    std::size_t count = 0;            // elements
    std::vector<std::uint8_t> bytes;  // count × element size
    // A sparse accessor's layout, so a save writes it sparse again (glTF §3.6.2.3): `bytes` hold
    // the expanded elements; these say which of them the file stored as sparse values, and what
    // its base buffer view had there.
    struct Sparse {
        int indexComponentType = 5125;       // 5121, 5123 or 5125, as the file had it
        std::vector<std::uint32_t> indices;  // element indices, in the file's order
        bool hasBase = false;                // false: no buffer view, the base is zeros
        std::vector<std::uint8_t> baseBytes; // hasBase: the base's elements at `indices` (indices.size() × element size)
        KeptObject indicesView{};            // the buffer views of the sparse indices and values
        KeptObject valuesView{};
        // The extras and extensions of the `sparse`, `sparse.indices` and `sparse.values` objects
        // (read from the file's JSON: tinygltf 2.7 does not read them).
        KeptGltf sparseKept{};
        KeptGltf indicesKept{};
        KeptGltf valuesKept{};
        bool operator==(const Sparse&) const = default;
    };
    std::optional<Sparse> sparse{};
    KeptAccessorInfo info{};
    bool operator==(const KeptAccessor&) const = default;
};

// Vertex attributes by glTF name ("TEXCOORD_1", "COLOR_0", "JOINTS_0", "_TEMPERATURE", ...).
using KeptAttributes = std::map<std::string, KeptAccessor>;

struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz tangent, w bitangent sign (glTF convention)
    // TEXCOORD_1, for the texture references that read it (drawnTexCoord); TEXCOORD_0 where the
    // primitive has none, so a reference to a set the mesh lacks still samples something defined.
    glm::vec2 uv1{0.0f};
};
static_assert(sizeof(Vertex) == 56, "Vertex is uploaded as-is; keep it tightly packed");

struct Primitive {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // always triangles; non-indexed input gets 0,1,2,...
    int material = -1;                   // index into Scene::materials, -1 = default material
    Aabb bounds;                         // object space
    // Whether the file gave TANGENT (else the loader generated them): only then does a save
    // write them, so a file without tangents does not grow by a third.
    bool fileHasTangents = false;
    // The file's attributes other than POSITION, NORMAL, TEXCOORD_0 and TANGENT and its morph
    // targets (TEXCOORD_1 is drawn from Vertex::uv1 and kept here too, as the file stored it), one
    // element per vertex in `vertices` order (the loader reorders them with the vertices when it
    // unwelds a primitive without normals). Written back only while their count matches
    // `vertices` (an edit that rebuilt the geometry drops them).
    KeptAttributes keptAttributes{};
    std::vector<KeptAttributes> morphTargets{};
    KeptGltf kept{};
    // How the file stored the drawn data, so that a save can store it the same way: POSITION,
    // NORMAL, TEXCOORD_0 and TANGENT in the file's buffer views (fileAccessors' fileView,
    // byteOffset and viewStride: one view per attribute as Blender writes them, two attributes one
    // after the other in one view, or interleaved) rather than Lit's interleaved view, and the
    // indices' component type (5121, 5123 or 5125; 0 = the file had no indices: written without
    // while they are still 0, 1, 2, ...). A type too small for an edited primitive's indices is
    // widened.
    bool fileViews = false;
    int fileIndexType = 5125;
    // The names, extras, extensions, min/max and file indices of the file's POSITION, NORMAL,
    // TEXCOORD_0, TANGENT and "indices" accessors (and their buffer views), by that name. A save
    // gives them to the accessors it writes for that attribute, edited or not (an edit changes
    // the values, not what the data is); min/max are always recomputed from the written values.
    std::map<std::string, KeptAccessorInfo> fileAccessors{};
    // The file's TANGENTs as it wrote them, only when some were not unit length (the loader
    // normalizes those in `vertices`): a save writes these while every vertex's tangent is still
    // the normalized file tangent, so an unedited primitive keeps the file's numbers.
    std::vector<glm::vec4> fileTangents{};
};

// A primitive Lit does not draw (mode POINTS, LINES, LINE_LOOP, LINE_STRIP, TRIANGLE_STRIP or
// TRIANGLE_FAN), kept as the file had it so that a save writes it back.
struct KeptPrimitive {
    int mode = 0;       // glTF primitive mode
    int material = -1;  // index into Scene::materials
    KeptAttributes attributes;
    std::optional<KeptAccessor> indices;  // none = not indexed
    std::vector<KeptAttributes> morphTargets;
    KeptGltf kept{};
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
    std::vector<KeptPrimitive> otherPrimitives{};  // written after `primitives`
    std::vector<double> weights{};                 // default morph target weights
    KeptGltf kept{};
};

// Decoded pixels, RGBA8. Whether they hold sRGB colour or linear data depends on the material
// slot that uses them (base colour and emissive are sRGB): see Image::srgb.
struct Image {
    std::string name;
    std::string uri;  // as written in the file ("" for embedded images)
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
    bool srgb = false;  // set by the loader from how materials use it
    // An embedded image's bytes as the file had them (a buffer view or a data URI) and its MIME
    // type, so a save writes them back unchanged (16-bit PNG, KTX2, JPEG are not re-encoded);
    // empty for images from files and for generated ones. Whoever changes `rgba` clears it.
    // An image referenced by URI has the file's optional mimeType here ("" when it had none),
    // written back while the image is still referenced by URI.
    std::vector<std::uint8_t> encoded{};
    std::string mimeType{};
    KeptObject view{};  // the buffer view an embedded image was in (name, extras, extensions)
    KeptGltf kept{};
    // Made by the loader (the white stand-in for textures without a readable source), not in the
    // file: a save does not write it, and textures using it are written without a source.
    bool generated = false;
    // The earlier image whose bytes this one's equal (the loader decodes them once; textures
    // use that one), -1 for none.
    int sameAs = -1;
};

struct Texture {
    int image = -1;
    int wrapS = 10497;  // glTF sampler values are GL enums: 10497 REPEAT, 33071 CLAMP_TO_EDGE, 33648 MIRRORED_REPEAT
    int wrapT = 10497;
    int minFilter = 9987;  // LINEAR_MIPMAP_LINEAR
    int magFilter = 9729;  // LINEAR
    KeptGltf kept{};
    std::string name{};
    // The file's sampler of this texture: its name, extras and extensions (wrap and filters are
    // above); textures whose samplers agree in all of it share one sampler in a save.
    std::string samplerName{};
    KeptGltf samplerKept{};
    // Whether the file's texture had a sampler (glTF: none = repeat, filters up to the renderer),
    // and which of wrapS, wrapT, minFilter, magFilter that sampler wrote. A save writes no sampler
    // and no field the file left out while the values are still the defaults Lit gave them
    // (10497 REPEAT, 9987 LINEAR_MIPMAP_LINEAR, 9729 LINEAR). Textures Lit makes have all.
    bool hasSampler = true;
    std::array<bool, 4> samplerFields{true, true, true, true};
    // The file's image of this texture (-1: none, or made by Lit): where the loader pointed
    // `image` at an identical earlier image (Image::sameAs), a save writes the file's own while
    // `image` is still that one, so the file keeps its texture sources.
    int fileImage = -1;
    // Whether `image` is the texture's EXT_texture_webp source (a save writes it there again);
    // `fallbackImage` is then the file's plain `source` (-1: none), which Lit does not draw.
    bool webp = false;
    int fallbackImage = -1;
};

enum class AlphaMode { Opaque, Mask, Blend };

// glTF 2.0 metallic-roughness material. Texture fields are indices into Scene::textures, -1 = none.
// A texture reference inside a material extension (KHR_materials_transmission's
// transmissionTexture): drawn from here, saved as the extension's JSON the file had.
struct ExtensionTexture {
    int texture = -1;  // index into Scene::textures, -1 = none
    int texCoord = 0;  // the TEXCOORD_n set it names
    float scale = 1.0f;  // a normal texture's scale of its x and y (normalTextureInfo), else 1
    TextureTransform transform{};
    bool operator==(const ExtensionTexture&) const = default;
};

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};  // linear RGBA
    int baseColorTexture = -1;
    float metallic = 1.0f;
    float roughness = 1.0f;
    int metallicRoughnessTexture = -1;  // G roughness, B metalness
    int normalTexture = -1;
    float normalScale = 1.0f;
    glm::vec3 emissiveFactor{0.0f};  // linear RGB
    float emissiveStrength = 1.0f;   // KHR_materials_emissive_strength
    int emissiveTexture = -1;
    int occlusionTexture = -1;  // R channel
    float occlusionStrength = 1.0f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    // Dielectric reflectance, sheen and the clear coat (docs/MATERIALS.md). Lit draws these
    // extensions' factors and textures (below); their objects stay in `kept` (the texture
    // references included) and a save writes the factors into them, keeping the file's number
    // where unchanged.
    float ior = 1.5f;                       // KHR_materials_ior: dielectric F0 = ((ior − 1)/(ior + 1))²
    float specularFactor = 1.0f;            // KHR_materials_specular: F90 and a scale of the dielectric F0
    glm::vec3 specularColorFactor{1.0f};    // KHR_materials_specular: tint of the dielectric F0 (may exceed 1)
    glm::vec3 sheenColorFactor{0.0f};       // KHR_materials_sheen: linear RGB, 0..1 (0: no sheen)
    float sheenRoughness = 0.0f;            // KHR_materials_sheen: perceptual, 0..1
    float clearcoatFactor = 0.0f;           // KHR_materials_clearcoat: the coat's weight, 0..1
    float clearcoatRoughness = 0.0f;        // KHR_materials_clearcoat: perceptual, 0..1
    // KHR_materials_transmission: the share of the dielectric's light that passes through instead of
    // scattering diffusely, 0..1. Lit draws every transmissive surface as a thin sheet: light passes
    // straight through, dimmed by transmittanceOfSheet (docs/MATERIALS.md, "Transmission").
    float transmission = 0.0f;
    // KHR_materials_transmission.transmissionTexture: its red channel multiplies `transmission`.
    ExtensionTexture transmissionTexture{};
    // The layers' textures, each multiplying its factor: KHR_materials_specular's specularTexture
    // (alpha) and specularColorTexture (rgb, sRGB), KHR_materials_sheen's sheenColorTexture (rgb,
    // sRGB) and sheenRoughnessTexture (alpha), KHR_materials_clearcoat's clearcoatTexture (red)
    // and clearcoatRoughnessTexture (green), and the coat's own normal map, clearcoatNormalTexture
    // (its `scale` the map's strength; without one the coat follows the interpolated normal).
    ExtensionTexture specularTexture{};
    ExtensionTexture specularColorTexture{};
    ExtensionTexture sheenColorTexture{};
    ExtensionTexture sheenRoughnessTexture{};
    ExtensionTexture clearcoatTexture{};
    ExtensionTexture clearcoatRoughnessTexture{};
    ExtensionTexture clearcoatNormalTexture{};
    // KHR_materials_volume: a transmissive mesh with a thickness is a solid that bends the view by
    // its `ior` and holds a medium that absorbs what crosses it, attenuationColor left after
    // attenuationDistance (Beer–Lambert) (docs/MATERIALS.md, "Volume").
    float thickness = 0.0f;                        // metres in the mesh's space; 0: thin-walled (no volume)
    float attenuationDistance = 0.0f;              // metres, world; 0: infinite (the file leaves it out)
    glm::vec3 attenuationColor{1.0f};              // linear RGB, 0..1
    ExtensionTexture thicknessTexture{};           // its green channel multiplies `thickness`
    KeptGltf kept{};
    // Extensions of each texture reference other than KHR_texture_transform, JSON object text, in
    // the order base colour, metallic-roughness, normal, emissive, occlusion.
    std::array<std::string, 5> textureExtensions{};
    // KHR_texture_transform of each texture reference, same order (identity when absent).
    std::array<TextureTransform, 5> textureTransforms{};
    // The TEXCOORD_n set each texture reference reads, same order, saved back as the file had it.
    // Lit draws TEXCOORD_0 and TEXCOORD_1 (drawnTexCoord); a higher set is drawn with TEXCOORD_0
    // and the loader warns.
    std::array<int, 5> textureTexCoord{};
    // Extras of each texture reference (JSON text, "" when absent), same order, and the extras and
    // extensions of pbrMetallicRoughness.
    std::array<std::string, 5> textureExtras{};
    KeptGltf pbrKept{};
    // The file's exact numbers of factors a float cannot hold (FileNumbers: "baseColorFactor0".."3",
    // "metallicFactor", "roughnessFactor", "normalScale", "emissiveFactor0".."2",
    // "occlusionStrength", "alphaCutoff", "emissiveStrength"), and the optional fields the file
    // wrote, as JSON pointers inside the material ("alphaCutoff", "pbrMetallicRoughness/
    // roughnessFactor", "normalTexture/texCoord", ...: scene/GltfKeep.h kMaterialFields). A save
    // writes those fields even where they hold glTF's default (which it leaves out otherwise),
    // so a file keeps what it had and gets nothing it did not have.
    FileNumbers fileNumbers{};
    std::vector<std::string> fileFields{};

    bool operator==(const Material&) const = default;
};

// The UV set texture reference `slot` of `m` is drawn with: 1 for TEXCOORD_1, else 0. The
// reference's KHR_texture_transform texCoord, when it has one, overrides its own texCoord.
inline int drawnTexCoord(const Material& m, std::size_t slot) {
    const int transformSet = m.textureTransforms[slot].texCoord;
    return (transformSet >= 0 ? transformSet : m.textureTexCoord[slot]) == 1 ? 1 : 0;
}

// The same for a reference inside a material extension.
inline int drawnTexCoord(const ExtensionTexture& t) {
    return (t.transform.texCoord >= 0 ? t.transform.texCoord : t.texCoord) == 1 ? 1 : 0;
}

// A material's texture references inside extensions, in the order of their material slots after
// the five core ones (shaders/include/shared.h, LIT_MATERIAL_SLOT_TRANSMISSION onwards).
struct ExtensionTextureSlot {
    const char* extension;  // "KHR_materials_sheen", ...
    const char* key;        // the reference's key in the extension's object
    ExtensionTexture Material::*member;
    bool colour;  // sRGB-encoded colour (else linear data)
};
inline constexpr std::array<ExtensionTextureSlot, 9> kExtensionTextureSlots{{
    {"KHR_materials_transmission", "transmissionTexture", &Material::transmissionTexture, false},
    {"KHR_materials_clearcoat", "clearcoatTexture", &Material::clearcoatTexture, false},
    {"KHR_materials_clearcoat", "clearcoatRoughnessTexture", &Material::clearcoatRoughnessTexture, false},
    {"KHR_materials_specular", "specularTexture", &Material::specularTexture, false},
    {"KHR_materials_specular", "specularColorTexture", &Material::specularColorTexture, true},
    {"KHR_materials_sheen", "sheenColorTexture", &Material::sheenColorTexture, true},
    {"KHR_materials_sheen", "sheenRoughnessTexture", &Material::sheenRoughnessTexture, false},
    {"KHR_materials_clearcoat", "clearcoatNormalTexture", &Material::clearcoatNormalTexture, false},
    {"KHR_materials_volume", "thicknessTexture", &Material::thicknessTexture, false},
}};

enum class LightType { Directional, Point, Spot };

// KHR_lights_punctual. Position and direction come from the node that holds the light: it shines
// down the node's local −Z. Units: see docs/UNITS.md.
struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 color{1.0f};  // linear RGB
    // Radiometric: W/sr (point, spot) or W/m² (directional). The file holds candela or lux; the
    // loader divides by 683 lm/W (scene/LightUnits.h, docs/UNITS.md).
    float intensity = 1.0f;
    float range = 0.0f;      // metres; 0 = infinite
    float innerConeAngle = 0.0f;                  // radians, spot only
    float outerConeAngle = 0.7853981633974483f;   // radians (π/4), spot only
    bool castsShadow = true;
    // The photometric number of the file (cd or lx) and the `intensity` it became, so that saving
    // an unedited light writes the file's number exactly (float(x / 683) · 683 need not be x).
    // The writer uses `fileIntensity` only while `intensity == fileIntensityAsLoaded`.
    double fileIntensity = 0.0;
    float fileIntensityAsLoaded = -1.0f;  // -1: not from a file
    FileNumbers fileNumbers{};  // color0..2, range, innerConeAngle, outerConeAngle
    KeptGltf kept{};

    bool operator==(const Light&) const = default;
};

// Perspective camera (glTF). The node that holds it gives its pose; it looks down local −Z.
struct Camera {
    std::string name;
    float yfov = 0.8f;         // radians
    float aspectRatio = 0.0f;  // 0 = use the output's aspect
    float znear = 0.05f;       // metres
    float zfar = 0.0f;         // metres; 0 = fitted to the scene bounds
    // An orthographic camera of the file: Lit renders it as a perspective camera (yfov 0.8) and
    // saves it back as orthographic with these half extents (metres).
    bool orthographic = false;
    float xmag = 0.0f;
    float ymag = 0.0f;
    FileNumbers fileNumbers{};  // yfov, aspectRatio, znear, zfar, xmag, ymag
    KeptGltf kept{};

    bool operator==(const Camera&) const = default;
};

struct Node {
    std::string name;
    int parent = -1;
    std::vector<int> children;
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    int mesh = -1;
    int light = -1;
    int camera = -1;
    int skin = -1;                // index into Scene::skins (kept, not drawn: Lit draws the bind pose)
    std::vector<double> weights{};  // morph target weights of this node's mesh instance
    glm::mat4 world{1.0f};  // computed by Scene::updateWorldTransforms()
    FileNumbers fileNumbers{};  // t0..t2, r0..r3 (x, y, z, w), s0..s2
    KeptGltf kept{};
    // A node the file gave a `matrix`: its 16 numbers (column-major) and the translation,
    // rotation and scale they became. A save writes the matrix again while the node's transform
    // still equals those (unedited); an edited node is written as translation, rotation, scale.
    std::vector<double> fileMatrix{};
    glm::vec3 matrixTranslation{0.0f};
    glm::quat matrixRotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 matrixScale{1.0f};
    // The node's index in the file (-1: made by Lit). A save writes the file's nodes in this
    // order, nodes Lit made after them, so a file keeps its node indices while none is deleted.
    int fileIndex = -1;

    // The pose the scene's node animations give this node at the time shown
    // (animation/NodeAnimation.h): each channel an animation drives replaces the rest transform's
    // in localMatrix(). Translation, rotation and scale above stay the rest transform: edits
    // change it and a save writes it, whatever the time shown.
    struct AnimatedPose {
        std::optional<glm::vec3> translation;
        std::optional<glm::quat> rotation;
        std::optional<glm::vec3> scale;
        bool empty() const { return !translation && !rotation && !scale; }
        bool operator==(const AnimatedPose&) const = default;
    };
    AnimatedPose pose{};

    // The transform drawn: the rest transform with the animated channels of `pose` in its place.
    glm::mat4 localMatrix() const;
};

// A glTF animation as the file had it, kept so a save writes it back. Lit plays camera
// animations as camera paths (animation/CameraPathIO.h) and the translation, rotation and scale
// channels of other nodes as node animations (animation/NodeAnimation.h); morph weights are kept,
// not played. Values are floats as they were read (normalized integers converted).
struct Animation {
    struct Sampler {
        std::vector<float> input;   // key times, seconds
        std::vector<float> output;  // components × keys (× 3 for CUBICSPLINE)
        int components = 3;         // 1 (weights), 3 (translation, scale), 4 (rotation)
        std::string interpolation = "LINEAR";
        KeptGltf kept{};                // the sampler's extras and extensions
        KeptAccessorInfo inputInfo{};   // its input and output accessors' names, extras, extensions
        KeptAccessorInfo outputInfo{};
        // The file's input and output accessor indices (-1: made by Lit): samplers that shared an
        // accessor share it again in a save while their values are still the same.
        int fileInput = -1;
        int fileOutput = -1;
        // The output's component type and normalization (5126 float; normalized 5120, 5121,
        // 5122 or 5123 for rotations and morph weights): written back in that type.
        int outputComponentType = 5126;
        bool outputNormalized = false;
    };
    struct Channel {
        int sampler = 0;
        int node = -1;          // a node reference (see keptNodeRef); a channel of a node not saved is dropped
        std::string path;       // "translation", "rotation", "scale" or "weights"
        KeptGltf kept{};        // the channel's extras and extensions
        bool operator==(const Channel&) const = default;
    };
    std::string name;
    std::vector<Sampler> samplers;
    std::vector<Channel> channels;
    KeptGltf kept{};  // extras hold Lit's own path keys (litCameraPath) when Lit wrote the animation
};

// A glTF skin, kept for saving (Lit does not animate skins).
struct Skin {
    std::string name;
    std::vector<int> joints;  // node references (see keptNodeRef); a save drops a skin whose joint is gone
    int skeleton = -1;        // a node reference, -1 = none
    std::vector<float> inverseBindMatrices;  // 16 per joint, column-major; empty = identities
    KeptAccessorInfo inverseBindMatricesInfo{};
    KeptGltf kept{};
};

// Nodes of the file that are in none of the shown scene's trees live in Scene::keptNodes (they
// are not drawn, listed or edited; a save writes them back). What names a node in a skin, an
// animation channel or another scene's roots is a node reference: an index into Scene::nodes
// (>= 0), or keptNodeRef(k) for Scene::keptNodes[k] (<= -2); -1 is none. Code that only knows
// Scene::nodes sees a kept node's reference as "no node".
constexpr int keptNodeRef(int keptIndex) { return -2 - keptIndex; }
constexpr int keptNodeIndex(int reference) { return -2 - reference; }  // for reference <= -2

struct Scene {
    std::string name;
    // False when the file's scene had no name (the loader then names it after the file): a save
    // writes no name while `name` is still the source file's stem.
    bool fileSceneNamed = true;
    std::filesystem::path sourcePath;
    std::vector<Node> nodes;
    std::vector<int> roots;
    // The file's nodes outside the shown scene's trees, in file order: their parent and children
    // index this list (a kept node's subtree is all kept); mesh, light, camera and skin index the
    // Scene's lists as a shown node's do. World transforms are not computed for them.
    std::vector<Node> keptNodes;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Image> images;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    std::vector<Skin> skins;
    // Every animation of the file, in file order. Camera animations (those a camera path can be
    // read from) are listed in cameraAnimationNames; animation/CameraPathIO.h's
    // loadCameraPath(scene, name) turns one into a CameraPath for the timeline and lit-render
    // --path. The writer saves them all, except one of the name the editor saves its own path
    // under (GltfSaveOptions::cameraPathName), which that path replaces.
    std::vector<Animation> animations;
    std::vector<std::string> cameraAnimationNames;  // filled by the loader (CameraPathIO's rule)
    KeptGltf kept{};           // the glTF scene object's extras and extensions
    KeptGltf fileKept{};     // the file's top-level extras and extensions (KHR_lights_punctual left out)
    std::string copyright;   // asset.copyright
    // asset.generator as the file had it ("" when absent). A save writes "Lit" (the tool that
    // wrote the file, as glTF means it) and this in the asset's extras as "litSourceGenerator".
    std::string generator;
    // The file's buffers' names, extras and extensions, in file order: a save writes one buffer,
    // which gets the first's name and all their extras keys and extensions (the first wins).
    std::vector<KeptObject> buffers;
    // Where the file kept each buffer view's bytes (in file order) and a hash of them: a save puts
    // a view whose bytes are the same again at the same place of its one buffer (the file's
    // buffers one after the other, each starting 4-byte aligned), so an unedited file's .bin comes
    // back byte for byte (scene/GltfWriter.cpp: keepFileLayout).
    struct FileBufferView {
        int buffer = 0;
        std::size_t byteOffset = 0;
        std::size_t byteLength = 0;
        std::uint64_t hash = 0;  // gltfkeep::hashBytes of the view's bytes
        bool operator==(const FileBufferView&) const = default;
    };
    std::vector<FileBufferView> fileBufferViews;
    std::vector<std::size_t> fileBufferSizes;  // the file's buffers' byte lengths, in file order
    KeptGltf assetKept{};    // asset's extras and extensions
    // The file's other glTF scenes (Lit shows one, `roots`): written back around it in the file's
    // order, the shown one at `sceneIndex`. Their roots are node references (nodes the shown
    // scene shares, or kept nodes).
    struct OtherScene {
        std::string name;
        std::vector<int> roots;
        KeptGltf kept{};
        bool operator==(const OtherScene&) const = default;
    };
    std::vector<OtherScene> otherScenes;
    int sceneIndex = 0;  // where the shown scene stands among the file's scenes
    std::vector<std::string> unknownExtensionsUsed;  // extensionsUsed Lit does not read; written back
    // The compression extensions the file's geometry was decoded from (EXT_meshopt_compression,
    // KHR_draco_mesh_compression). A save writes plain accessors: Lit has no encoders, and an
    // uncompressed file is one every glTF reader takes (scene/GltfWriter.h: uncompressedSaveNote).
    std::vector<std::string> decodedCompression;
    // The file's extensionsRequired (all ones Lit reads, or the load fails): a save declares each
    // again while the saved file still uses it.
    std::vector<std::string> extensionsRequired;

    // Bumped by whoever edits the scene; the renderer redoes only what changed.
    std::uint64_t geometryRevision = 0;  // meshes, node transforms → shadows, voxels
    std::uint64_t materialRevision = 0;  // material parameters → voxels (albedo, emission)
    std::uint64_t lightRevision = 0;     // lights → shadows, radiance injection

    // Recomputes Node::world for every node from the roots down.
    void updateWorldTransforms();
    // World-space bounds of all mesh primitives (needs up-to-date world transforms).
    Aabb worldBounds() const;
    // The first node holding camera `cameraIndex`, or -1.
    int nodeOfCamera(int cameraIndex) const;
    int nodeOfLight(int lightIndex) const;
    int findCamera(const std::string& name) const;  // by camera or node name; -1 if none
    std::size_t triangleCount() const;
};

}  // namespace lit
