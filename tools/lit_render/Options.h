#pragma once
// lit-render's command line: parsed by a pure function so every accepted and rejected form is a
// unit test (tests/unit/test_options.cpp), then applied to RenderSettings in one place. The flags
// themselves, with their help, are one table (OptionFlags.h).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "RenderSettings.h"
#include "gi/GiBudget.h"

namespace lit {
struct Scene;
}

namespace lit::cli {

// A command line that cannot be run; the message says what is wrong with which argument.
// lit-render prints it with a short usage and exits with status 2.
class UsageError : public std::runtime_error {
public:
    explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

inline constexpr int kMaxImageSide = 16384;  // pixels; GL_MAX_TEXTURE_SIZE on llvmpipe and most GPUs
inline constexpr int kMaxFrames = 100000;    // a guard against typos, not a GPU limit
inline constexpr double kDefaultPathFps = 30.0;  // frames per second of --path renders
inline constexpr double kMaxPathFps = 1000.0;    // a guard against typos
inline constexpr int kDefaultReferenceSpp = 64;   // samples per pixel of --reference renders
inline constexpr int kMaxReferenceSpp = 1 << 20;  // a guard against typos
inline constexpr int kMaxReferenceBounces = 64;   // --bounces N; "all" is unbounded (Russian roulette)
inline constexpr int kAllReferenceBounces = -1;   // --bounces all
inline constexpr float kDefaultMaxError = 0.5f;   // --max-error: ±50 % at the Difference ramp's ends (the editor's default)

// --set KEY=VALUE: one render setting by its "group.field" JSON key, as typed.
struct SettingAssignment {
    std::string key, value;
    bool operator==(const SettingAssignment&) const = default;
};

struct Options {
    bool help = false;                 // --help: print usage, ignore the rest
    std::filesystem::path scene;       // SCENE.gltf or .glb
    std::filesystem::path out;         // PNG (tone-mapped, sRGB); may be empty with --bench
    std::filesystem::path hdr;         // optional Radiance .hdr of the linear image
    std::filesystem::path compare;     // --compare REF.hdr: print the image's figures against a reference
    std::filesystem::path difference;  // --difference FILE.png: the Difference view's false colour (needs --compare)
    std::optional<float> maxError;     // --max-error X: relative error at the ramp's ends (default kDefaultMaxError)
    std::optional<int> width, height;  // pixels; unset = the settings' size
    std::optional<std::string> camera; // camera name or index as typed; unset = the scene's first
    std::optional<float> exposure;     // --exposure: linear multiplier (stored as log2 stops)
    std::optional<float> ev;           // --ev: exposure in stops (2^ev), −10..+20
    std::optional<bool> autoExposure;  // --auto-exposure on|off
    std::optional<SkyMode> sky;        // --sky auto|none|uniform|gradient|hdr
    std::filesystem::path skyHdr;      // --sky-hdr FILE.hdr (implies --sky hdr)
    bool noShadows = false;
    bool allowExternalUris = false;    // --allow-external-uris: buffers/images outside the scene's folder
    std::optional<View> view;
    std::optional<bool> gi;
    std::optional<int> voxels;         // voxels per side
    std::optional<GiMode> giMode;      // --gi-mode fast|accurate|cached (GiSettings::mode)
    std::optional<int> voxelRays;      // --voxel-rays N (GiSettings::voxelRays)
    std::optional<float> footprint;    // --footprint X: GiSettings::coneFootprintPerHeight (0 = off)
    // The GI work per frame (GiBudget). Unset: each frame finishes what is pending, the refinement
    // included, so a still shows the converged light the editor shows after refinement.
    std::optional<int> giUpdatePerFrame;  // --gi-update-per-frame N: the update's voxels per frame (0 = all)
    std::optional<int> giRefinePerFrame;  // --gi-refine-per-frame N: the refinement's voxels per frame (0 = none)
    std::optional<int> giMsPerFrame;      // --gi-ms-per-frame MS: GPU time the spread GI work may take a frame
    bool singleFrame = false;             // --single-frame: the update in the first frame, no refinement
    std::optional<bool> culling;       // --culling on|off: frustum culling of the G-buffer and shadow views
    std::optional<bool> antialiasing;  // --antialiasing on|off: temporal anti-aliasing
    std::optional<int> indirectScale;  // --indirect-scale 1|2|4
    std::optional<bool> temporal;      // --temporal on|off
    std::optional<bool> coneSubsets;   // --cone-subsets on|off
    std::optional<int> frames;         // frames rendered before the image is read (GI settles)
    int benchFrames = 0;               // 0 = no benchmark
    std::filesystem::path benchJson;   // --json: benchmark results as JSON
    std::filesystem::path settings;    // --settings: RenderSettings JSON applied before the flags
    std::vector<SettingAssignment> set;  // --set KEY=VALUE, in the order given: after --settings, before the flags
    // Camera paths: --path FILE.json (a path file) or NAME (a camera animation in the scene file).
    std::optional<std::string> path;
    std::optional<double> fps;         // --fps: frames per second along the path
    std::filesystem::path framesOut;   // --frames-out DIR: every frame as DIR/frame_00000.png, ...
    bool benchPath = false;            // --bench-path: per-frame times along the path (and a flicker figure)
    // --time SECONDS: a still at that time of the scene's node animations (and, with --path, of the
    // camera path, which is then the still's camera). Without it a still shows the nodes at 0 s.
    std::optional<double> time;
    int giUpdateRounds = 0;            // --bench-gi-updates N: light edit vs re-voxelize, N interleaved rounds
    int giMoveRounds = 0;              // --bench-gi-moves N: a move's changed boxes vs the whole volume, N rounds
    // --reference: path-trace the scene on the CPU (renderer/reference/) instead of rasterizing.
    bool reference = false;
    std::optional<int> spp;            // --spp: samples per pixel (reference only)
    bool pixelCentres = false;         // --pixel-centres: the reference samples each pixel's centre (reference only)
    std::optional<int> bounces;        // --bounces N|all: indirect bounces of the reference and the voxel GI (all = -1)
    std::optional<std::uint64_t> seed; // --seed: random seed (reference only)
    std::filesystem::path nodeMap;     // --node-map: the node each pixel sees (reference only)

    int referenceSpp() const { return spp.value_or(kDefaultReferenceSpp); }

    double pathFps() const { return fps.value_or(kDefaultPathFps); }
    // --path names a JSON file when it ends in .json (any case), else an animation in the scene.
    bool pathIsFile() const;
    // --path with --time: one still through the path at that time, not a fly-through.
    bool pathStill() const { return path && time; }

    int frameCount() const { return benchFrames > 0 ? benchFrames : frames.value_or(1); }
};

// Parses the arguments after the program name. Throws UsageError for unknown flags, missing or
// malformed values, a missing scene, a missing --out (required unless --bench or --path), or
// flags that do not go together (--frames-out without --path, --path with --out, ...).
Options parseOptions(const std::vector<std::string>& args);

// `base` (defaults or a --settings file) with --set and then the other flags that were given
// applied on top. The deprecation messages of older keys given to --set go to `warnings`.
RenderSettings applyOptions(const Options& options, RenderSettings base, std::vector<std::string>* warnings = nullptr);
// The GI work each frame may do: converge (everything pending, the refinement included) unless
// --single-frame or the per-frame flags say otherwise.
GiBudget giBudgetFor(const Options& options);

// The scene camera the options choose: an integer is an index into scene.cameras, anything else
// a camera or node name. Returns -1 (the framing camera) when the scene has no camera and none
// was asked for. Throws UsageError listing the scene's cameras when the choice matches none.
int resolveCamera(const Options& options, const Scene& scene);

// The usage text printed by --help, generated from the flag table (the short form follows usage
// errors).
std::string usageText();
std::string shortUsage();

}  // namespace lit::cli
