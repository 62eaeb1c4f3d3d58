#pragma once
// Image regions for measuring GI accuracy, defined once for the accuracy benchmark
// (tools/gi_accuracy) and the GL tests that compare the cone tracer with the reference: masks over
// the pixels of an image rendered through a given camera, from the reference's first hits at the
// pixel centres (the rasterizer's G-buffer sees the same surfaces there).
//
// A pixel is *lit only indirectly* when its surface is not emissive and no punctual light reaches
// it (FirstHit::litBy == 0: outside every cone and range, facing away, or occluded); *directly lit*
// when at least one does. Named regions of the Cornell box (assets/cornell_box.gltf, found by node
// name) are those the GI accuracy bars name: the ceiling, the shadowed floor next to the red wall
// and next to the green wall, and the back wall above the blocks (all lit only indirectly by its
// down-pointing spot).

#include "reference/PathTracer.h"

#include <string>
#include <vector>

namespace lit {
struct Scene;
}

namespace lit::reference {

using PixelMask = std::vector<bool>;  // one per pixel, rows bottom-up like the images

struct NamedRegion {
    std::string name;
    PixelMask mask;
    std::size_t pixels() const;
};

PixelMask indirectOnlyMask(const std::vector<FirstHit>& hits);
PixelMask directlyLitMask(const std::vector<FirstHit>& hits);
PixelMask surfaceMask(const std::vector<FirstHit>& hits);  // every pixel that sees a surface
// Pixels of the nodes called `nodeName` (exact scene node name).
PixelMask nodeMask(const Scene& scene, const std::vector<FirstHit>& hits, const std::string& nodeName);
// `mask` without pixels within `radius` pixels of a pixel that sees another node or another set
// of lights (shadow edges, silhouettes), for comparisons that must not depend on edge filtering.
PixelMask erodeEdges(const PixelMask& mask, const std::vector<FirstHit>& hits, int width, int height, int radius);

// The Cornell box regions above; a region whose node is missing is left out. The floor's halves are
// named by the wall on their side (the red wall's side found from where the camera sees it). Regions may be
// empty when the camera does not see them.
std::vector<NamedRegion> cornellBoxRegions(const Scene& scene, const std::vector<FirstHit>& hits, int width, int height);

// Mean of linear RGB `rgb` (3 floats per pixel) over a mask; 0 for an empty mask.
glm::dvec3 maskedMean(const std::vector<float>& rgb, const PixelMask& mask);

}  // namespace lit::reference
