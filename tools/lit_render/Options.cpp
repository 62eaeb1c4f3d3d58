#include "Options.h"

#include "scene/Scene.h"

#include "reference/ViewSupport.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace lit::cli {

namespace {

// Integer in [lo, hi] spelled exactly (no sign, spaces or trailing text), else nullopt.
std::optional<int> parseInt(std::string_view text, int lo, int hi) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || value < lo || value > hi) return std::nullopt;
    return value;
}

// A finite number spelled exactly, else nullopt.
// A float as the help text shows it: "0.5", not "0.500000".
std::string formatNumber(float x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(x));
    return text;
}

std::optional<float> parseFloat(std::string_view text) {
    float value = 0.0f;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// "final, direct-diffuse, ..." — every View, in declaration order (VoxelSlice is last).
std::string viewNames() {
    std::string names;
    for (int i = 0; i <= static_cast<int>(View::VoxelSlice); ++i)
        names += (i ? ", " : "") + std::string(toString(static_cast<View>(i)));
    return names;
}

// `verb`: what the flag does with the file ("writes", "reads").
void requireExtension(const std::filesystem::path& path, const char* flag, const char* extension,
                      const char* verb = "writes") {
    if (lower(path.extension().string()) != extension)
        throw UsageError(std::string(flag) + " " + verb + " a " + extension + " file; got '" + path.string() + "'");
}

}  // namespace

Options parseOptions(const std::vector<std::string>& args) {
    Options options;
    bool haveScene = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() < 2 || arg[0] != '-') {
            if (haveScene)
                throw UsageError("unexpected argument '" + arg + "' (the scene is already '" + options.scene.string() + "')");
            if (arg.empty()) throw UsageError("the scene file name is empty");
            options.scene = arg;
            haveScene = true;
            continue;
        }

        // "--flag value" or "--flag=value".
        std::string flag = arg;
        std::optional<std::string> inlineValue;
        if (const std::size_t eq = arg.find('='); arg.starts_with("--") && eq != std::string::npos) {
            flag = arg.substr(0, eq);
            inlineValue = arg.substr(eq + 1);
        }
        // The value of a flag is the next argument, unless that is another flag: then the value
        // was forgotten, and taking "--size" as a file name would only confuse later.
        const auto value = [&](const char* expects) -> std::string {
            if (inlineValue) return *inlineValue;
            if (i + 1 >= args.size() || args[i + 1].starts_with("--"))
                throw UsageError("missing value for " + flag + " (expects " + expects + ")");
            return args[++i];
        };
        // An on|off flag's value; anything else is a usage error naming the flag.
        const auto onOff = [&]() -> bool {
            const std::string text = value("on or off");
            if (text == "on") return true;
            if (text == "off") return false;
            throw UsageError(flag + " expects on or off, got '" + text + "'");
        };
        const auto noValue = [&] {
            if (inlineValue) throw UsageError(flag + " takes no value, got '" + arg + "'");
        };

        if (flag == "--help" || flag == "-h") {
            noValue();
            Options help;
            help.help = true;
            return help;
        } else if (flag == "--out" || flag == "-o") {
            options.out = value("FILE.png");
            if (options.out.empty()) throw UsageError("--out expects a file name, got ''");
        } else if (flag == "--hdr") {
            options.hdr = value("FILE.hdr");
            if (options.hdr.empty()) throw UsageError("--hdr expects a file name, got ''");
        } else if (flag == "--compare") {
            options.compare = value("REF.hdr");
            if (options.compare.empty()) throw UsageError("--compare expects a file name, got ''");
        } else if (flag == "--difference") {
            options.difference = value("FILE.png");
            if (options.difference.empty()) throw UsageError("--difference expects a file name, got ''");
        } else if (flag == "--max-error") {
            const std::string text = value("X");
            const auto x = parseFloat(text);
            if (!x || !(*x > 0.0f) || *x > 100.0f)
                throw UsageError("--max-error expects a relative error above 0 and at most 100 (0.5 = 50 %), got '" + text + "'");
            options.maxError = *x;
        } else if (flag == "--size") {
            const std::string text = value("WxH");
            const std::size_t x = text.find_first_of("xX");
            const auto w = x == std::string::npos ? std::nullopt : parseInt(std::string_view(text).substr(0, x), 1, kMaxImageSide);
            const auto h = x == std::string::npos ? std::nullopt : parseInt(std::string_view(text).substr(x + 1), 1, kMaxImageSide);
            if (!w || !h)
                throw UsageError("--size expects WxH with 1.." + std::to_string(kMaxImageSide) + ", got '" + text + "'");
            options.width = *w;
            options.height = *h;
        } else if (flag == "--camera") {
            const std::string text = value("NAME or INDEX");
            if (text.empty()) throw UsageError("--camera expects a camera name or index, got ''");
            options.camera = text;
        } else if (flag == "--exposure") {
            const std::string text = value("a number");
            const auto exposure = parseFloat(text);
            if (!exposure || *exposure <= 0.0f) throw UsageError("--exposure expects a positive number, got '" + text + "'");
            options.exposure = *exposure;
        } else if (flag == "--ev") {
            const std::string text = value("stops");
            const auto ev = parseFloat(text);
            if (!ev || *ev < -10.0f || *ev > 20.0f) throw UsageError("--ev expects stops from -10 to 20, got '" + text + "'");
            options.ev = *ev;
        } else if (flag == "--auto-exposure") {
            options.autoExposure = onOff();
        } else if (flag == "--sky") {
            const std::string text = value("auto, none, uniform, gradient or hdr");
            const auto mode = parseSkyMode(text);
            if (!mode) throw UsageError("--sky expects auto, none, uniform, gradient or hdr, got '" + text + "'");
            options.sky = *mode;
        } else if (flag == "--sky-hdr") {
            options.skyHdr = value("FILE.hdr");
            if (options.skyHdr.empty()) throw UsageError("--sky-hdr expects a file name, got ''");
        } else if (flag == "--no-shadows") {
            noValue();
            options.noShadows = true;
        } else if (flag == "--allow-external-uris") {
            noValue();
            options.allowExternalUris = true;
        } else if (flag == "--view") {
            const std::string text = value("a view name");
            const auto view = parseView(text);
            if (!view) throw UsageError("unknown view '" + text + "'; views are: " + viewNames());
            options.view = *view;
        } else if (flag == "--gi") {
            options.gi = onOff();
        } else if (flag == "--culling") {
            options.culling = onOff();
        } else if (flag == "--indirect-scale") {
            const std::string text = value("1, 2 or 4");
            const auto n = parseInt(text, 1, 4);
            if (!n || *n == 3) throw UsageError("--indirect-scale expects 1, 2 or 4, got '" + text + "'");
            options.indirectScale = *n;
        } else if (flag == "--temporal") {
            options.temporal = onOff();
        } else if (flag == "--cone-subsets") {
            options.coneSubsets = onOff();
        } else if (flag == "--voxels") {
            const std::string text = value("64, 128, 256 or 512");
            const auto n = parseInt(text, 64, 512);
            if (!n || (*n & (*n - 1)) != 0)
                throw UsageError("--voxels expects a power of two from 64 to 512, got '" + text + "'");
            options.voxels = *n;
        } else if (flag == "--gi-mode") {
            const std::string text = value("fast, accurate or cached");
            options.giMode = parseGiMode(text);
            if (!options.giMode) throw UsageError("--gi-mode expects fast, accurate or cached, got '" + text + "'");
        } else if (flag == "--anisotropic" || flag == "--voxel-irradiance") {
            throw UsageError(flag + " was replaced by --gi-mode fast|accurate|cached");
        } else if (flag == "--gi-update-per-frame") {
            const std::string text = value("a voxel count");
            const auto n = parseInt(text, 0, 1 << 30);
            if (!n) throw UsageError("--gi-update-per-frame expects a voxel count from 0, got '" + text + "'");
            options.giUpdatePerFrame = *n;
        } else if (flag == "--voxel-rays") {
            const std::string text = value("a ray count");
            const auto n = parseInt(text, 0, kMaxVoxelRays);
            if (!n)
                throw UsageError("--voxel-rays expects a ray count from 0 to " + std::to_string(kMaxVoxelRays) + ", got '" +
                                 text + "'");
            options.voxelRays = *n;
        } else if (flag == "--gi-refine-per-frame") {
            const std::string text = value("a voxel count");
            const auto n = parseInt(text, 0, 1 << 30);
            if (!n) throw UsageError("--gi-refine-per-frame expects a voxel count from 0, got '" + text + "'");
            options.giRefinePerFrame = *n;
        } else if (flag == "--single-frame") {
            noValue();
            options.singleFrame = true;
        } else if (flag == "--footprint") {
            const std::string text = value("a number");
            const auto x = parseFloat(text);
            if (!x || *x < 0.0f || *x > 100.0f) throw UsageError("--footprint expects a number from 0 to 100, got '" + text + "'");
            options.footprint = *x;
        } else if (flag == "--frames") {
            const std::string text = value("a frame count");
            const auto n = parseInt(text, 1, kMaxFrames);
            if (!n) throw UsageError("--frames expects an integer from 1 to " + std::to_string(kMaxFrames) + ", got '" + text + "'");
            options.frames = *n;
        } else if (flag == "--bench") {
            const std::string text = value("a frame count");
            const auto n = parseInt(text, 1, kMaxFrames);
            if (!n) throw UsageError("--bench expects a frame count from 1 to " + std::to_string(kMaxFrames) + ", got '" + text + "'");
            options.benchFrames = *n;
        } else if (flag == "--json") {
            options.benchJson = value("FILE.json");
            if (options.benchJson.empty()) throw UsageError("--json expects a file name, got ''");
        } else if (flag == "--settings") {
            options.settings = value("FILE.json");
            if (options.settings.empty()) throw UsageError("--settings expects a file name, got ''");
        } else if (flag == "--path") {
            const std::string text = value("FILE.json or an animation name");
            if (text.empty()) throw UsageError("--path expects a .json file or an animation name, got ''");
            options.path = text;
        } else if (flag == "--fps") {
            const std::string text = value("frames per second");
            const auto fps = parseFloat(text);
            if (!fps || !(*fps > 0.0f) || *fps > kMaxPathFps)
                throw UsageError("--fps expects frames per second above 0 and up to " +
                                 std::to_string(static_cast<int>(kMaxPathFps)) + ", got '" + text + "'");
            options.fps = *fps;
        } else if (flag == "--frames-out") {
            options.framesOut = value("DIR");
            if (options.framesOut.empty()) throw UsageError("--frames-out expects a folder, got ''");
        } else if (flag == "--bench-gi-updates") {
            const std::string text = value("a round count");
            const auto n = parseInt(text, 1, 1000);
            if (!n) throw UsageError("--bench-gi-updates expects a round count from 1 to 1000, got '" + text + "'");
            options.giUpdateRounds = *n;
        } else if (flag == "--bench-path") {
            noValue();
            options.benchPath = true;
        } else if (flag == "--reference") {
            noValue();
            options.reference = true;
        } else if (flag == "--spp") {
            const std::string text = value("samples per pixel");
            const auto n = parseInt(text, 1, kMaxReferenceSpp);
            if (!n) throw UsageError("--spp expects samples per pixel from 1 to " + std::to_string(kMaxReferenceSpp) + ", got '" + text + "'");
            options.spp = *n;
        } else if (flag == "--bounces") {
            const std::string text = value("a bounce count or all");
            const auto n = text == "all" ? std::optional<int>(kAllReferenceBounces) : parseInt(text, 0, kMaxReferenceBounces);
            if (!n) throw UsageError("--bounces expects 0 to " + std::to_string(kMaxReferenceBounces) + " or all, got '" + text + "'");
            options.bounces = *n;
        } else if (flag == "--seed") {
            const std::string text = value("an integer");
            std::uint64_t seed = 0;
            const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), seed);
            if (text.empty() || ec != std::errc() || end != text.data() + text.size())
                throw UsageError("--seed expects a non-negative integer, got '" + text + "'");
            options.seed = seed;
        } else {
            throw UsageError("unknown option '" + flag + "'");
        }
    }

    if (!haveScene) throw UsageError("no scene given (lit-render SCENE.gltf --out image.png)");
    if (options.ev && options.exposure) throw UsageError("--ev and --exposure both set the exposure; give one of them");
    if (!options.skyHdr.empty() && options.sky && *options.sky != SkyMode::Hdr)
        throw UsageError("--sky-hdr needs --sky hdr (or no --sky)");
    if (options.path) {
        // A path renders many frames: its outputs and its camera are its own.
        if (!options.out.empty()) throw UsageError("--out writes one image; with --path use --frames-out DIR");
        if (!options.hdr.empty()) throw UsageError("--hdr writes one image; with --path use --frames-out DIR");
        if (!options.compare.empty()) throw UsageError("--compare compares one image; it does not apply to --path");
        if (options.camera) throw UsageError("--path and --camera both choose the camera; give one of them");
        if (options.frames) throw UsageError("--frames does not apply to --path (each frame of the path is rendered once)");
        if (options.benchFrames > 0) throw UsageError("--bench renders a still view; use --bench-path to time the path");
        if (options.framesOut.empty() && !options.benchPath) throw UsageError("--path needs --frames-out DIR or --bench-path");
    } else {
        if (!options.framesOut.empty()) throw UsageError("--frames-out needs --path");
        if (options.benchPath) throw UsageError("--bench-path needs --path");
        if (options.fps) throw UsageError("--fps needs --path");
    }
    if (options.reference) {
        if (options.path) throw UsageError("--reference renders a still image; it does not fly --path");
        if (options.benchFrames > 0) throw UsageError("--reference and --bench do not go together (the reference prints its own rays/s)");
        if (options.frames) throw UsageError("--frames does not apply to --reference (use --spp)");
        if (options.view && !reference::referenceRendersView(*options.view))
            throw UsageError("--reference renders the views final, direct-diffuse, indirect-diffuse, direct-specular and "
                             "indirect-specular, not '" + std::string(toString(*options.view)) + "'");
    } else {
        if (options.spp) throw UsageError("--spp needs --reference");
        if (options.seed) throw UsageError("--seed needs --reference");
    }
    if (options.benchFrames == 0 && !options.path && options.out.empty() && options.hdr.empty() &&
        options.compare.empty())
        throw UsageError("--out is required (unless --hdr, --bench, --path or --compare)");
    if (!options.out.empty()) requireExtension(options.out, "--out", ".png");
    if (!options.hdr.empty()) requireExtension(options.hdr, "--hdr", ".hdr");
    if (!options.compare.empty()) requireExtension(options.compare, "--compare", ".hdr", "reads");
    if (!options.difference.empty()) {
        if (options.compare.empty()) throw UsageError("--difference needs --compare REF.hdr (the image to compare against)");
        requireExtension(options.difference, "--difference", ".png");
    }
    if (options.maxError && options.difference.empty()) throw UsageError("--max-error needs --difference FILE.png");
    if (!options.benchJson.empty() && options.benchFrames == 0 && !options.benchPath)
        throw UsageError("--json needs --bench or --bench-path");
    if (options.frames && options.benchFrames > 0)
        throw UsageError("--frames and --bench both set the number of frames; give one of them");
    if (options.singleFrame && (options.giUpdatePerFrame || options.giRefinePerFrame))
        throw UsageError(
            "--single-frame sets the GI work per frame; give it or --gi-update-per-frame / --gi-refine-per-frame");
    if (options.giUpdateRounds > 0 && options.benchFrames == 0)
        throw UsageError("--bench-gi-updates needs --bench (the steady frames come first)");
    return options;
}

bool Options::pathIsFile() const { return path && lower(std::filesystem::path(*path).extension().string()) == ".json"; }

RenderSettings applyOptions(const Options& options, RenderSettings base) {
    if (options.width) base.output.width = *options.width;
    if (options.height) base.output.height = *options.height;
    if (options.exposure) base.output.exposureEv = std::log2(*options.exposure);
    if (options.ev) base.output.exposureEv = *options.ev;
    if (options.autoExposure) base.output.autoExposure = *options.autoExposure;
    if (options.sky) base.sky.mode = *options.sky;
    if (!options.skyHdr.empty()) {
        base.sky.mode = SkyMode::Hdr;
        base.sky.hdrPath = options.skyHdr.string();
    }
    if (options.noShadows) base.shadows.enabled = false;
    if (options.view) base.debug.view = *options.view;
    if (options.gi) base.gi.enabled = *options.gi;
    if (options.voxels) base.gi.voxelResolution = *options.voxels;
    // --bounces also sets the voxel GI's bounces (at least 1, "all" = the most it does).
    if (options.bounces)
        base.gi.bounces =
            *options.bounces == kAllReferenceBounces ? kMaxBounces : std::clamp(*options.bounces, 1, kMaxBounces);
    if (options.giMode) base.gi.mode = *options.giMode;
    if (options.voxelRays) base.gi.voxelRays = *options.voxelRays;
    if (options.footprint) base.gi.coneFootprintPerHeight = *options.footprint;
    if (options.culling) base.output.frustumCulling = *options.culling;
    if (options.indirectScale) base.indirect.scale = *options.indirectScale;
    if (options.temporal) base.indirect.temporalAccumulation = *options.temporal;
    if (options.coneSubsets) base.indirect.temporalConeSubsets = *options.coneSubsets;
    return base;
}

GiBudget giBudgetFor(const Options& options) {
    GiBudget budget = options.singleFrame ? GiBudget::updateOnly() : GiBudget::converge();
    if (options.giUpdatePerFrame && *options.giUpdatePerFrame > 0)
        budget.updateVoxels = static_cast<std::uint32_t>(*options.giUpdatePerFrame);
    if (options.giRefinePerFrame) budget.refineVoxels = static_cast<std::uint32_t>(*options.giRefinePerFrame);
    return budget;
}

int resolveCamera(const Options& options, const Scene& scene) {
    if (!options.camera) return scene.cameras.empty() ? -1 : 0;
    const std::string& wanted = *options.camera;
    int index = -1;
    if (std::all_of(wanted.begin(), wanted.end(), [](unsigned char c) { return std::isdigit(c); })) {
        const auto n = parseInt(wanted, 0, std::max(0, static_cast<int>(scene.cameras.size()) - 1));
        if (n && !scene.cameras.empty()) index = *n;
    } else {
        index = scene.findCamera(wanted);
    }
    if (index >= 0) return index;

    std::string message = "unknown camera '" + wanted + "'; ";
    if (scene.cameras.empty()) throw UsageError(message + "the scene has no cameras");
    message += "the scene's cameras are:";
    for (std::size_t i = 0; i < scene.cameras.size(); ++i)
        message += (i ? ", " : " ") + std::to_string(i) + " '" + scene.cameras[i].name + "'";
    throw UsageError(message);
}

std::string shortUsage() {
    return "usage: lit-render SCENE.gltf --out image.png [--hdr image.hdr] [--size WxH] [--camera NAME|INDEX]\n"
           "                  [--ev STOPS|--exposure X] [--auto-exposure on|off] [--sky MODE] [--sky-hdr FILE.hdr]\n"
           "                  [--no-shadows] [--view VIEW] [--gi on|off] [--voxels N] [--frames N]\n"
           "                  [--bounces N] [--gi-mode fast|accurate|cached] [--footprint X] [--single-frame]\n"
           "                  [--culling on|off] [--indirect-scale 1|2|4] [--temporal on|off]\n"
           "                  [--cone-subsets on|off]\n"
           "                  [--bench FRAMES [--json FILE]] [--settings FILE.json] [--help]\n"
           "                  [--compare REF.hdr [--difference FILE.png [--max-error X]]]\n"
           "       lit-render SCENE.gltf --path FILE.json|ANIMATION [--fps N] [--frames-out DIR] [--bench-path]\n"
           "       lit-render SCENE.gltf --reference --out image.png [--spp N] [--bounces N|all] [--seed S] [...]\n";
}

std::string usageText() {
    const RenderSettings defaults;  // the defaults quoted below come from the struct, not from memory
    const std::string size = std::to_string(defaults.output.width) + "x" + std::to_string(defaults.output.height);
    return shortUsage() +
           "\n"
           "Renders a glTF scene headless (EGL, no window) with voxel cone traced global illumination.\n"
           "\n"
           "  --out FILE.png       tone-mapped sRGB image (required unless --hdr, --bench, --path or --compare)\n"
           "  --hdr FILE.hdr       also write the linear HDR image of the chosen view (Radiance .hdr)\n"
           "  --compare REF.hdr    compare the linear image of the chosen view with REF.hdr (same size; e.g. a\n"
           "                       --reference render's --hdr): print both mean luminances, their ratio and\n"
           "                       the RMSE of luminance relative to the reference's mean\n"
           "  --difference FILE.png  with --compare: write the editor's Difference view, the signed relative\n"
           "                       error per pixel (blue too dark, white right, red too bright)\n"
           "  --max-error X        relative error at the Difference ramp's ends (default " +
           formatNumber(kDefaultMaxError) +
           " = ±50 %)\n"
           "  --size WxH           output size in pixels, 1.." +
           std::to_string(kMaxImageSide) + " each (default: the settings', " + size +
           ")\n"
           "  --camera NAME|INDEX  scene camera by name or index (default: the scene's first camera, else a\n"
           "                       camera framing the whole scene)\n"
           "  --ev STOPS           exposure in stops, -10..20: radiance x 2^STOPS before tone mapping (default 0;\n"
           "                       with --auto-exposure on, a compensation of the metered value)\n"
           "  --exposure X         the same as a linear multiplier (X = 2^STOPS)\n"
           "  --auto-exposure on|off  meter the image (log-luminance histogram) and expose it to middle grey\n"
           "  --sky MODE           auto (gradient sky and a sun when the scene has no lights, else none), none,\n"
           "                       uniform, gradient or hdr (default auto)\n"
           "  --sky-hdr FILE.hdr   equirectangular Radiance .hdr environment (implies --sky hdr)\n"
           "  --no-shadows         render without shadow maps\n"
           "  --allow-external-uris  let the scene read buffers and images outside its folder\n"
           "                       (absolute paths, '..', file:); off: such a scene is refused\n"
           "  --view VIEW          what to write (default final), one of:\n"
           "                       " +
           viewNames() +
           "\n"
           "  --gi on|off          voxel cone traced indirect light (default on)\n"
           "  --voxels N           voxel volume resolution per side: 64, 128, 256 or 512 (default " +
           std::to_string(defaults.gi.voxelResolution) +
           ")\n"
           "  --bounces N|all      light bounces of the voxel GI, 1.." +
           std::to_string(kMaxBounces) + " (default " + std::to_string(defaults.gi.bounces) +
           "; 1 = one bounce, only direct light is injected; all = " + std::to_string(kMaxBounces) +
           "); with --reference see below\n"
           "  --gi-mode MODE       fast, accurate or cached (default " +
           std::string(toString(defaults.gi.mode)) +
           "):\n"
           "                       cached = the voxels gather their own irradiance once per light or geometry\n"
           "                       edit and each pixel gathers it from the voxels around it; accurate = directional\n"
           "                       voxels and footprint-bounded cones traced per pixel (several times the fast\n"
           "                       mode's frame); fast = the classic six cones per pixel over isotropic voxels\n"
           "  --single-frame       the GI update in the first frame and no refinement: the single-frame steady\n"
           "                       state benchmarks time (default: every frame finishes the GI work pending, the\n"
           "                       refinement included, so a still shows the editor's converged light)\n"
           "  --gi-update-per-frame N  occupied voxels the GI update after an edit traces per frame, as the\n"
           "                       editor spreads it (default 0 = all at once; with --frames)\n"
           "  --gi-refine-per-frame N  voxels the refinement (the other cone sets, after the update) traces\n"
           "                       per frame (default: all at once; 0 = none)\n"
           "  --voxel-rays N       rays per voxel for the voxels' own gathered light (the cached mode's\n"
           "                       irradiance, bounces 2..N), marched through the voxel grid (default " +
           std::to_string(defaults.gi.voxelRays) +
           ";\n"
           "                       0 = the accurate mode's cones; at most " +
           std::to_string(kMaxVoxelRays) +
           ")\n"
           "  --footprint X        accurate and cached modes: largest voxel a cone leaving a surface samples,\n"
           "                       × its height above the surface (default " +
           formatNumber(defaults.gi.coneFootprintPerHeight) +
           "; 0 = unbounded)\n"
           "  --frames N           frames rendered before the image is read (default 1)\n"
           "  --culling on|off     frustum culling of the camera and shadow views against a BVH (default " +
           std::string(defaults.output.frustumCulling ? "on" : "off") +
           ")\n"
           "  --indirect-scale S   trace indirect light for one pixel in S×S (1, 2 or 4; default " +
           std::to_string(defaults.indirect.scale) +
           ") and upsample\n"
           "                       edge-aware; 1 traces every pixel\n"
           "  --temporal on|off    accumulate indirect light over frames (default " +
           std::string(defaults.indirect.temporalAccumulation ? "on" : "off") +
           "); a still then renders\n"
           "                       temporalMaxFrames (" +
           std::to_string(defaults.indirect.temporalMaxFrames) +
           ") frames unless --frames says otherwise, so it converges\n"
           "  --cone-subsets on|off with --temporal on: each traced texel marches the normal cone and 2 of\n"
           "                       the 5 side cones per frame, a different pair each frame (default " +
           std::string(defaults.indirect.temporalConeSubsets ? "on" : "off") +
           ")\n"
           "  --bench FRAMES       render FRAMES frames and print per-pass GPU times and the frame rate\n"
           "  --bench-gi-updates N after the frames, time N interleaved rounds of a light edit (re-inject +\n"
           "                       mipmaps) against a re-voxelization (voxelize + inject + mipmaps), each\n"
           "                       with the bounces and the cached mode's voxel irradiance that follow it;\n"
           "                       with --gi-update-per-frame, each update is let finish over\n"
           "                       frames before the next is timed (its frames are printed)\n"
           "  --json FILE          with --bench or --bench-path: also write the results as JSON\n"
           "  --settings FILE      RenderSettings JSON (as saved by the editor); flags override it\n"
           "  --path FILE|NAME     fly a camera path: a .json path file, or the name of a camera animation\n"
           "                       in the scene file (see renderer/animation/CameraPathIO.h)\n"
           "  --fps N              frames per second along the path (default " +
           std::to_string(static_cast<int>(kDefaultPathFps)) +
           ")\n"
           "  --frames-out DIR     write every frame of the path to DIR/frame_00000.png, ... (creates DIR)\n"
           "  --bench-path         time every frame of the path (after one untimed warm-up frame) and\n"
           "                       print the lowest and highest FPS and the mean frame time, and a flicker\n"
           "                       figure: mean |frame-to-frame change| of pixels whose surface did not move\n"
           "  --reference          path-trace the scene on the CPU (Embree): Lit's ground truth, same scene,\n"
           "                       camera, BRDF and light units; writes the same --out/--hdr/--view images.\n"
           "                       Ctrl+C writes the image so far (see docs/REFERENCE.md)\n"
           "  --spp N              with --reference: samples per pixel (default " +
           std::to_string(kDefaultReferenceSpp) +
           ")\n"
           "  --bounces N|all      with --reference: indirect bounces, 0 = direct light only, 1 = the same\n"
           "                       light paths as Lit's one-bounce VCT (default), all = until Russian roulette\n"
           "  --seed S             with --reference: random seed; the same seed gives the same image (default 0)\n"
           "  --help               this text\n"
           "\n"
           "Exit status: 0 success, 1 runtime failure (scene, GL, file), 2 bad command line,\n"
           "130 a --reference render stopped by Ctrl+C (the image so far was written).\n";
}

}  // namespace lit::cli
