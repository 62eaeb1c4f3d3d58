#include "NodeMap.h"

#include <fstream>

#include "scene/Scene.h"

namespace lit::cli {

bool writeNodeMap(const std::filesystem::path& path, const Scene& scene,
                  const std::vector<reference::FirstHit>& hits, int width, int height, std::string& error) {
    std::ofstream out(path);
    if (!out) {
        error = "cannot write " + path.string();
        return false;
    }
    out << "lit-node-map 1\n" << width << ' ' << height << "\nnodes " << scene.nodes.size() << '\n';
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) out << n << ' ' << scene.nodes[n].name << '\n';
    out << "pixels\n";
    for (int y = height - 1; y >= 0; --y) {
        for (int x = 0; x < width; ++x) {
            const reference::FirstHit& hit = hits[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                                  static_cast<std::size_t>(x)];
            out << (x > 0 ? " " : "") << hit.node << (hit.litBy != 0 || hit.emissive ? "*" : "");
        }
        out << '\n';
    }
    if (!out) {
        error = "cannot write " + path.string();
        return false;
    }
    return true;
}

}  // namespace lit::cli
