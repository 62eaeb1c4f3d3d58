#include "reference/ReferenceScene.h"

#include "Log.h"
#include "RenderSettings.h"
#include "passes/LightSetup.h"
#include "reference/MicrofacetBrdf.h"
#include "scene/Sheets.h"

#include <embree3/rtcore.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lit::reference {

namespace {

constexpr int kWrapRepeat = 10497;
constexpr int kWrapMirroredRepeat = 33648;
constexpr int kFilterNearest = 9728;

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// Texel index along one axis under a glTF wrap mode (GL enums).
int wrapTexel(int i, int size, int mode) {
    if (mode == kWrapRepeat) return ((i % size) + size) % size;
    if (mode == kWrapMirroredRepeat) {
        const int period = 2 * size;
        int m = ((i % period) + period) % period;
        return m < size ? m : period - 1 - m;
    }
    return std::clamp(i, 0, size - 1);  // CLAMP_TO_EDGE and anything unknown
}

// Material's texture references (scene/Scene.h order; shared.h's LIT_MATERIAL_SLOT_*).
constexpr std::size_t kSlotBaseColor = 0, kSlotMetallicRoughness = 1, kSlotNormal = 2, kSlotEmissive = 3,
                      kSlotOcclusion = 4;

// The UVs reference `slot` samples at mesh UVs `uvs` (xy TEXCOORD_0, zw TEXCOORD_1): its set and
// KHR_texture_transform, as material.glsl's materialUv applies them.
// The UVs a texture reference reading UV set `set` (0 or 1) through `transform` samples at mesh
// UVs `uvs` (xy TEXCOORD_0, zw TEXCOORD_1).
glm::vec2 transformedUv(int set, const TextureTransform& transform, const glm::vec4& uvs) {
    const glm::vec2 uv = set == 1 ? glm::vec2(uvs.z, uvs.w) : glm::vec2(uvs.x, uvs.y);
    return transform.present ? applyUvTransform(uvTransformRows(transform), uv) : uv;
}

glm::vec2 slotUv(const Material& m, std::size_t slot, const glm::vec4& uvs) {
    return transformedUv(drawnTexCoord(m, slot), m.textureTransforms[slot], uvs);
}

// The same for a reference inside a material extension.
glm::vec2 extensionUv(const ExtensionTexture& t, const glm::vec4& uvs) {
    return transformedUv(drawnTexCoord(t), t.transform, uvs);
}

// What Embree hands the alpha-mask filter of one geometry.
struct AlphaFilterData {
    const ReferenceScene* scene = nullptr;
    unsigned geometry = 0;  // Embree geometry ID = index into Impl::geometries
};

}  // namespace

// One mesh primitive of one node, flattened to world space (Embree geometry ID = index).
struct ReferenceScene::Geometry {
    int node = -1;
    int material = -1;  // -1 or out of range: the default material
    bool alphaMasked = false;
    std::vector<glm::vec3> positions;  // world
    std::vector<glm::vec3> normals;    // world (normal matrix applied, not normalised)
    std::vector<glm::vec4> uvs;        // xy TEXCOORD_0, zw TEXCOORD_1 (Vertex::uv, uv1)
    std::vector<glm::vec4> tangents;   // world xyz, w bitangent sign
    std::vector<std::uint32_t> indices;  // 3 per triangle, validated
    int emitterBase = -1;              // emitter index of triangle 0 when the material emits
};

struct ReferenceScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<Geometry> geometries;
    std::vector<AlphaFilterData> alphaFilters;  // one per geometry; sized once, Embree keeps pointers
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Image> images;
    std::array<float, 256> srgbToLinear{};
    Material fallback;  // the default material: white, metallic 0, roughness 1 (as GpuScene)

    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

namespace {

// Embree filter callback for alpha-masked geometry: rejects hits on cut-out texels, for closest
// hits and shadow rays alike (the G-buffer and shadow passes discard the same texels).
void alphaMaskFilter(const RTCFilterFunctionNArguments* args) {
    const auto* user = static_cast<const AlphaFilterData*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const unsigned primitive = RTCHitN_primID(args->hit, args->N, i);
        const float u = RTCHitN_u(args->hit, args->N, i);
        const float v = RTCHitN_v(args->hit, args->N, i);
        if (user->scene->alphaCutOut(user->geometry, primitive, u, v)) args->valid[i] = 0;
    }
}

}  // namespace

ReferenceScene::ReferenceScene(const Scene& scene, Log& log) : impl_(std::make_unique<Impl>()) {
    Impl& s = *impl_;
    for (int i = 0; i < 256; ++i) s.srgbToLinear[static_cast<std::size_t>(i)] = srgbToLinear(static_cast<float>(i) / 255.0f);
    s.materials = scene.materials;
    s.textures = scene.textures;
    s.images = scene.images;
    s.fallback.metallic = 0.0f;

    // The same light table the GL passes upload (positions, directions, spot factors, the
    // LIT_MAX_LIGHTS cap); shadow maps are not needed here.
    RenderSettings lightSettings;
    lightSettings.shadows.enabled = false;
    // Only the scene's own lights: a front end that wants the rasterizer's default sun for a scene
    // without lights adds it to the Scene it gives (lit-render --reference does, scene/Sky.h).
    lightSettings.sky.sunIrradiance = 0.0f;
    lights_ = buildLightSetup(scene, scene.worldBounds(), lightSettings, log).lights;

    s.device = rtcNewDevice(nullptr);
    if (!s.device) throw std::runtime_error("cannot start Embree (rtcNewDevice failed, error " +
                                            std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
    s.scene = rtcNewScene(s.device);
    rtcSetSceneBuildQuality(s.scene, RTC_BUILD_QUALITY_HIGH);

    // Geometries first (their vectors must not move once Embree holds pointers to user data).
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        const Node& node = scene.nodes[n];
        if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= scene.meshes.size()) continue;
        const glm::mat3 model(node.world);
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(model));
        for (const Primitive& primitive : scene.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
            Geometry g;
            g.node = static_cast<int>(n);
            g.material = primitive.material;
            const std::size_t count = primitive.vertices.size();
            for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
                const std::uint32_t a = primitive.indices[t], b = primitive.indices[t + 1], c = primitive.indices[t + 2];
                if (a >= count || b >= count || c >= count) continue;
                g.indices.insert(g.indices.end(), {a, b, c});
            }
            if (g.indices.empty()) continue;
            g.positions.reserve(count);
            for (const Vertex& v : primitive.vertices) {
                g.positions.push_back(glm::vec3(node.world * glm::vec4(v.position, 1.0f)));
                g.normals.push_back(normalMatrix * v.normal);
                g.uvs.push_back(glm::vec4(v.uv, v.uv1));
                g.tangents.push_back(glm::vec4(model * glm::vec3(v.tangent), v.tangent.w));
            }
            s.geometries.push_back(std::move(g));
        }
    }

    s.alphaFilters.resize(s.geometries.size());
    for (std::size_t i = 0; i < s.geometries.size(); ++i) {
        Geometry& g = s.geometries[i];
        const Material& m = (g.material >= 0 && static_cast<std::size_t>(g.material) < s.materials.size())
                                ? s.materials[static_cast<std::size_t>(g.material)]
                                : s.fallback;
        g.alphaMasked = m.alphaMode == AlphaMode::Mask;
        hasSheets_ = hasSheets_ || drawnAsSheet(m);

        RTCGeometry geometry = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                     3 * sizeof(float), g.positions.size()));
        for (std::size_t v = 0; v < g.positions.size(); ++v) {
            vertices[3 * v + 0] = g.positions[v].x;
            vertices[3 * v + 1] = g.positions[v].y;
            vertices[3 * v + 2] = g.positions[v].z;
        }
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                       3 * sizeof(unsigned), g.indices.size() / 3));
        std::copy(g.indices.begin(), g.indices.end(), indices);
        if (g.alphaMasked) {
            s.alphaFilters[i] = {this, static_cast<unsigned>(i)};
            rtcSetGeometryUserData(geometry, &s.alphaFilters[i]);
            rtcSetGeometryIntersectFilterFunction(geometry, alphaMaskFilter);
            rtcSetGeometryOccludedFilterFunction(geometry, alphaMaskFilter);
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometryByID(s.scene, geometry, static_cast<unsigned>(i));
        rtcReleaseGeometry(geometry);
        triangleCount_ += g.indices.size() / 3;

        // Emissive triangles become area lights, weighted by area × emissive luminance.
        const glm::vec3 emissive = m.emissiveFactor * m.emissiveStrength;
        if (luminance(emissive) > 0.0f) {
            g.emitterBase = static_cast<int>(emitters_.size());
            for (std::size_t t = 0; t < g.indices.size(); t += 3) {
                Emitter e;
                const std::uint32_t a = g.indices[t], b = g.indices[t + 1], c = g.indices[t + 2];
                e.p0 = g.positions[a];
                e.e1 = g.positions[b] - e.p0;
                e.e2 = g.positions[c] - e.p0;
                e.uvs = {g.uvs[a], g.uvs[b], g.uvs[c]};
                e.material = g.material;
                e.area = 0.5f * glm::length(glm::cross(e.e1, e.e2));
                e.power = e.area * luminance(emissive);
                emitters_.push_back(e);
            }
        }
    }
    rtcCommitScene(s.scene);
    if (const RTCError error = rtcGetDeviceError(s.device); error != RTC_ERROR_NONE)
        throw std::runtime_error("Embree could not build the scene (error " + std::to_string(static_cast<int>(error)) + ")");

    double total = 0.0;
    emitterCdf_.reserve(emitters_.size());
    for (const Emitter& e : emitters_) {
        total += e.power;
        emitterCdf_.push_back(static_cast<float>(total));
    }
    emitterPower_ = static_cast<float>(total);
    for (float& c : emitterCdf_) c = total > 0.0 ? static_cast<float>(c / total) : 0.0f;
}

ReferenceScene::~ReferenceScene() = default;

bool ReferenceScene::alphaCutOut(unsigned geometry, unsigned primitive, float u, float v) const {
    const Geometry& g = impl_->geometries[geometry];
    const std::size_t t = 3 * static_cast<std::size_t>(primitive);
    const glm::vec4 uv =
        (1.0f - u - v) * g.uvs[g.indices[t]] + u * g.uvs[g.indices[t + 1]] + v * g.uvs[g.indices[t + 2]];
    const Material& m = impl_->materials[static_cast<std::size_t>(g.material)];
    float alpha = m.baseColorFactor.a;
    if (m.baseColorTexture >= 0) alpha *= sampleTexture(m.baseColorTexture, slotUv(m, kSlotBaseColor, uv)).a;
    return alpha < m.alphaCutoff;
}

glm::vec4 ReferenceScene::sampleTexture(int texture, glm::vec2 uv) const {
    const Impl& s = *impl_;
    if (texture < 0 || static_cast<std::size_t>(texture) >= s.textures.size()) return glm::vec4(1.0f);
    const Texture& tex = s.textures[static_cast<std::size_t>(texture)];
    if (tex.image < 0 || static_cast<std::size_t>(tex.image) >= s.images.size()) return glm::vec4(1.0f);
    const Image& image = s.images[static_cast<std::size_t>(tex.image)];
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() < static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4)
        return glm::vec4(1.0f);
    // GL_NEAREST magnification (glTF magFilter 9728): the texel under the point, as GpuScene sets
    // it up (its minification is then GL_NEAREST or mipmapped; mip levels are not modelled here).
    if (tex.magFilter == kFilterNearest) {
        const float nx = uv.x * static_cast<float>(image.width), ny = uv.y * static_cast<float>(image.height);
        if (!std::isfinite(nx) || !std::isfinite(ny)) return glm::vec4(1.0f);
        const auto wrapped = [](float f, int size, int mode) {
            const double period = 2.0 * size;
            const int i = static_cast<int>(std::floor(f - std::floor(f / period) * period));
            return wrapTexel(i, size, mode);
        };
        const std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(wrapped(ny, image.height, tex.wrapT)) *
                                                 static_cast<std::size_t>(image.width) +
                                             static_cast<std::size_t>(wrapped(nx, image.width, tex.wrapS))) * 4];
        if (image.srgb) return glm::vec4(s.srgbToLinear[p[0]], s.srgbToLinear[p[1]], s.srgbToLinear[p[2]], p[3] / 255.0f);
        return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
    }
    // Bilinear between texel centres: texel i covers [i, i+1)/size.
    const float x = uv.x * static_cast<float>(image.width) - 0.5f;
    const float y = uv.y * static_cast<float>(image.height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return glm::vec4(1.0f);
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    // Keep the integer part in range before converting (huge UVs on a repeating texture).
    const auto reduce = [](float f, int size) {
        const double period = 2.0 * size;
        return static_cast<int>(f - static_cast<float>(std::floor(f / period) * period));
    };
    const int x0 = reduce(fx, image.width), y0 = reduce(fy, image.height);
    const auto texel = [&](int tx, int ty) {
        const int cx = wrapTexel(tx, image.width, tex.wrapS);
        const int cy = wrapTexel(ty, image.height, tex.wrapT);
        const std::uint8_t* p =
            &image.rgba[(static_cast<std::size_t>(cy) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(cx)) * 4];
        if (image.srgb) return glm::vec4(s.srgbToLinear[p[0]], s.srgbToLinear[p[1]], s.srgbToLinear[p[2]], p[3] / 255.0f);
        return glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
    };
    return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), ax), glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), ax),
                    ay);
}

namespace {

// Normal `n` (unit) bent by a normal map's texel `texel` of strength `scale`, in the frame of the
// vertex tangent `tangent` turned by the map's KHR_texture_transform `rows`: shaders/gbuffer.frag.glsl.
glm::vec3 mappedNormal(const glm::vec3& n, const glm::vec4& tangent, const std::array<glm::vec3, 2>& rows,
                       const glm::vec4& texel, float scale) {
    glm::vec3 t = glm::vec3(tangent) - n * glm::dot(n, glm::vec3(tangent));
    if (glm::dot(t, t) <= 1e-10f) return n;
    t = glm::normalize(t);
    const float handedness = tangent.w < 0.0f ? -1.0f : 1.0f;
    // The map's frame follows its KHR_texture_transform (identity: t itself).
    const glm::vec3 frame = uvTangentOfTransform(rows);
    t = glm::normalize(t * frame.x + glm::cross(n, t) * handedness * frame.y);
    const glm::vec3 b = glm::cross(n, t) * handedness * frame.z;
    glm::vec3 tn = glm::vec3(texel) * 2.0f - 1.0f;
    tn.x *= scale;
    tn.y *= scale;
    const glm::vec3 mapped = t * tn.x + b * tn.y + n * tn.z;
    return glm::dot(mapped, mapped) > 0.0f ? glm::normalize(mapped) : n;
}

}  // namespace

float ReferenceScene::resolveMaterial(int material, const glm::vec4& uv, glm::vec3 normal, const glm::vec4& tangent,
                                      bool frontFacing, SurfaceHit& hit) const {
    const Impl& s = *impl_;
    const Material& m =
        (material >= 0 && static_cast<std::size_t>(material) < s.materials.size()) ? s.materials[static_cast<std::size_t>(material)]
                                                                                      : s.fallback;
    // shaders/gbuffer.frag.glsl, line by line.
    glm::vec4 baseColor = m.baseColorFactor;
    if (m.baseColorTexture >= 0) baseColor *= sampleTexture(m.baseColorTexture, slotUv(m, kSlotBaseColor, uv));

    glm::vec3 n = glm::length(normal) > 0.0f ? glm::normalize(normal) : hit.geometricNormal;
    if (!frontFacing) n = -n;
    const glm::vec3 interpolatedNormal = n;  // the clear coat's normal without its own map
    if (m.normalTexture >= 0)
        n = mappedNormal(n, tangent, uvTransformRows(m.textureTransforms[kSlotNormal]),
                         sampleTexture(m.normalTexture, slotUv(m, kSlotNormal, uv)), m.normalScale);
    float metalness = m.metallic;
    float roughness = m.roughness;
    if (m.metallicRoughnessTexture >= 0) {
        const glm::vec4 mr = sampleTexture(m.metallicRoughnessTexture, slotUv(m, kSlotMetallicRoughness, uv));
        roughness *= mr.g;
        metalness *= mr.b;
    }
    float occlusion = 1.0f;
    if (m.occlusionTexture >= 0)
        occlusion =
            1.0f + m.occlusionStrength * (sampleTexture(m.occlusionTexture, slotUv(m, kSlotOcclusion, uv)).r - 1.0f);
    glm::vec3 emissive = m.emissiveFactor * m.emissiveStrength;
    if (m.emissiveTexture >= 0) emissive *= glm::vec3(sampleTexture(m.emissiveTexture, slotUv(m, kSlotEmissive, uv)));

    hit.baseColor = glm::vec3(baseColor);
    hit.normal = n;
    hit.roughness = std::clamp(roughness, 0.0f, 1.0f);
    hit.metalness = std::clamp(metalness, 0.0f, 1.0f);
    hit.occlusion = occlusion;
    hit.emission = emissive;
    // docs/MATERIALS.md: the dielectric's F0 and F90, the sheen, the clear coat and the
    // transmission, each factor times its texture where the material has one.
    const auto extensionTexel = [&](const ExtensionTexture& t) {
        return t.texture < 0 ? glm::vec4(1.0f) : sampleTexture(t.texture, extensionUv(t, uv));
    };
    const float specular = m.specularFactor * extensionTexel(m.specularTexture).a;
    hit.dielectricF0 =
        dielectricF0(m.ior, specular, m.specularColorFactor * glm::vec3(extensionTexel(m.specularColorTexture)));
    hit.dielectricF90 = dielectricF90(specular);
    hit.sheenColor = glm::clamp(m.sheenColorFactor * glm::vec3(extensionTexel(m.sheenColorTexture)), glm::vec3(0.0f),
                                glm::vec3(1.0f));
    hit.sheenRoughness = std::clamp(m.sheenRoughness * extensionTexel(m.sheenRoughnessTexture).a, 0.0f, 1.0f);
    hit.clearcoat = std::clamp(m.clearcoatFactor * extensionTexel(m.clearcoatTexture).r, 0.0f, 1.0f);
    hit.clearcoatRoughness =
        std::clamp(m.clearcoatRoughness * extensionTexel(m.clearcoatRoughnessTexture).g, 0.0f, 1.0f);
    hit.clearcoatNormal = interpolatedNormal;
    if (const ExtensionTexture& t = m.clearcoatNormalTexture; t.texture >= 0)
        hit.clearcoatNormal = mappedNormal(interpolatedNormal, tangent, uvTransformRows(t.transform),
                                           sampleTexture(t.texture, extensionUv(t, uv)), t.scale);
    const float transmission = m.transmission * extensionTexel(m.transmissionTexture).r;
    hit.transmission = std::clamp(transmission, 0.0f, 1.0f);
    // A ray that meets a closed volume's face from behind travelled through its medium.
    hit.absorption = frontFacing ? glm::vec3(0.0f) : volumeAbsorption(m);
    hit.refractiveIndex = refractiveIndexOfVolume(m);
    hit.inside = !frontFacing;
    return baseColor.a;
}

bool ReferenceScene::intersect(const Ray& ray, SurfaceHit& hit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = ray.origin.x;
    rh.ray.org_y = ray.origin.y;
    rh.ray.org_z = ray.origin.z;
    rh.ray.dir_x = ray.direction.x;
    rh.ray.dir_y = ray.direction.y;
    rh.ray.dir_z = ray.direction.z;
    rh.ray.tnear = ray.tnear;
    rh.ray.tfar = ray.tfar;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

    const Geometry& g = impl_->geometries[rh.hit.geomID];
    const std::size_t t = 3 * static_cast<std::size_t>(rh.hit.primID);
    const std::uint32_t i0 = g.indices[t], i1 = g.indices[t + 1], i2 = g.indices[t + 2];
    const float u = rh.hit.u, v = rh.hit.v, w = 1.0f - u - v;
    hit.t = rh.ray.tfar;
    hit.position = ray.origin + ray.direction * hit.t;
    glm::vec3 ng = glm::cross(g.positions[i1] - g.positions[i0], g.positions[i2] - g.positions[i0]);
    const float length = glm::length(ng);
    ng = length > 0.0f ? ng / length : -ray.direction;
    // gl_FrontFacing: the counter-clockwise side (the cross product's side) faces the viewer.
    const bool frontFacing = glm::dot(ng, ray.direction) < 0.0f;
    hit.geometricNormal = frontFacing ? ng : -ng;
    const glm::vec4 uv = w * g.uvs[i0] + u * g.uvs[i1] + v * g.uvs[i2];
    const glm::vec3 normal = w * g.normals[i0] + u * g.normals[i1] + v * g.normals[i2];
    const glm::vec4 tangent = w * g.tangents[i0] + u * g.tangents[i1] + v * g.tangents[i2];
    resolveMaterial(g.material, uv, normal, tangent, frontFacing, hit);
    hit.node = g.node;
    hit.emitter = g.emitterBase >= 0 ? g.emitterBase + static_cast<int>(rh.hit.primID) : -1;
    return true;
}

bool ReferenceScene::occluded(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r{};
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.tnear = ray.tnear;
    r.tfar = ray.tfar;
    r.mask = 0xFFFFFFFFu;
    rtcOccluded1(impl_->scene, &context, &r);
    return r.tfar < 0.0f;  // Embree sets tfar to −inf when something blocks the ray
}

glm::vec3 ReferenceScene::sheetTransmittance(const SurfaceHit& hit, const glm::vec3& direction) {
    return transmittanceOfSheet(hit.baseColor, hit.metalness, hit.transmission, hit.dielectricF0, hit.dielectricF90,
                                glm::dot(hit.normal, direction));
}

Crossing ReferenceScene::cross(const SurfaceHit& hit, const Ray& ray) {
    Crossing c;
    if (hit.refractiveIndex <= 0.0f) {
        c.ray = ray;
        c.ray.tnear = pastHit(hit.t);
        c.from = hit.t;
        c.through = sheetTransmittance(hit, ray.direction);
        return c;
    }
    // Snell's law about the shading normal, which faces the ray's origin.
    const glm::vec3 n = hit.normal;
    const float eta = hit.inside ? hit.refractiveIndex : 1.0f / hit.refractiveIndex;
    const float cosIn = std::min(std::max(-glm::dot(n, ray.direction), 0.0f), 1.0f);
    const float k = 1.0f - eta * eta * (1.0f - cosIn * cosIn);
    const float scale = std::max(
        1.0f, std::max(std::abs(hit.position.x), std::max(std::abs(hit.position.y), std::abs(hit.position.z))));
    c.ray.tnear = 0.0f;
    c.ray.tfar = INFINITY;
    c.refracted = true;
    if (k <= 0.0f) {
        // Totally reflected inside: all of it goes on as a mirror's reflection, tinted as what
        // passes (the dielectric's share of the base colour), and stays in the volume.
        c.ray.direction = glm::normalize(ray.direction + 2.0f * cosIn * n);
        c.ray.origin = hit.position + hit.geometricNormal * (1e-4f * scale);
        c.through = glm::vec3(hit.transmission * (1.0f - hit.metalness)) * hit.baseColor;
        return c;
    }
    const float cosOut = std::sqrt(k);
    c.ray.direction = glm::normalize(eta * ray.direction + (eta * cosIn - cosOut) * n);
    c.ray.origin = hit.position - hit.geometricNormal * (1e-4f * scale);  // just past the face
    // Fresnel at the angle outside the volume, the same for the way in and the way out.
    c.through = transmittanceOfSheet(hit.baseColor, hit.metalness, hit.transmission, hit.dielectricF0,
                                     hit.dielectricF90, hit.inside ? cosOut : cosIn);
    return c;
}

glm::vec3 ReferenceScene::mediumTransmittance(const SurfaceHit& hit, float from) {
    if (hit.absorption == glm::vec3(0.0f)) return glm::vec3(1.0f);
    return glm::exp(-hit.absorption * std::max(hit.t - from, 0.0f));
}

glm::vec3 ReferenceScene::transmittance(const Ray& ray) const {
    if (!hasSheets_) return occluded(ray) ? glm::vec3(0.0f) : glm::vec3(1.0f);
    glm::vec3 through(1.0f);
    Ray rest = ray;
    float from = ray.tnear;  // where the ray crossed the last sheet (or started)
    // A bound on the sheets crossed, so a degenerate stack of coplanar sheets cannot loop forever.
    for (int crossed = 0; crossed < 64; ++crossed) {
        SurfaceHit hit;
        if (!intersect(rest, hit)) return through;
        through *= mediumTransmittance(hit, from) * sheetTransmittance(hit, rest.direction);
        from = hit.t;
        if (std::max(through.r, std::max(through.g, through.b)) <= 0.0f) return glm::vec3(0.0f);
        rest.tnear = pastHit(hit.t);
        if (rest.tnear >= rest.tfar) return through;
    }
    return glm::vec3(0.0f);
}

EmitterSample ReferenceScene::sampleEmitter(float u, const glm::vec2& uv) const {
    EmitterSample sample;
    if (emitters_.empty()) return sample;
    const auto it = std::lower_bound(emitterCdf_.begin(), emitterCdf_.end(), u);
    const std::size_t index = std::min(static_cast<std::size_t>(it - emitterCdf_.begin()), emitters_.size() - 1);
    const Emitter& e = emitters_[index];
    // Uniform on the triangle (Pharr, Jakob, Humphreys, PBRT 3rd ed., 13.6.5).
    const float su = std::sqrt(uv.x);
    const float b1 = 1.0f - su, b2 = uv.y * su;
    sample.position = e.p0 + b1 * e.e1 + b2 * e.e2;
    sample.normal = glm::normalize(glm::cross(e.e1, e.e2));
    const glm::vec4 texcoord = (1.0f - b1 - b2) * e.uvs[0] + b1 * e.uvs[1] + b2 * e.uvs[2];
    SurfaceHit hit;
    hit.geometricNormal = sample.normal;
    resolveMaterial(e.material, texcoord, sample.normal, glm::vec4(1, 0, 0, 1), true, hit);
    sample.emission = hit.emission;
    sample.pdfArea = emitterPdfArea(static_cast<int>(index));
    return sample;
}

float ReferenceScene::emitterPdfArea(int index) const {
    if (index < 0 || static_cast<std::size_t>(index) >= emitters_.size() || emitterPower_ <= 0.0f) return 0.0f;
    const Emitter& e = emitters_[static_cast<std::size_t>(index)];
    if (e.area <= 0.0f) return 0.0f;
    return e.power / emitterPower_ / e.area;
}

}  // namespace lit::reference
