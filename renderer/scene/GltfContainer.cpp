// Sniffing a glTF file: JSON or GLB, and a GLB header that agrees with the file's size.

#include "scene/GltfContainer.h"

#include "io/LittleEndian.h"
#include "scene/GltfLoader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

namespace lit::gltfimport {

namespace fs = std::filesystem;

namespace {

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

}  // namespace

Container detectContainer(const fs::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) throw SceneLoadError(name + ": file not found");
    if (fs::is_directory(status)) throw SceneLoadError(name + ": is a directory, not a glTF file");
    const std::uintmax_t fileSize = fs::file_size(path, ec);
    if (ec) throw SceneLoadError(name + ": cannot read the file size (" + ec.message() + ")");

    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneLoadError(name + ": cannot open the file for reading");
    std::array<unsigned char, 20> head{};
    in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
    const std::size_t got = static_cast<std::size_t>(in.gcount());
    if (got == 0) throw SceneLoadError(name + ": the file is empty, not a glTF file");

    const bool glbMagic = got >= 4 && std::memcmp(head.data(), "glTF", 4) == 0;
    // JSON starts with '{', possibly after whitespace and a UTF-8 byte order mark.
    std::size_t first = 0;
    if (got >= 3 && head[0] == 0xEF && head[1] == 0xBB && head[2] == 0xBF) first = 3;
    while (first < got && std::isspace(head[first])) ++first;
    const bool looksJson = first < got && head[first] == '{';

    const std::string ext = lowercase(path.extension().string());
    if (ext == ".glb" && !glbMagic) {
        if (looksJson)
            throw SceneLoadError(name + ": has the extension .glb but holds JSON text; was a .gltf file renamed?");
        throw SceneLoadError(name + ": not a glTF file (a .glb file must start with the magic bytes \"glTF\")");
    }
    if (ext == ".gltf" && glbMagic)
        throw SceneLoadError(name +
                             ": is a binary glTF (GLB) file but has the extension .gltf; was a .glb file renamed?");
    if (!glbMagic && !looksJson)
        throw SceneLoadError(name + ": not a glTF file (neither JSON text nor the GLB magic bytes \"glTF\")");
    if (!glbMagic) {
        // tinygltf reports a JSON syntax error without saying so; check the syntax here first
        // so a truncated or hand-broken file gets a message that names the problem and place.
        std::ifstream whole(path, std::ios::binary);
        const std::string text{std::istreambuf_iterator<char>(whole), std::istreambuf_iterator<char>()};
        if (nlohmann::json::accept(text)) return Container::Json;
        std::string reason = "syntax error";
        try {
            // Parse again only to get the error's position and reason.
            const nlohmann::json parsed = nlohmann::json::parse(text);
            (void)parsed;
        } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for 1e999
            reason = e.what();
            // "[json.exception.parse_error.101] parse error at line 3, ..." → "parse error at line 3, ..."
            if (const auto bracket = reason.find("] ");
                reason.starts_with("[json.exception") && bracket != std::string::npos)
                reason.erase(0, bracket + 2);
        }
        throw SceneLoadError(name + ": invalid JSON (is the file truncated?): " + reason);
    }

    // GLB header: magic, version, total length; then the JSON chunk's length and type.
    if (got < 12) throw SceneLoadError(name + ": truncated GLB: the file is shorter than the 12-byte header");
    const std::uint32_t version = readLittleEndian32(head.data() + 4);
    const std::uint32_t declared = readLittleEndian32(head.data() + 8);
    if (version != 2)
        throw SceneLoadError(name + ": GLB container version " + std::to_string(version) +
                             " is not supported (only 2)");
    if (declared > fileSize)
        throw SceneLoadError(name + ": truncated GLB: the header declares " + std::to_string(declared) +
                             " bytes but the file has " + std::to_string(fileSize));
    if (got < 20) throw SceneLoadError(name + ": truncated GLB: the file ends inside the JSON chunk header");
    const std::uint64_t jsonEnd = 20ull + readLittleEndian32(head.data() + 12);
    if (jsonEnd > declared)
        throw SceneLoadError(name + ": truncated GLB: the JSON chunk (" + std::to_string(jsonEnd - 20) +
                             " bytes) runs past the declared length of " + std::to_string(declared) + " bytes");
    return Container::Binary;
}

}  // namespace lit::gltfimport
