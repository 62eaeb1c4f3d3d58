#pragma once
// The checks a glTF file's data must pass before the import reads it (internal to the glTF
// import): accessors, buffer views, index values, node trees and texture references (extensions
// are checked before parsing, scene/GltfExtensions.h). tinygltf 2.7 checks little of what it
// hands over, and a bad file must give a SceneLoadError naming the problem, never a crash or a
// read past a buffer.

#include "scene/GltfImportDetail.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace lit::gltfimport {

// A validated view of an accessor's elements.
struct AccessorData {
    const unsigned char* first = nullptr;  // first element
    std::size_t count = 0;
    std::size_t stride = 0;  // bytes between consecutive elements
    int componentType = 0;
    int components = 0;
    bool normalized = false;

    // Component c of element i as float, normalised integers mapped to [0,1] / [-1,1].
    float component(std::size_t i, int c) const;
    // Component 0 of element i as an unsigned integer (index data).
    std::uint32_t index(std::size_t i) const;
};

// Accessor `index` of type `expectedType` (not sparse, in a buffer view inside its buffer, every
// element inside the view); `role` names its use in messages ("POSITION of mesh 'a' primitive 0").
AccessorData readAccessor(const GltfSource& source, int index, int expectedType, const std::string& role);

// A validated pointer to `count` elements of `elementSize` bytes in buffer view `viewIndex`
// starting `byteOffset` bytes in, and the bytes between them (the view's byteStride where
// `strided`, else elementSize). `what` names the accessor in messages.
std::pair<const unsigned char*, std::size_t> viewElements(const GltfSource& source, const std::string& what,
                                                          int viewIndex, std::size_t byteOffset,
                                                          std::size_t elementSize, std::size_t count, bool strided);

// The values of index accessor `accessor` of a primitive with `vertexCount` vertices: an
// unsigned integer type, every value a vertex. `where` names the primitive in messages.
std::vector<std::uint32_t> readIndices(const GltfSource& source, int accessor, std::size_t vertexCount,
                                       const std::string& where);

// Every node's parent (-1 for none), with every child index checked, one parent per node and no
// cycle.
std::vector<int> checkNodeTree(const GltfSource& source);

// A material's texture reference (-1 for none), checked against the file's textures.
int checkedTextureIndex(const GltfSource& source, int index, const std::string& what);

// "node 3 ('hip')" for messages.
std::string describeNode(const tinygltf::Model& model, std::size_t index);
// "VEC3" for TINYGLTF_TYPE_VEC3; "unknown" for anything else.
const char* typeName(int type);
// Components of a SCALAR or VECn accessor type, 0 for others.
int componentsOf(int type);
// Components per element of an accessor type (matrices included), 0 for an unknown type.
int elementComponents(int type);

}  // namespace lit::gltfimport
