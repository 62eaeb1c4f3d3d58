// Decoding and importing a glTF file's images (scene/GltfImportImages.h).

#include "scene/GltfImportImages.h"

#include "io/GltfFile.h"
#include "scene/GltfImportKept.h"
#include "scene/GltfKeep.h"

#include <stb_image.h>
#if LIT_HAS_WEBP
#include <webp/decode.h>
#endif

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace lit::gltfimport {

namespace {

// Pixels decoded from one image, or why not.
struct DecodedImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
    std::string error;  // empty on success
};

// A WebP file starts "RIFF", a 4-byte size, "WEBP" (RFC 9649, 2.5).
bool isWebp(const std::vector<unsigned char>& bytes) {
    return bytes.size() >= 12 && std::equal(bytes.begin(), bytes.begin() + 4, "RIFF") &&
           std::equal(bytes.begin() + 8, bytes.begin() + 12, "WEBP");
}

// WebP (EXT_texture_webp) through libwebp; stb_image does not read it.
DecodedImage decodeWebp(const std::vector<unsigned char>& encoded) {
    DecodedImage out;
#if LIT_HAS_WEBP
    int width = 0, height = 0;
    std::unique_ptr<std::uint8_t, void (*)(void*)> pixels(
        WebPDecodeRGBA(encoded.data(), encoded.size(), &width, &height), WebPFree);
    if (!pixels) {
        out.error = "libwebp could not decode it (not a valid WebP image)";
        return out;
    }
    out.width = width;
    out.height = height;
    out.rgba.assign(pixels.get(),
                    pixels.get() + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4u);
#else
    (void)encoded;
    out.error = "it is WebP, and this build of Lit has no libwebp (configure with -DLIT_WEBP=ON)";
#endif
    return out;
}

DecodedImage decodeImage(const std::vector<unsigned char>& encoded) {
    DecodedImage out;
    if (encoded.empty()) {
        out.error = "the file is missing or could not be read";
        return out;
    }
    if (encoded.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
        out.error = "the image is larger than 2 GiB";
        return out;
    }
    if (isWebp(encoded)) return decodeWebp(encoded);
    int width = 0, height = 0, channels = 0;
    // stb_image's failure reason is thread-local in stb 2.27, so workers do not race on it.
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(encoded.data(), static_cast<int>(encoded.size()), &width, &height, &channels, 4),
        stbi_image_free);
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        out.error = std::string("stb_image could not decode it (") + (reason ? reason : "unknown reason") + ")";
        return out;
    }
    out.width = width;
    out.height = height;
    out.rgba.assign(pixels.get(),
                    pixels.get() + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4u);
    return out;
}

// The MIME type of an embedded image without a mimeType (a data URI): from the URI
// ("data:image/png;base64,...") or else from the bytes' signature.
std::string mimeTypeOf(const std::string& uri, const std::vector<unsigned char>& bytes) {
    if (uri.starts_with("data:")) {
        const std::size_t end = uri.find_first_of(";,", 5);
        if (end != std::string::npos && end > 5) return uri.substr(5, end - 5);
    }
    const auto starts = [&](std::initializer_list<unsigned char> magic) {
        return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
    };
    if (starts({0x89, 'P', 'N', 'G'})) return "image/png";
    if (starts({0xFF, 0xD8, 0xFF})) return "image/jpeg";
    if (starts({0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB})) return "image/ktx2";
    if (isWebp(bytes)) return "image/webp";
    return "application/octet-stream";
}

}  // namespace

void importImages(const GltfSource& source, Scene& scene) {
    const std::size_t count = source.model.images.size();
    std::vector<DecodedImage> decoded(count);
    source.report("images", 0, count);
    const std::size_t threads = std::min<std::size_t>(
        count, source.options.decodeThreads > 0 ? static_cast<std::size_t>(source.options.decodeThreads)
                                                : std::max(1u, std::thread::hardware_concurrency()));
    if (threads <= 1) {
        for (std::size_t i = 0; i < count; ++i) {
            decoded[i] = decodeImage(source.model.images[i].image);
            source.report("images", i + 1, count);
        }
    } else {
        // Workers pull image indices from a shared counter (Sponza has 69 1024² JPEGs; decoding
        // dominates its load time) and each writes only its own slot, so the result does not
        // depend on the thread count. The calling thread only waits and reports progress, so the
        // callback runs on it.
        std::atomic<std::size_t> next{0};
        std::mutex mutex;
        std::condition_variable imageDone;
        std::size_t finished = 0;
        std::exception_ptr error;  // the first worker exception (std::bad_alloc), rethrown here
        const auto work = [&] {
            for (std::size_t i = next++; i < count; i = next++) {
                try {
                    decoded[i] = decodeImage(source.model.images[i].image);
                } catch (...) {
                    const std::lock_guard lock(mutex);
                    if (!error) error = std::current_exception();
                }
                {
                    const std::lock_guard lock(mutex);
                    ++finished;
                }
                imageDone.notify_one();
            }
        };
        {
            std::vector<std::jthread> workers;
            for (std::size_t w = 0; w < threads; ++w) workers.emplace_back(work);
            std::unique_lock lock(mutex);
            for (std::size_t reported = 0; reported < count;) {
                imageDone.wait(lock, [&] { return finished != reported; });
                reported = finished;
                lock.unlock();
                source.report("images", reported, count);
                lock.lock();
            }
        }  // joins the workers
        if (error) std::rethrow_exception(error);
    }

    // How materials use each image: colour slots are sRGB; normal maps need care on failure.
    std::vector<std::uint8_t> usedAsColour(count, 0), usedAsData(count, 0);
    const auto imageOf = [&](int texture) {
        return texture >= 0 ? scene.textures[static_cast<std::size_t>(texture)].image : -1;
    };
    for (const Material& m : scene.materials) {
        for (int t : {m.baseColorTexture, m.emissiveTexture})
            if (int i = imageOf(t); i >= 0) usedAsColour[static_cast<std::size_t>(i)] = 1;
        for (int t : {m.metallicRoughnessTexture, m.normalTexture, m.occlusionTexture})
            if (int i = imageOf(t); i >= 0) usedAsData[static_cast<std::size_t>(i)] = 1;
        for (const ExtensionTextureSlot& slot : kExtensionTextureSlots)
            if (int i = imageOf((m.*slot.member).texture); i >= 0)
                (slot.colour ? usedAsColour : usedAsData)[static_cast<std::size_t>(i)] = 1;
    }

    std::vector<std::uint8_t> failed(count, 0);
    scene.images.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const tinygltf::Image& in = source.model.images[i];
        Image& out = scene.images[i];
        out.name = in.name;
        out.uri = in.uri;
        out.kept = gltfkeep::keep(in.extras, in.extensions);
        // Optional for an image by URI (tinygltf reads it only beside a bufferView); set below for
        // embedded ones.
        if (const nlohmann::json& file = source.fileObject("images", i); file.is_object())
            if (const auto mime = file.find("mimeType"); mime != file.end() && mime->is_string())
                out.mimeType = mime->get<std::string>();
        if (in.uri.empty() || isDataUri(in.uri)) {
            // Embedded: keep the file's bytes for a save (a copy of an earlier image shares its
            // bytes, which the canonical entry holds).
            out.encoded =
                source.model.images[static_cast<std::size_t>(source.images.canonical(static_cast<int>(i)))].image;
            out.mimeType = in.mimeType.empty() ? mimeTypeOf(in.uri, out.encoded) : in.mimeType;
            out.view = keptView(source, in.bufferView);
        }
        if (source.images.canonical(static_cast<int>(i)) != static_cast<int>(i)) {
            // A copy of an earlier image: textures use that one; this entry keeps its name and
            // uri but no pixels of its own.
            out.sameAs = source.images.canonical(static_cast<int>(i));
            out.width = 1;
            out.height = 1;
            out.rgba = {255, 255, 255, 255};
            continue;
        }
        out.srgb = usedAsColour[i] != 0;
        if (usedAsColour[i] && usedAsData[i])
            source.warn("image " + std::to_string(i) +
                        " is used both as colour and as data; it is treated as sRGB colour");
        if (decoded[i].error.empty()) {
            out.width = decoded[i].width;
            out.height = decoded[i].height;
            out.rgba = std::move(decoded[i].rgba);
            continue;
        }
        failed[i] = 1;
        const std::string label =
            !in.uri.empty() ? "'" + in.uri + "'" : (in.name.empty() ? "(embedded)" : "'" + in.name + "'");
        source.warn("image " + std::to_string(i) + " " + label + ": " + decoded[i].error +
                    "; using a 1x1 white texture");
        out.width = 1;
        out.height = 1;
        out.rgba = {255, 255, 255, 255};
    }

    // Textures without a source (only an unsupported extension's image) get one white image.
    int neutral = -1;
    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        if (scene.textures[t].image >= 0) continue;
        if (neutral < 0) {
            neutral = static_cast<int>(scene.images.size());
            scene.images.push_back(Image{"neutral", "", 1, 1, {255, 255, 255, 255}, false});
            scene.images.back().generated = true;  // not in the file: a save leaves it out
            failed.push_back(1);
        }
        source.warn("texture " + std::to_string(t) + " has no image Lit can read; using a 1x1 white texture");
        scene.textures[t].image = neutral;
    }

    // A white normal map would tilt every normal; drop it so the material uses vertex normals.
    for (Material& m : scene.materials) {
        const int image = imageOf(m.normalTexture);
        if (image >= 0 && failed[static_cast<std::size_t>(image)]) m.normalTexture = -1;
    }
}

}  // namespace lit::gltfimport
