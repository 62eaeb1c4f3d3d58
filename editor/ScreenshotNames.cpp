#include "ScreenshotNames.h"

#include <ctime>
#include <string>

namespace lit::editor {

std::filesystem::path timestampedScreenshotPath(const std::filesystem::path& folder, bool withUi,
                                                std::chrono::system_clock::time_point time) {
    const std::time_t seconds = std::chrono::system_clock::to_time_t(time);
    std::tm local{};
    localtime_r(&seconds, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y-%m-%d_%H-%M-%S", &local);
    const std::string stem = std::string("lit_") + stamp + (withUi ? "_ui" : "");

    std::filesystem::path file = folder / (stem + ".png");
    std::error_code error;  // an unreadable folder: take the name; writing it will say why
    for (int n = 2; std::filesystem::exists(file, error); ++n) file = folder / (stem + "_" + std::to_string(n) + ".png");
    return file;
}

}  // namespace lit::editor
