// libFuzzer harness over the decoders of compressed glTF geometry alone (scene/GltfMeshopt.h,
// scene/GltfDraco.h), without the JSON around them: every mutation reaches a decoder, where a
// mutation of a whole file (fuzz_gltf_loader.cpp) mostly breaks the JSON or the GLB first.
// Built only by tools/fuzz.sh (`build-decoders`, `run-decoders`); never by the default build.
//
// An input is one header byte and a compressed stream:
//   byte 0, bits 0-1: 0 Draco; 1 meshopt ATTRIBUTES, 2 TRIANGLES, 3 INDICES
//   byte 0, bits 2-3: the meshopt filter (NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL)
//   byte 0, bits 4-7: the meshopt byteStride / 4 (ATTRIBUTES) or 2 << (bit 4) (indices); for
//                     Draco, the POSITION accessor's component type (float, then the integers)
//   bytes 1-2:        the element count (meshopt) or the point count (Draco), little-endian
//   bytes 3-4:        the face count (Draco), little-endian
//   bytes 5...:       the stream (tools/fuzz.sh's seeds: the streams of tests/data/compressed)
// The expected outcomes are success or a SceneLoadError; anything else is a finding.

#include <cstdint>
#include <vector>

#include "scene/GltfDraco.h"
#include "scene/GltfLoader.h"
#include "scene/GltfMeshopt.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 5) return 0;
    const int kind = data[0] & 3;
    const std::size_t count = data[1] | (std::size_t(data[2]) << 8);
    const std::size_t faces = data[3] | (std::size_t(data[4]) << 8);
    const std::vector<unsigned char> stream(data + 5, data + size);
    try {
        if (kind == 0) {
            static const int kTypes[] = {5126, 5120, 5121, 5122, 5123, 5125};
            tinygltf::Model model;
            model.buffers.resize(2);  // the stream; the decoded data
            model.buffers[0].data = stream;
            tinygltf::BufferView view;
            view.buffer = 0;
            view.byteLength = stream.size();
            model.bufferViews.push_back(view);
            tinygltf::Accessor indices;
            indices.type = TINYGLTF_TYPE_SCALAR;
            indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
            indices.count = faces * 3;
            tinygltf::Accessor positions;
            positions.type = TINYGLTF_TYPE_VEC3;
            positions.componentType = kTypes[(data[0] >> 4) % 6];
            positions.count = count;
            model.accessors = {indices, positions};
            tinygltf::Primitive primitive;
            primitive.indices = 0;
            primitive.attributes["POSITION"] = 1;
            primitive.mode = TINYGLTF_MODE_TRIANGLES;
            const nlohmann::json extension = {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}};
            lit::gltfimport::decodeDracoPrimitive("fuzz", extension, primitive, model, 1);
        } else {
            static const char* kModes[] = {"", "ATTRIBUTES", "TRIANGLES", "INDICES"};
            static const char* kFilters[] = {"NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL"};
            const std::size_t stride = kind == 1 ? 4 * (1 + (data[0] >> 4)) : std::size_t(2) << ((data[0] >> 4) & 1);
            const nlohmann::json extension = {{"buffer", 0},          {"byteLength", stream.size()},
                                              {"byteStride", stride}, {"count", count},
                                              {"mode", kModes[kind]}, {"filter", kFilters[(data[0] >> 2) & 3]}};
            std::vector<unsigned char> destination(count * stride);
            lit::gltfimport::decodeMeshoptView("fuzz", extension, stream.data(), stream.size(), destination.data(),
                                               destination.size());
        }
    } catch (const lit::SceneLoadError&) {
    }
    return 0;
}
