#pragma once
// The Khronos glTF validator for the tests that check what Lit reads and saves: where
// tools/install-gltf-validator.sh put it, and one run over a list of files through
// tools/validate_gltf.cjs. The tests skip, with the reason, where node or the validator is missing.

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "TempDir.h"

namespace lit::testing {

// The validator's folder ($LIT_GLTF_VALIDATOR_DIR, else the user cache's lit/gltf-validator), or
// empty with `whyNot` saying what is missing.
inline std::filesystem::path findGltfValidator(std::string& whyNot) {
    namespace fs = std::filesystem;
    const char* env = std::getenv("LIT_GLTF_VALIDATOR_DIR");
    const char* home = std::getenv("HOME");
    const char* cache = std::getenv("XDG_CACHE_HOME");
    const fs::path dir =
        env && *env ? fs::path(env)
                    : (cache && *cache ? fs::path(cache) : fs::path(home ? home : "") / ".cache") / "lit" / "gltf-validator";
    if (std::system("node --version > /dev/null 2>&1") != 0) {
        whyNot = "node is not installed: skipped";
        return {};
    }
    if (!fs::exists(dir / "node_modules" / "gltf-validator")) {
        whyNot = "gltf-validator not found in " + dir.string() + " (run tools/install-gltf-validator.sh): skipped";
        return {};
    }
    return dir;
}

// Validates `files`; the report ("NAME: N errors" a file) goes to `report`. Returns the exit
// status (0: no file has an error).
inline int runGltfValidator(const std::filesystem::path& validatorDir, const std::vector<std::filesystem::path>& files,
                            std::string& report, const std::filesystem::path& reportFile) {
    std::string command = "node '" + (std::filesystem::path(LIT_SOURCE_DIR) / "tools" / "validate_gltf.cjs").string() +
                          "' '" + validatorDir.string() + "'";
    for (const std::filesystem::path& file : files) command += " '" + file.string() + "'";
    command += " > '" + reportFile.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    report = readText(reportFile);
    return status;
}

}  // namespace lit::testing
