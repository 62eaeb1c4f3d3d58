#pragma once
// What the glTF import keeps of a file without drawing it, for a lossless save (scene/Scene.h:
// KeptAccessor and friends; internal to the glTF import): vertex attributes besides POSITION,
// NORMAL, TEXCOORD_0 and TANGENT, morph targets, primitives of other modes, skins, animations,
// names, extras and extensions of accessors, buffer views and buffers, the other scenes and the
// buffers' layout. Unreadable kept data is reported and left out; the load goes on.

#include "scene/GltfImportDetail.h"

#include <cstddef>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lit::gltfimport {

// A buffer view's name, extras and extensions (empty for an invalid index).
KeptObject keptView(const GltfSource& source, int index);
// An accessor's name, extras, extensions, min/max and place in the file (empty for an invalid index).
KeptAccessorInfo keptAccessorInfo(const GltfSource& source, int index);
// An accessor's elements, any type, sparse ones expanded, for data Lit keeps without using.
// `expectedCount`: the element count the accessor must have (attributes: the vertex count);
// without one the accessor must have a buffer view (so its size is bounded by the file).
KeptAccessor keptAccessor(const GltfSource& source, int index, const std::string& role,
                          std::optional<std::size_t> expectedCount);
// The attributes of `attributes` except those named in `skip`; an unreadable one is reported
// and left out.
KeptAttributes keptAttributes(const GltfSource& source, const std::map<std::string, int>& attributes,
                              std::initializer_list<std::string_view> skip, const std::string& where,
                              std::size_t vertexCount);
// A primitive's morph targets, each as keptAttributes.
std::vector<KeptAttributes> keptTargets(const GltfSource& source, const tinygltf::Primitive& in,
                                        const std::string& where, std::size_t vertexCount);
// A primitive of a mode Lit does not draw, as the file had it; none when its data is unusable.
std::optional<KeptPrimitive> keptPrimitive(const GltfSource& source, const tinygltf::Primitive& in,
                                           const std::string& where);

// `nodeRefs`: each file node's node reference in the Scene (scene/Scene.h: keptNodeRef).
void importSkins(const GltfSource& source, const std::vector<int>& nodeRefs, Scene& scene);
void importAnimations(const GltfSource& source, const std::vector<int>& nodeRefs, Scene& scene);
// The file-level data Lit does not use (scenes, asset, buffers and their layout, extensions).
void keepFileData(const GltfSource& source, const std::vector<int>& nodeRefs, Scene& scene);

}  // namespace lit::gltfimport
