// The radiance volume's mip chain (MipmapPass). The volume holds premultiplied radiance
// (rgb = radiance × opacity, a = opacity), and a parent stacks its 2×2×2 children along the axis
// where they are most opaque (directional opacity, mipmap.comp.glsl and docs/GI.md "Mipmaps"):
// per axis, each of the 4 child pairs along it is composited front to back in both orders,
//   a = 1 − (1 − a1)(1 − a2),   rgb = ((c1 + (1 − a1)c2) + (c2 + (1 − a2)c1)) / 2,
// the 4 pairs are averaged, and the parent is the axis of largest a (tied axes averaged).
// Checked here:
//  - the shader's algebraic form of that formula against the compositing as written (CPU only);
//  - every level of an RGBA8 and an RGBA16F volume against a CPU reference that repeats the
//    shader's arithmetic, each level rounded to the texture format before it feeds the next one.
//    Level 0 holds runs of empty voxels (0, 0), opaque ones (L, 1) and partially transparent
//    ones (a·L, a), so every branch of the reduction (ties, partial opacity) is exercised;
//  - a one-voxel wall along each axis stays opaque with its colour at every level, a lone voxel
//    becomes (C/4^l, 1/4^l), and the edge of an opaque box keeps its colour.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <glm/gtc/packing.hpp>
#include <random>
#include <sstream>

#include "GlTestSupport.h"
#include "gi/MipmapBenchmark.h"
#include "gi/MipmapPass.h"
#include "gi/VoxelVolume.h"
#include "gl/GlError.h"

namespace lit::test {
namespace {

using Level = std::vector<glm::vec4>;  // voxels of one level, x fastest, then y, then z

int edgeOf(const Level& level) { return static_cast<int>(std::lround(std::cbrt(static_cast<double>(level.size())))); }

// `x` rounded to the nearest half float, ties to even (IEEE, as the GPU's packHalf2x16; glm's
// packHalf1x16 rounds ties away from zero, and the sums of half floats the reduction makes hit
// ties often: 2-6 % of the values of a level came out one step apart). Values past the half range
// (65504) are not expected here and are clamped to it.
float roundToHalf(float x) {
    if (x == 0.0f || !std::isfinite(x)) return x;
    int exponent = 0;
    // |x| = m·2^exponent with m in [0.5, 1): the half-float step there is 2^(exponent − 11), and
    // 2^-24 for subnormal halves. nearbyint rounds in the default mode, to nearest, ties to even.
    std::frexp(x, &exponent);
    const int step = std::max(exponent - 11, -24);
    const float rounded = std::ldexp(std::nearbyint(std::ldexp(x, -step)), step);
    return std::clamp(rounded, -65504.0f, 65504.0f);
}

// What the texture holds once `v` is stored: RGBA8 rounds to 1/255 (as packUnorm4x8), RGBA16F to
// the nearest half float.
glm::vec4 quantize(glm::vec4 v, bool rgba8) {
    if (rgba8) return glm::round(glm::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
    for (int c = 0; c < 4; ++c) v[c] = roundToHalf(v[c]);
    return v;
}

// Children of a block, index i = x + 2y + 4z, and the 4 pairs along each axis (as the shader).
using Block = std::array<glm::vec4, 8>;
constexpr int kAxisPairs[3][4][2] = {{{0, 1}, {2, 3}, {4, 5}, {6, 7}},   // X
                                     {{0, 2}, {1, 3}, {4, 6}, {5, 7}},   // Y
                                     {{0, 4}, {1, 5}, {2, 6}, {3, 7}}};  // Z

// Σ_pairs a1·a2 along X, Y and Z: how much the children of each axis's pairs overlap.
template <typename Alpha>
glm::vec<3, Alpha> overlapOf(const std::array<Alpha, 8>& a) {
    glm::vec<3, Alpha> overlap;
    for (int axis = 0; axis < 3; ++axis) {
        const auto& p = kAxisPairs[axis];
        overlap[axis] =
            (a[p[0][0]] * a[p[0][1]] + a[p[1][0]] * a[p[1][1]]) + (a[p[2][0]] * a[p[2][1]] + a[p[3][0]] * a[p[3][1]]);
    }
    return overlap;
}

// RGBA8: mipmap.comp.glsl's exact integer reduction on the bytes (C, A) = 255·(rgb, a). For the
// k axes of least overlap P: round((k·510·S − Σ_i C_i·B_i, k·(510·S.a − 2P)) / (2040k)), with
// S = Σ children and B_i = Σ_tied axes A of i's partner (i^1, i^2, i^4), rounded half up.
glm::vec4 reduceBlockRgba8(const Block& c) {
    std::array<glm::uvec4, 8> b{};
    std::array<unsigned, 8> alpha{};
    glm::uvec4 s(0u);
    for (int i = 0; i < 8; ++i) {
        b[i] = glm::uvec4(glm::round(glm::clamp(c[i], 0.0f, 1.0f) * 255.0f));
        alpha[i] = b[i].w;
        s += b[i];
    }
    const glm::uvec3 overlap = overlapOf(alpha);
    const unsigned least = std::min({overlap.x, overlap.y, overlap.z});
    const glm::bvec3 tied = glm::equal(overlap, glm::uvec3(least));
    const unsigned count = unsigned(tied.x) + unsigned(tied.y) + unsigned(tied.z);
    glm::uvec3 cross(0u);
    for (int i = 0; i < 8; ++i) {
        const unsigned partners =
            (tied.x ? alpha[i ^ 1] : 0u) + (tied.y ? alpha[i ^ 2] : 0u) + (tied.z ? alpha[i ^ 4] : 0u);
        cross += glm::uvec3(b[i]) * partners;
    }
    const glm::uvec4 numerator(count * 510u * glm::uvec3(s) - cross, count * (510u * s.w - 2u * least));
    const unsigned scale = count == 1 ? 6u : count == 2 ? 3u : 2u;
    return glm::vec4(glm::min((numerator * scale + 6120u) / 12240u, glm::uvec4(255u))) / 255.0f;
}

// RGBA16F: the shader's fp32 arithmetic in the same order (the x86-64 baseline has no FMA, so
// nothing is fused here either), so both choose the same axes and round alike. Not yet rounded
// to half floats.
glm::vec4 reduceBlockFloat(const Block& c) {
    const glm::vec4 s = ((c[0] + c[1]) + (c[2] + c[3])) + ((c[4] + c[5]) + (c[6] + c[7]));
    std::array<float, 8> alpha{};
    for (int i = 0; i < 8; ++i) alpha[i] = c[i].w;
    const glm::vec3 overlap = overlapOf(alpha);
    const float least = std::min({overlap.x, overlap.y, overlap.z});
    const glm::bvec3 tied = glm::equal(overlap, glm::vec3(least));
    const int count = int(tied.x) + int(tied.y) + int(tied.z);
    glm::vec3 cross(0.0f);
    for (int i = 0; i < 8; ++i) {
        const float partners =
            ((tied.x ? alpha[i ^ 1] : 0.0f) + (tied.y ? alpha[i ^ 2] : 0.0f)) + (tied.z ? alpha[i ^ 4] : 0.0f);
        cross = cross + glm::vec3(c[i]) * partners;
    }
    const float scale = count == 1 ? 0.25f : count == 2 ? 0.125f : 0.25f / 3.0f;
    return glm::vec4((float(count) * glm::vec3(s) - 0.5f * cross) * scale, (s.w - least) * 0.25f);
}

glm::vec4 reduceBlock(const Block& c, bool rgba8) {
    return rgba8 ? reduceBlockRgba8(c) : quantize(reduceBlockFloat(c), false);
}

// The reduction as docs/GI.md states it, in double: per axis, composite each pair in both orders
// and average the orders and the 4 pairs; the parent is the axis with the largest opacity, axes
// within 1e-9 of it averaged.
glm::dvec4 stackByCompositing(const std::array<glm::dvec4, 8>& c) {
    std::array<glm::dvec4, 3> axes{};
    for (int axis = 0; axis < 3; ++axis) {
        for (const auto& [front, back] : kAxisPairs[axis]) {
            const glm::dvec4 c1 = c[front], c2 = c[back];
            const glm::dvec3 frontToBack = glm::dvec3(c1) + (1.0 - c1.w) * glm::dvec3(c2);
            const glm::dvec3 backToFront = glm::dvec3(c2) + (1.0 - c2.w) * glm::dvec3(c1);
            axes[axis] += glm::dvec4((frontToBack + backToFront) / 2.0, 1.0 - (1.0 - c1.w) * (1.0 - c2.w));
        }
        axes[axis] /= 4.0;
    }
    const double most = std::max({axes[0].w, axes[1].w, axes[2].w});
    glm::dvec3 rgb(0.0);
    int count = 0;
    for (const glm::dvec4& a : axes)
        if (a.w >= most - 1e-9) rgb += glm::dvec3(a), ++count;
    return glm::dvec4(rgb / double(count), most);
}

// The chain below `level0` (levels 1..log2(n)), each level quantized before the next.
std::vector<Level> referenceChain(const Level& level0, bool rgba8) {
    std::vector<Level> chain;
    const Level* source = &level0;
    for (int n = edgeOf(level0) / 2; n >= 1; n /= 2) {
        Level parent(static_cast<std::size_t>(n) * n * n);
        const int s = n * 2;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    Block children;
                    for (int c = 0; c < 8; ++c) {
                        const int cx = 2 * x + (c & 1), cy = 2 * y + ((c >> 1) & 1), cz = 2 * z + (c >> 2);
                        children[c] = (*source)[(static_cast<std::size_t>(cz) * s + cy) * s + cx];
                    }
                    parent[(static_cast<std::size_t>(z) * n + y) * n + x] = reduceBlock(children, rgba8);
                }
        chain.push_back(std::move(parent));
        source = &chain.back();
    }
    return chain;
}

Level readLevel(const gl::Texture& texture, int level) {
    const int n = std::max(texture.desc().width >> level, 1);
    Level data(static_cast<std::size_t>(n) * n * n);
    glGetTextureImage(texture.id(), level, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(data.size() * sizeof(glm::vec4)),
                      data.data());
    return data;
}

// Level 0 in runs of 1..12 voxels (x fastest), premultiplied: empty (0, 0), opaque (L, 1) or
// partially transparent (a·L, a) with a random per voxel. RGBA8 L in [0,1]; RGBA16F L in [0,4].
// Uploaded in the texture's own format (bytes / half floats) so the returned values are exactly
// what the texture holds.
Level fillLevel0(const VoxelVolume& volume, std::uint32_t seed) {
    const int n = volume.resolution();
    const bool rgba8 = volume.radianceRgba8();
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> runLength(1, 12), kind(0, 2), partialByte(1, 254);
    std::uniform_real_distribution<float> radiance(0.0f, 4.0f), partialAlpha(0.01f, 0.99f);
    Level values(static_cast<std::size_t>(n) * n * n);
    std::vector<std::uint8_t> bytes(rgba8 ? values.size() * 4 : 0);
    std::vector<std::uint16_t> halves(rgba8 ? 0 : values.size() * 4);
    for (std::size_t i = 0; i < values.size();) {
        const int k = kind(rng);  // 0 empty, 1 opaque, 2 partial
        for (int r = runLength(rng); r > 0 && i < values.size(); --r, ++i) {
            if (rgba8) {
                const int alpha = k == 0 ? 0 : k == 1 ? 255 : partialByte(rng);
                for (int c = 0; c < 4; ++c) {
                    // Premultiplied: a colour byte is at most the alpha byte.
                    const int b = c == 3 ? alpha : std::uniform_int_distribution<int>(0, alpha)(rng);
                    bytes[i * 4 + c] = static_cast<std::uint8_t>(b);
                    values[i][c] = static_cast<float>(b) / 255.0f;
                }
            } else {
                const float alpha = k == 0 ? 0.0f : k == 1 ? 1.0f : partialAlpha(rng);
                for (int c = 0; c < 4; ++c) {
                    halves[i * 4 + c] = glm::packHalf1x16(c == 3 ? alpha : radiance(rng) * alpha);
                    values[i][c] = glm::unpackHalf1x16(halves[i * 4 + c]);
                }
            }
        }
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (rgba8)
        glTextureSubImage3D(volume.radiance().id(), 0, 0, 0, 0, n, n, n, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    else
        glTextureSubImage3D(volume.radiance().id(), 0, 0, 0, 0, n, n, n, GL_RGBA, GL_HALF_FLOAT, halves.data());
    return values;
}

// RGBA8: within one step of 1/255 per channel (the GPU's float sums may round a value the other
// way, and that can carry into the next level by at most one step). RGBA16F: within two half-float
// ulps of the value (2^-10 relative each), plus a floor for values near zero.
float tolerance(float reference, bool rgba8) {
    return rgba8 ? 1.0f / 255.0f + 1e-6f : std::abs(reference) * (2.0f / 1024.0f) + 1e-6f;
}

// One rounding step of the format near x: 1/255 for RGBA8; for half floats 2^-24 below 2^-14
// (subnormals), else 2^-10 of the power of two at or below x.
float formatStep(float x, bool rgba8) {
    if (rgba8) return 1.0f / 255.0f;
    x = std::abs(x);
    if (x < std::ldexp(1.0f, -14)) return std::ldexp(1.0f, -24);
    int exponent = 0;
    std::frexp(x, &exponent);  // x = m·2^exponent, m in [0.5, 1)
    return std::ldexp(1.0f, exponent - 11);
}

// Compares every level 1.. of `texture` with `reference`; returns a description of the failures.
std::string compareChain(const gl::Texture& texture, const std::vector<Level>& reference, bool rgba8) {
    std::ostringstream failures;
    for (std::size_t l = 0; l < reference.size(); ++l) {
        const int level = static_cast<int>(l) + 1;
        const Level gpu = readLevel(texture, level);
        const int n = edgeOf(gpu);
        std::size_t bad = 0;
        float worst = 0.0f;
        std::string first;
        for (std::size_t i = 0; i < gpu.size(); ++i)
            for (int c = 0; c < 4; ++c) {
                const float diff = std::abs(gpu[i][c] - reference[l][i][c]);
                worst = std::max(worst, diff);
                if (diff <= tolerance(reference[l][i][c], rgba8)) continue;
                if (bad++ == 0) {
                    std::ostringstream s;
                    s << " first at (" << i % n << "," << (i / n) % n << "," << i / n / n << ") channel " << c
                      << ": GPU " << gpu[i][c] << ", reference " << reference[l][i][c];
                    first = s.str();
                }
            }
        if (bad)
            failures << "level " << level << " (" << n << "³): " << bad << " channels off, worst " << worst << ";"
                     << first << "\n";
    }
    return failures.str();
}

// The shader's form (S − ½·Σ_i c_i·a_partner(i), integers for RGBA8) against the compositing as
// written (both orders, in double), on random blocks of empty, opaque and partial voxels with
// colour up to the alpha (premultiplied). RGBA8 gets bytes and may be off by its final rounding
// (half a step); the fp32 form (not yet rounded to half floats) by fp32 error.
TEST(MipmapFormula, ShaderFormEqualsCompositingInBothOrders) {
    std::mt19937 rng(99u);
    std::uniform_int_distribution<int> kind(0, 2), byte(1, 254);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int partialBlocks = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const bool rgba8 = trial % 2 == 0;
        Block block;
        std::array<glm::dvec4, 8> exact;
        bool partial = false;
        for (int i = 0; i < 8; ++i) {
            const int k = kind(rng);  // 0 empty, 1 opaque, 2 partial
            partial |= k == 2;
            // Partial opacities are multiples of 1/256 for RGBA16F, so the fp32 form computes exact
            // ties (as the double form does) and both choose the same axes.
            const float alpha = k == 0 ? 0.0f : k == 1 ? 1.0f : float(byte(rng)) / (rgba8 ? 255.0f : 256.0f);
            glm::vec4 v(unit(rng) * alpha, unit(rng) * alpha, unit(rng) * alpha, alpha);
            if (rgba8) v = quantize(v, true);
            block[i] = v;
            exact[i] = rgba8 ? glm::dvec4(glm::round(glm::dvec4(v) * 255.0)) / 255.0 : glm::dvec4(v);
        }
        partialBlocks += partial;
        const glm::dvec4 want = stackByCompositing(exact);
        const glm::vec4 got = rgba8 ? reduceBlockRgba8(block) : reduceBlockFloat(block);
        for (int c = 0; c < 4; ++c)
            ASSERT_NEAR(got[c], want[c], rgba8 ? 0.5 / 255.0 + 1e-6 : 1e-6)
                << (rgba8 ? "RGBA8" : "RGBA16F") << " trial " << trial << " channel " << c;
    }
    EXPECT_GT(partialBlocks, 3000);
}

class Mipmap : public ContextFixture {
protected:
    void SetUp() override {
        ContextFixture::SetUp();
        if (HasFatalFailure()) return;
        pass_ = std::make_unique<MipmapPass>(sourceDir() / "shaders");
    }

    Log log_;
    std::unique_ptr<MipmapPass> pass_;
};

struct ChainCase {
    const char* name;
    bool rgba8;
    int resolution;
};

// gtest prints the case by name instead of its bytes.
void PrintTo(const ChainCase& c, std::ostream* os) { *os << c.name; }

class MipmapChain : public Mipmap, public ::testing::WithParamInterface<ChainCase> {};

TEST_P(MipmapChain, EveryLevelMatchesTheCpuReference) {
    VoxelVolume volume;
    volume.ensure(GetParam().resolution, GetParam().rgba8, log_);
    ASSERT_EQ(volume.resolution(), GetParam().resolution);
    ASSERT_EQ(volume.mipCount(), static_cast<int>(std::log2(GetParam().resolution)) + 1);
    const Level level0 = fillLevel0(volume, 20240611u);
    pass_->execute(volume);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const std::string failures =
        compareChain(volume.radiance(), referenceChain(level0, GetParam().rgba8), GetParam().rgba8);
    EXPECT_TRUE(failures.empty()) << failures;
}

INSTANTIATE_TEST_SUITE_P(Formats, MipmapChain,
                         ::testing::Values(ChainCase{"Rgba8_64", true, 64}, ChainCase{"Rgba16f_64", false, 64},
                                           ChainCase{"Rgba8_128", true, 128}, ChainCase{"Rgba16f_128", false, 128}),
                         [](const ::testing::TestParamInfo<ChainCase>& info) { return std::string(info.param.name); });

class MipmapFormat : public Mipmap, public ::testing::WithParamInterface<bool> {};

// One opaque voxel (C, 1) with empty neighbours. Along any axis one of the 4 child pairs of its
// parent holds it and stacks to a = 1, the others are empty, and all three axes tie: the parent is
// (C/4, 1/4), and at level l (C·4^-l, 4^-l), the share of the cross-section the voxel covers.
// (A plain average gave 8^-l.) Its colour rgb/a stays C, not darkened by the empty space around
// it. Every level's stored values are compared with that chain rounded per level, and rgb/a with C
// within the rounding the format allows (the bound adds, per level, one step of rgb and C times one
// step of a, divided by a). RGBA8 (a = 64, 16, 4, 1, 0 /255) resolves rgb/a to level 2; RGBA16F
// holds 4^-l exactly and is checked at every level.
TEST_P(MipmapFormat, OpaqueVoxelNextToEmptySpaceKeepsItsColour) {
    const bool rgba8 = GetParam();
    VoxelVolume volume;
    volume.ensure(64, rgba8, log_);  // every level starts cleared to 0
    const glm::ivec3 voxel(5, 6, 7);
    const glm::vec4 colour(0.8f, 0.4f, 0.2f, 1.0f);  // RGBA8 (204, 102, 51, 255)
    glTextureSubImage3D(volume.radiance().id(), 0, voxel.x, voxel.y, voxel.z, 1, 1, 1, GL_RGBA, GL_FLOAT, &colour);
    pass_->execute(volume);

    const glm::vec4 stored = quantize(colour, rgba8);  // level 0 as the texture holds it
    glm::vec4 expected = stored;
    glm::vec3 ratioTolerance(0.0f);
    const int ratioLevels = rgba8 ? 2 : volume.mipCount() - 1;
    for (int level = 1; level < volume.mipCount(); ++level) {
        expected = quantize(expected / 4.0f, rgba8);
        const float exactAlpha = std::pow(1.0f / 4.0f, static_cast<float>(level));
        if (!rgba8) {
            EXPECT_EQ(expected.a, exactAlpha) << "level " << level;
        }
        for (int c = 0; c < 3; ++c)
            ratioTolerance[c] +=
                (formatStep(stored[c] * exactAlpha, rgba8) + stored[c] * formatStep(exactAlpha, rgba8)) / exactAlpha;

        const Level data = readLevel(volume.radiance(), level);
        const int n = edgeOf(data);
        const glm::ivec3 parent = voxel >> level;
        for (int i = 0; i < static_cast<int>(data.size()); ++i) {
            const glm::ivec3 p(i % n, (i / n) % n, i / n / n);
            const glm::vec4 v = data[static_cast<std::size_t>(i)];
            if (p != parent) {
                ASSERT_EQ(v, glm::vec4(0.0f)) << "level " << level << " voxel " << p.x << "," << p.y << "," << p.z;
                continue;
            }
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(v[c], expected[c], tolerance(expected[c], rgba8)) << "level " << level << " channel " << c;
            if (level > ratioLevels) continue;
            ASSERT_GT(v.a, 0.0f) << "level " << level;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(v[c] / v.a, stored[c], ratioTolerance[c])
                    << "level " << level << " channel " << c << ": rgb/a must stay the voxel's colour (rgb " << v[c]
                    << ", a " << v.a << ")";
        }
    }
    if (rgba8) {
        // In bytes: 255 → 64 → 16 → 4 → 1 → 0 (each a quarter, rounded half up).
        const int alphaBytes[] = {64, 16, 4, 1, 0};
        for (int level = 1; level <= 5; ++level) {
            const Level data = readLevel(volume.radiance(), level);
            const int n = edgeOf(data);
            const glm::ivec3 p = voxel >> level;
            const float alpha = data[(static_cast<std::size_t>(p.z) * n + p.y) * n + p.x].a;
            EXPECT_EQ(std::lround(alpha * 255.0f), alphaBytes[level - 1]) << "alpha byte at level " << level;
        }
    }
}

// A one-voxel-thick opaque wall of colour C: the plane {p : p[axis] = 21} of a 64³ volume, for
// each axis in turn. Along the wall's normal every child pair of a block holds one wall voxel and
// one empty one and stacks to a = 1 with colour C, so the wall stays opaque, one voxel thick and
// exactly C at every level down to the last (1³) voxel, and everything else stays empty. (A plain
// average made it 2^-l opaque at level l, and wide cones saw through it.)
TEST_P(MipmapFormat, OneVoxelWallStaysOpaqueAtEveryLevel) {
    const bool rgba8 = GetParam();
    constexpr int kResolution = 64, kWall = 21;
    const glm::vec4 colour(0.8f, 0.4f, 0.2f, 1.0f);
    const glm::vec4 stored = quantize(colour, rgba8);
    for (int axis = 0; axis < 3; ++axis) {
        SCOPED_TRACE("wall normal to axis " + std::to_string(axis));
        VoxelVolume volume;
        volume.ensure(kResolution, rgba8, log_);  // every level starts cleared to 0
        glm::ivec3 offset(0), size(kResolution);
        offset[axis] = kWall;
        size[axis] = 1;
        const std::vector<glm::vec4> wall(static_cast<std::size_t>(kResolution) * kResolution, colour);
        glTextureSubImage3D(volume.radiance().id(), 0, offset.x, offset.y, offset.z, size.x, size.y, size.z, GL_RGBA,
                            GL_FLOAT, wall.data());
        pass_->execute(volume);
        for (int level = 1; level < volume.mipCount(); ++level) {
            const Level data = readLevel(volume.radiance(), level);
            const int n = edgeOf(data);
            int wrong = 0;
            // A stream rather than a chain of std::string operator+: GCC 12 at -O3 (Release) reports
            // a false -Wrestrict inside `"(" + std::string&&` (its string insert), an error with -Werror.
            std::ostringstream first;
            for (int i = 0; i < static_cast<int>(data.size()); ++i) {
                const glm::ivec3 p(i % n, (i / n) % n, i / n / n);
                const glm::vec4 want = p[axis] == kWall >> level ? stored : glm::vec4(0.0f);
                const glm::vec4 v = data[static_cast<std::size_t>(i)];
                // Exact in the formula; 1e-6 for the GPU's and the CPU's byte → float conversions.
                if (glm::all(glm::lessThanEqual(glm::abs(v - want), glm::vec4(1e-6f)))) continue;
                if (wrong++ == 0)
                    first << "(" << p.x << "," << p.y << "," << p.z << ") = " << v.r << "," << v.g << "," << v.b << ","
                          << v.a << ", want " << want.r << ",...," << want.a;
            }
            EXPECT_EQ(wrong, 0) << "level " << level << ": first " << first.str();
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Formats, MipmapFormat, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& info) { return info.param ? "Rgba8" : "Rgba16f"; });

// An opaque box of colour C, (C, 1), in empty space (RGBA16F). Its faces are not aligned to any
// power of two; stacked across a face a parent is opaque, but along its edges and corners every
// level has voxels it covers partly (0 < a < 1). Each of them must keep colour C: rgb/a = C. The
// bound: each level rounds rgb and a by at most a half-float step (2^-11 relative) each, and the
// GPU may round the other way, so 2^-9 of C per level; errors of lower levels carry over
// unchanged, because a parent's colour is a weighted mean of its children's (pair weights
// a1(1 − a2/2) and a2(1 − a1/2)).
TEST_F(Mipmap, EdgeOfAnOpaqueRegionKeepsItsColourAtEveryLevel) {
    VoxelVolume volume;
    volume.ensure(64, false, log_);                  // every level starts cleared to 0
    const glm::ivec3 lo(11, 5, 19), hi(45, 50, 64);  // the box, [lo, hi) in voxels
    const glm::vec3 colour(3.0f, 0.75f, 0.125f);     // exact in half floats
    const glm::ivec3 size = hi - lo;
    const std::vector<glm::vec4> box(static_cast<std::size_t>(size.x) * size.y * size.z, glm::vec4(colour, 1.0f));
    glTextureSubImage3D(volume.radiance().id(), 0, lo.x, lo.y, lo.z, size.x, size.y, size.z, GL_RGBA, GL_FLOAT,
                        box.data());
    pass_->execute(volume);

    for (int level = 1; level < volume.mipCount(); ++level) {
        const Level data = readLevel(volume.radiance(), level);
        const int n = edgeOf(data);
        const float relativeTolerance = static_cast<float>(level) / 512.0f;
        int covered = 0, partial = 0;
        for (int i = 0; i < static_cast<int>(data.size()); ++i) {
            const glm::vec4 v = data[static_cast<std::size_t>(i)];
            if (v.a <= 0.0f) continue;
            ++covered;
            partial += v.a < 1.0f;
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(v[c] / v.a, colour[c], colour[c] * relativeTolerance)
                    << "level " << level << " voxel " << i % n << "," << (i / n) % n << "," << i / n / n << " channel "
                    << c << " (rgb " << v[c] << ", a " << v.a << ")";
        }
        EXPECT_GT(partial, 0) << "level " << level << " has no edge voxel to check";
        EXPECT_GT(covered, 0) << "level " << level;
    }
}

TEST_F(Mipmap, RejectsVolumesItCannotReduce) {
    const auto message = [&](const gl::Texture& texture) {
        try {
            pass_->execute(texture);
        } catch (const gl::GlError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(gl::Texture("flat", {GL_TEXTURE_2D, GL_RGBA8, 64, 64, 1, 7})),
              "MipmapPass: the volume must be a GL_TEXTURE_3D");
    EXPECT_EQ(message(gl::Texture("float32", {GL_TEXTURE_3D, GL_RGBA32F, 8, 8, 8, 4})),
              "MipmapPass: the volume must be GL_RGBA8 or GL_RGBA16F, not format 0x8814");
    EXPECT_EQ(message(gl::Texture("box", {GL_TEXTURE_3D, GL_RGBA8, 16, 8, 8, 5})),
              "MipmapPass: the volume must be a cube with a power-of-two side, not 16×8×8");
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The benchmark runs glGenerateTextureMipmap on the same texture, a box filter: the same
// reduction, with the driver's rounding. The chain it leaves behind must match the reference.
// (On llvmpipe the RGBA8 glGenerateTextureMipmap chain is up to 2/255 off the reference at level 2
// and 4/255 at levels 4-6, so a chain that was not rebuilt fails here.)
TEST_F(Mipmap, BenchmarkLeavesTheComputeChainInPlace) {
    VoxelVolume volume;
    volume.ensure(64, true, log_);
    const Level level0 = fillLevel0(volume, 7u);
    const MipmapTimings timings = benchmarkMipmaps(*pass_, volume, 2);
    EXPECT_EQ(timings.resolution, 64);
    EXPECT_TRUE(timings.rgba8);
    EXPECT_EQ(timings.repetitions, 2);
    EXPECT_GT(timings.computeMedianMs, 0.0);
    EXPECT_GT(timings.generateMedianMs, 0.0);
    EXPECT_LE(timings.computeMinMs, timings.computeMedianMs);
    EXPECT_LE(timings.generateMinMs, timings.generateMedianMs);
    const std::string failures = compareChain(volume.radiance(), referenceChain(level0, true), true);
    EXPECT_TRUE(failures.empty()) << failures;
}

// Timings for tuning, not a check: run with --gtest_also_run_disabled_tests
// --gtest_filter='*MipmapTimings*'. Prints benchmarkMipmaps at 128³ and 256³ for both formats.
TEST_F(Mipmap, DISABLED_MipmapTimings) {
    for (const int resolution : {128, 256})
        for (const bool rgba8 : {true, false}) {
            VoxelVolume volume;
            volume.ensure(resolution, rgba8, log_);
            fillLevel0(volume, 1u);
            const MipmapTimings t = benchmarkMipmaps(*pass_, volume, 7);
            std::printf(
                "%d³ %-7s compute min %7.2f median %7.2f cpu %7.2f ms | glGenerateTextureMipmap min %7.2f "
                "median %7.2f cpu %7.2f ms | speedup %.2f\n",
                resolution, rgba8 ? "RGBA8" : "RGBA16F", t.computeMinMs, t.computeMedianMs, t.computeCpuMedianMs,
                t.generateMinMs, t.generateMedianMs, t.generateCpuMedianMs, t.speedup());
        }
}

}  // namespace
}  // namespace lit::test
