// IndirectFallbackPass: the per-pixel cone trace of the pixels the resolve cannot reconstruct
// runs in its own pass, over only the pixels the resolve marked. The image must be the one a
// single resolve pass with the trace inline writes (the path before the split), and the pass must
// run on the marked pixels only.
// Cost: about 5-8 s on llvmpipe (2 cores): three renderers per GI mode, 3 frames each at 96², 64³ voxels.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "GlTestSupport.h"
#include "gi/ConeProgram.h"
#include "passes/MaterialLayersVariant.h"

namespace lit::test {
namespace {

namespace fs = std::filesystem;

class IndirectFallback : public ContextFixture {
protected:
    void TearDown() override {
        std::error_code ignored;
        if (!shaderCopies_.empty()) fs::remove_all(shaderCopies_, ignored);
    }

    // A copy of shaders/ with `file` (relative to it) replaced by `text`.
    fs::path shadersWith(const std::string& name, const std::string& file, const std::string& text) {
        if (shaderCopies_.empty())
            shaderCopies_ = fs::temp_directory_path() / ("lit_indirect_fallback_" + std::to_string(::getpid()));
        const fs::path root = shaderCopies_ / name;
        fs::create_directories(root);
        fs::copy(sourceDir() / "shaders", root, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
        std::ofstream(root / file, std::ios::trunc) << text;
        return root;
    }

    // Renders `frames` frames of the Cornell box from inside (the full-frame view of the
    // benchmarks) with the shaders under `shaderRoot`; returns the last frame. Temporal
    // accumulation on, so the history outputs of both passes feed the later frames.
    HdrImage renderWith(const fs::path& shaderRoot, GiMode mode, int scale, int frames, View view = View::Final) {
        Renderer renderer(shaderRoot, log_);
        const Scene scene = loadGltf(sourceDir() / "assets" / "cornell_box.gltf", log_);
        renderer.setScene(scene);
        RenderSettings s = settingsFor(mode);
        s.output.width = s.output.height = kSize;
        s.gi.voxelResolution = 64;
        s.gi.enabled = true;
        s.indirect.scale = scale;
        s.indirect.temporalAccumulation = true;
        s.debug.view = view;
        const glm::mat4 world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.95f));
        const CameraView camera = makeCameraView(world, glm::radians(70.0f), 1.0f, 0.05f, 20.0f);
        for (int i = 0; i < frames; ++i) renderer.render(scene, camera, s);
        return HdrImage{kSize, kSize, renderer.readHdrRgb()};
    }

    static RenderSettings settingsFor(GiMode mode) {
        RenderSettings s;
        s.gi.mode = mode;
        return s;
    }

    static double meanLuminance(const HdrImage& image) {
        double sum = 0.0;
        for (const glm::vec3& c : pixels(image)) sum += luminance(c);
        return sum / double(image.width * image.height);
    }
    static std::vector<glm::vec3> pixels(const HdrImage& image) {
        std::vector<glm::vec3> out;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) out.push_back(image.at(x, y));
        return out;
    }

    static constexpr int kSize = 96;
    Log log_;
    fs::path shaderCopies_;
};

// The resolve as it was before the split: the trace inline (the fallback's body as the resolve's
// shader). It writes no trace mask of its own (the triangle's depth, 0.5, everywhere), so the
// fallback pass then runs on no pixel. The resolve's program is built without the cone features'
// defines (it has no cone code), so the one-pass shader states those of the settings rendered
// (each GI mode's, here), as the fallback's ConeProgram variant gets them: without them
// it traced the fast mode's fixed cone set where the fallback traces the accurate mode's
// stratified set, and the images differed by 41 % of the mean at the worst pixel.
// The resolve's program defines LIT_MATERIAL_LAYERS itself (MaterialLayersVariant: built with
// layers at start-up, without them for the Cornell box), so the features' own line is left out: a
// second definition with another value is a preprocessor error.
std::string onePassResolve(const RenderSettings& settings) {
    std::string defines = ConeFeatures::of(settings).defines();
    const std::string layers = MaterialLayersVariant{}.defines();
    if (const std::size_t at = defines.find(layers); at != std::string::npos) defines.erase(at, layers.size());
    return "#version 450 core\n" + defines + "#define LIT_INDIRECT_FALLBACK 1\n#include \"indirect_resolve.glsl\"\n";
}
// A fallback that writes nothing: the marked pixels keep what the resolve left there.
constexpr const char* kNoFallback = "#version 450 core\nvoid main() { discard; }\n";

// Both GI modes: the fast mode's fixed cone set and the accurate mode's stratified sets (the
// fallback traces the set of the texel its pixel falls in) are separate programs of both passes.
TEST_F(IndirectFallback, SplitPassesMatchTheOnePassResolve) {
    if (HasFatalFailure()) return;
    for (const GiMode mode : {GiMode::Fast, GiMode::Accurate}) {
        const std::string name(toString(mode));
        SCOPED_TRACE(name + " mode");
        // Quarter resolution: the most pixels without a neighbour on their surface.
        const int scale = 4, frames = 3;
        const HdrImage split = renderWith(sourceDir() / "shaders", mode, scale, frames);
        const HdrImage onePass = renderWith(
            shadersWith("one_pass_" + name, "indirect_resolve.frag.glsl", onePassResolve(settingsFor(mode))), mode, scale,
            frames);
        const HdrImage noFallback =
            renderWith(shadersWith("no_fallback_" + name, "indirect_fallback.frag.glsl", kNoFallback), mode, scale, frames);

        const double mean = meanLuminance(onePass);
        ASSERT_GT(mean, 0.0);
        const std::vector<glm::vec3> a = pixels(split), b = pixels(onePass), c = pixels(noFallback);
        double worst = 0.0;
        int fallbackPixels = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            const glm::vec3 d = glm::abs(a[i] - b[i]);
            worst = std::max(worst, double(std::max(d.r, std::max(d.g, d.b))));
            // A pixel the fallback wrote: without it the pixel differs from the split passes' image.
            const glm::vec3 e = glm::abs(a[i] - c[i]);
            if (std::max(e.r, std::max(e.g, e.b)) > 1e-3 * mean) ++fallbackPixels;
        }
        const double fraction = double(fallbackPixels) / double(a.size());
        std::printf("%s mode: split vs one-pass resolve: worst channel difference %.3g (%.4f %% of the mean luminance); "
                    "pixels the fallback wrote: %d (%.2f %%)\n",
                    name.c_str(), worst, 100.0 * worst / mean, fallbackPixels, 100.0 * fraction);
        // Same code, same inputs, same order of operations: the images agree to float rounding. The
        // bound, 0.01 % of the mean, is 50× below a 1/255 step of the tone-mapped image at mid grey
        // and far below the 2 % RMSE quality target; a wrong mask or missing history write moves
        // whole edge pixels by tens of per cent (a one-pass shader tracing the other mode's cone
        // set: 41 % of the mean).
        EXPECT_LE(worst, 1e-4 * mean);
        // The fallback pass does the work of the marked pixels: without it they differ. Measured on
        // llvmpipe: 11-14 pixels (0.12-0.15 %) in this view at 1/4 in the fast mode, 16 (0.17 %) in the
        // accurate mode (silhouettes of the boxes), so a fallback that never runs, or a resolve that
        // marks nothing, fails here. Nearly every pixel of this view is reconstructed from its
        // neighbours: a resolve that leaves much more to the fallback (2 % is 16× the fast mode's
        // measured share) has lost its upsampling.
        EXPECT_GE(fallbackPixels, 5);
        EXPECT_LT(fraction, 0.02);
    }
}

}  // namespace
}  // namespace lit::test
