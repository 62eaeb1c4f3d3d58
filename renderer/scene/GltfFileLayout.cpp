// Laying out a saved glTF file's one buffer (scene/GltfFileLayout.h).

#include "scene/GltfFileLayout.h"

#include "scene/GltfKeep.h"
#include "scene/Scene.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace lit::gltfexport {

// Moves every buffer's bytes into buffer 0 (the camera path animation brings a buffer of its
// own), so the scene is one .bin or one BIN chunk.
void mergeBuffers(tinygltf::Model& model) {
    if (model.buffers.size() < 2) return;
    std::vector<unsigned char>& first = model.buffers[0].data;
    std::vector<std::size_t> offset(model.buffers.size(), 0);
    for (std::size_t i = 1; i < model.buffers.size(); ++i) {
        first.resize((first.size() + 3) & ~std::size_t(3), 0);
        offset[i] = first.size();
        first.insert(first.end(), model.buffers[i].data.begin(), model.buffers[i].data.end());
    }
    for (tinygltf::BufferView& view : model.bufferViews) {
        if (view.buffer <= 0) continue;
        view.byteOffset += offset[static_cast<std::size_t>(view.buffer)];
        view.buffer = 0;
    }
    model.buffers.resize(1);
}

// Puts written buffer views whose bytes a view of the source file had (same length and hash,
// Scene::fileBufferViews) at that view's place: the file's buffers one after the other, each
// starting 4-byte aligned, so a file with one buffer keeps its offsets, and an unedited file's
// .bin comes back byte for byte (bytes the file had outside every view are written as zeros).
// A place is taken only where every accessor using the view stays aligned to its component size
// (glTF §3.6.2.4) and it agrees with the views already placed where they overlap (views the
// file let share bytes share them again). The other views (edited or new data) go into the gaps
// that are large enough, 4-byte aligned, else after the end. Runs on the merged buffer 0.
void keepFileLayout(tinygltf::Model& model, const Scene& scene) {
    if (model.buffers.size() != 1 || scene.fileBufferViews.empty()) return;
    for (const tinygltf::BufferView& view : model.bufferViews)  // mergeBuffers made them so; else leave the layout
        if (view.buffer != 0 || view.byteOffset > model.buffers[0].data.size() ||
            view.byteLength > model.buffers[0].data.size() - view.byteOffset)
            return;
    const auto align4 = [](std::size_t n) { return (n + 3) & ~std::size_t(3); };
    std::vector<std::size_t> base(scene.fileBufferSizes.size(), 0);
    for (std::size_t b = 0, end = 0; b < base.size(); ++b) {
        base[b] = align4(end);
        end = base[b] + scene.fileBufferSizes[b];
    }
    std::map<std::pair<std::size_t, std::uint64_t>, std::vector<std::size_t>> byContent;  // (length, hash) → file views
    for (std::size_t f = 0; f < scene.fileBufferViews.size(); ++f) {
        const Scene::FileBufferView& v = scene.fileBufferViews[f];
        if (v.buffer >= 0 && static_cast<std::size_t>(v.buffer) < base.size() && v.byteLength > 0)
            byContent[{v.byteLength, v.hash}].push_back(f);
    }
    // What each written view's place must be a multiple of, per accessor: (byteOffset, component size).
    std::vector<std::vector<std::pair<std::size_t, int>>> needs(model.bufferViews.size());
    const auto need = [&](int view, std::size_t offset, int componentType) {
        if (view >= 0 && static_cast<std::size_t>(view) < needs.size())
            needs[static_cast<std::size_t>(view)].emplace_back(offset,
                                                               std::max(gltfkeep::componentBytes(componentType), 1));
    };
    for (const tinygltf::Accessor& a : model.accessors) {
        need(a.bufferView, a.byteOffset, a.componentType);
        if (a.sparse.isSparse) {
            need(a.sparse.indices.bufferView, a.sparse.indices.byteOffset, a.sparse.indices.componentType);
            need(a.sparse.values.bufferView, a.sparse.values.byteOffset, a.componentType);
        }
    }
    const std::vector<unsigned char>& written = model.buffers[0].data;
    constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> place(model.bufferViews.size(), kNone);
    std::vector<char> taken(scene.fileBufferViews.size(), 0);
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
        const tinygltf::BufferView& view = model.bufferViews[v];
        if (view.byteLength == 0) continue;
        const auto it =
            byContent.find({view.byteLength, gltfkeep::hashBytes(written.data() + view.byteOffset, view.byteLength)});
        if (it == byContent.end()) continue;
        const auto fits = [&](std::size_t at) {
            return std::all_of(needs[v].begin(), needs[v].end(),
                               [&](const auto& n) { return (at + n.first) % static_cast<std::size_t>(n.second) == 0; });
        };
        // The first file view of these bytes not taken yet (files write equal data more than once), else a taken one.
        for (int pass = 0; pass < 2 && place[v] == kNone; ++pass)
            for (std::size_t f : it->second) {
                const Scene::FileBufferView& file = scene.fileBufferViews[f];
                const std::size_t at = base[static_cast<std::size_t>(file.buffer)] + file.byteOffset;
                if ((pass == 0 && taken[f]) || !fits(at)) continue;
                place[v] = at;
                taken[f] = 1;
                break;
            }
    }
    std::vector<std::size_t> order;
    for (std::size_t v = 0; v < place.size(); ++v)
        if (place[v] != kNone) order.push_back(v);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return place[a] < place[b]; });
    std::vector<unsigned char> out;
    std::vector<std::pair<std::size_t, std::size_t>> gaps;  // [begin, end) between placed views
    std::size_t end = 0;  // of the placed views so far; [place, end) is inside the view that reached `end`
    for (std::size_t v : order) {
        const tinygltf::BufferView& view = model.bufferViews[v];
        const unsigned char* bytes = written.data() + view.byteOffset;
        const std::size_t at = place[v];
        const std::size_t overlap = at < end ? std::min(end, at + view.byteLength) - at : 0;
        if (overlap > 0 && std::memcmp(out.data() + at, bytes, overlap) != 0) {
            place[v] = kNone;  // shares bytes with a placed view that now differ: written elsewhere
            continue;
        }
        if (at > end) gaps.emplace_back(end, at);
        if (at + view.byteLength > out.size()) out.resize(at + view.byteLength, 0);
        std::memcpy(out.data() + at + overlap, bytes + overlap, view.byteLength - overlap);
        end = std::max(end, at + view.byteLength);
    }
    for (std::size_t v = 0; v < place.size(); ++v) {
        tinygltf::BufferView& view = model.bufferViews[v];
        if (place[v] != kNone) continue;
        std::size_t at = kNone;
        for (auto& gap : gaps)
            if (align4(gap.first) + view.byteLength <= gap.second) {
                at = align4(gap.first);
                gap.first = at + view.byteLength;
                break;
            }
        if (at == kNone) {
            at = align4(out.size());
            out.resize(at, 0);
        }
        if (at + view.byteLength > out.size()) out.resize(at + view.byteLength, 0);
        std::memcpy(out.data() + at, written.data() + view.byteOffset, view.byteLength);
        place[v] = at;
    }
    for (std::size_t v = 0; v < place.size(); ++v) model.bufferViews[v].byteOffset = place[v];
    model.buffers[0].data = std::move(out);
}

}  // namespace lit::gltfexport
