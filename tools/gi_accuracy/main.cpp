// lit-gi-accuracy — the GI accuracy benchmark. Renders a suite of scenes with Lit's voxel cone
// tracing at several voxel resolutions and with the reference path tracer (one bounce: the same
// light paths as the VCT), and writes markdown tables of how far the cone-traced light is from the
// truth (docs/GI.md, "Accuracy against the reference"; tools/gi-accuracy.sh runs it).
//
//   lit-gi-accuracy [--voxels 64,128,256] [--spp 256] [--size 128] [--scenes a,b,...]
//                   [--shared DIR] [--out FILE.md] [--bounces N] [--settings FILE.json] [--cone-split]
//                   [--frames N] [--images DIR] [--scene FILE.gltf]...
// --bounces N|all: light bounces of both the VCT (GiSettings::bounces) and the reference (default 1);
// --settings: RenderSettings JSON the VCT starts from (size, view, GI switch, resolution and
// bounces are set by the tool), to compare GI variants (e.g. anisotropicVoxels off).
// --frames N: render each VCT view N times and measure the last (default 1), for settings with
// temporalAccumulation (the still camera's history then averages the jitter and the cone sets).
// --scene FILE.gltf: measure this scene too (its first camera; named by its file's stem), e.g. an
// edited copy of the Cornell box (the region tables need its node names); only the --scene files
// run when --scenes is not given.
// --images DIR: also write, per scene, the reference's and each VCT run's indirect radiance (L_ID +
// L_IS) as linear .hdr, the Difference view of each run against the reference (.png) and a map of
// the named regions (.png, one colour per region), to see where in a region the light is wrong.
// --cone-split: also a table of the indirect diffuse of each Cornell region split by the six
// diffuse cones' regions of the hemisphere (see coneSplit below), the truth's and the VCT's.
// cornell_room, cornell_mirrored and cornell_swapped (assets/gi, the Cornell box rebuilt, mirrored
// in x, its wall colours swapped) run only when --scenes names them (diagnostics).
//
// Metrics (luminance, per scene and resolution; regions from reference/AccuracyRegions.h):
//   indirect-only VCT/ref   mean indirect radiance (L_ID + L_IS) of the VCT over the pixels lit only
//                           indirectly, divided by the reference's (1 = right; its distance from 1 is
//                           the mean relative error of the indirect terms there)
//   final RMSE              RMSE of the final image over all surface pixels after scaling the VCT so
//                           that its mean over directly lit pixels matches the reference's, relative
//                           to the reference's mean; in brackets the reference's own noise on the
//                           same scale (from a second reference image with another seed)
//   indirect energy         Σ VCT indirect / Σ reference indirect over all pixels
// Exit status: 0 success, 1 failure, 2 bad command line.

#include "Log.h"
#include "Renderer.h"
#include "RenderSettings.h"
#include "context/HeadlessContext.h"
#include "gl/Capabilities.h"
#include "reference/AccuracyRegions.h"
#include "reference/PunctualLights.h"
#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"
#include "scene/CameraView.h"
#include "scene/GltfLoader.h"
#include "scene/SceneBuilder.h"
#include "scene/Sky.h"
#include "scene/Scene.h"
#include "io/AtomicFile.h"
#include "image/ImageIO.h"
#include "reference/DifferenceImage.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using namespace lit;
using namespace lit::reference;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }
double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

struct SuiteScene {
    std::string name;
    fs::path file;
    std::string what;          // one line for the table
    bool sealed = false;       // report inside radiance as a fraction of the sunlit ground's
    bool framedInside = false;  // no camera in the file: look along the long axis from inside
    bool onlyWhenNamed = false;  // a diagnostic variant: run only when --scenes names it
    // The VCT's near levels (GiSettings::nearLevelSide in m, nearLevels) instead of the settings'.
    std::optional<std::pair<float, int>> nearLevels{};
};

struct Args {
    std::vector<int> voxels{64, 128, 256};
    int spp = 256;
    int size = 128;
    std::vector<std::string> only;
    fs::path shared;
    fs::path out;
    int bounces = 1;
    RenderSettings vct;  // what the VCT runs start from (--settings)
    bool coneSplit = false;
    int frames = 1;  // renders per VCT view (--frames), the last one measured
    fs::path images;  // --images: where the per-scene images go (empty: none)
    std::vector<fs::path> extraScenes;  // --scene
};

std::string readTextFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::invalid_argument("cannot read " + path.string());
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');)
        if (!part.empty()) parts.push_back(part);
    return parts;
}

const char* const kUsage =
    "usage: lit-gi-accuracy [--voxels 64,128,256] [--spp 256] [--size 128] [--scenes a,b,...]\n"
    "                       [--shared DIR] [--out FILE.md] [--bounces N|all] [--settings FILE.json] [--cone-split]\n"
    "                       [--frames N] [--images DIR] [--scene FILE.gltf]...\n"
    "The GI accuracy benchmark: the VCT against the reference path tracer (docs/GI.md; the options are\n"
    "described at the top of tools/gi_accuracy/main.cpp).\n";

Args parseArgs(int argc, char** argv) {
    Args args;
    args.shared = fs::path(LIT_SOURCE_DIR) / ".." / "shared" / "scenes";
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            std::fputs(kUsage, stdout);
            std::exit(0);
        }
        if (flag == "--cone-split") {
            args.coneSplit = true;
            continue;
        }
        if (i + 1 >= argc) throw std::invalid_argument("missing value for " + flag);
        const std::string value = argv[++i];
        if (flag == "--voxels") {
            args.voxels.clear();
            for (const std::string& v : split(value)) {
                const int n = std::stoi(v);
                if (n < 64 || n > 512 || (n & (n - 1)) != 0) throw std::invalid_argument("--voxels: 64, 128, 256 or 512, got " + v);
                args.voxels.push_back(n);
            }
        } else if (flag == "--spp") {
            args.spp = std::stoi(value);
        } else if (flag == "--size") {
            args.size = std::stoi(value);
        } else if (flag == "--scenes") {
            args.only = split(value);
        } else if (flag == "--shared") {
            args.shared = value;
        } else if (flag == "--out") {
            args.out = value;
        } else if (flag == "--bounces") {
            // all: every bounce, the GI's default (kAllBounces) and the reference's until Russian roulette.
            args.bounces = value == "all" ? lit::kAllBounces : std::stoi(value);
            if (args.bounces != lit::kAllBounces && (args.bounces < 1 || args.bounces > kMaxBounces))
                throw std::invalid_argument("--bounces: 1.." + std::to_string(kMaxBounces) + " or all");
        } else if (flag == "--frames") {
            args.frames = std::stoi(value);
            if (args.frames < 1 || args.frames > 1000) throw std::invalid_argument("--frames: 1..1000");
        } else if (flag == "--scene") {
            if (!fs::is_regular_file(value)) throw std::invalid_argument("--scene: no such file " + value);
            args.extraScenes.emplace_back(value);
        } else if (flag == "--images") {
            args.images = value;
            if (args.images.empty()) throw std::invalid_argument("--images: a folder");
        } else if (flag == "--settings") {
            args.vct = renderSettingsFromJson(readTextFile(value));
        } else {
            throw std::invalid_argument("unknown option " + flag);
        }
    }
    if (args.spp < 1 || args.size < 16 || args.voxels.empty()) throw std::invalid_argument("bad --spp, --size or --voxels");
    return args;
}

// Every name --scenes gives must be one of the suite's (a typo would otherwise measure nothing).
void checkSceneNames(const Args& args, const std::vector<SuiteScene>& all) {
    for (const std::string& name : args.only)
        if (std::none_of(all.begin(), all.end(), [&](const SuiteScene& s) { return s.name == name; })) {
            std::string known;
            for (const SuiteScene& s : all) known += (known.empty() ? "" : ", ") + s.name;
            throw std::invalid_argument("--scenes: no scene called " + name + " (known: " + known + ")");
        }
}

std::vector<SuiteScene> suite(const Args& args) {
    const fs::path assets = fs::path(LIT_SOURCE_DIR) / "assets";
    std::vector<SuiteScene> scenes = {
        {"cornell_box", assets / "cornell_box.gltf", "Cornell box, 13 660 cd (20 W/sr) spot pointing down (ceiling lit only indirectly)"},
        {"sealed_room", assets / "gi" / "sealed_room.gltf", "closed room (0.2 m walls) on a ground under a 50 W/m² sun", true},
        {"thin_walls", assets / "gi" / "thin_walls.gltf", "Cornell room with walls 1 voxel thick at 128³, 20 W/m² sun on the roof"},
        {"glossy_floor", assets / "gi" / "glossy_floor.gltf", "Cornell room with a glossy metal floor (roughness 0.2)"},
        {"city", assets / "gi" / "city.gltf", "640 m of box buildings and 14 m streets, 50 W/m² sun 30° high, seen from street level"},
        {"city_one_volume", assets / "gi" / "city.gltf", "the city without near levels: one volume around it all", false, false, false,
         std::pair{0.0f, 0}},
        {"city_two_levels", assets / "gi" / "city.gltf", "the city with near levels of 32 m and 64 m", false, false, false,
         std::pair{32.0f, 2}},
        {"sponza", args.shared / "sponza" / "Sponza.gltf", "Sponza (textured, ../shared/scenes), the default sun (4 W/m²)", false, true},
        {"sponza_near_levels", args.shared / "sponza" / "Sponza.gltf",
         "Sponza with near levels of 8 m and 16 m (the default 64 m level does not run in a scene 36 m across)", false, true,
         false, std::pair{8.0f, 2}},
        {"cornell_room", assets / "gi" / "cornell_room.gltf", "the Cornell box rebuilt by make-gi-suite", false, false, true},
        {"cornell_mirrored", assets / "gi" / "cornell_mirrored.gltf", "the Cornell box mirrored in x", false, false, true},
        {"cornell_swapped", assets / "gi" / "cornell_swapped.gltf", "the Cornell box, wall colours swapped", false, false, true},
    };
    checkSceneNames(args, scenes);
    std::vector<SuiteScene> chosen;
    if (args.only.empty() && args.extraScenes.empty()) {
        std::erase_if(scenes, [](const SuiteScene& s) { return s.onlyWhenNamed; });
        chosen = std::move(scenes);
    } else {
        for (const SuiteScene& s : scenes)
            if (std::find(args.only.begin(), args.only.end(), s.name) != args.only.end()) chosen.push_back(s);
    }
    for (const fs::path& file : args.extraScenes) chosen.push_back({file.stem().string(), file, "--scene " + file.string()});
    return chosen;
}

// Radiance of a Lambertian ground (material "ground") under the first directional light:
// ρ/π · E · cos θ — the outside brightness a sealed room's inside is compared with.
double outsideRadiance(const Scene& scene) {
    double albedo = 0.0;
    for (const Material& m : scene.materials)
        if (m.name == "ground") albedo = luminance(glm::dvec3(glm::vec3(m.baseColorFactor)));
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        const int l = scene.nodes[n].light;
        if (l < 0 || scene.lights[static_cast<std::size_t>(l)].type != LightType::Directional) continue;
        const Light& light = scene.lights[static_cast<std::size_t>(l)];
        const glm::vec3 direction = glm::normalize(glm::vec3(scene.nodes[n].world * glm::vec4(0, 0, -1, 0)));
        return albedo / 3.14159265358979323846 * light.intensity * luminance(glm::dvec3(light.color)) * std::max(0.0f, -direction.y);
    }
    return 0.0;
}

std::vector<float> addImages(const std::vector<float>& a, const std::vector<float>& b) {
    std::vector<float> sum(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) sum[i] = a[i] + b[i];
    return sum;
}

double maskedLuminance(const std::vector<float>& rgb, const PixelMask& mask) { return luminance(maskedMean(rgb, mask)); }

double sumLuminance(const std::vector<float>& rgb) {
    double sum = 0.0;
    for (std::size_t i = 0; i < rgb.size(); i += 3) sum += luminance(glm::dvec3(rgb[i], rgb[i + 1], rgb[i + 2]));
    return sum;
}

struct Images {
    std::vector<float> indirectDiffuse, indirectSpecular, final;
    std::vector<float> indirect() const { return addImages(indirectDiffuse, indirectSpecular); }
};

struct VctRun {
    int voxels = 0;
    Images images;
    double firstFrameSeconds = 0.0;   // with voxelization, injection and mipmaps
    double steadyFrameSeconds = 0.0;  // a frame with a clean volume
};

std::string format(const char* fmt, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, fmt, value);
    return buffer;
}

std::string ratioCell(double vct, double truth) { return truth > 0.0 ? format("%.2f", vct / truth) : "–"; }

// --images: DIR/<scene>_reference_{indirect,final}.hdr, <scene>_vct<N>_{indirect,final}.hdr and
// <scene>_vct<N>_difference.png (the editor's Difference view, ramp ends ±50 %), and
// <scene>_regions.png: the named regions in colour (in the order of the region table: red, green,
// blue, yellow, ...), other surfaces dark grey.
void writeImages(const fs::path& folder, const std::string& scene, int size, const Images& truth,
                 const std::vector<VctRun>& runs, const std::vector<NamedRegion>& regions, const PixelMask& surfaces) {
    fs::create_directories(folder);
    const auto prefix = [&](const std::string& what) { return folder / (scene + "_" + what); };
    const std::vector<float> truthIndirect = truth.indirect();
    writeHdr(prefix("reference_indirect.hdr"), size, size, truthIndirect);
    writeHdr(prefix("reference_final.hdr"), size, size, truth.final);
    for (const VctRun& run : runs) {
        const std::vector<float> indirect = run.images.indirect();
        const std::string name = "vct" + std::to_string(run.voxels);
        writeHdr(prefix(name + "_indirect.hdr"), size, size, indirect);
        writeHdr(prefix(name + "_final.hdr"), size, size, run.images.final);
        writePng(prefix(name + "_difference.png"), size, size,
                 displayColoursToRgba8(relativeErrorColours(indirect, truthIndirect, 0.5f)));
    }
    if (regions.empty()) return;
    const glm::vec3 palette[] = {{1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.3f, 0.4f, 1}, {1, 1, 0.2f}, {1, 0.3f, 1}, {0.2f, 1, 1}};
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4, 255);
    for (std::size_t p = 0; p < surfaces.size(); ++p) {
        glm::vec3 colour = surfaces[p] ? glm::vec3(0.08f) : glm::vec3(0.0f);
        for (std::size_t r = 0; r < regions.size(); ++r)
            if (regions[r].mask[p]) colour = palette[r % std::size(palette)];
        for (int c = 0; c < 3; ++c) rgba[4 * p + static_cast<std::size_t>(c)] = encodeSrgb8(colour[c]);
    }
    writePng(prefix("regions.png"), size, size, rgba);
}

struct SceneReport {
    std::string summaryRows, regionRows, bleedingRows, leakRows, coneRows;
};

// The indirect diffuse of a pixel split by the regions of the hemisphere the six diffuse cones
// stand for (cone.glsl: cone 0 the cap θ < 30°, cones 1..5 the ring 30° < θ < 90° in five 72°
// sectors centred on their axes' azimuths, in the same tangent frame, unturned as the accurate
// mode and a still without temporal accumulation trace them). For each region i the truth's share
// is albedo/π · ∫_{Ω_i} L cos θ dω, the one-bounce radiance L of what a ray hits being its
// Lambertian direct light (albedo/π · E, shadow rays: what the VCT injects into the voxels), by
// cosine-weighted stratified sampling. Summed over i it is the one-bounce indirect diffuse with
// Lambertian second surfaces (the reference's also has their GGX term). The VCT's share of cone i
// is its indirect diffuse with every other cone's weight 0 (shaders/include/shared.h,
// LIT_DIFFUSE_CONE_WEIGHTS, through a copy of the shaders under LIT_SHADER_DIR).
constexpr int kConeSplitSamplesPerSide = 24;  // 576 stratified directions per pixel

// cone.glsl tangentFrame (Duff et al. 2017), column by column.
glm::mat3 coneTangentFrame(const glm::vec3& n) {
    const float s = n.z >= 0.0f ? 1.0f : -1.0f;
    const float a = -1.0f / (s + n.z);
    const float b = n.x * n.y * a;
    return glm::mat3(glm::vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x), glm::vec3(b, s + n.y * n.y * a, -n.y), n);
}

// Which diffuse cone's region a tangent-space direction (z up) falls in.
int coneRegion(const glm::vec3& d) {
    if (d.z > std::cos(std::numbers::pi_v<float> / 6.0f)) return 0;
    float azimuth = std::atan2(d.y, d.x);  // cone 1 at 0, cone k at (k − 1)·72°
    if (azimuth < 0.0f) azimuth += 2.0f * std::numbers::pi_v<float>;
    const int sector = static_cast<int>(std::floor(azimuth / (0.4f * std::numbers::pi_v<float>) + 0.5f)) % 5;
    return 1 + sector;
}

// Per cone region, the truth's indirect diffuse share averaged over the pixels of `mask` (RGB).
std::vector<glm::dvec3> coneSplit(const ReferenceScene& scene, const std::vector<FirstHit>& hits, const PixelMask& mask) {
    std::vector<glm::dvec3> sums(LIT_DIFFUSE_CONE_COUNT, glm::dvec3(0.0));
    std::size_t pixels = 0;
    const int k = kConeSplitSamplesPerSide;
    for (std::size_t p = 0; p < hits.size(); ++p) {
        if (!mask[p]) continue;
        ++pixels;
        const FirstHit& first = hits[p];
        const glm::vec3 albedo = [&] {
            SurfaceHit h;
            const glm::vec3 eyeSide = first.position + first.normal * 0.01f;
            return scene.intersect(Ray{eyeSide, -first.normal, 0.0f, 0.02f}, h) ? h.baseColor * (1.0f - h.metalness) : glm::vec3(0.0f);
        }();
        const glm::mat3 frame = coneTangentFrame(first.normal);
        const glm::vec3 origin = first.position + first.normal * 1e-4f;
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j) {
                // Cosine-weighted (Malley): a uniform point of the unit disc lifted to the hemisphere.
                const float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(k), v = (static_cast<float>(j) + 0.5f) / static_cast<float>(k);
                const float r = std::sqrt(u), phi = 2.0f * std::numbers::pi_v<float> * v;
                const glm::vec3 local(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u)));
                const glm::vec3 direction = glm::normalize(frame * local);
                SurfaceHit hit;
                if (!scene.intersect(Ray{origin, direction, 0.0f, INFINITY}, hit)) continue;
                glm::vec3 radiance(0.0f);
                const glm::vec3 n = glm::dot(hit.normal, direction) < 0.0f ? hit.normal : -hit.normal;
                const glm::vec3 lightOrigin = hit.position + hit.geometricNormal * 1e-4f;
                for (const gpu::GpuLight& light : scene.punctualLights()) {
                    const PunctualSample ls = samplePunctualLight(light, hit.position);
                    const float NdotL = glm::dot(n, ls.l);
                    if (NdotL <= 0.0f) continue;
                    if (scene.occluded(Ray{lightOrigin, ls.l, 0.0f, std::isinf(ls.distance) ? INFINITY : ls.distance * (1.0f - 1e-4f)}))
                        continue;
                    radiance += ls.irradiance * NdotL * hit.baseColor * (1.0f - hit.metalness) / std::numbers::pi_v<float>;
                }
                // E_i = π · mean over the cosine-distributed samples of L·[in Ω_i]; × albedo/π.
                sums[static_cast<std::size_t>(coneRegion(local))] += glm::dvec3(albedo * radiance) / static_cast<double>(k * k);
            }
    }
    for (glm::dvec3& s : sums) s /= static_cast<double>(std::max<std::size_t>(pixels, 1));
    return sums;
}

SceneReport measure(const SuiteScene& entry, const Args& args, Renderer& renderer, Log& log) {
    SceneReport report;
    Scene scene = loadGltf(entry.file, log);
    addDefaultCamera(scene, log);
    // A scene without lights gets the rasterizer's default sun as a light of its own, so that the
    // reference (which adds no default light) and the rasterizer see the same light.
    if (hasDefaultSun(scene, RenderSettings{})) {
        Light sun;
        sun.name = "default sun";
        sun.type = LightType::Directional;
        sun.intensity = RenderSettings{}.sky.sunIrradiance;
        addLightNode(scene, sun, glm::vec3(0.0f), defaultSunDirection(RenderSettings{}));
    }
    scene.updateWorldTransforms();
    const int size = args.size;
    CameraView camera = sceneCameraView(scene, entry.framedInside ? -1 : 0, 1.0f);
    if (entry.framedInside) {
        // From the middle of the open courtyard, a fifth of the height up, looking along the longest
        // horizontal axis at the far end: walls, arcades and the sunlit floor in view.
        const Aabb b = scene.worldBounds();
        const glm::vec3 e = b.max - b.min, c = b.center();
        const bool alongX = e.x >= e.z;
        const glm::vec3 axis = alongX ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
        const float length = alongX ? e.x : e.z;
        const glm::vec3 eye = glm::vec3(c.x, b.min.y + 0.2f * e.y, c.z);
        const glm::vec3 target = eye + axis * (0.4f * length) + glm::vec3(0.0f, 0.05f * e.y, 0.0f);
        Camera cam;
        cam.name = "accuracy";
        cam.yfov = 1.0f;
        cam.znear = 0.05f;
        addCameraNode(scene, cam, eye, target);
        scene.updateWorldTransforms();
        camera = sceneCameraView(scene, static_cast<int>(scene.cameras.size()) - 1, 1.0f);
    }

    // The reference: the VCT's light paths (--bounces, default one bounce).
    const Clock::time_point referenceStart = Clock::now();
    const ReferenceScene referenceScene(scene, log);
    ReferenceSettings referenceSettings;
    referenceSettings.bounces = args.bounces == lit::kAllBounces ? reference::kAllBounces : args.bounces;
    // At the pixel centres, as the rasterizer samples: the columns measure the light, not the
    // raster's missing anti-aliasing (a sunlit edge against the sky is most of a 128² image's error).
    referenceSettings.pixelCentres = true;
    PathTracer tracer(referenceScene, camera, size, size, referenceSettings);
    tracer.addSamples(args.spp);
    const double referenceSeconds = secondsSince(referenceStart);
    const double raysPerSecond = static_cast<double>(tracer.raysTraced()) / referenceSeconds;
    RenderSettings viewSettings;
    Images truth;
    truth.indirectDiffuse = tracer.image().viewRgb(View::IndirectDiffuse, viewSettings);
    truth.indirectSpecular = tracer.image().viewRgb(View::IndirectSpecular, viewSettings);
    truth.final = tracer.image().viewRgb(View::Final, viewSettings);
    std::fprintf(stderr, "%s: reference %d spp in %.1f s (%.2f Mrays/s)\n", entry.name.c_str(), args.spp, referenceSeconds,
                 raysPerSecond * 1e-6);

    // The reference's own noise: a second image with another seed; the RMSE between two
    // independent images is √2 × the RMSE of one against the converged truth.
    referenceSettings.seed = 1;
    PathTracer second(referenceScene, camera, size, size, referenceSettings);
    second.addSamples(args.spp);
    const std::vector<float> secondFinal = second.image().viewRgb(View::Final, viewSettings);

    const std::vector<FirstHit> hits = traceFirstHits(referenceScene, camera, size, size);
    const PixelMask surfaces = surfaceMask(hits);
    const PixelMask indirectOnly = erodeEdges(indirectOnlyMask(hits), hits, size, size, 1);
    const PixelMask directlyLit = directlyLitMask(hits);

    // The VCT at each resolution: three views of the same frame state.
    renderer.setScene(scene);
    std::vector<VctRun> runs;
    for (const int voxels : args.voxels) {
        RenderSettings settings = args.vct;
        if (entry.nearLevels) std::tie(settings.gi.nearLevelSide, settings.gi.nearLevels) = *entry.nearLevels;
        settings.gi.bounces = args.bounces;
        settings.output.width = size;
        settings.output.height = size;
        settings.gi.enabled = true;
        settings.gi.voxelResolution = voxels;
        // The reference samples the pixel centres: so does each frame without anti-aliasing (with
        // --frames N it would average jittered frames over the pixels' area instead), and each
        // lobe at its own roughness without specular anti-aliasing (which widens it by the pixel's
        // footprint).
        settings.output.antialiasing = false;
        settings.output.specularAntialiasing = false;
        VctRun run;
        run.voxels = voxels;
        const auto frame = [&](View view) {
            settings.debug.view = view;
            const Clock::time_point start = Clock::now();
            for (int f = 0; f < args.frames; ++f) renderer.render(scene, camera, settings);
            glFinish();
            const double seconds = secondsSince(start);
            return std::pair{renderer.readHdrRgb(), seconds};
        };
        auto [id, first] = frame(View::IndirectDiffuse);
        run.firstFrameSeconds = first;
        run.images.indirectDiffuse = std::move(id);
        auto [is, steady] = frame(View::IndirectSpecular);
        run.steadyFrameSeconds = steady;
        run.images.indirectSpecular = std::move(is);
        run.images.final = frame(View::Final).first;
        std::fprintf(stderr, "%s: VCT %d³ first frame %.2f s, frame %.2f s\n", entry.name.c_str(), voxels, first, steady);
        runs.push_back(std::move(run));
    }

    const std::vector<float> truthIndirect = truth.indirect();
    const double truthIndirectOnly = maskedLuminance(truthIndirect, indirectOnly);
    const double truthDirectFinal = maskedLuminance(truth.final, directlyLit);
    const double truthSurfaceMean = maskedLuminance(truth.final, surfaces);
    const double truthEnergy = sumLuminance(truthIndirect);
    const std::size_t indirectPixels = static_cast<std::size_t>(std::count(indirectOnly.begin(), indirectOnly.end(), true));
    const auto finalRmse = [&](const std::vector<float>& image, double scale) {
        double squares = 0.0;
        std::size_t count = 0;
        for (std::size_t p = 0; p < surfaces.size(); ++p) {
            if (!surfaces[p]) continue;
            const double v = luminance(glm::dvec3(image[3 * p], image[3 * p + 1], image[3 * p + 2]));
            const double t = luminance(glm::dvec3(truth.final[3 * p], truth.final[3 * p + 1], truth.final[3 * p + 2]));
            squares += (scale * v - t) * (scale * v - t);
            ++count;
        }
        return count ? std::sqrt(squares / static_cast<double>(count)) : 0.0;
    };
    const double referenceNoise = finalRmse(secondFinal, 1.0) / std::sqrt(2.0);

    if (!args.images.empty())
        writeImages(args.images, entry.name, size, truth, runs, cornellBoxRegions(scene, hits, size, size), surfaces);

    for (const VctRun& run : runs) {
        const std::vector<float> indirect = run.images.indirect();
        const double vctIndirectOnly = maskedLuminance(indirect, indirectOnly);
        // Exposure match on directly lit pixels, then RMSE over every surface pixel.
        const double vctDirect = maskedLuminance(run.images.final, directlyLit);
        const double k = vctDirect > 0.0 ? truthDirectFinal / vctDirect : 1.0;
        const double rmse = finalRmse(run.images.final, k);
        report.summaryRows += "| " + entry.name + " | " + std::to_string(run.voxels) + "³ | " +
                              (indirectPixels ? ratioCell(vctIndirectOnly, truthIndirectOnly) + " (" + std::to_string(indirectPixels) + " px)"
                                              : std::string("– (none)")) +
                              " | " + (truthSurfaceMean > 0.0 ? format("%.1f %%", 100.0 * rmse / truthSurfaceMean) + " (" +
                                                                    format("%.1f %%", 100.0 * referenceNoise / truthSurfaceMean) + ")"
                                                              : "–") +
                              " | " +
                              ratioCell(sumLuminance(indirect), truthEnergy) + " | " + format("%.2f", run.firstFrameSeconds) + " | " +
                              format("%.2f", run.steadyFrameSeconds) + " | " + format("%.1f", referenceSeconds) + " (" +
                              std::to_string(args.spp) + " spp, " + format("%.2f", raysPerSecond * 1e-6) + " Mrays/s) |\n";
    }

    // Named regions (scenes with the Cornell room's node names).
    for (const NamedRegion& region : cornellBoxRegions(scene, hits, size, size)) {
        const std::size_t pixels = region.pixels();
        if (pixels == 0) continue;
        const double t = maskedLuminance(truthIndirect, region.mask);
        std::string row = "| " + entry.name + " | " + region.name + " | " + std::to_string(pixels) + " | " + format("%.4f", t);
        for (const VctRun& run : runs) row += " | " + ratioCell(maskedLuminance(run.images.indirect(), region.mask), t);
        report.regionRows += row + " |\n";
        // Colour bleeding onto the shadowed floor: R/G by the red wall, G/R by the green wall.
        const bool red = region.name == "shadowed floor by red wall", green = region.name == "shadowed floor by green wall";
        if (!red && !green) continue;
        const auto bleed = [&](const std::vector<float>& rgb) {
            const glm::dvec3 m = maskedMean(rgb, region.mask);
            const double num = red ? m.r : m.g, den = red ? m.g : m.r;
            return den > 0.0 ? format("%.2f", num / den) : std::string("–");
        };
        std::string bleedRow = "| " + entry.name + " | " + region.name + " | " + (red ? "R/G" : "G/R") + " | " + bleed(truth.indirectDiffuse);
        for (const VctRun& run : runs) bleedRow += " | " + bleed(run.images.indirectDiffuse);
        report.bleedingRows += bleedRow + " |\n";
    }
    if (args.coneSplit) {
        const auto rgb = [](const glm::dvec3& c) {
            char buffer[96];
            std::snprintf(buffer, sizeof buffer, "%.4f %.4f %.4f (%.4f)", c.r, c.g, c.b, luminance(c));
            return std::string(buffer);
        };
        for (const NamedRegion& region : cornellBoxRegions(scene, hits, size, size)) {
            if (region.pixels() == 0) continue;
            const std::vector<glm::dvec3> split = coneSplit(referenceScene, hits, region.mask);
            glm::dvec3 total(0.0);
            for (int i = 0; i < LIT_DIFFUSE_CONE_COUNT; ++i) {
                total += split[static_cast<std::size_t>(i)];
                report.coneRows += "| " + entry.name + " | " + region.name + " | truth cone " + std::to_string(i) + " | " +
                                   rgb(split[static_cast<std::size_t>(i)]) + " |\n";
            }
            report.coneRows += "| " + entry.name + " | " + region.name + " | truth, sum | " + rgb(total) + " |\n";
            report.coneRows += "| " + entry.name + " | " + region.name + " | reference L_ID | " +
                               rgb(maskedMean(truth.indirectDiffuse, region.mask)) + " |\n";
            for (const VctRun& run : runs)
                report.coneRows += "| " + entry.name + " | " + region.name + " | VCT " + std::to_string(run.voxels) + "³ L_ID | " +
                                   rgb(maskedMean(run.images.indirectDiffuse, region.mask)) + " |\n";
        }
    }

    if (entry.sealed) {
        const double outside = outsideRadiance(scene);
        std::string row = "| " + entry.name + " | " + format("%.3f", outside) + " | " +
                          format("%.2e", maskedLuminance(truth.final, surfaces) / outside);
        for (const VctRun& run : runs) row += " | " + format("%.2e", maskedLuminance(run.images.final, surfaces) / outside);
        report.leakRows += row + " |\n";
    }
    return report;
}

}  // namespace

int main(int argc, char** argv) {
    Args args;
    std::vector<SuiteScene> scenes;
    try {
        args = parseArgs(argc, argv);
        scenes = suite(args);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lit-gi-accuracy: %s\n", e.what());
        return 2;
    }
    try {
        Log log;
        log.setSink([](const LogMessage& m) {
            if (m.level != LogLevel::Info) std::fprintf(stderr, "%s\n", m.text.c_str());
        });
        HeadlessContext context;
        gl::requireCapabilities();
        Renderer renderer(defaultShaderRoot(), log);

        std::string voxelColumns, voxelRule;
        for (const int v : args.voxels) {
            voxelColumns += " | VCT " + std::to_string(v) + "³";
            voxelRule += "|---:";
        }
        std::string summary, regions, bleeding, leaks, cones, skipped;
        for (const SuiteScene& entry : scenes) {
            if (!fs::exists(entry.file)) {
                skipped += "- " + entry.name + ": skipped, " + entry.file.lexically_normal().string() + " is not there\n";
                std::fprintf(stderr, "%s: skipped (%s not found)\n", entry.name.c_str(), entry.file.string().c_str());
                continue;
            }
            const SceneReport r = measure(entry, args, renderer, log);
            summary += r.summaryRows;
            regions += r.regionRows;
            bleeding += r.bleedingRows;
            leaks += r.leakRows;
            cones += r.coneRows;
        }

        std::string md;
        md += "Measured by `tools/gi-accuracy.sh` (" + std::to_string(args.size) + "×" + std::to_string(args.size) +
              " pixels, reference " + std::to_string(args.spp) + " spp with " +
              (args.bounces == 1                  ? std::string("one bounce")
               : args.bounces == lit::kAllBounces ? std::string("every bounce")
                                                  : std::to_string(args.bounces) + " bounces") +
              ", " + context.description() + "):\n\n";
        md += "| scene | voxels | indirect-only VCT/ref | final RMSE, exposure-matched (reference noise) | indirect energy VCT/ref | VCT first "
              "frame s | VCT frame s | reference s |\n|---|---:|---:|---:|---:|---:|---:|---:|\n" + summary;
        if (!regions.empty())
            md += "\nIndirect radiance (L_ID + L_IS) in named regions: the reference's value (W/(sr·m²)) and VCT/reference:\n\n"
                  "| scene | region | pixels | reference" + voxelColumns + " |\n|---|---|---:|---:" + voxelRule + "|\n" + regions;
        if (!bleeding.empty())
            md += "\nColour bleeding onto the shadowed floor (indirect diffuse):\n\n| scene | region | ratio | reference" +
                  voxelColumns + " |\n|---|---|---|---:" + voxelRule + "|\n" + bleeding;
        if (!leaks.empty())
            md += "\nLight inside the sealed room: mean radiance of the inside view as a fraction of the sunlit ground's "
                  "radiance (W/(sr·m²)); any light inside is a leak:\n\n| scene | outside | reference" + voxelColumns +
                  " |\n|---|---:|---:" + voxelRule + "|\n" + leaks;
        if (!cones.empty())
            md += "\nIndirect diffuse by diffuse-cone region (--cone-split; W/(sr·m²) R G B (luminance), region means):\n\n"
                  "| scene | region | what | value |\n|---|---|---|---|\n" + cones;
        if (!skipped.empty()) md += "\n" + skipped;
        if (args.out.empty()) {
            std::fputs(md.c_str(), stdout);
        } else {
            writeFileAtomically(args.out, md);
            std::printf("wrote %s\n", args.out.string().c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lit-gi-accuracy: %s\n", e.what());
        return 1;
    }
    return 0;
}
