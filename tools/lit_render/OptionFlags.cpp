#include "OptionFlags.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "ParseText.h"

namespace lit::cli {

namespace {

// A float as the help text shows it: "0.5", not "0.500000".
std::string formatNumber(float x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(x));
    return text;
}

std::string onOff(bool on) { return on ? "on" : "off"; }

// "final, direct-diffuse, ..." — every View, in declaration order (VoxelLevels is last).
std::string viewNames() {
    std::string names;
    for (int i = 0; i <= static_cast<int>(View::VoxelLevels); ++i)
        names += (i ? ", " : "") + std::string(toString(static_cast<View>(i)));
    return names;
}

std::string got(const std::string& flag, const std::string& expectation, const std::string& value) {
    return flag + " expects " + expectation + ", got '" + value + "'";
}

// A file or folder name, which must not be empty; `what` is "a file name" or "a folder".
ParseValue pathInto(std::filesystem::path Options::*member, std::string what = "a file name") {
    return [member, what](Options& options, const std::string& flag, const std::string& value) {
        if (value.empty()) throw UsageError(got(flag, what, value));
        options.*member = value;
    };
}

// An integer in [lo, hi]; `expectation` says which ("a frame count from 1 to 100000").
template <typename Member>
ParseValue integerInto(Member Options::*member, int lo, int hi, std::string expectation) {
    return [=](Options& options, const std::string& flag, const std::string& value) {
        const auto n = parseInt(value, lo, hi);
        if (!n) throw UsageError(got(flag, expectation, value));
        options.*member = *n;
    };
}

// --set KEY=VALUE. The key and the value are tried on default settings now, so a typo is a usage
// error before anything loads; the values are applied for real in applyOptions.
void parseSetting(Options& options, const std::string& flag, const std::string& text) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw UsageError(got(flag, "KEY=VALUE (e.g. gi.voxelResolution=256)", text));
    SettingAssignment assignment{text.substr(0, eq), text.substr(eq + 1)};
    RenderSettings probe;
    try {
        setRenderSetting(probe, assignment.key, assignment.value);
    } catch (const std::exception& e) {
        std::string reason = e.what();
        if (reason.starts_with("unknown"))
            throw UsageError(flag + ": " + reason +
                             " (the keys: renderer/RenderSettings.h, docs/GI.md \"Parameters\")");
        if (const std::string prefix = "render settings: "; reason.starts_with(prefix)) reason.erase(0, prefix.size());
        throw UsageError(flag + " " + text + ": " + reason);
    }
    options.set.push_back(std::move(assignment));
}

}  // namespace

std::string_view title(FlagGroup group) {
    switch (group) {
        case FlagGroup::General:
            return "";
        case FlagGroup::Files:
            return "Files";
        case FlagGroup::Settings:
            return "Settings";
        case FlagGroup::Output:
            return "Output";
        case FlagGroup::Sky:
            return "Sky";
        case FlagGroup::Shadows:
            return "Shadows";
        case FlagGroup::Gi:
            return "GI";
        case FlagGroup::Indirect:
            return "Indirect";
        case FlagGroup::Debug:
            return "Debug views";
        case FlagGroup::Benchmarks:
            return "Benchmarks";
        case FlagGroup::Paths:
            return "Camera paths and node animations";
        case FlagGroup::Reference:
            return "Reference";
    }
    return "";
}

std::optional<std::string_view> replacementOf(std::string_view flag) {
    // Both were booleans of the GI mode before it was one field.
    if (flag == "--anisotropic" || flag == "--voxel-irradiance") return "--gi-mode fast|accurate|cached";
    return std::nullopt;
}

std::vector<Flag> flagTable() {
    const RenderSettings defaults;  // the defaults quoted below come from the struct, not from memory
    using G = FlagGroup;
    std::vector<Flag> flags;

    flags.push_back({.names = {"--help", "-h"}, .group = G::General, .help = "this text", .store = &Options::help});

    // ---- Files
    flags.push_back({.names = {"--out", "-o"},
                     .value = "FILE.png",
                     .expects = "FILE.png",
                     .group = G::Files,
                     .help = "tone-mapped sRGB image (required unless --hdr, --bench, --path or --compare)",
                     .store = pathInto(&Options::out)});
    flags.push_back({.names = {"--hdr"},
                     .value = "FILE.hdr",
                     .expects = "FILE.hdr",
                     .group = G::Files,
                     .help = "also write the linear HDR image of the chosen view (Radiance .hdr)",
                     .store = pathInto(&Options::hdr)});
    flags.push_back({.names = {"--allow-external-uris"},
                     .group = G::Files,
                     .help = "let the scene read buffers and images outside its folder (absolute paths, '..', "
                             "file:); off: such a scene is refused",
                     .store = &Options::allowExternalUris});

    // ---- Settings
    flags.push_back({.names = {"--settings"},
                     .value = "FILE.json",
                     .expects = "FILE.json",
                     .group = G::Settings,
                     .help = "RenderSettings JSON (as saved by the editor); --set and the other flags override it",
                     .store = pathInto(&Options::settings)});
    flags.push_back(
        {.names = {"--set"},
         .value = "KEY=VALUE",
         .expects = "KEY=VALUE",
         .group = G::Settings,
         .help = "set any render setting by its JSON key \"group.field\" (gi.voxelResolution=256, gi.mode=fast, "
                 "indirect.temporalAccumulation=true); the value is JSON or a bare word. Repeatable; applied in "
                 "order after --settings and before the other flags, so a flag that sets the same value wins. Older "
                 "flat keys are read with a warning. The keys, their units and ranges: renderer/RenderSettings.h "
                 "and docs/GI.md, \"Parameters\"",
         .store = parseSetting});

    // ---- Output (RenderSettings::output)
    flags.push_back(
        {.names = {"--size"},
         .value = "WxH",
         .expects = "WxH",
         .group = G::Output,
         .help = "output size in pixels, 1.." + std::to_string(kMaxImageSide) + " each (default: the settings', " +
                 std::to_string(defaults.output.width) + "x" + std::to_string(defaults.output.height) + ")",
         .store = [](Options& options, const std::string& flag, const std::string& text) {
             const std::size_t x = text.find_first_of("xX");
             const std::string_view view(text);
             const auto w = x == std::string::npos ? std::nullopt : parseInt(view.substr(0, x), 1, kMaxImageSide);
             const auto h = x == std::string::npos ? std::nullopt : parseInt(view.substr(x + 1), 1, kMaxImageSide);
             if (!w || !h) throw UsageError(got(flag, "WxH with 1.." + std::to_string(kMaxImageSide), text));
             options.width = *w;
             options.height = *h;
         }});
    flags.push_back({.names = {"--camera"},
                     .value = "NAME|INDEX",
                     .expects = "NAME or INDEX",
                     .group = G::Output,
                     .help = "scene camera by name or index (default: the scene's first camera, else a camera "
                             "framing the whole scene)",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         if (text.empty()) throw UsageError(got(flag, "a camera name or index", text));
                         options.camera = text;
                     }});
    flags.push_back(
        {.names = {"--frames"},
         .value = "N",
         .expects = "a frame count",
         .group = G::Output,
         .help = "frames rendered before the image is read (default: output.antialiasingFrames with "
                 "--antialiasing on, the more of it and indirect.temporalMaxFrames with --temporal on; else 1)",
         .store = integerInto(&Options::frames, 1, kMaxFrames, "an integer from 1 to " + std::to_string(kMaxFrames))});
    flags.push_back({.names = {"--ev"},
                     .value = "STOPS",
                     .expects = "stops",
                     .group = G::Output,
                     .help = "exposure in stops, -10..20: radiance x 2^STOPS before tone mapping (default " +
                             formatNumber(defaults.output.exposureEv) +
                             "; with --auto-exposure on, a compensation of the metered value)",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         const auto ev = parseFloat(text);
                         if (!ev || *ev < -10.0f || *ev > 20.0f)
                             throw UsageError(got(flag, "stops from -10 to 20", text));
                         options.ev = *ev;
                     }});
    flags.push_back({.names = {"--exposure"},
                     .value = "X",
                     .expects = "a number",
                     .group = G::Output,
                     .help = "the same as a linear multiplier (X = 2^STOPS)",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         const auto exposure = parseFloat(text);
                         if (!exposure || *exposure <= 0.0f) throw UsageError(got(flag, "a positive number", text));
                         options.exposure = *exposure;
                     }});
    flags.push_back({.names = {"--auto-exposure"},
                     .group = G::Output,
                     .help = "meter the image (log-luminance histogram) and expose it to middle grey (default " +
                             onOff(defaults.output.autoExposure) + ")",
                     .store = &Options::autoExposure});
    flags.push_back({.names = {"--culling"},
                     .group = G::Output,
                     .help = "frustum culling of the camera and shadow views against a BVH (default " +
                             onOff(defaults.output.frustumCulling) + ")",
                     .store = &Options::culling});
    flags.push_back({.names = {"--antialiasing"},
                     .group = G::Output,
                     .help = "temporal anti-aliasing: each frame drawn at a sub-pixel offset and blended with "
                             "the last ones (default " +
                             onOff(defaults.output.antialiasing) +
                             "); a still then renders output.antialiasingFrames (" +
                             std::to_string(defaults.output.antialiasingFrames) +
                             ") frames unless --frames says otherwise, each pixel the mean over its area",
                     .store = &Options::antialiasing});

    // ---- Sky (RenderSettings::sky)
    flags.push_back({.names = {"--sky"},
                     .value = "MODE",
                     .expects = "auto, none, uniform, gradient or hdr",
                     .group = G::Sky,
                     .help = "auto (gradient sky and a sun when the scene has no lights, else none), none, uniform, "
                             "gradient or hdr (default " +
                             std::string(toString(defaults.sky.mode)) + ")",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         const auto mode = parseSkyMode(text);
                         if (!mode) throw UsageError(got(flag, "auto, none, uniform, gradient or hdr", text));
                         options.sky = *mode;
                     }});
    flags.push_back({.names = {"--sky-hdr"},
                     .value = "FILE.hdr",
                     .expects = "FILE.hdr",
                     .group = G::Sky,
                     .help = "equirectangular Radiance .hdr environment (implies --sky hdr)",
                     .store = pathInto(&Options::skyHdr)});

    // ---- Shadows (RenderSettings::shadows)
    flags.push_back({.names = {"--no-shadows"},
                     .group = G::Shadows,
                     .help = "render without shadow maps",
                     .store = &Options::noShadows});

    // ---- GI (RenderSettings::gi, and the GI work per frame)
    flags.push_back({.names = {"--gi"},
                     .group = G::Gi,
                     .help = "voxel cone traced indirect light (default " + onOff(defaults.gi.enabled) + ")",
                     .store = &Options::gi});
    flags.push_back(
        {.names = {"--gi-mode"},
         .value = "MODE",
         .expects = "fast, accurate or cached",
         .group = G::Gi,
         .help = "fast, accurate or cached (default " + std::string(toString(defaults.gi.mode)) +
                 "): cached = the voxels gather their own irradiance once per light or geometry edit and each pixel "
                 "gathers it from the voxels around it; accurate = directional voxels and footprint-bounded cones "
                 "traced per pixel (several times the fast mode's frame); fast = the classic six cones per pixel "
                 "over isotropic voxels",
         .store = [](Options& options, const std::string& flag, const std::string& text) {
             options.giMode = parseGiMode(text);
             if (!options.giMode) throw UsageError(got(flag, "fast, accurate or cached", text));
         }});
    flags.push_back({.names = {"--voxels"},
                     .value = "N",
                     .expects = "64, 128, 256 or 512",
                     .group = G::Gi,
                     .help = "voxel volume resolution per side: 64, 128, 256 or 512 (default " +
                             std::to_string(defaults.gi.voxelResolution) + ")",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         const auto n = parseInt(text, 64, 512);
                         if (!n || (*n & (*n - 1)) != 0)
                             throw UsageError(got(flag, "a power of two from 64 to 512", text));
                         options.voxels = *n;
                     }});
    flags.push_back(
        {.names = {"--bounces"},
         .value = "N|all",
         .expects = "a bounce count or all",
         .group = G::Gi,
         .help = "light bounces of the voxel GI, 1.." + std::to_string(kMaxBounces) + " or all (default " +
                 std::string(defaults.gi.bounces == kAllBounces ? "all" : std::to_string(defaults.gi.bounces)) +
                 "; 1 = one bounce, only direct light is injected; 0 counts as 1; all = every bounce, the "
                 "voxels' light iterated until it converges). With --reference, the path tracer's indirect "
                 "bounces, 0.." +
                 std::to_string(kMaxReferenceBounces) +
                 ": 0 = direct light only, 1 = the same light paths as a one-bounce voxel GI, all = until Russian "
                 "roulette (default: the voxel GI's bounces, 0 with --gi off)",
         .store = [](Options& options, const std::string& flag, const std::string& text) {
             const auto n =
                 text == "all" ? std::optional<int>(kAllReferenceBounces) : parseInt(text, 0, kMaxReferenceBounces);
             if (!n) throw UsageError(got(flag, "0 to " + std::to_string(kMaxReferenceBounces) + " or all", text));
             options.bounces = *n;
         }});
    flags.push_back({.names = {"--voxel-rays"},
                     .value = "N",
                     .expects = "a ray count",
                     .group = G::Gi,
                     .help = "rays per voxel for the voxels' own gathered light (the cached mode's irradiance, "
                             "bounces 2..N), marched through the voxel grid (default " +
                             std::to_string(defaults.gi.voxelRays) + "; 0 = the accurate mode's cones; at most " +
                             std::to_string(kMaxVoxelRays) + ")",
                     .store = integerInto(&Options::voxelRays, 0, kMaxVoxelRays,
                                          "a ray count from 0 to " + std::to_string(kMaxVoxelRays))});
    flags.push_back({.names = {"--footprint"},
                     .value = "X",
                     .expects = "a number",
                     .group = G::Gi,
                     .help = "accurate and cached modes: largest voxel a cone leaving a surface samples, × its "
                             "height above the surface (default " +
                             formatNumber(defaults.gi.coneFootprintPerHeight) + "; 0 = unbounded)",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         const auto x = parseFloat(text);
                         if (!x || *x < 0.0f || *x > 100.0f)
                             throw UsageError(got(flag, "a number from 0 to 100", text));
                         options.footprint = *x;
                     }});
    flags.push_back({.names = {"--single-frame"},
                     .group = G::Gi,
                     .help = "the GI update in the first frame and no refinement: the single-frame steady state "
                             "benchmarks time (default: every frame finishes the GI work pending, the refinement "
                             "included, so a still shows the editor's converged light)",
                     .store = &Options::singleFrame});
    flags.push_back({.names = {"--gi-update-per-frame"},
                     .value = "N",
                     .expects = "a voxel count",
                     .group = G::Gi,
                     .help = "occupied voxels the GI update after an edit traces per frame, as the editor spreads it "
                             "(default 0 = all at once; with --frames)",
                     .store = integerInto(&Options::giUpdatePerFrame, 0, 1 << 30, "a voxel count from 0")});
    flags.push_back({.names = {"--gi-refine-per-frame"},
                     .value = "N",
                     .expects = "a voxel count",
                     .group = G::Gi,
                     .help = "voxels the refinement (the other cone sets, after the update) traces per frame "
                             "(default: all at once; 0 = none)",
                     .store = integerInto(&Options::giRefinePerFrame, 0, 1 << 30, "a voxel count from 0")});
    flags.push_back({.names = {"--gi-ms-per-frame"},
                     .value = "MS",
                     .expects = "milliseconds",
                     .group = G::Gi,
                     .help = "GPU time the spread GI work (the update's and the refinement's shares) may take a frame, "
                             "the voxel counts above being the most it traces, as the editor paces it (default 0 = "
                             "the counts alone)",
                     .store = integerInto(&Options::giMsPerFrame, 0, 60000, "milliseconds from 0 to 60000")});

    // ---- Indirect (RenderSettings::indirect)
    flags.push_back({.names = {"--indirect-scale"},
                     .value = "S",
                     .expects = "1, 2 or 4",
                     .group = G::Indirect,
                     .help = "trace indirect light for one pixel in S×S (1, 2 or 4; default " +
                             std::to_string(defaults.indirect.scale) +
                             ") and upsample edge-aware; 1 traces every pixel",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         const auto n = parseInt(text, 1, 4);
                         if (!n || *n == 3) throw UsageError(got(flag, "1, 2 or 4", text));
                         options.indirectScale = *n;
                     }});
    flags.push_back({.names = {"--temporal"},
                     .group = G::Indirect,
                     .help = "accumulate indirect light over frames (default " +
                             onOff(defaults.indirect.temporalAccumulation) +
                             "); a still then renders indirect.temporalMaxFrames (" +
                             std::to_string(defaults.indirect.temporalMaxFrames) +
                             ") frames unless --frames says otherwise, so it converges",
                     .store = &Options::temporal});
    flags.push_back({.names = {"--cone-subsets"},
                     .group = G::Indirect,
                     .help = "with --temporal on: each traced texel marches the normal cone and 2 of the 5 side "
                             "cones per frame, a different pair each frame (default " +
                             onOff(defaults.indirect.temporalConeSubsets) + ")",
                     .store = &Options::coneSubsets});

    // ---- Debug views (RenderSettings::debug)
    flags.push_back(
        {.names = {"--view"},
         .value = "VIEW",
         .expects = "a view name",
         .group = G::Debug,
         .help = "what to write (default " + std::string(toString(defaults.debug.view)) + "), one of: " + viewNames(),
         .store = [](Options& options, const std::string&, const std::string& text) {
             const auto view = parseView(text);
             if (!view) throw UsageError("unknown view '" + text + "'; views are: " + viewNames());
             options.view = *view;
         }});

    // ---- Benchmarks
    flags.push_back({.names = {"--bench"},
                     .value = "FRAMES",
                     .expects = "a frame count",
                     .group = G::Benchmarks,
                     .help = "render FRAMES frames and print per-pass GPU times and the frame rate",
                     .store = integerInto(&Options::benchFrames, 1, kMaxFrames,
                                          "a frame count from 1 to " + std::to_string(kMaxFrames))});
    flags.push_back({.names = {"--bench-gi-updates"},
                     .value = "N",
                     .expects = "a round count",
                     .group = G::Benchmarks,
                     .help = "after the frames, time N interleaved rounds of a light edit (re-inject + mipmaps) "
                             "against a re-voxelization (voxelize + inject + mipmaps), each with the bounces and the "
                             "cached mode's voxel irradiance that follow it; with --gi-update-per-frame, each update "
                             "is let finish over frames before the next is timed (its frames are printed)",
                     .store = integerInto(&Options::giUpdateRounds, 1, 1000, "a round count from 1 to 1000")});
    flags.push_back({.names = {"--bench-gi-moves"},
                     .value = "N",
                     .expects = "a round count",
                     .group = G::Benchmarks,
                     .help = "after the frames, time N interleaved rounds of moving the smallest mesh node with only "
                             "its changed boxes voxelized again against the same move with the whole volume "
                             "voxelized; each update (and its refinement) is let finish before the next",
                     .store = integerInto(&Options::giMoveRounds, 1, 1000, "a round count from 1 to 1000")});
    flags.push_back({.names = {"--json"},
                     .value = "FILE.json",
                     .expects = "FILE.json",
                     .group = G::Benchmarks,
                     .help = "with --bench or --bench-path: also write the results as JSON",
                     .store = pathInto(&Options::benchJson)});

    // ---- Camera paths
    flags.push_back({.names = {"--path"},
                     .value = "FILE|NAME",
                     .expects = "FILE.json or an animation name",
                     .group = G::Paths,
                     .help = "fly a camera path: a .json path file, or the name of a camera animation in the scene "
                             "file (see renderer/animation/CameraPathIO.h)",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         if (text.empty()) throw UsageError(got(flag, "a .json file or an animation name", text));
                         options.path = text;
                     }});
    flags.push_back(
        {.names = {"--fps"},
         .value = "N",
         .expects = "frames per second",
         .group = G::Paths,
         .help = "frames per second along the path (default " + std::to_string(static_cast<int>(kDefaultPathFps)) + ")",
         .store = [](Options& options, const std::string& flag, const std::string& text) {
             const auto fps = parseFloat(text);
             if (!fps || !(*fps > 0.0f) || *fps > kMaxPathFps)
                 throw UsageError(
                     got(flag, "frames per second above 0 and up to " + std::to_string(static_cast<int>(kMaxPathFps)),
                         text));
             options.fps = *fps;
         }});
    flags.push_back({.names = {"--time"},
                     .value = "SECONDS",
                     .expects = "seconds",
                     .group = G::Paths,
                     .help = "render the still at this time of the scene's node animations (they start at 0 s; "
                             "before or after their keys they hold the first or last pose); with --path, the still "
                             "is the path's view at this time. Without it a still shows the nodes at 0 s",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         const auto seconds = parseFloat(text);
                         if (!seconds || !std::isfinite(*seconds)) throw UsageError(got(flag, "seconds", text));
                         options.time = *seconds;
                     }});
    flags.push_back({.names = {"--frames-out"},
                     .value = "DIR",
                     .expects = "DIR",
                     .group = G::Paths,
                     .help = "write every frame of the path to DIR/frame_00000.png, ... (creates DIR); with "
                             "--reference each frame is path-traced with --spp samples",
                     .store = pathInto(&Options::framesOut, "a folder")});
    flags.push_back({.names = {"--bench-path"},
                     .group = G::Paths,
                     .help = "time every frame of the path (after one untimed warm-up frame that finishes the GI "
                             "work) and print the lowest and highest FPS and the mean frame time, and a flicker "
                             "figure: mean |frame-to-frame change| of pixels whose surface did not move",
                     .store = &Options::benchPath});

    // ---- Reference (the CPU path tracer, and comparing with its images)
    flags.push_back({.names = {"--reference"},
                     .group = G::Reference,
                     .help = "path-trace the scene on the CPU (Embree): Lit's ground truth, same scene, camera, BRDF "
                             "and light units; writes the same --out/--hdr/--view images; --bounces (under GI) sets "
                             "its bounces; with --path and --frames-out every frame of the path, node animations in "
                             "step. Ctrl+C writes the image so far (see docs/REFERENCE.md)",
                     .store = &Options::reference});
    flags.push_back(
        {.names = {"--spp"},
         .value = "N",
         .expects = "samples per pixel",
         .group = G::Reference,
         .help = "with --reference: samples per pixel (default " + std::to_string(kDefaultReferenceSpp) + ")",
         .store = integerInto(&Options::spp, 1, kMaxReferenceSpp,
                              "samples per pixel from 1 to " + std::to_string(kMaxReferenceSpp))});
    flags.push_back({.names = {"--pixel-centres"},
                     .group = G::Reference,
                     .help = "with --reference: sample each pixel at its centre, as the rasterizer does, instead of "
                             "over its area: a comparison then counts a sunlit edge only where the light differs, "
                             "not for the rasterizer's missing anti-aliasing",
                     .store = &Options::pixelCentres});
    flags.push_back({.names = {"--seed"},
                     .value = "S",
                     .expects = "an integer",
                     .group = G::Reference,
                     .help = "with --reference: random seed; the same seed gives the same image (default 0)",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         std::uint64_t seed = 0;
                         const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), seed);
                         if (text.empty() || ec != std::errc() || end != text.data() + text.size())
                             throw UsageError(got(flag, "a non-negative integer", text));
                         options.seed = seed;
                     }});
    flags.push_back({.names = {"--node-map"},
                     .value = "FILE.txt",
                     .expects = "FILE.txt",
                     .group = G::Reference,
                     .help = "with --reference: also write which scene node each pixel sees (the first hit at its "
                             "centre) and whether a light reaches it there, for per-surface comparisons "
                             "(tools/room_accuracy.py --nodes)",
                     .store = pathInto(&Options::nodeMap)});
    flags.push_back({.names = {"--compare"},
                     .value = "REF.hdr",
                     .expects = "REF.hdr",
                     .group = G::Reference,
                     .help = "compare the linear image of the chosen view with REF.hdr (same size; e.g. a "
                             "--reference render's --hdr): print both mean luminances, their ratio and the RMSE of "
                             "luminance relative to the reference's mean",
                     .store = pathInto(&Options::compare)});
    flags.push_back({.names = {"--difference"},
                     .value = "FILE.png",
                     .expects = "FILE.png",
                     .group = G::Reference,
                     .help = "with --compare: write the editor's Difference view, the signed relative error per pixel "
                             "(blue too dark, white right, red too bright)",
                     .store = pathInto(&Options::difference)});
    flags.push_back({.names = {"--max-error"},
                     .value = "X",
                     .expects = "X",
                     .group = G::Reference,
                     .help = "relative error at the Difference ramp's ends (default " + formatNumber(kDefaultMaxError) +
                             " = ±50 %)",
                     .store = [](Options& options, const std::string& flag, const std::string& text) {
                         const auto x = parseFloat(text);
                         if (!x || !(*x > 0.0f) || *x > 100.0f)
                             throw UsageError(got(flag, "a relative error above 0 and at most 100 (0.5 = 50 %)", text));
                         options.maxError = *x;
                     }});
    return flags;
}

}  // namespace lit::cli
