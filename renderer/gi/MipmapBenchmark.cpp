#include "gi/MipmapBenchmark.h"

#include <algorithm>
#include <array>
#include <ctime>
#include <functional>

#include "gi/MipmapPass.h"
#include "gi/VoxelVolume.h"
#include "gl/Handle.h"

namespace lit {

namespace {

struct Runs {
    std::vector<double> gpuMs, cpuMs;
};

// Times `work` with a GL_TIMESTAMP pair (GPU ms) and the process CPU clock (ms, all threads).
void timeOnce(const std::function<void()>& work, Runs& runs) {
    std::array<GLuint, 2> ids{};
    glCreateQueries(GL_TIMESTAMP, 2, ids.data());
    const gl::QueryHandle begin(ids[0]), end(ids[1]);
    glFinish();  // the previous run must not overlap this one
    const std::clock_t cpuStart = std::clock();
    glQueryCounter(begin.id(), GL_TIMESTAMP);
    work();
    glQueryCounter(end.id(), GL_TIMESTAMP);
    glFinish();
    const std::clock_t cpuEnd = std::clock();
    GLuint64 t0 = 0, t1 = 0;
    glGetQueryObjectui64v(begin.id(), GL_QUERY_RESULT, &t0);
    glGetQueryObjectui64v(end.id(), GL_QUERY_RESULT, &t1);
    runs.gpuMs.push_back(t1 >= t0 ? static_cast<double>(t1 - t0) * 1e-6 : 0.0);
    runs.cpuMs.push_back(static_cast<double>(cpuEnd - cpuStart) * 1000.0 / CLOCKS_PER_SEC);
}

double minOf(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }
double medianOf(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t mid = v.size() / 2;
    return v.size() % 2 ? v[mid] : 0.5 * (v[mid - 1] + v[mid]);
}

}  // namespace

MipmapTimings benchmarkMipmaps(MipmapPass& pass, VoxelVolume& volume, int repetitions, bool anisotropic) {
    MipmapTimings t;
    t.resolution = volume.resolution();
    t.rgba8 = volume.radianceRgba8();
    t.repetitions = std::clamp(repetitions, 1, 100);
    t.anisotropic = anisotropic;
    const bool lists = volume.parentListsValid();
    const GLuint texture = volume.radiance().id();
    // Each entry: what it runs and where its runs go; skipped when `runs` is null.
    Runs compute, occupied, generate, directional, directionalOccupied;
    struct Method {
        std::function<void()> work;
        Runs* runs;
    };
    const std::vector<Method> methods{
        {[&] { pass.execute(volume, false, false); }, &compute},
        {[&] { pass.execute(volume, false, true); }, lists ? &occupied : nullptr},
        {[&] { glGenerateTextureMipmap(texture); }, &generate},
        {[&] { pass.executeDirectional(volume, false); }, anisotropic ? &directional : nullptr},
        {[&] { pass.executeDirectional(volume, true); }, anisotropic && lists ? &directionalOccupied : nullptr},
    };
    // Warm-up: llvmpipe compiles the blit shaders of glGenerateMipmap on first use (~0.25 s).
    for (const Method& m : methods) {
        Runs ignored;
        if (m.runs) timeOnce(m.work, ignored);
    }
    for (int i = 0; i < t.repetitions; ++i)
        for (const Method& m : methods)
            if (m.runs) timeOnce(m.work, *m.runs);
    // Leave execute()'s chains in place, rounded as the cone tracer expects.
    pass.execute(volume, anisotropic, false);

    t.computeMinMs = minOf(compute.gpuMs);
    t.computeMedianMs = medianOf(compute.gpuMs);
    t.computeCpuMedianMs = medianOf(compute.cpuMs);
    t.generateMinMs = minOf(generate.gpuMs);
    t.generateMedianMs = medianOf(generate.gpuMs);
    t.generateCpuMedianMs = medianOf(generate.cpuMs);
    t.occupiedMinMs = minOf(occupied.gpuMs);
    t.occupiedMedianMs = medianOf(occupied.gpuMs);
    t.occupiedCpuMedianMs = medianOf(occupied.cpuMs);
    t.directionalMinMs = minOf(directional.gpuMs);
    t.directionalMedianMs = medianOf(directional.gpuMs);
    t.directionalOccupiedMinMs = minOf(directionalOccupied.gpuMs);
    t.directionalOccupiedMedianMs = medianOf(directionalOccupied.gpuMs);
    t.computeRunsMs = compute.gpuMs;
    t.occupiedRunsMs = occupied.gpuMs;
    t.directionalRunsMs = directional.gpuMs;
    t.directionalOccupiedRunsMs = directionalOccupied.gpuMs;
    return t;
}

}  // namespace lit
