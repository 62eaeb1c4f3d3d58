#include "SaveAsName.h"

#include <string>
#include <system_error>

#include "Renderer.h"

namespace lit::editor {

namespace {

namespace fs = std::filesystem;

// `stem` without a trailing "-copy" or "-copy-N", and whether it had one.
std::string withoutCopySuffix(const std::string& stem) {
    const std::string marker = "-copy";
    const std::size_t at = stem.rfind(marker);
    if (at == std::string::npos || at == 0) return stem;
    const std::string tail = stem.substr(at + marker.size());
    if (tail.empty()) return stem.substr(0, at);
    if (tail.size() < 2 || tail[0] != '-') return stem;
    for (std::size_t i = 1; i < tail.size(); ++i)
        if (tail[i] < '0' || tail[i] > '9') return stem;
    return stem.substr(0, at);
}

bool sameFolder(const fs::path& a, const fs::path& b) {
    std::error_code error;
    const fs::path left = fs::weakly_canonical(a.empty() ? fs::path(".") : a, error);
    if (error) return false;
    const fs::path right = fs::weakly_canonical(b.empty() ? fs::path(".") : b, error);
    return !error && left == right;
}

}  // namespace

fs::path suggestSaveAsName(const fs::path& current, const fs::path& builtInFolder, const FileExists& exists) {
    std::string base = "untitled";
    std::string first = base;  // the first name to offer
    std::string extension = ".gltf";
    fs::path folder;
    if (!current.empty()) {
        const std::string own = current.extension().string();
        if (own == ".gltf" || own == ".glb") extension = own;
        base = withoutCopySuffix(current.stem().string()) + "-copy";
        first = base;
        if (!builtInFolder.empty() && sameFolder(current.parent_path(), builtInFolder))
            folder = fs::path();  // the working directory
        else
            folder = current.parent_path();
    }
    fs::path candidate = folder / (first + extension);
    for (int n = 2; exists(candidate) || candidate == current; ++n)
        candidate = folder / (base + "-" + std::to_string(n) + extension);
    return candidate;
}

fs::path suggestSaveAsName(const fs::path& current) {
    return suggestSaveAsName(current, defaultAssetRoot(), [](const fs::path& path) {
        std::error_code error;
        return fs::exists(path, error);
    });
}

}  // namespace lit::editor
