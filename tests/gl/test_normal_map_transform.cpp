// KHR_texture_transform on a normal map (label gl): the Blender scene of
// tools/blender/make_normal_map_transform.py (a plane whose tangent-space normal map, 4×4 texels
// tilted 35° each in its own direction, is placed by a Mapping node with a 60° rotation) against
// its twin, where the script baked the Mapping into the mesh UVs, so the tangents Lit derives from
// those UVs are the frame the map was painted in. A transform that turns the UVs turns the map's
// tangent frame with them: the rasterizer's and the reference tracer's shading normals must match
// the twin's, and differ from it with the transform removed.
#include "GlTestSupport.h"

#include "reference/PathTracer.h"
#include "reference/ReferenceScene.h"

#include <cmath>
#include <cstdio>

namespace lit::test {
namespace {

using reference::FirstHit;
using reference::ReferenceScene;

constexpr int kSize = 128;

// The share of the plane's pixels (both hit it) where the two normals lie within 3°.
double agreement(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b, const std::vector<bool>& onPlane) {
    int same = 0, total = 0;
    for (std::size_t p = 0; p < onPlane.size(); ++p) {
        if (!onPlane[p]) continue;
        ++total;
        same += glm::dot(glm::normalize(a[p]), glm::normalize(b[p])) > std::cos(glm::radians(3.0f));
    }
    return total ? double(same) / total : 0.0;
}

class NormalMapTransform : public GlFixture {
protected:
    void SetUp() override {
        GlFixture::SetUp();
        if (HasFatalFailure()) return;
        const auto dir = sourceDir() / "tests" / "data" / "blender" / "normal_map_transform";
        quiet_.setSink(nullptr);
        mapped_ = loadGltf(dir / "normal_map_transform.gltf", quiet_);
        baked_ = loadGltf(dir / "normal_map_transform_baked.gltf", quiet_);
        untransformed_ = mapped_;
        for (Material& m : untransformed_.materials) m.textureTransforms = {};
        ASSERT_TRUE(mapped_.materials.at(0).textureTransforms[2].present) << "the normal texture's transform";
        settings_ = smallSettings();
        settings_.output.width = settings_.output.height = kSize;
        camera_ = cameraFor(mapped_, settings_);
        for (const FirstHit& h : firstHits(mapped_)) onPlane_.push_back(h.node >= 0);
        ASSERT_GT(std::count(onPlane_.begin(), onPlane_.end(), true), kSize * kSize / 2);
    }

    std::vector<FirstHit> firstHits(const Scene& scene) {
        const ReferenceScene rs(scene, quiet_);
        return reference::traceFirstHits(rs, camera_, kSize, kSize);
    }
    // The reference tracer's shading normals.
    std::vector<glm::vec3> referenceNormals(const Scene& scene) {
        std::vector<glm::vec3> normals;
        for (const FirstHit& h : firstHits(scene)) normals.push_back(h.normal);
        return normals;
    }
    // The rasterizer's G-buffer normals (the Normal view shows 0.5 + 0.5 n), bottom-up rows as
    // the reference's first hits.
    std::vector<glm::vec3> rasterNormals(const Scene& scene) {
        RenderSettings s = settings_;
        s.debug.view = View::Normal;
        const std::vector<float> rgb = render(scene, s).rgb;
        std::vector<glm::vec3> normals;
        for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
            normals.push_back(glm::vec3(rgb[i], rgb[i + 1], rgb[i + 2]) * 2.0f - 1.0f);
        return normals;
    }

    Log quiet_;
    Scene mapped_, baked_, untransformed_;
    RenderSettings settings_;
    CameraView camera_;
    std::vector<bool> onPlane_;
};

TEST_F(NormalMapTransform, RasterizerTurnsTheTangentFrameWithTheUvs) {
    const std::vector<glm::vec3> baked = rasterNormals(baked_);
    const double same = agreement(rasterNormals(mapped_), baked, onPlane_);
    const double without = agreement(rasterNormals(untransformed_), baked, onPlane_);
    std::printf("rasterizer normals within 3 deg of the baked twin's: transformed %.4f, untransformed %.4f\n", same,
                without);
    // Only pixels whose centre falls within float rounding of a texel edge may differ.
    EXPECT_GT(same, 0.97);
    EXPECT_LT(without, 0.5) << "the transform must change the normals, or this test proves nothing";
}

TEST_F(NormalMapTransform, ReferenceTurnsTheTangentFrameWithTheUvs) {
    const std::vector<glm::vec3> baked = referenceNormals(baked_);
    const double same = agreement(referenceNormals(mapped_), baked, onPlane_);
    const double without = agreement(referenceNormals(untransformed_), baked, onPlane_);
    const double raster = agreement(referenceNormals(mapped_), rasterNormals(mapped_), onPlane_);
    std::printf("reference normals within 3 deg of the baked twin's: transformed %.4f, untransformed %.4f; of the "
                "rasterizer's %.4f\n",
                same, without, raster);
    EXPECT_GT(same, 0.97);
    EXPECT_LT(without, 0.5);
    EXPECT_GT(raster, 0.95);
}

}  // namespace
}  // namespace lit::test
