#include "reference/PathTracer.h"

#include "reference/DifferenceImage.h"
#include "reference/MicrofacetBrdf.h"
#include "reference/PunctualLights.h"
#include "reference/ReferenceBsdf.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lit::reference {

namespace {

// ---- Random numbers ------------------------------------------------------------------------

// SplitMix64 (Steele, Lea, Flood 2014): turns (seed, pixel, sample) into a well-mixed state.
std::uint64_t splitMix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// PCG32 (O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient Statistically Good
// Algorithms for Random Number Generation", pcg32 XSH RR).
class Random {
public:
    Random(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample) {
        state_ = splitMix64(seed ^ splitMix64(pixel ^ splitMix64(sample)));
        increment_ = (splitMix64(state_ + pixel) << 1u) | 1u;
        next();
    }
    std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + increment_;
        const auto xorShifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorShifted >> rot) | (xorShifted << ((32u - rot) & 31u));
    }
    float uniform() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }  // [0, 1)
    glm::vec2 uniform2() {
        const float a = uniform();
        return {a, uniform()};
    }

private:
    std::uint64_t state_ = 0, increment_ = 1;
};

// ---- Shading helpers -----------------------------------------------------------------------

float maxComponent(const glm::vec3& c) { return bsdfMaxComponent(c); }

// Ray origin just off the surface on the side `side` points to (metres; relative to the
// position's magnitude so far-away scenes keep float precision).
glm::vec3 offsetOrigin(const glm::vec3& p, const glm::vec3& side) {
    const float scale = std::max(1.0f, std::max(std::abs(p.x), std::max(std::abs(p.y), std::abs(p.z))));
    return p + side * (1e-4f * scale);
}

float powerHeuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

// A direction drawn from the Bsdf's mixture (ReferenceBsdf.h) with this sample's random numbers.
bool sampleBsdf(const Bsdf& bsdf, Random& random, glm::vec3& l) {
    const float choice = random.uniform();
    const glm::vec2 u = random.uniform2();
    return bsdf.sample(choice, u, l);
}

struct Contribution {
    glm::vec3 terms[kTermCount]{};
    void add(Term t, const glm::vec3& c) { terms[static_cast<int>(t)] += c; }
};

class PathIntegrator {
public:
    PathIntegrator(const ReferenceScene& scene, const ReferenceSettings& settings) : scene_(scene), settings_(settings) {}

    std::uint64_t rays = 0;

    // Direct light at a surface from every punctual light and (by NEE) from the emitters.
    Split direct(const SurfaceHit& hit, const Bsdf& bsdf, Random& random) {
        Split out;
        const glm::vec3 origin = offsetOrigin(hit.position, hit.geometricNormal);
        for (const gpu::GpuLight& light : scene_.punctualLights()) {
            const PunctualSample ls = samplePunctualLight(light, hit.position);
            if (!bsdf.above(ls.l) || maxComponent(ls.irradiance) <= 0.0f) continue;
            Ray shadow{origin, ls.l, 0.0f, std::isinf(ls.distance) ? INFINITY : ls.distance * (1.0f - 1e-4f)};
            ++rays;
            // Transmissive sheets on the way let their transmittance through (1 in empty space).
            const glm::vec3 through = scene_.transmittance(shadow);
            if (maxComponent(through) <= 0.0f) continue;
            const glm::vec3 irradiance = ls.irradiance * through;
            // Each lobe with its own cosine: the base's and the sheen's n·l, the coat's n_c·l. The
            // sheen's light is diffuse.
            const float NdotL = glm::dot(bsdf.n, ls.l);
            if (NdotL > 0.0f) {
                const glm::vec3 E = irradiance * NdotL;
                out.diffuse += E * bsdf.albedo / kPi * bsdf.sheenScale * bsdf.baseScale;
                if (bsdf.hasSheen()) out.diffuse += E * bsdf.sheenLobe(ls.l);
                out.specular += E * specularBrdf(bsdf.n, bsdf.v, ls.l, bsdf.f0, bsdf.f90, bsdf.alpha) * bsdf.sheenScale *
                                bsdf.baseScale;
            }
            if (bsdf.hasCoat()) {
                const float NcdotL = glm::dot(bsdf.nc, ls.l);
                if (NcdotL > 0.0f) out.specular += irradiance * NcdotL * bsdf.coatLobe(ls.l);
            }
        }
        if (!scene_.emitters().empty()) {
            const float u = random.uniform();
            const EmitterSample es = scene_.sampleEmitter(u, random.uniform2());
            const glm::vec3 toLight = es.position - hit.position;
            const float distance2 = glm::dot(toLight, toLight);
            const float distance = std::sqrt(distance2);
            if (distance > 0.0f && es.pdfArea > 0.0f) {
                const glm::vec3 l = toLight / distance;
                const float cosLight = std::abs(glm::dot(es.normal, l));
                const float NdotL = glm::dot(bsdf.n, l);
                if (cosLight > 0.0f && bsdf.above(l) && maxComponent(es.emission) > 0.0f) {
                    Ray shadow{origin, l, 0.0f, distance * (1.0f - 1e-3f)};
                    ++rays;
                    const glm::vec3 through = scene_.transmittance(shadow);
                    if (maxComponent(through) > 0.0f) {
                        const glm::vec3 emission = es.emission * through;
                        const float pdfLight = es.pdfArea * distance2 / cosLight;
                        const float weight = powerHeuristic(pdfLight, bsdf.pdf(l));
                        if (NdotL > 0.0f) {
                            const glm::vec3 scale = emission * (weight * NdotL / pdfLight);
                            out.diffuse += scale * bsdf.diffuse(l);
                            out.specular += scale * bsdf.specular(l);
                        }
                        if (bsdf.hasCoat()) {
                            const float NcdotL = glm::dot(bsdf.nc, l);
                            if (NcdotL > 0.0f) out.specular += emission * (weight * NcdotL / pdfLight) * bsdf.coatLobe(l);
                        }
                    }
                }
            }
        }
        return out;
    }

    // MIS weight of emission found by BRDF sampling from a surface with density pdfBsdf.
    float emissionWeight(const SurfaceHit& hit, const glm::vec3& direction, float pdfBsdf) const {
        if (hit.emitter < 0) return 1.0f;  // textured emission on non-emitter geometry cannot happen
        const float cosLight = std::abs(glm::dot(hit.geometricNormal, direction));
        if (cosLight <= 0.0f) return 0.0f;
        const float pdfLight = scene_.emitterPdfArea(hit.emitter) * hit.t * hit.t / cosLight;
        return powerHeuristic(pdfBsdf, pdfLight);
    }

    // The chance that a path meeting a sheet passes through it: the luminance of what passes
    // against that plus what the sheet reflects (its Fresnel share and its remaining diffuse albedo),
    // at most 0.95 so the sheet's own reflection keeps being sampled.
    static float passChance(const SurfaceHit& sheet, const glm::vec3& direction, const glm::vec3& through) {
        const float cosine = std::abs(glm::dot(sheet.normal, direction));
        const glm::vec3 reflected =
            F_Schlick(specularF0(sheet.baseColor, sheet.metalness, sheet.dielectricF0),
                      specularF90(sheet.metalness, sheet.dielectricF90), cosine) +
            diffuseAlbedo(sheet.baseColor, sheet.metalness) * sheetDiffuseShare(sheet.transmission);
        const float pass = bsdfLuminance(through);
        const float total = pass + bsdfLuminance(reflected);
        return total > 0.0f ? std::min(pass / total, 0.95f) : 0.0f;
    }

    glm::vec3 environment(const glm::vec3& direction) const {
        return settings_.environment ? settings_.environment(direction) : glm::vec3(0.0f);
    }

    // One camera path through `ray`; adds its four term contributions to `out`. A transmissive
    // sheet the camera sees adds its own light and lets its transmittance of what lies behind it
    // through, term by term (the rasterizer blends its sheets over the image the same way).
    void trace(const Ray& cameraRay, Random& random, Contribution& out) {
        Ray ray = cameraRay;
        glm::vec3 behind(1.0f);  // the product of the sheets' and their media's transmittances so far
        float from = ray.tnear;  // where the ray crossed the last sheet
        for (int sheets = 0; sheets < kMaxSheets; ++sheets) {
            SurfaceHit hit;
            ++rays;
            if (!scene_.intersect(ray, hit)) {
                out.add(Term::DirectDiffuse, behind * environment(ray.direction));
                return;
            }
            behind *= ReferenceScene::mediumTransmittance(hit, from);
            Contribution own;
            shade(hit, ray, random, own);
            for (int t = 0; t < kTermCount; ++t) out.terms[t] += behind * own.terms[t];
            const Crossing crossing = ReferenceScene::cross(hit, ray);
            behind *= crossing.through;
            if (maxComponent(behind) <= 0.0f) return;
            ray = crossing.ray;
            from = crossing.from;
            if (ray.tnear >= ray.tfar) return;
        }
    }

private:
    // Sheets a camera ray is followed through before what remains counts as black.
    static constexpr int kMaxSheets = 16;

    // The path from the camera's surface `hit`, met along `cameraRay`: its own terms into `out`.
    void shade(SurfaceHit hit, const Ray& cameraRay, Random& random, Contribution& out) {
        const bool hasEmitters = !scene_.emitters().empty();
        const bool hasEnvironment = static_cast<bool>(settings_.environment);
        const int maxBounces = settings_.bounces == kAllBounces ? kMaxPathVertices : settings_.bounces;

        // First surface: emission seen directly, then direct light split by lobe.
        out.add(Term::DirectDiffuse, hit.emission);
        Bsdf bsdf(hit, -cameraRay.direction);
        if (!bsdf.reflects()) return;
        const Split d = direct(hit, bsdf, random);
        out.add(Term::DirectDiffuse, d.diffuse);
        out.add(Term::DirectSpecular, d.specular);

        // The first bounce. Its diffuse and specular shares, f_d·cos/pdf and f_s·cos/pdf, weight
        // everything found along the rest of the path: each share is an unbiased estimate of its
        // own lobe's integral, whichever lobe the direction was drawn from.
        if (maxBounces == 0 && !hasEmitters && !hasEnvironment) return;
        // The coat's reflection is part of the specular share.
        glm::vec3 l;
        if (!sampleBsdf(bsdf, random, l)) return;
        float pdf = bsdf.pdf(l);
        if (pdf <= 0.0f) return;
        const Split first = bsdf.weight(l, pdf);
        glm::vec3 throughputD = first.diffuse;
        glm::vec3 throughputS = first.specular;

        // Follows `ray` one segment: the sky it escapes to, or the emission of the surface it
        // meets (into `next`), weighted by the two throughputs into the diffuse/specular terms.
        // False when the ray left the scene.
        // A transmissive sheet on the way either lets the path through (on past it, straight or
        // bent at a volume's face, weighted by its transmittance) or scatters it (the next vertex), each chosen
        // by its share of the light leaving the sheet and weighted by the chance's inverse.
        SurfaceHit next;
        // `ray` ends as the segment's last piece, the direction it arrives at `next` from.
        const auto segment = [&](Ray& ray, Term diffuseTerm, Term specularTerm) {
            float from = ray.tnear;  // where the ray crossed the last sheet
            // Emission met past a volume's bent face is not weighted against the lights' sampling:
            // shadow rays cross volumes straight and stand for it (ReferenceScene::cross).
            bool refracted = false;
            for (int sheets = 0;; ++sheets) {
                ++rays;
                if (!scene_.intersect(ray, next)) {
                    const glm::vec3 sky = environment(ray.direction);
                    out.add(diffuseTerm, throughputD * sky);
                    out.add(specularTerm, throughputS * sky);
                    return false;
                }
                // A volume's medium on the way (the ray met its face from inside).
                const glm::vec3 medium = ReferenceScene::mediumTransmittance(next, from);
                throughputD *= medium;
                throughputS *= medium;
                if (maxComponent(next.emission) > 0.0f && !(refracted && next.emitter >= 0)) {
                    const glm::vec3 e = next.emission * emissionWeight(next, ray.direction, pdf);
                    out.add(diffuseTerm, throughputD * e);
                    out.add(specularTerm, throughputS * e);
                }
                const Crossing crossing = ReferenceScene::cross(next, ray);
                const glm::vec3& through = crossing.through;
                if (maxComponent(through) <= 0.0f) return true;
                const float passShare = passChance(next, ray.direction, through);
                if (sheets + 1 < kMaxSheets && random.uniform() < passShare) {
                    throughputD *= through / passShare;
                    throughputS *= through / passShare;
                    ray = crossing.ray;
                    from = crossing.from;
                    refracted = refracted || crossing.refracted;
                    continue;
                }
                throughputD /= 1.0f - passShare;
                throughputS /= 1.0f - passShare;
                return true;
            }
        };
        Ray ray{offsetOrigin(hit.position, hit.geometricNormal), l, 0.0f, INFINITY};
        if (!segment(ray, Term::DirectDiffuse, Term::DirectSpecular)) return;
        if (maxBounces == 0) return;

        // Indirect light: Lit scales both indirect terms by the material's ambient occlusion.
        throughputD *= hit.occlusion;
        throughputS *= hit.occlusion;
        for (int bounce = 1;; ++bounce) {
            hit = next;
            const Bsdf b(hit, -ray.direction);
            if (!b.reflects()) return;
            const Split dl = direct(hit, b, random);
            const glm::vec3 reflected = dl.diffuse + dl.specular;
            out.add(Term::IndirectDiffuse, throughputD * reflected);
            out.add(Term::IndirectSpecular, throughputS * reflected);

            // Light that reaches this surface by one more segment: from an emitter or the sky
            // (still `bounce` bounces), or a further bounce when allowed.
            const bool moreBounces = bounce < maxBounces && bounce + 1 < kMaxPathVertices;
            if (!moreBounces && !hasEmitters && !hasEnvironment) return;
            if (!sampleBsdf(b, random, l)) return;
            pdf = b.pdf(l);
            if (pdf <= 0.0f) return;
            glm::vec3 weight = (b.diffuse(l) + b.specular(l)) * (glm::dot(b.n, l) / pdf);
            if (b.hasCoat()) weight += b.coatLobe(l) * (glm::dot(b.nc, l) / pdf);
            throughputD *= weight;
            throughputS *= weight;
            if (moreBounces && bounce >= settings_.russianRouletteStart) {
                const float survive = std::min(0.95f, maxComponent(throughputD + throughputS));
                if (random.uniform() >= survive) return;
                throughputD /= survive;
                throughputS /= survive;
            }
            ray = Ray{offsetOrigin(hit.position, hit.geometricNormal), l, 0.0f, INFINITY};
            if (!segment(ray, Term::IndirectDiffuse, Term::IndirectSpecular)) return;
            if (!moreBounces) return;
        }
    }

private:
    const ReferenceScene& scene_;
    const ReferenceSettings& settings_;
};

// The camera ray through window position (x, y) in pixels (origin bottom left), from the near
// plane to the far plane, exactly what the rasterizer's depth range keeps.
Ray cameraRay(const glm::mat4& inverseViewProjection, float x, float y, int width, int height) {
    const float ndcX = x / static_cast<float>(width) * 2.0f - 1.0f;
    const float ndcY = y / static_cast<float>(height) * 2.0f - 1.0f;
    glm::vec4 nearPoint = inverseViewProjection * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    glm::vec4 farPoint = inverseViewProjection * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w;
    const glm::vec3 b = glm::vec3(farPoint) / farPoint.w;
    const float length = glm::length(b - a);
    return Ray{a, (b - a) / length, 0.0f, length};
}

}  // namespace

// ---- ReferenceImage ----------------------------------------------------------------------

void ReferenceImage::resize(int w, int h) {
    width = w;
    height = h;
    clear();
}

void ReferenceImage::clear() {
    for (auto& sum : sums) sum.assign(pixelCount(), glm::dvec3(0.0));
    samples.assign(pixelCount(), 0u);
}

glm::vec3 ReferenceImage::mean(Term term, std::size_t pixel) const {
    const std::uint32_t n = samples[pixel];
    return n > 0 ? glm::vec3(sums[static_cast<int>(term)][pixel] / static_cast<double>(n)) : glm::vec3(0.0f);
}

std::uint32_t ReferenceImage::minSamples() const {
    return samples.empty() ? 0u : *std::min_element(samples.begin(), samples.end());
}

std::vector<float> ReferenceImage::viewRgb(View view, const RenderSettings& settings) const {
    if (!referenceRendersView(view))
        throw std::invalid_argument("the reference renders only the final image and the four lighting terms, not '" +
                                    std::string(toString(view)) + "'");
    bool on[kTermCount] = {settings.terms.directDiffuse, settings.terms.directSpecular, settings.terms.indirectDiffuse,
                           settings.terms.indirectSpecular};
    if (view != View::Final) {
        const Term only = view == View::DirectDiffuse    ? Term::DirectDiffuse
                          : view == View::DirectSpecular ? Term::DirectSpecular
                          : view == View::IndirectDiffuse ? Term::IndirectDiffuse
                                                          : Term::IndirectSpecular;
        for (int t = 0; t < kTermCount; ++t) on[t] = t == static_cast<int>(only);
    }
    std::vector<float> rgb(pixelCount() * 3, 0.0f);
    for (std::size_t p = 0; p < pixelCount(); ++p) {
        glm::vec3 c(0.0f);
        for (int t = 0; t < kTermCount; ++t)
            if (on[t]) c += mean(static_cast<Term>(t), p);
        rgb[3 * p + 0] = c.r;
        rgb[3 * p + 1] = c.g;
        rgb[3 * p + 2] = c.b;
    }
    return rgb;
}

// ---- PathTracer ------------------------------------------------------------------------------

PathTracer::PathTracer(const ReferenceScene& scene, const CameraView& camera, int width, int height,
                       ReferenceSettings settings)
    : scene_(scene), inverseViewProjection_(glm::inverse(camera.viewProjection())), settings_(std::move(settings)) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("the reference image needs a positive size");
    if (settings_.bounces < 0 && settings_.bounces != kAllBounces)
        throw std::invalid_argument("bounces must be 0 or more (or all)");
    image_.resize(width, height);
}

bool PathTracer::addSamples(int count, const std::atomic<bool>* cancel) {
    constexpr int kTile = 16;  // pixels per tile side: small enough to balance, large enough to amortise
    const int first = passSamples_;
    std::atomic<bool> cancelled{false};
    tbb::parallel_for(tbb::blocked_range2d<int>(0, image_.height, kTile, 0, image_.width, kTile),
                      [&](const tbb::blocked_range2d<int>& tile) {
                          if (cancelled.load(std::memory_order_relaxed)) return;
                          if (cancel && cancel->load(std::memory_order_relaxed)) {
                              cancelled = true;
                              return;
                          }
                          PathIntegrator integrator(scene_, settings_);
                          for (int y = tile.rows().begin(); y < tile.rows().end(); ++y) {
                              for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) {
                                  const std::size_t pixel = static_cast<std::size_t>(y) * static_cast<std::size_t>(image_.width) +
                                                            static_cast<std::size_t>(x);
                                  for (int s = first; s < first + count; ++s) {
                                      Random random(settings_.seed, pixel, static_cast<std::uint64_t>(s));
                                      const glm::vec2 u = random.uniform2();
                                      const glm::vec2 jitter = settings_.pixelCentres ? glm::vec2(0.5f) : u;
                                      const Ray ray = cameraRay(inverseViewProjection_, static_cast<float>(x) + jitter.x,
                                                                static_cast<float>(y) + jitter.y, image_.width, image_.height);
                                      Contribution c;
                                      integrator.trace(ray, random, c);
                                      for (int t = 0; t < kTermCount; ++t) {
                                          // A NaN or infinity from a degenerate triangle would poison
                                          // the pixel for good; such a sample counts as black.
                                          const glm::vec3 v = c.terms[t];
                                          if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))
                                              image_.sums[t][pixel] += glm::dvec3(v);
                                      }
                                      ++image_.samples[pixel];
                                  }
                              }
                          }
                          rays_.fetch_add(integrator.rays, std::memory_order_relaxed);
                      });
    if (cancelled) return false;
    passSamples_ += count;
    return true;
}

std::vector<FirstHit> traceFirstHits(const ReferenceScene& scene, const CameraView& camera, int width, int height) {
    std::vector<FirstHit> hits(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    const glm::mat4 inverse = glm::inverse(camera.viewProjection());
    tbb::parallel_for(tbb::blocked_range2d<int>(0, height, 16, 0, width, 16), [&](const tbb::blocked_range2d<int>& tile) {
        for (int y = tile.rows().begin(); y < tile.rows().end(); ++y)
            for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) {
                const Ray ray = cameraRay(inverse, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, width, height);
                SurfaceHit hit;
                FirstHit& out = hits[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
                if (!scene.intersect(ray, hit)) continue;
                out.node = hit.node;
                out.position = hit.position;
                out.normal = shadingNormal(hit.normal, -ray.direction);
                out.emissive = maxComponent(hit.emission) > 0.0f;
                out.metalness = hit.metalness;
                out.roughness = hit.roughness;
                const glm::vec3 origin = offsetOrigin(hit.position, hit.geometricNormal);
                const auto& lights = scene.punctualLights();
                for (std::size_t i = 0; i < lights.size() && i < 32; ++i) {
                    const PunctualSample ls = samplePunctualLight(lights[i], hit.position);
                    if (glm::dot(out.normal, ls.l) <= 0.0f || maxComponent(ls.irradiance) <= 0.0f) continue;
                    const Ray shadow{origin, ls.l, 0.0f, std::isinf(ls.distance) ? INFINITY : ls.distance * (1.0f - 1e-4f)};
                    if (maxComponent(scene.transmittance(shadow)) > 0.0f) out.litBy |= 1u << i;
                }
            }
    });
    return hits;
}

std::vector<std::uint8_t> toneMapToRgba8(const std::vector<float>& rgb, float exposure) {
    std::vector<std::uint8_t> rgba(rgb.size() / 3 * 4, 255);
    const auto aces = [](float x) {  // Narkowicz 2015, as tonemap.glsl acesFilmic
        const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
        return std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
    };
    for (std::size_t p = 0; p < rgb.size() / 3; ++p)
        for (int c = 0; c < 3; ++c) rgba[4 * p + static_cast<std::size_t>(c)] = encodeSrgb8(aces(std::max(rgb[3 * p + static_cast<std::size_t>(c)], 0.0f) * exposure));
    return rgba;
}

}  // namespace lit::reference
