// lit-render's command line (tools/lit_render/Options.cpp): what is accepted, what it means, and
// the exact message for what is rejected (the message is the only help a user gets).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "OptionFlags.h"
#include "Options.h"
#include "scene/Scene.h"

namespace {

using lit::cli::Options;
using lit::cli::parseOptions;
using lit::cli::UsageError;

// The message parseOptions throws for `args`, or "" when it accepts them.
std::string usageError(const std::vector<std::string>& args) {
    try {
        parseOptions(args);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(Options, MinimalCommandLine) {
    const Options o = parseOptions({"scene.gltf", "--out", "image.png"});
    EXPECT_FALSE(o.help);
    EXPECT_EQ(o.scene, "scene.gltf");
    EXPECT_EQ(o.out, "image.png");
    EXPECT_TRUE(o.hdr.empty());
    EXPECT_FALSE(o.width.has_value());
    EXPECT_FALSE(o.camera.has_value());
    EXPECT_EQ(o.frameCount(), 1);
    EXPECT_EQ(o.benchFrames, 0);
    // No flag given: the settings come through untouched.
    EXPECT_EQ(lit::cli::applyOptions(o, lit::RenderSettings{}), lit::RenderSettings{});
}

TEST(Options, EveryFlag) {
    const Options o = parseOptions({"--size", "320x200", "s.glb", "--out", "a/b.png", "--hdr", "c.hdr", "--camera", "top",
                                    "--exposure", "2.5", "--no-shadows", "--view", "indirect-diffuse", "--gi", "off",
                                    "--voxels", "256", "--frames", "3", "--settings", "s.json", "--culling", "off"});
    EXPECT_EQ(o.scene, "s.glb");
    EXPECT_EQ(o.out, "a/b.png");
    EXPECT_EQ(o.hdr, "c.hdr");
    EXPECT_EQ(o.camera, "top");
    EXPECT_EQ(o.settings, "s.json");
    EXPECT_EQ(o.frameCount(), 3);

    const lit::RenderSettings s = lit::cli::applyOptions(o, lit::RenderSettings{});
    EXPECT_EQ(s.output.width, 320);
    EXPECT_EQ(s.output.height, 200);
    EXPECT_FLOAT_EQ(s.output.exposureEv, std::log2(2.5f));
    EXPECT_FALSE(s.shadows.enabled);
    EXPECT_EQ(s.debug.view, lit::View::IndirectDiffuse);
    EXPECT_FALSE(s.gi.enabled);
    EXPECT_EQ(s.gi.voxelResolution, 256);
    EXPECT_FALSE(s.output.frustumCulling);
}

TEST(Options, CullingOnOrOff) {
    const auto culling = [](std::vector<std::string> extra) {
        std::vector<std::string> args{"x.gltf", "--out", "x.png"};
        args.insert(args.end(), extra.begin(), extra.end());
        return lit::cli::applyOptions(parseOptions(args), lit::RenderSettings{}).output.frustumCulling;
    };
    EXPECT_TRUE(lit::RenderSettings{}.output.frustumCulling) << "on by default";
    EXPECT_TRUE(culling({}));
    EXPECT_FALSE(culling({"--culling", "off"}));
    EXPECT_FALSE(culling({"--culling=off"}));
    EXPECT_TRUE(culling({"--culling", "on"}));
    lit::RenderSettings off;
    off.output.frustumCulling = false;  // e.g. from --settings
    EXPECT_FALSE(lit::cli::applyOptions(parseOptions({"x.gltf", "--out", "x.png"}), off).output.frustumCulling);
    EXPECT_TRUE(lit::cli::applyOptions(parseOptions({"x.gltf", "--out", "x.png", "--culling", "on"}), off)
                    .output.frustumCulling);
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--culling", "yes"}), "--culling expects on or off, got 'yes'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--culling"}), "missing value for --culling (expects on or off)");
    EXPECT_NE(lit::cli::usageText().find("--culling on|off"), std::string::npos);
}

TEST(Options, FlagsOverrideOnlyWhatTheyName) {
    lit::RenderSettings base;
    base.output.width = 64;
    base.output.height = 48;
    base.gi.enabled = false;
    base.output.exposureEv = 3.0f;
    const lit::RenderSettings s = lit::cli::applyOptions(parseOptions({"x.gltf", "--out", "x.png", "--gi", "on"}), base);
    EXPECT_EQ(s.output.width, 64);
    EXPECT_EQ(s.output.height, 48);
    EXPECT_TRUE(s.gi.enabled);
    EXPECT_FLOAT_EQ(s.output.exposureEv, 3.0f);
}

TEST(Options, ExposureStopsAutoExposureAndSky) {
    const Options o = parseOptions({"x.gltf", "--out", "x.png", "--ev", "-2.5", "--auto-exposure", "on", "--sky-hdr", "e.hdr"});
    const lit::RenderSettings s = lit::cli::applyOptions(o, lit::RenderSettings{});
    EXPECT_FLOAT_EQ(s.output.exposureEv, -2.5f);
    EXPECT_TRUE(s.output.autoExposure);
    EXPECT_EQ(s.sky.mode, lit::SkyMode::Hdr);
    EXPECT_EQ(s.sky.hdrPath, "e.hdr");
    EXPECT_EQ(lit::cli::applyOptions(parseOptions({"x.gltf", "--out", "x.png", "--sky", "none"}), {}).sky.mode,
              lit::SkyMode::None);
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--ev", "21"}), "--ev expects stops from -10 to 20, got '21'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--ev", "1", "--exposure", "2"}),
              "--ev and --exposure both set the exposure; give one of them");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--sky", "blue"}),
              "--sky expects auto, none, uniform, gradient or hdr, got 'blue'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--auto-exposure", "1"}), "--auto-exposure expects on or off, got '1'");
}

TEST(Options, EqualsFormAndUppercaseSizeSeparator) {
    const Options o = parseOptions({"x.gltf", "--out=x.png", "--size=16X9", "--exposure=0.5"});
    EXPECT_EQ(o.out, "x.png");
    EXPECT_EQ(o.width, 16);
    EXPECT_EQ(o.height, 9);
    EXPECT_FLOAT_EQ(*o.exposure, 0.5f);
}

TEST(Options, HelpWinsOverEverythingElse) {
    EXPECT_TRUE(parseOptions({"--help"}).help);
    EXPECT_EQ(usageError({"--bogus", "-h"}), "unknown option '--bogus'");  // arguments are read in order
    EXPECT_TRUE(parseOptions({"scene.gltf", "--help", "--size", "0x0"}).help);
    EXPECT_FALSE(lit::cli::usageText().empty());
}

TEST(Options, BenchNeedsNoOutput) {
    const Options o = parseOptions({"x.gltf", "--bench", "10", "--json", "bench.json"});
    EXPECT_EQ(o.benchFrames, 10);
    EXPECT_EQ(o.frameCount(), 10);
    EXPECT_EQ(o.benchJson, "bench.json");
    EXPECT_TRUE(o.out.empty());
}

TEST(Options, SizeMessages) {
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--size", "12x"}), "--size expects WxH with 1..16384, got '12x'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--size", "0x10"}), "--size expects WxH with 1..16384, got '0x10'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--size", "16385x1"}), "--size expects WxH with 1..16384, got '16385x1'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--size", "64"}), "--size expects WxH with 1..16384, got '64'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--size", "-4x4"}), "--size expects WxH with 1..16384, got '-4x4'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--size", "4x4x4"}), "--size expects WxH with 1..16384, got '4x4x4'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--size", " 4x4"}), "--size expects WxH with 1..16384, got ' 4x4'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--size", "16384x1"}), "");
}

TEST(Options, NumberMessages) {
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--exposure", "bright"}), "--exposure expects a positive number, got 'bright'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--exposure", "0"}), "--exposure expects a positive number, got '0'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--exposure", "-1"}), "--exposure expects a positive number, got '-1'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--exposure", "inf"}), "--exposure expects a positive number, got 'inf'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--exposure", "1.5x"}), "--exposure expects a positive number, got '1.5x'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--frames", "0"}), "--frames expects an integer from 1 to 100000, got '0'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--frames", "2.5"}), "--frames expects an integer from 1 to 100000, got '2.5'");
    EXPECT_EQ(usageError({"x.gltf", "--bench", "many"}), "--bench expects a frame count from 1 to 100000, got 'many'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--voxels", "100"}), "--voxels expects a power of two from 64 to 512, got '100'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--voxels", "1024"}), "--voxels expects a power of two from 64 to 512, got '1024'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--gi", "yes"}), "--gi expects on or off, got 'yes'");
}

TEST(Options, ViewMessageListsTheViews) {
    const std::string message = usageError({"x.gltf", "--out", "x.png", "--view", "fancy"});
    EXPECT_EQ(message.rfind("unknown view 'fancy'; views are: final, direct-diffuse", 0), 0u) << message;
    EXPECT_NE(message.find("indirect-diffuse"), std::string::npos) << message;
}

TEST(Options, StructuralMessages) {
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--fast"}), "unknown option '--fast'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "-q"}), "unknown option '-q'");
    EXPECT_EQ(usageError({"--out", "x.png"}), "no scene given (lit-render SCENE.gltf --out image.png)");
    EXPECT_EQ(usageError({}), "no scene given (lit-render SCENE.gltf --out image.png)");
    EXPECT_EQ(usageError({"x.gltf"}), "--out is required (unless --hdr, --bench, --path or --compare)");
    EXPECT_EQ(usageError({"x.gltf", "--reference", "--hdr", "r.hdr"}), "") << "the linear image alone is an output";
    EXPECT_EQ(usageError({"x.gltf", "--out"}), "missing value for --out (expects FILE.png)");
    EXPECT_EQ(usageError({"x.gltf", "--out", "--size", "4x4"}), "missing value for --out (expects FILE.png)");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--size"}), "missing value for --size (expects WxH)");
    EXPECT_EQ(usageError({"x.gltf", "y.gltf", "--out", "x.png"}), "unexpected argument 'y.gltf' (the scene is already 'x.gltf')");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.jpg"}), "--out writes a .png file; got 'x.jpg'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--hdr", "x.exr"}), "--hdr writes a .hdr file; got 'x.exr'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--json", "b.json"}), "--json needs --bench or --bench-path");
    EXPECT_EQ(usageError({"x.gltf", "--bench", "5", "--frames", "2"}),
              "--frames and --bench both set the number of frames; give one of them");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--no-shadows=1"}), "--no-shadows takes no value, got '--no-shadows=1'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--camera", ""}), "--camera expects a camera name or index, got ''");
}

// --voxel-rays sets RenderSettings::voxelRays (0 = cones); counts outside 0..kMaxVoxelRays are refused.
TEST(Options, VoxelRays) {
    EXPECT_EQ(applyOptions(parseOptions({"x.gltf", "--out", "x.png", "--voxel-rays", "64"}), {}).gi.voxelRays, 64);
    EXPECT_EQ(applyOptions(parseOptions({"x.gltf", "--out", "x.png", "--voxel-rays", "0"}), {}).gi.voxelRays, 0);
    EXPECT_EQ(applyOptions(parseOptions({"x.gltf", "--out", "x.png"}), {}).gi.voxelRays,
              lit::RenderSettings{}.gi.voxelRays);
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--voxel-rays", "257"}),
              "--voxel-rays expects a ray count from 0 to 256, got '257'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--voxel-rays", "many"}),
              "--voxel-rays expects a ray count from 0 to 256, got 'many'");
}

TEST(Options, ReferenceFlags) {
    const Options o = parseOptions({"x.gltf", "--reference", "--spp", "32", "--bounces", "all", "--seed", "7", "--out", "r.png",
                                    "--view", "indirect-diffuse"});
    EXPECT_TRUE(o.reference);
    EXPECT_EQ(o.referenceSpp(), 32);
    EXPECT_EQ(o.bounces, lit::cli::kAllReferenceBounces);
    EXPECT_EQ(o.seed, 7u);
    EXPECT_EQ(parseOptions({"x.gltf", "--reference", "--out", "r.png"}).referenceSpp(), lit::cli::kDefaultReferenceSpp);
    EXPECT_EQ(parseOptions({"x.gltf", "--reference", "--bounces=2", "--out", "r.png"}).bounces, 2);
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--spp", "8"}), "--spp needs --reference");
    // Without --reference, --bounces sets the voxel GI's bounces: at least 1, all = the most.
    EXPECT_EQ(applyOptions(parseOptions({"x.gltf", "--out", "x.png", "--bounces", "3"}), {}).gi.bounces, 3);
    EXPECT_EQ(applyOptions(parseOptions({"x.gltf", "--out", "x.png", "--bounces", "0"}), {}).gi.bounces, 1);
    EXPECT_EQ(applyOptions(parseOptions({"x.gltf", "--out", "x.png", "--bounces", "all"}), {}).gi.bounces,
              lit::kAllBounces);
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--seed", "1"}), "--seed needs --reference");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--node-map", "m.txt"}), "--node-map needs --reference");
    EXPECT_EQ(usageError({"x.gltf", "--reference", "--out", "x.png", "--spp", "0"}),
              "--spp expects samples per pixel from 1 to 1048576, got '0'");
    EXPECT_EQ(usageError({"x.gltf", "--reference", "--out", "x.png", "--bounces", "-1"}),
              "--bounces expects 0 to 64 or all, got '-1'");
    EXPECT_EQ(usageError({"x.gltf", "--reference", "--out", "x.png", "--seed", "x"}),
              "--seed expects a non-negative integer, got 'x'");
    EXPECT_EQ(usageError({"x.gltf", "--reference", "--out", "x.png", "--view", "albedo"}),
              "--reference renders the views final, direct-diffuse, indirect-diffuse, direct-specular and "
              "indirect-specular, not 'albedo'");
    EXPECT_EQ(usageError({"x.gltf", "--reference", "--bench", "3"}),
              "--reference and --bench do not go together (the reference prints its own rays/s)");
    EXPECT_EQ(usageError({"x.gltf", "--reference", "--path", "p.json", "--bench-path"}),
              "--reference and --bench-path do not go together (the reference is not timed per frame)");
    const Options tracedPath = parseOptions({"x.gltf", "--reference", "--path", "p.json", "--frames-out", "f"});
    EXPECT_TRUE(tracedPath.reference && tracedPath.path && !tracedPath.pathStill())
        << "--reference --path --frames-out traces every frame of the path";
}

TEST(Options, TimeRendersAStillAtThatTime) {
    Options o = parseOptions({"x.gltf", "--time", "1.5", "--out", "x.png"});
    EXPECT_EQ(o.time, 1.5);
    EXPECT_FALSE(o.pathStill());
    o = parseOptions({"x.gltf", "--time", "2", "--path", "fly", "--out", "x.png"});
    EXPECT_TRUE(o.pathStill()) << "--path with --time is one still through the path";
    o = parseOptions({"x.gltf", "--time", "2", "--path", "fly", "--reference", "--out", "x.png"});
    EXPECT_TRUE(o.pathStill());
    EXPECT_FALSE(parseOptions({"x.gltf", "--out", "x.png"}).time);
    EXPECT_EQ(usageError({"x.gltf", "--time", "soon", "--out", "x.png"}), "--time expects seconds, got 'soon'");
    EXPECT_EQ(usageError({"x.gltf", "--time", "1", "--path", "fly", "--frames-out", "f"}),
              "--time with --path renders one still (--out); --frames-out, --bench-path and --fps fly the whole path "
              "(leave out --time)");
    EXPECT_EQ(usageError({"x.gltf", "--time", "1", "--path", "fly", "--camera", "c", "--out", "x.png"}),
              "--path and --camera both choose the camera; give one of them");
    EXPECT_EQ(usageError({"x.gltf", "--time", "1", "--path", "fly"}),
              "--out is required (unless --hdr, --bench, --path or --compare)");
}

TEST(Options, CompareFlags) {
    const Options o = parseOptions({"x.gltf", "--compare", "ref.hdr", "--difference", "d.png", "--max-error", "0.25"});
    EXPECT_EQ(o.compare, "ref.hdr");
    EXPECT_EQ(o.difference, "d.png");
    EXPECT_EQ(o.maxError, 0.25f);
    EXPECT_TRUE(o.out.empty()) << "--compare alone needs no --out: its figures are the output";
    EXPECT_FALSE(parseOptions({"x.gltf", "--compare", "r.HDR"}).maxError.has_value());
    EXPECT_EQ(usageError({"x.gltf", "--compare", "ref.png"}), "--compare reads a .hdr file; got 'ref.png'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--difference", "d.png"}),
              "--difference needs --compare REF.hdr (the image to compare against)");
    EXPECT_EQ(usageError({"x.gltf", "--compare", "r.hdr", "--difference", "d.hdr"}), "--difference writes a .png file; got 'd.hdr'");
    EXPECT_EQ(usageError({"x.gltf", "--compare", "r.hdr", "--max-error", "0.5"}), "--max-error needs --difference FILE.png");
    EXPECT_EQ(usageError({"x.gltf", "--compare", "r.hdr", "--difference", "d.png", "--max-error", "0"}),
              "--max-error expects a relative error above 0 and at most 100 (0.5 = 50 %), got '0'");
    EXPECT_EQ(usageError({"x.gltf", "--compare", ""}), "--compare expects a file name, got ''");
    EXPECT_EQ(usageError({"x.gltf", "--path", "p.json", "--bench-path", "--compare", "r.hdr"}),
              "--compare compares one image; it does not apply to --path");
}

TEST(Options, PathFlags) {
    const Options o = parseOptions({"x.gltf", "--path", "orbit.path.json", "--fps", "12.5", "--frames-out", "frames"});
    EXPECT_EQ(o.path, "orbit.path.json");
    EXPECT_TRUE(o.pathIsFile());
    EXPECT_DOUBLE_EQ(o.pathFps(), 12.5);
    EXPECT_EQ(o.framesOut, "frames");
    EXPECT_FALSE(o.benchPath);
    EXPECT_TRUE(o.out.empty());

    const Options bench = parseOptions({"x.gltf", "--path", "camera path", "--bench-path", "--json", "b.json", "--gi", "off"});
    EXPECT_FALSE(bench.pathIsFile());  // no .json: an animation in the scene file
    EXPECT_TRUE(bench.benchPath);
    EXPECT_DOUBLE_EQ(bench.pathFps(), lit::cli::kDefaultPathFps);
    EXPECT_EQ(bench.benchJson, "b.json");
    EXPECT_TRUE(parseOptions({"x.gltf", "--path", "P.JSON", "--bench-path"}).pathIsFile());
    EXPECT_NE(lit::cli::usageText().find("--frames-out DIR"), std::string::npos);
}

TEST(Options, PathFlagsThatDoNotGoTogether) {
    EXPECT_EQ(usageError({"x.gltf", "--frames-out", "d"}), "--frames-out needs --path");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--frames-out", "d"}), "--frames-out needs --path");
    EXPECT_EQ(usageError({"x.gltf", "--bench-path"}), "--bench-path needs --path");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--fps", "30"}), "--fps needs --path");
    EXPECT_EQ(usageError({"x.gltf", "--path", "p.json"}), "--path needs --frames-out DIR or --bench-path");
    EXPECT_EQ(usageError({"x.gltf", "--path", "p.json", "--bench-path", "--out", "x.png"}),
              "--out writes one image; with --path use --frames-out DIR");
    EXPECT_EQ(usageError({"x.gltf", "--path", "p.json", "--bench-path", "--hdr", "x.hdr"}),
              "--hdr writes one image; with --path use --frames-out DIR");
    EXPECT_EQ(usageError({"x.gltf", "--path", "p.json", "--bench-path", "--camera", "top"}),
              "--path and --camera both choose the camera; give one of them");
    EXPECT_EQ(usageError({"x.gltf", "--path", "p.json", "--frames-out", "d", "--frames", "3"}),
              "--frames does not apply to --path (each frame of the path is rendered once)");
    EXPECT_EQ(usageError({"x.gltf", "--path", "p.json", "--bench", "10"}),
              "--bench renders a still view; use --bench-path to time the path");
    EXPECT_EQ(usageError({"x.gltf", "--path", "p.json", "--bench-path", "--fps", "0"}),
              "--fps expects frames per second above 0 and up to 1000, got '0'");
    EXPECT_EQ(usageError({"x.gltf", "--path", "p.json", "--bench-path", "--fps", "fast"}),
              "--fps expects frames per second above 0 and up to 1000, got 'fast'");
    EXPECT_EQ(usageError({"x.gltf", "--path", "", "--bench-path"}), "--path expects a .json file or an animation name, got ''");
    EXPECT_EQ(usageError({"x.gltf", "--path", "p.json", "--bench-path=yes"}), "--bench-path takes no value, got '--bench-path=yes'");
}

lit::Scene sceneWithCameras() {
    lit::Scene scene;
    scene.cameras.push_back({.name = "front"});
    scene.cameras.push_back({.name = "top"});
    lit::Node node;
    node.name = "top_node";
    node.camera = 1;
    scene.nodes.push_back(node);
    return scene;
}

TEST(Options, CameraByIndexOrName) {
    const lit::Scene scene = sceneWithCameras();
    const auto camera = [&](std::vector<std::string> extra) {
        std::vector<std::string> args{"x.gltf", "--out", "x.png"};
        args.insert(args.end(), extra.begin(), extra.end());
        return lit::cli::resolveCamera(parseOptions(args), scene);
    };
    EXPECT_EQ(camera({}), 0);  // default: the scene's first camera
    EXPECT_EQ(camera({"--camera", "1"}), 1);
    EXPECT_EQ(camera({"--camera", "top"}), 1);
    EXPECT_EQ(camera({"--camera", "top_node"}), 1);  // node names work too
    EXPECT_EQ(camera({"--camera", "front"}), 0);
}

TEST(Options, UnknownCameraListsTheCameras) {
    const lit::Scene scene = sceneWithCameras();
    const auto message = [&](const std::string& name) {
        try {
            lit::cli::resolveCamera(parseOptions({"x.gltf", "--out", "x.png", "--camera", name}), scene);
        } catch (const UsageError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message("side"), "unknown camera 'side'; the scene's cameras are: 0 'front', 1 'top'");
    EXPECT_EQ(message("2"), "unknown camera '2'; the scene's cameras are: 0 'front', 1 'top'");
}

TEST(Options, SceneWithoutCamerasUsesTheFramingCamera) {
    const lit::Scene empty;
    EXPECT_EQ(lit::cli::resolveCamera(parseOptions({"x.gltf", "--out", "x.png"}), empty), -1);
    try {
        lit::cli::resolveCamera(parseOptions({"x.gltf", "--out", "x.png", "--camera", "0"}), empty);
        FAIL() << "camera 0 of a scene without cameras was accepted";
    } catch (const UsageError& e) {
        EXPECT_STREQ(e.what(), "unknown camera '0'; the scene has no cameras");
    }
}

TEST(Options, FastGiFlags) {
    const Options o = parseOptions({"x.gltf", "--bench", "3", "--indirect-scale", "4", "--temporal", "on",
                                    "--bench-gi-updates", "2"});
    EXPECT_EQ(o.giUpdateRounds, 2);
    const lit::RenderSettings s = lit::cli::applyOptions(o, lit::RenderSettings{});
    EXPECT_EQ(s.indirect.scale, 4);
    EXPECT_TRUE(s.indirect.temporalAccumulation);
    EXPECT_EQ(usageError({"x.gltf", "--out", "a.png", "--indirect-scale", "3"}),
              "--indirect-scale expects 1, 2 or 4, got '3'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "a.png", "--temporal", "yes"}), "--temporal expects on or off, got 'yes'");
    EXPECT_TRUE(s.indirect.temporalConeSubsets);  // the default
    EXPECT_FALSE(lit::cli::applyOptions(parseOptions({"x.gltf", "--out", "a.png", "--cone-subsets", "off"}),
                                        lit::RenderSettings{})
                     .indirect.temporalConeSubsets);
    EXPECT_EQ(usageError({"x.gltf", "--out", "a.png", "--cone-subsets", "1"}),
              "--cone-subsets expects on or off, got '1'");
    lit::RenderSettings noSubsets;
    noSubsets.indirect.temporalConeSubsets = false;
    EXPECT_EQ(lit::renderSettingsFromJson(lit::toJson(noSubsets)), noSubsets);  // saved and read back
    EXPECT_EQ(usageError({"x.gltf", "--out", "a.png", "--bench-gi-updates", "2"}),
              "--bench-gi-updates needs --bench (the steady frames come first)");
    EXPECT_EQ(usageError({"x.gltf", "--out", "a.png", "--bench-gi-moves", "2"}),
              "--bench-gi-moves needs --bench (the steady frames come first)");
}

// The GI work per frame: a still converges by default (the editor's refined light), --single-frame
// is the old single-frame steady state, and the per-frame flags spread the work as the editor does.
TEST(Options, GiBudgetFlags) {
    EXPECT_EQ(lit::cli::giBudgetFor(parseOptions({"x.gltf", "--out", "a.png"})), lit::GiBudget::converge());
    EXPECT_EQ(lit::cli::giBudgetFor(parseOptions({"x.gltf", "--out", "a.png", "--single-frame"})),
              lit::GiBudget::updateOnly());
    const lit::GiBudget spread = lit::cli::giBudgetFor(
        parseOptions({"x.gltf", "--out", "a.png", "--gi-update-per-frame", "20000", "--gi-refine-per-frame", "0"}));
    EXPECT_EQ(spread.updateVoxels, 20000u);
    EXPECT_EQ(spread.refineVoxels, 0u);
    EXPECT_EQ(spread.milliseconds, 0.0);
    const lit::GiBudget paced = lit::cli::giBudgetFor(
        parseOptions({"x.gltf", "--out", "a.png", "--gi-update-per-frame", "16384", "--gi-ms-per-frame", "25"}));
    EXPECT_EQ(paced.updateVoxels, 16384u);
    EXPECT_EQ(paced.milliseconds, 25.0);
    // 0 = the whole update at once.
    EXPECT_EQ(
        lit::cli::giBudgetFor(parseOptions({"x.gltf", "--out", "a.png", "--gi-update-per-frame", "0"})).updateVoxels,
        lit::GiBudget::kAll);
    EXPECT_EQ(usageError({"x.gltf", "--out", "a.png", "--gi-update-per-frame", "-1"}),
              "--gi-update-per-frame expects a voxel count from 0, got '-1'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "a.png", "--single-frame", "--gi-refine-per-frame", "5"}),
              "--single-frame sets the GI work per frame; give it or --gi-update-per-frame / --gi-refine-per-frame / "
              "--gi-ms-per-frame");
    EXPECT_EQ(usageError({"x.gltf", "--out", "a.png", "--voxel-irradiance", "on"}),
              "--voxel-irradiance was replaced by --gi-mode fast|accurate|cached");
}

TEST(Options, GiMode) {
    using lit::GiMode;
    const lit::RenderSettings defaults;
    EXPECT_EQ(defaults.gi.mode, GiMode::Cached);
    const auto settingsFor = [](const std::vector<std::string>& args) {
        return lit::cli::applyOptions(parseOptions(args), lit::RenderSettings{});
    };
    const lit::RenderSettings accurate = settingsFor({"x.gltf", "--out", "a.png", "--gi-mode", "accurate"});
    EXPECT_TRUE(accurate.gi.anisotropicVoxels());
    EXPECT_EQ(accurate.gi.footprintPerHeight(), lit::kAccurateGiFootprint);
    EXPECT_FALSE(accurate.gi.voxelIrradiance());
    EXPECT_EQ(accurate.gi.mode, GiMode::Accurate);
    // --footprint sets the bounded cones' parameter; the mode stays.
    const lit::RenderSettings bounded =
        settingsFor({"x.gltf", "--footprint", "0.5", "--out", "a.png", "--gi-mode", "accurate"});
    EXPECT_EQ(bounded.gi.footprintPerHeight(), 0.5f);
    EXPECT_EQ(bounded.gi.mode, GiMode::Accurate);
    // fast: isotropic voxels and unbounded cones whatever the footprint; cached puts back the defaults.
    lit::RenderSettings fromFile = accurate;
    const lit::RenderSettings fast = lit::cli::applyOptions(parseOptions({"x.gltf", "--out", "a.png", "--gi-mode", "fast"}), fromFile);
    EXPECT_EQ(fast.gi.mode, GiMode::Fast);
    EXPECT_FALSE(fast.gi.anisotropicVoxels());
    EXPECT_EQ(fast.gi.footprintPerHeight(), 0.0f);
    EXPECT_FALSE(fast.gi.voxelIrradiance());
    const lit::RenderSettings cached = lit::cli::applyOptions(parseOptions({"x.gltf", "--out", "a.png", "--gi-mode", "cached"}), fast);
    EXPECT_EQ(cached, defaults);
    EXPECT_EQ(usageError({"x.gltf", "--out", "a.png", "--gi-mode", "custom"}),
              "--gi-mode expects fast, accurate or cached, got 'custom'");
    EXPECT_EQ(lit::toString(GiMode::Accurate), "accurate");
    EXPECT_EQ(lit::toString(GiMode::Cached), "cached");
    EXPECT_NE(lit::cli::usageText().find("--gi-mode MODE       fast, accurate or cached (default cached)"), std::string::npos);
}

// --set KEY=VALUE sets any render setting by its "group.field" key: after --settings (the base),
// before the other flags, in the order given.
TEST(Options, SetAnyRenderSettingByItsKey) {
    const Options o = parseOptions({"x.gltf", "--out", "x.png", "--set", "gi.voxelResolution=256", "--set=gi.mode=fast",
                                    "--set", "indirect.temporalAccumulation=true", "--set", "sky.zenith=[1, 2, 3]",
                                    "--set", "sky.hdrPath=a=b.hdr", "--set", "debug.view=albedo"});
    ASSERT_EQ(o.set.size(), 6u);
    EXPECT_EQ(o.set[0], (lit::cli::SettingAssignment{"gi.voxelResolution", "256"}));
    const lit::RenderSettings s = applyOptions(o, {});
    EXPECT_EQ(s.gi.voxelResolution, 256);
    EXPECT_EQ(s.gi.mode, lit::GiMode::Fast);  // a bare word is a string
    EXPECT_TRUE(s.indirect.temporalAccumulation);
    EXPECT_EQ(s.sky.zenith, (std::array<float, 3>{1.0f, 2.0f, 3.0f}));
    EXPECT_EQ(s.sky.hdrPath, "a=b.hdr");  // the key ends at the first '='
    EXPECT_EQ(s.debug.view, lit::View::Albedo);

    lit::RenderSettings fromFile;
    fromFile.gi.bounces = 4;
    fromFile.gi.voxelResolution = 64;
    const auto settingsFor = [&](std::vector<std::string> extra) {
        std::vector<std::string> args{"x.gltf", "--out", "x.png"};
        args.insert(args.end(), extra.begin(), extra.end());
        return applyOptions(parseOptions(args), fromFile);
    };
    EXPECT_EQ(settingsFor({"--set", "gi.bounces=3"}).gi.bounces, 3) << "--set overrides --settings";
    EXPECT_EQ(settingsFor({"--set", "gi.bounces=3"}).gi.voxelResolution, 64) << "and nothing else";
    EXPECT_EQ(settingsFor({"--voxels", "128", "--set", "gi.voxelResolution=256"}).gi.voxelResolution, 128)
        << "the other flags override --set";
    EXPECT_EQ(settingsFor({"--set", "gi.bounces=3", "--set", "gi.bounces=1"}).gi.bounces, 1) << "in order";

    // An older flat key is read, with its deprecation message (lit-render prints it as a warning).
    std::vector<std::string> warnings;
    EXPECT_EQ(applyOptions(parseOptions({"x.gltf", "--out", "x.png", "--set", "voxelResolution=64"}), {}, &warnings)
                  .gi.voxelResolution,
              64);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "render settings: 'voxelResolution' is deprecated; read as gi.voxelResolution");

    EXPECT_EQ(
        usageError({"x.gltf", "--out", "x.png", "--set", "gi.sparkles=1"}),
        "--set: unknown render setting 'gi.sparkles' (the keys: renderer/RenderSettings.h, docs/GI.md \"Parameters\")");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--set", "gi.voxelResolution=big"}),
              "--set gi.voxelResolution=big: 'gi.voxelResolution' has the wrong type");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--set", "gi.mode=turbo"}),
              "--set gi.mode=turbo: 'gi.mode' is not a known name");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--set", "gi.voxelResolution"}),
              "--set expects KEY=VALUE (e.g. gi.voxelResolution=256), got 'gi.voxelResolution'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--set", "=1"}),
              "--set expects KEY=VALUE (e.g. gi.voxelResolution=256), got '=1'");
    EXPECT_EQ(usageError({"x.gltf", "--out", "x.png", "--set"}), "missing value for --set (expects KEY=VALUE)");

    const std::string help = lit::cli::usageText();
    EXPECT_NE(help.find("--set KEY=VALUE"), std::string::npos);
    EXPECT_NE(help.find("renderer/RenderSettings.h and"), std::string::npos);
    EXPECT_NE(help.find("docs/GI.md, \"Parameters\""), std::string::npos);
}

// --help is generated from the flag table: every flag is listed under its group's heading, and
// every flag listed is one the parser takes.
TEST(Options, HelpListsEveryFlagUnderItsGroup) {
    const std::string help = lit::cli::usageText();
    const auto headingAt = [&](lit::cli::FlagGroup group) {
        const std::string title(lit::cli::title(group));
        return title.empty() ? help.find("\n\n") : help.find("\n" + title + ":\n");
    };
    for (const char* heading : {"Files", "Settings", "Output", "Sky", "Shadows", "GI", "Indirect", "Debug views",
                                "Benchmarks", "Camera paths and node animations", "Reference"})
        EXPECT_NE(help.find(std::string("\n") + heading + ":\n"), std::string::npos) << heading;
    for (const lit::cli::Flag& flag : lit::cli::flagTable()) {
        const std::size_t start = headingAt(flag.group);
        ASSERT_NE(start, std::string::npos) << flag.names.front();
        const std::size_t end = flag.group == lit::cli::kLastFlagGroup
                                    ? help.size()
                                    : headingAt(static_cast<lit::cli::FlagGroup>(static_cast<int>(flag.group) + 1));
        for (const std::string& name : flag.names) {
            const std::size_t at = help.find(" " + name + (name.starts_with("--") ? " " : ","), start);
            EXPECT_TRUE(at != std::string::npos && at < end) << name << " is not under its heading";
        }
        // The parser knows it: whatever it says about the value, it is not an unknown option.
        EXPECT_EQ(usageError({"x.gltf", flag.names.front()}).find("unknown option"), std::string::npos)
            << flag.names.front();
    }
    EXPECT_NE(usageError({"x.gltf", "--out", "x.png", "--anisotropic"}).find("was replaced by --gi-mode"),
              std::string::npos);
    EXPECT_EQ(help.find("--anisotropic"), std::string::npos) << "replaced flags are not listed";
}

}  // namespace
