#pragma once
// A lit::Scene made ready for path tracing: its triangles in world space in an Embree scene,
// materials resolved at a hit the way the G-buffer pass resolves them (shaders/gbuffer.frag.glsl:
// base colour, metal-rough, normal, emissive and occlusion textures, alpha mask; the ior, specular,
// sheen and clear-coat factors of docs/MATERIALS.md, the transmission texture), the punctual
// lights of passes/LightSetup, and the emissive triangles as area lights with a power CDF.
// Built once per scene (or per edit); read-only while rendering, so many threads share it.

#include <shared.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "scene/Scene.h"

namespace lit {
class Log;
}

namespace lit::reference {

// A ray segment: origin, unit direction, and the parametric range [tnear, tfar] in metres.
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    float tnear = 0.0f;
    float tfar = INFINITY;
};

// Where a ray hit and what is there, resolved as the G-buffer would store it.
struct SurfaceHit {
    float t = 0.0f;                 // metres along the ray
    glm::vec3 position{0.0f};       // world
    glm::vec3 geometricNormal{0.0f};  // unit, facing the ray's origin side
    glm::vec3 normal{0.0f};         // shading normal: interpolated, flipped like the geometric one, normal-mapped
    glm::vec3 baseColor{1.0f};      // linear
    float metalness = 0.0f;
    float roughness = 1.0f;         // perceptual
    float occlusion = 1.0f;         // material ambient occlusion (applies to indirect light only, as in Lit)
    // The dielectric reflectance of docs/MATERIALS.md (KHR_materials_ior, KHR_materials_specular):
    // F0 = min(((η − 1)/(η + 1))² · k, 1) · s per channel, F90 = s. Metals replace both (specularF0/F90).
    glm::vec3 dielectricF0{0.04f};
    float dielectricF90 = 1.0f;
    // KHR_materials_sheen: the sheen colour s_c (linear; 0 = no sheen) and its perceptual roughness r_s.
    glm::vec3 sheenColor{0.0f};
    float sheenRoughness = 0.0f;
    // KHR_materials_clearcoat: the coat's weight cc (0 = no coat), its perceptual roughness, and its
    // normal n_c: the interpolated normal flipped like the others, without the normal map.
    float clearcoat = 0.0f;
    float clearcoatRoughness = 0.0f;
    glm::vec3 clearcoatNormal{0.0f};  // unit; zero where unresolved (the Bsdf then takes `normal`)
    // KHR_materials_transmission's t: a thin sheet that lets transmittanceOfSheet through
    // (MicrofacetBrdf.h; 0: opaque).
    float transmission = 0.0f;
    // KHR_materials_volume: the absorption coefficient σ_a (1/m) of the medium the ray crossed to
    // get here, the material's where the ray met the face of a closed volume from behind (it was
    // inside), else 0 (scene/Sheets.h volumeAbsorption; mediumTransmittance).
    glm::vec3 absorption{0.0f};
    // KHR_materials_volume with KHR_materials_ior: the index of refraction η of a volume whose face
    // this is (a crossing ray bends by Snell's law, ReferenceScene::cross), 0 for none (a thin sheet,
    // an opaque surface). `inside`: the ray met the triangle's back (for a closed volume, from inside).
    float refractiveIndex = 0.0f;
    bool inside = false;
    glm::vec3 emission{0.0f};       // W/(sr·m²)
    int node = -1;                  // scene node index
    int emitter = -1;               // index into emitters() when the triangle emits, else -1
};

// A camera ray or path going on past a sheet (ReferenceScene::cross).
struct Crossing {
    Ray ray;                  // the ray that goes on
    float from = 0.0f;        // where along `ray` the sheet lies (mediumTransmittance's start)
    glm::vec3 through{0.0f};  // what the sheet lets through along it (0: nothing, e.g. totally reflected)
    bool refracted = false;   // the ray bent (or was totally reflected) at a volume's face
};

struct Emitter {
    glm::vec3 p0{0.0f}, e1{0.0f}, e2{0.0f};  // world vertex 0 and edges to vertices 1 and 2
    std::array<glm::vec4, 3> uvs{};          // per corner: xy TEXCOORD_0, zw TEXCOORD_1
    int material = -1;
    float area = 0.0f;  // m²
    float power = 0.0f;  // sampling weight: area × luminance of the emissive factor
};

// A point drawn on the emissive triangles, density `pdfArea` per m² of the whole emitter set.
struct EmitterSample {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};     // unit geometric normal (emitters are two-sided, as in Lit)
    glm::vec3 emission{0.0f};   // W/(sr·m²) at the point
    float pdfArea = 0.0f;       // 1/m²
};

class ReferenceScene {
public:
    // Needs up-to-date world transforms (Scene::updateWorldTransforms). Throws std::runtime_error
    // when Embree cannot be initialised. `log` gets the lights LightSetup warns about.
    ReferenceScene(const Scene& scene, Log& log);
    ~ReferenceScene();
    ReferenceScene(const ReferenceScene&) = delete;
    ReferenceScene& operator=(const ReferenceScene&) = delete;

    // Closest hit along the ray (alpha-masked texels are skipped), resolved; false on a miss.
    bool intersect(const Ray& ray, SurfaceHit& hit) const;
    // True when anything blocks the ray between tnear and tfar.
    bool occluded(const Ray& ray) const;
    // What reaches tfar along the ray: 0 when an opaque surface blocks it, else the product of the
    // transmittanceOfSheet of every transmissive surface it crosses and of what the volumes'
    // media between them let through (1 through empty space).
    glm::vec3 transmittance(const Ray& ray) const;
    // Whether a surface of the scene is a transmissive sheet (scene/Sheets.h drawnAsSheet).
    bool hasSheets() const { return hasSheets_; }
    // The light a ray crossing `hit` passes through it (0 for an opaque surface).
    static glm::vec3 sheetTransmittance(const SurfaceHit& hit, const glm::vec3& direction);
    // How a camera ray or path along `ray` goes on past the sheet `hit` it met: straight on through
    // a thin sheet (sheetTransmittance); bent by Snell's law at a volume's face (into the volume on
    // its front, η = 1/refractiveIndex, out of it on its back), letting through transmittanceOfSheet
    // at the angle outside the volume; where the light is totally reflected inside, mirrored back
    // into the volume, tinted as what passes.
    // Shadow rays cross volumes straight (transmittance), as the rasterizer's shadow maps do.
    static Crossing cross(const SurfaceHit& hit, const Ray& ray);
    // What the medium the ray crossed to reach `hit` lets through since distance `from` along the
    // same ray (its last sheet, or its start): exp(−σ_a · (t − from)), 1 outside any volume.
    static glm::vec3 mediumTransmittance(const SurfaceHit& hit, float from);
    // Where a ray that met a surface at distance t goes on past it (relative to the distance, so far
    // hits keep float precision).
    static float pastHit(float t) { return t + std::max(1e-4f, t * 1e-5f); }

    const std::vector<gpu::GpuLight>& punctualLights() const { return lights_; }
    const std::vector<Emitter>& emitters() const { return emitters_; }
    float emitterPower() const { return emitterPower_; }
    // Draws a point on the emitters by power, then uniformly over the triangle's area.
    EmitterSample sampleEmitter(float u, const glm::vec2& uv) const;
    // Density (per m²) with which sampleEmitter produces a point on emitter `index`.
    float emitterPdfArea(int index) const;

    // Texture lookup as the GPU's sampler would do it at mip level 0: bilinear, with the glTF
    // sampler's wrap modes, sRGB images decoded to linear before filtering. RGBA in [0,1].
    glm::vec4 sampleTexture(int texture, glm::vec2 uv) const;
    // The material at a surface point from its interpolated attributes (UVs: xy TEXCOORD_0, zw
    // TEXCOORD_1; world normal and tangent
    // already transformed; `frontFacing` as gl_FrontFacing). Fills baseColor ... emission, the
    // dielectric F0/F90, the sheen, the clear coat, `normal` and `clearcoatNormal`; returns the
    // base colour alpha (for the mask test).
    float resolveMaterial(int material, const glm::vec4& uv, glm::vec3 normal, const glm::vec4& tangent,
                          bool frontFacing, SurfaceHit& hit) const;

    // The alpha-mask test for a hit on geometry `geometry`, triangle `primitive` at barycentrics
    // (u, v): true when the texel is cut out. Used by Embree's filter callbacks.
    bool alphaCutOut(unsigned geometry, unsigned primitive, float u, float v) const;

    std::size_t triangleCount() const { return triangleCount_; }

private:
    struct Geometry;
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::vector<gpu::GpuLight> lights_;
    std::vector<Emitter> emitters_;
    std::vector<float> emitterCdf_;  // cumulative power, normalised to end at 1
    float emitterPower_ = 0.0f;
    std::size_t triangleCount_ = 0;
    bool hasSheets_ = false;
};

}  // namespace lit::reference
