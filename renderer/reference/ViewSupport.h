#pragma once
// Which RenderSettings views the reference path tracer renders: the final image and the four
// lighting terms. The data views (albedo, normals, shadow map, voxels) are the rasterizer's own.

#include "RenderSettings.h"

namespace lit::reference {

inline bool referenceRendersView(View view) {
    return view == View::Final || view == View::DirectDiffuse || view == View::DirectSpecular ||
           view == View::IndirectDiffuse || view == View::IndirectSpecular;
}

}  // namespace lit::reference
