#include "Options.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "OptionFlags.h"
#include "ParseText.h"
#include "reference/ViewSupport.h"
#include "scene/Scene.h"

namespace lit::cli {

namespace {

// `verb`: what the flag does with the file ("writes", "reads").
void requireExtension(const std::filesystem::path& path, const char* flag, const char* extension,
                      const char* verb = "writes") {
    if (lower(path.extension().string()) != extension)
        throw UsageError(std::string(flag) + " " + verb + " a " + extension + " file; got '" + path.string() + "'");
}

const Flag* findFlag(const std::vector<Flag>& flags, const std::string& name) {
    for (const Flag& flag : flags)
        if (std::find(flag.names.begin(), flag.names.end(), name) != flag.names.end()) return &flag;
    return nullptr;
}

// `text` wrapped into lines of at most `width` columns, every line after the first indented by
// `indent` spaces; `column` is where the first line starts. Words longer than a line stay whole.
std::string wrap(const std::string& text, std::size_t column, std::size_t indent, std::size_t width) {
    std::string out;
    bool lineEmpty = true;
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t end = std::min(text.find(' ', i), text.size());
        const std::string_view word(text.data() + i, end - i);
        i = end + 1;
        if (word.empty()) continue;
        if (!lineEmpty && column + 1 + word.size() > width) {
            out += "\n" + std::string(indent, ' ');
            column = indent;
            lineEmpty = true;
        }
        if (!lineEmpty) {
            out += ' ';
            ++column;
        }
        out += word;
        column += word.size();
        lineEmpty = false;
    }
    return out;
}

}  // namespace

Options parseOptions(const std::vector<std::string>& args) {
    const std::vector<Flag> flags = flagTable();
    Options options;
    bool haveScene = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() < 2 || arg[0] != '-') {
            if (haveScene)
                throw UsageError("unexpected argument '" + arg + "' (the scene is already '" + options.scene.string() +
                                 "')");
            if (arg.empty()) throw UsageError("the scene file name is empty");
            options.scene = arg;
            haveScene = true;
            continue;
        }

        // "--flag value" or "--flag=value".
        std::string name = arg;
        std::optional<std::string> inlineValue;
        if (const std::size_t eq = arg.find('='); arg.starts_with("--") && eq != std::string::npos) {
            name = arg.substr(0, eq);
            inlineValue = arg.substr(eq + 1);
        }
        if (const auto replacement = replacementOf(name))
            throw UsageError(name + " was replaced by " + std::string(*replacement));
        const Flag* flag = findFlag(flags, name);
        if (!flag) throw UsageError("unknown option '" + name + "'");
        if (!flag->takesValue()) {
            if (inlineValue) throw UsageError(name + " takes no value, got '" + arg + "'");
            options.*std::get<Switch>(flag->store) = true;
            if (options.help) {  // --help: print usage, ignore the rest
                Options help;
                help.help = true;
                return help;
            }
            continue;
        }
        // The value of a flag is the next argument, unless that is another flag: then the value
        // was forgotten, and taking "--size" as a file name would only confuse later.
        if (!inlineValue && (i + 1 >= args.size() || args[i + 1].starts_with("--")))
            throw UsageError("missing value for " + name + " (expects " + flag->expected() + ")");
        const std::string value = inlineValue ? *inlineValue : args[++i];
        if (const OnOff* member = std::get_if<OnOff>(&flag->store)) {
            if (value != "on" && value != "off") throw UsageError(name + " expects on or off, got '" + value + "'");
            options.*(*member) = value == "on";
        } else {
            // Messages name the flag by its first name, whatever alias was typed.
            std::get<ParseValue>(flag->store)(options, flag->names.front(), value);
        }
    }

    if (!haveScene) throw UsageError("no scene given (lit-render SCENE.gltf --out image.png)");
    if (options.ev && options.exposure) throw UsageError("--ev and --exposure both set the exposure; give one of them");
    if (!options.skyHdr.empty() && options.sky && *options.sky != SkyMode::Hdr)
        throw UsageError("--sky-hdr needs --sky hdr (or no --sky)");
    if (options.pathStill()) {
        // One still through the path: the path is the camera, the outputs are a still's.
        if (options.camera) throw UsageError("--path and --camera both choose the camera; give one of them");
        if (!options.framesOut.empty() || options.benchPath || options.fps)
            throw UsageError("--time with --path renders one still (--out); --frames-out, --bench-path and --fps fly "
                             "the whole path (leave out --time)");
    } else if (options.path) {
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
        if (options.benchPath)
            throw UsageError("--reference and --bench-path do not go together (the reference is not timed per frame)");
        if (options.benchFrames > 0) throw UsageError("--reference and --bench do not go together (the reference prints its own rays/s)");
        if (options.frames) throw UsageError("--frames does not apply to --reference (use --spp)");
        if (options.view && !reference::referenceRendersView(*options.view))
            throw UsageError("--reference renders the views final, direct-diffuse, indirect-diffuse, direct-specular and "
                             "indirect-specular, not '" + std::string(toString(*options.view)) + "'");
    } else {
        if (options.spp) throw UsageError("--spp needs --reference");
        if (options.seed) throw UsageError("--seed needs --reference");
        if (!options.nodeMap.empty()) throw UsageError("--node-map needs --reference");
        if (options.pixelCentres) throw UsageError("--pixel-centres needs --reference");
    }
    if (options.benchFrames == 0 && (!options.path || options.time) && options.out.empty() && options.hdr.empty() &&
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
    if (options.singleFrame && (options.giUpdatePerFrame || options.giRefinePerFrame || options.giMsPerFrame))
        throw UsageError(
            "--single-frame sets the GI work per frame; give it or --gi-update-per-frame / --gi-refine-per-frame / "
            "--gi-ms-per-frame");
    if (options.giUpdateRounds > 0 && options.benchFrames == 0)
        throw UsageError("--bench-gi-updates needs --bench (the steady frames come first)");
    if (options.giMoveRounds > 0 && options.benchFrames == 0)
        throw UsageError("--bench-gi-moves needs --bench (the steady frames come first)");
    return options;
}

bool Options::pathIsFile() const { return path && lower(std::filesystem::path(*path).extension().string()) == ".json"; }

RenderSettings applyOptions(const Options& options, RenderSettings base, std::vector<std::string>* warnings) {
    for (const SettingAssignment& assignment : options.set) {
        try {
            setRenderSetting(base, assignment.key, assignment.value, warnings);
        } catch (const std::exception& e) {  // parseOptions tried each already; a hand-made Options may not have
            throw UsageError("--set " + assignment.key + "=" + assignment.value + ": " + e.what());
        }
    }
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
    // --bounces also sets the voxel GI's bounces (at least 1; all = every bounce, until converged).
    if (options.bounces)
        base.gi.bounces =
            *options.bounces == kAllReferenceBounces ? kAllBounces : std::clamp(*options.bounces, 1, kMaxBounces);
    if (options.giMode) base.gi.mode = *options.giMode;
    if (options.voxelRays) base.gi.voxelRays = *options.voxelRays;
    if (options.footprint) base.gi.coneFootprintPerHeight = *options.footprint;
    if (options.culling) base.output.frustumCulling = *options.culling;
    if (options.indirectScale) base.indirect.scale = *options.indirectScale;
    if (options.temporal) base.indirect.temporalAccumulation = *options.temporal;
    if (options.antialiasing) base.output.antialiasing = *options.antialiasing;
    if (options.coneSubsets) base.indirect.temporalConeSubsets = *options.coneSubsets;
    return base;
}

GiBudget giBudgetFor(const Options& options) {
    GiBudget budget = options.singleFrame ? GiBudget::updateOnly() : GiBudget::converge();
    if (options.giUpdatePerFrame && *options.giUpdatePerFrame > 0)
        budget.updateVoxels = static_cast<std::uint32_t>(*options.giUpdatePerFrame);
    if (options.giRefinePerFrame) budget.refineVoxels = static_cast<std::uint32_t>(*options.giRefinePerFrame);
    if (options.giMsPerFrame) budget.milliseconds = *options.giMsPerFrame;
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
    return "usage: lit-render SCENE.gltf --out IMAGE.png [--hdr IMAGE.hdr] [OPTIONS]         a still\n"
           "       lit-render SCENE.gltf --bench FRAMES [--json FILE.json] [OPTIONS]         per-pass timings\n"
           "       lit-render SCENE.gltf --path FILE.json|ANIMATION --frames-out DIR|--bench-path [OPTIONS]\n"
           "       lit-render SCENE.gltf --time SECONDS [--path FILE.json|ANIMATION] --out IMAGE.png   at a time\n"
           "       lit-render SCENE.gltf --reference --out IMAGE.png [--spp N] [--bounces N|all] [OPTIONS]\n"
           "       lit-render SCENE.gltf --compare REF.hdr [--difference FILE.png] [OPTIONS]\n"
           "       lit-render --help                                                         every option\n";
}

std::string usageText() {
    constexpr std::size_t kIndent = 2;       // of a flag's names
    constexpr std::size_t kHelpColumn = 23;  // where help text starts
    constexpr std::size_t kWidth = 100;      // columns
    std::string text = shortUsage() +
                       "\n"
                       "Renders a glTF scene headless (EGL, no window) with voxel cone traced global illumination.\n"
                       "A flag's value is the next argument or follows '=' (--size=64x64).\n";
    const std::vector<Flag> flags = flagTable();
    for (int g = 0; g <= static_cast<int>(kLastFlagGroup); ++g) {
        const auto group = static_cast<FlagGroup>(g);
        text += "\n";
        if (!title(group).empty()) text += std::string(title(group)) + ":\n";
        for (const Flag& flag : flags) {
            if (flag.group != group) continue;
            // Aliases first ("-o, --out FILE.png"), as most tools print them.
            std::string names;
            for (auto name = flag.names.rbegin(); name != flag.names.rend(); ++name)
                names += (names.empty() ? "" : ", ") + *name;
            // Appended, not " " + shownValue(): GCC 12 at -O3 warns (-Wrestrict, a false positive)
            // on that form, which breaks the -Werror Release build.
            if (!flag.shownValue().empty()) names.append(" ").append(flag.shownValue());
            std::string line = std::string(kIndent, ' ') + names;
            line += line.size() + 2 <= kHelpColumn ? std::string(kHelpColumn - line.size(), ' ')
                                                   : "  ";  // 2 spaces at least
            text += line + wrap(flag.help, line.size(), kHelpColumn, kWidth) + "\n";
        }
    }
    return text +
           "\n"
           "Exit status: 0 success, 1 runtime failure (scene, GL, file), 2 bad command line,\n"
           "130 a --reference render stopped by Ctrl+C (the image so far was written).\n";
}

}  // namespace lit::cli
