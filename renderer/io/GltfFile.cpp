#include "io/GltfFile.h"

#include "io/AtomicFile.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace lit {

namespace fs = std::filesystem;

namespace {

using OrderedJson = nlohmann::ordered_json;

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
    throw std::runtime_error(file.string() + ": " + problem);
}

bool keepImageUri(const std::string*, const std::string*, const tinygltf::Image*, bool, std::string*, void*) {
    return false;  // "not written": tinygltf then writes the image's uri as it is
}

void putLittleEndian32(std::uint8_t* at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) at[i] = static_cast<std::uint8_t>(value >> (8 * i));
}

// The GLB container (glTF 2.0, section 4.4): header, JSON chunk (padded with spaces), BIN chunk
// (padded with zeros) when there is one. The vector is sized once and filled by offset: GCC 12
// at -O3 reported a false -Wstringop-overflow for the reserve-then-insert form of this code.
std::vector<std::uint8_t> glbContainer(const fs::path& file, const std::string& json,
                                       const std::vector<unsigned char>* bin) {
    const auto padded = [](std::size_t n) { return (n + 3) & ~std::size_t(3); };
    const std::size_t jsonLength = padded(json.size());
    const std::size_t binLength = bin ? padded(bin->size()) : 0;
    const std::size_t total = 12 + 8 + jsonLength + (bin ? 8 + binLength : 0);
    if (total > 0xFFFFFFFFu) fail(file, "the scene is larger than the 4 GiB a GLB file can hold; save as .gltf");
    std::vector<std::uint8_t> out(total, 0);
    std::uint8_t* at = out.data();
    std::memcpy(at, "glTF", 4);
    putLittleEndian32(at + 4, 2);
    putLittleEndian32(at + 8, static_cast<std::uint32_t>(total));
    putLittleEndian32(at + 12, static_cast<std::uint32_t>(jsonLength));
    putLittleEndian32(at + 16, 0x4E4F534Au);  // "JSON"
    at += 20;
    if (!json.empty()) std::memcpy(at, json.data(), json.size());
    std::fill(at + json.size(), at + jsonLength, static_cast<std::uint8_t>(' '));
    at += jsonLength;
    if (bin) {
        putLittleEndian32(at, static_cast<std::uint32_t>(binLength));
        putLittleEndian32(at + 4, 0x004E4942u);  // "BIN\0"
        if (!bin->empty()) std::memcpy(at + 8, bin->data(), bin->size());  // padding stays zero
    }
    return out;
}

}  // namespace

bool isDataUri(std::string_view uri) { return uri.starts_with("data:"); }

std::string percentDecode(std::string_view uri) {
    std::string out;
    out.reserve(uri.size());
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 1])) && std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out += static_cast<char>(std::stoi(std::string(uri.substr(i + 1, 2)), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

std::string percentEncodePath(std::string_view path) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    for (const char c : path) {
        const auto byte = static_cast<unsigned char>(c);
        if (std::isalnum(byte) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
            out += c;
        } else {
            out += '%';
            out += kHex[byte >> 4];
            out += kHex[byte & 15];
        }
    }
    return out;
}

bool staysInFolder(std::string_view uri) {
    const fs::path path(percentDecode(uri));
    if (path.empty() || path.is_absolute() || path.has_root_name() || path.has_root_directory()) return false;
    for (const fs::path& part : path)
        if (part == "..") return false;
    return true;
}

std::string base64Encode(std::span<const std::uint8_t> bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t b0 = bytes[i];
        const std::uint32_t b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0;
        const std::uint32_t b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const std::uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
        out += kAlphabet[(triple >> 18) & 63];
        out += kAlphabet[(triple >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(triple >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[triple & 63] : '=';
    }
    return out;
}

void writeGltfModel(tinygltf::Model model, const fs::path& file, bool binary,
                    const std::vector<std::pair<fs::path, std::string>>& alsoWrite,
                    const std::vector<std::pair<std::string, std::string>>& jsonPatches) {
    // tinygltf's stream writer base64-encodes every buffer; take the bytes out so that it writes
    // only the JSON, and put the buffers where they belong below.
    std::vector<std::vector<unsigned char>> data(model.buffers.size());
    for (std::size_t i = 0; i < model.buffers.size(); ++i) data[i].swap(model.buffers[i].data);

    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(&keepImageUri, nullptr);
    std::ostringstream stream;
    if (!writer.WriteGltfSceneToStream(&model, stream, /*prettyPrint=*/false, /*writeBinary=*/false))
        fail(file, "tinygltf could not serialise the scene");
    OrderedJson doc;
    try {
        doc = OrderedJson::parse(stream.str());
    } catch (const OrderedJson::exception& e) {
        fail(file, std::string("tinygltf wrote JSON that does not parse (") + e.what() + ")");
    }
    // tinygltf writes an object whose members all have their defaults (a scene without nodes or
    // name) as null, which glTF does not allow and no loader reads back: write it as {}.
    for (auto& [key, value] : doc.items())
        if (value.is_array())
            for (OrderedJson& element : value)
                if (element.is_null()) element = OrderedJson::object();

    for (const auto& [pointer, text] : jsonPatches) {
        try {
            const OrderedJson::json_pointer at(pointer);
            if (text.empty()) {  // remove the member
                if (doc.contains(at)) doc[at.parent_pointer()].erase(at.back());
                continue;
            }
            doc[at] = OrderedJson::parse(text);
        } catch (const OrderedJson::exception& e) {
            fail(file, "cannot write " + pointer + " (" + e.what() + ")");
        }
    }

    AtomicFileSet files;
    const fs::path folder = file.parent_path();
    std::map<fs::path, std::size_t> externalFiles;  // where each external buffer goes
    const std::vector<unsigned char>* bin = nullptr;
    for (std::size_t i = 0; i < model.buffers.size(); ++i) {
        const std::string& uri = model.buffers[i].uri;
        OrderedJson& buffer = doc.at("buffers").at(i);
        buffer["byteLength"] = data[i].size();
        if (binary && i == 0 && uri.empty()) {
            buffer.erase("uri");
            bin = &data[i];
        } else if (!uri.empty() && !isDataUri(uri)) {
            if (!staysInFolder(uri))
                fail(file, "buffer " + std::to_string(i) + "'s uri '" + uri + "' is not a relative path inside " +
                               (folder.empty() ? fs::path(".") : folder).string());
            const fs::path target = (folder / percentDecode(uri)).lexically_normal();
            if (target == file.lexically_normal())
                fail(file, "buffer " + std::to_string(i) + "'s uri '" + uri + "' names the scene file itself");
            buffer["uri"] = uri;
            if (const auto it = externalFiles.find(target); it != externalFiles.end()) {
                if (data[it->second] != data[i])
                    fail(file, "buffers " + std::to_string(it->second) + " and " + std::to_string(i) +
                                   " have the same uri '" + uri + "' but different contents");
                continue;
            }
            externalFiles.emplace(target, i);
            files.stage(target, data[i]);
        } else {
            buffer["uri"] = "data:application/octet-stream;base64," + base64Encode(data[i]);
        }
    }
    if (const auto cameras = doc.find("cameras"); cameras != doc.end())
        for (OrderedJson& camera : *cameras)
            if (const auto perspective = camera.find("perspective"); perspective != camera.end())
                if (const auto zfar = perspective->find("zfar");
                    zfar != perspective->end() && zfar->is_number() && zfar->get<double>() == 0.0)
                    perspective->erase(zfar);

    for (const auto& [path, text] : alsoWrite) files.stage(path, text);
    // Names come from files and users; replace invalid UTF-8 rather than fail the save.
    constexpr auto kReplace = nlohmann::json::error_handler_t::replace;
    if (binary) {
        files.stage(file, glbContainer(file, doc.dump(-1, ' ', false, kReplace), bin));
    } else {
        files.stage(file, doc.dump(2, ' ', false, kReplace) + "\n");
    }
    files.commit();
}

}  // namespace lit
