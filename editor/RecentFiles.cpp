#include "RecentFiles.h"

#include <algorithm>
#include <system_error>

namespace lit::editor {

namespace {
std::filesystem::path normalised(const std::filesystem::path& path) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    return (error ? path : absolute).lexically_normal();
}
}  // namespace

void RecentFiles::add(const std::filesystem::path& path) {
    if (capacity_ == 0) return;
    const std::filesystem::path entry = normalised(path);
    std::erase(paths_, entry);
    paths_.insert(paths_.begin(), entry);
    if (paths_.size() > capacity_) paths_.resize(capacity_);
}

void RecentFiles::remove(const std::filesystem::path& path) { std::erase(paths_, normalised(path)); }

}  // namespace lit::editor
