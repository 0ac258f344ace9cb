#include "rasterlab/image_io.hpp"

#include <stb_image.h>
#include <stb_image_write.h>
#include <turbojpeg.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <string_view>

namespace rl {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

bool is_png_jpeg_or_bmp(std::span<const std::uint8_t> bytes) {
    auto starts_with = [&](std::initializer_list<std::uint8_t> signature) {
        return bytes.size() >= signature.size() &&
               std::equal(signature.begin(), signature.end(), bytes.begin());
    };
    return starts_with({0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}) ||
           starts_with({0xff, 0xd8, 0xff}) || starts_with({'B', 'M'});
}

std::uint32_t little_endian(std::span<const std::uint8_t> bytes, std::size_t at, int size) {
    std::uint32_t v = 0;
    for (int i = size - 1; i >= 0; --i) v = (v << 8) | bytes[at + static_cast<std::size_t>(i)];
    return v;
}

// The fewest bytes a file of this format can hold a width x height image in,
// so that a header claiming 16384 x 16384 on a file of a few hundred bytes is
// refused before the decoder allocates the gigabyte it claims (a 54-byte BMP
// became a black 2.39 GB texture; a 649-byte JPEG took 397 MB before its
// decoder gave up). BMP: its rows, exactly (stb_image reads no compressed
// BMP). PNG: deflate expands at most 1032 times. JPEG: every 8 x 8 block of
// luma costs at least one bit.
std::uint64_t fewest_bytes(std::span<const std::uint8_t> bytes, int width, int height,
                           int channels) {
    const auto w = static_cast<std::uint64_t>(width), h = static_cast<std::uint64_t>(height);
    if (bytes[0] == 'B') {  // BMP: stb_info has read its 54-byte headers
        if (bytes.size() < 34) return 54;
        const std::uint64_t offset = little_endian(bytes, 10, 4);
        const std::uint32_t bits = little_endian(bytes, 28, 2);
        return offset + (w * bits + 31) / 32 * 4 * h;
    }
    if (bytes[0] == 0x89) return h * (1 + w * static_cast<std::uint64_t>(channels)) / 1032;  // PNG
    return (w + 7) / 8 * ((h + 7) / 8) / 8;                                                  // JPEG
}

// Refuses a width x height image that the file's bytes cannot hold, before
// the decoder allocates it.
void check_claimed_size(const std::filesystem::path& path, std::span<const std::uint8_t> bytes,
                        int width, int height, int channels) {
    try {
        check_dimensions(width, height);  // refuse absurd sizes before decoding
    } catch (const std::invalid_argument& e) {
        throw FileError(path, e.what());
    }
    const std::uint64_t fewest = fewest_bytes(bytes, width, height, channels);
    if (bytes.size() < fewest)
        throw FileError(path, "truncated pixel data: a " + std::to_string(width) + "x" +
                                  std::to_string(height) + " image in this format needs at least " +
                                  std::to_string(fewest) + " bytes, the file has " +
                                  std::to_string(bytes.size()));
}

// Rows of RGBA bytes, the top one first, into an image (bottom row first).
Image from_top_first_rgba(const std::uint8_t* data, int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* row = data + static_cast<std::size_t>(height - 1 - y) * width * 4;
        for (int x = 0; x < width; ++x) {
            const std::uint8_t* p = row + static_cast<std::size_t>(x) * 4;
            image.set(x, y, Rgba{p[0], p[1], p[2], p[3]});
        }
    }
    return image;
}

// JPEG through libjpeg-turbo, not stb_image: on some damaged files stb's
// decoder reads memory it never wrote, and the same 1 KB file gave four
// different pictures under four MALLOC_PERTURB_ values
// (ImageIo.DamagedJpegsDecodeTheSameEveryTime). A stream libjpeg-turbo only
// warns about (a premature end, corrupt data) is refused too: the same
// bytes always give the same picture or the same refusal.
Image load_jpeg(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    const std::unique_ptr<void, int (*)(tjhandle)> decoder(tjInitDecompress(), tjDestroy);
    if (!decoder) throw FileError(path, "cannot start the JPEG decoder");
    tjhandle handle = decoder.get();
    const auto reason = [&] { return std::string(tjGetErrorStr2(handle)); };
    int width = 0, height = 0, subsampling = 0, colour_space = 0;
    if (tjDecompressHeader3(handle, bytes.data(), static_cast<unsigned long>(bytes.size()), &width,
                            &height, &subsampling, &colour_space) != 0)
        throw FileError(path, "not a readable image: " + reason());
    check_claimed_size(path, bytes, width, height, 3);
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
    if (tjDecompress2(handle, bytes.data(), static_cast<unsigned long>(bytes.size()), rgba.data(),
                      width, 0, height, TJPF_RGBA, TJFLAG_STOPONWARNING) != 0)
        throw FileError(path, "cannot decode: " + reason());
    return from_top_first_rgba(rgba.data(), width, height);
}

Image load_png_jpeg_or_bmp(const std::filesystem::path& path) {
    const std::vector<std::uint8_t> bytes = read_file(path);
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw FileError(path, "file too large");
    // stb_image reads a dozen formats; rasterlab's textures come as PNG, JPEG
    // or BMP (and TGA, read by our own codec). The others (PSD, GIF, HDR, PIC,
    // PNM) are refused by their signature before stb sees them: less decoder
    // code reachable from a hostile file.
    if (!is_png_jpeg_or_bmp(bytes)) throw FileError(path, "not a PNG, JPEG, BMP or TGA file");
    if (bytes[0] == 0xff) return load_jpeg(path, bytes);
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height,
                               &channels))
        throw FileError(path, std::string("not a readable image: ") + stbi_failure_reason());
    check_claimed_size(path, bytes, width, height, channels);
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height,
                              &channels, 4),
        stbi_image_free);
    if (!data) throw FileError(path, std::string("cannot decode: ") + stbi_failure_reason());
    return from_top_first_rgba(data.get(), width, height);
}

bool is_radiance_hdr(std::span<const std::uint8_t> bytes) {
    const auto starts_with = [&](std::string_view signature) {
        return bytes.size() >= signature.size() &&
               std::equal(signature.begin(), signature.end(), bytes.begin());
    };
    return starts_with("#?RADIANCE\n") || starts_with("#?RGBE\n");
}

// What an .hdr's header says: the image's size and where its pixels begin.
struct HdrHeader {
    int width = 0, height = 0;
    std::size_t pixels = 0;  // the first byte after the resolution line
};

// A resolution line's number: decimal digits only, at most INT_MAX. stb_image
// reads it with strtol cast to int, so 4294967297 became 1 and a file loaded
// as another size without a word; here such a number is a corrupt header.
// As strtol reads it: blanks, then an optional plus sign, then digits.
std::optional<int> resolution_number(std::string_view& line) {
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    if (!line.empty() && line.front() == '+') line.remove_prefix(1);
    std::size_t digits = 0;
    long long value = 0;
    while (digits < line.size() && line[digits] >= '0' && line[digits] <= '9') {
        value = value * 10 + (line[digits] - '0');
        if (value > INT_MAX) return std::nullopt;
        ++digits;
    }
    if (digits == 0) return std::nullopt;
    line.remove_prefix(digits);
    return static_cast<int>(value);
}

// Reads the header of an .hdr: its lines up to the empty one that ends them,
// then the resolution line, "-Y <height> +X <width>" (rows top first, the one
// orientation stb_image reads). Throws FileError naming what is wrong.
HdrHeader read_hdr_header(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const std::size_t blank = text.find("\n\n");
    const std::size_t end = blank == std::string_view::npos ? blank : text.find('\n', blank + 2);
    if (end == std::string_view::npos) throw FileError(path, "no resolution line after the header");
    const std::string_view whole = text.substr(blank + 2, end - blank - 2);
    const auto corrupt = [&](const std::string& why) {
        return FileError(path, "corrupt header: the resolution line '" +
                                   std::string(whole.substr(0, 40)) + "' " + why);
    };
    std::string_view line = whole;
    const auto skip = [&](std::string_view word) {
        if (!line.starts_with(word)) return false;
        line.remove_prefix(word.size());
        return true;
    };
    const auto spaces = [&] {
        while (!line.empty() &&
               (line.front() == ' ' || line.front() == '\t' || line.front() == '\r'))
            line.remove_prefix(1);
    };
    if (!skip("-Y ")) throw corrupt("is not '-Y <height> +X <width>'");
    const std::optional<int> height = resolution_number(line);
    spaces();
    if (!skip("+X ")) throw corrupt("is not '-Y <height> +X <width>'");
    const std::optional<int> width = resolution_number(line);
    spaces();
    if (!height || !width || !line.empty())
        throw corrupt("does not hold two whole numbers of texels from 0 to " +
                      std::to_string(INT_MAX));
    return {*width, *height, end + 1};
}

// Why the pixels from `at` on cannot be read as a width x height image, or
// "" if they can: read as stb_image reads them. A row of 8 to 32767 pixels
// may be run-length encoded (2, 2, the width in two bytes, then each channel
// in runs: a count over 128 repeats the next byte count - 128 times, any
// other count copies that many bytes); from the first row that is not, the
// rest is flat, 4 bytes a pixel. Checked here, before stb_image sees the
// file, because stb_image reads zeros past the end of a file (a truncated
// one would load with black rows) and loops forever on a run of count 0.
std::string hdr_pixels_problem(std::span<const std::uint8_t> bytes, std::size_t at, int width,
                               int height) {
    const std::string truncated = "truncated pixel data: the file ends before the last of the " +
                                  std::to_string(width) + "x" + std::to_string(height) +
                                  " .hdr's pixels";
    const auto w = static_cast<std::uint64_t>(width);
    const auto flat_rest = [&](int rows) {
        return bytes.size() - at >= 4 * w * static_cast<std::uint64_t>(rows) ? "" : truncated;
    };
    if (width < 8 || width > 32767) return flat_rest(height);
    for (int row = 0; row < height; ++row) {
        if (bytes.size() - at < 4) return truncated;
        if (bytes[at] != 2 || bytes[at + 1] != 2 || (bytes[at + 2] & 0x80))
            return flat_rest(height - row);
        if ((bytes[at + 2] << 8 | bytes[at + 3]) != width)
            return "corrupt run-length data: row " + std::to_string(row) + " is not " +
                   std::to_string(width) + " pixels long";
        at += 4;
        for (int channel = 0; channel < 4; ++channel)
            for (std::uint64_t filled = 0; filled < w;) {
                if (at >= bytes.size()) return truncated;
                const unsigned count = bytes[at++];
                const unsigned length = count > 128 ? count - 128 : count;
                if (length == 0 || filled + length > w)
                    return "corrupt run-length data: a run of " + std::to_string(length) +
                           " in row " + std::to_string(row) + " (1 to " +
                           std::to_string(w - filled) + " fit)";
                const std::size_t data = count > 128 ? 1 : length;
                if (bytes.size() - at < data) return truncated;
                at += data;
                filled += length;
            }
    }
    return "";
}

void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

std::vector<std::uint8_t> encode_png(const std::filesystem::path& path, const Image& image) {
    Image top_first = image;
    top_first.flip_vertically();
    std::vector<std::uint8_t> png;
    const int ok = stbi_write_png_to_func(append_bytes, &png, image.width(), image.height(), 4,
                                          top_first.pixels().data(), image.width() * 4);
    if (!ok) throw FileError(path, "PNG encoding failed");
    return png;
}

void check_extension(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    if (ext != ".tga" && ext != ".png")
        throw FileError(path, "unknown image extension '" + ext + "' (use .tga or .png)");
}

}  // namespace

Image load_image(const std::filesystem::path& path) {
    try {
        if (lower_extension(path) == ".tga") return read_tga(path);
        return load_png_jpeg_or_bmp(path);
    } catch (const std::bad_alloc&) {
        throw FileError(path, "out of memory decoding the image");
    }
}

HdrImage load_hdr_image(const std::filesystem::path& path, const ImageCap& cap) {
    try {
        const std::vector<std::uint8_t> bytes = read_file(path);
        if (bytes.size() > static_cast<std::size_t>(INT_MAX))
            throw FileError(path, "file too large");
        if (!is_radiance_hdr(bytes))
            throw FileError(path, "not a Radiance .hdr file (it must start with #?RADIANCE)");
        const HdrHeader header = read_hdr_header(path, bytes);
        int width = 0, height = 0, channels = 0;
        if (!stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height,
                                   &channels))
            throw FileError(path, std::string("not a readable image: ") + stbi_failure_reason());
        if (width != header.width || height != header.height)  // the decoder reads another size
            throw FileError(path, "corrupt header: its size is read two ways");
        try {
            check_dimensions(width, height);
        } catch (const std::invalid_argument& e) {
            throw FileError(path, e.what());
        }
        if (width > cap.width || height > cap.height)
            throw FileError(path, "a " + std::to_string(width) + "x" + std::to_string(height) +
                                      " image, past " + cap.name + " of " +
                                      std::to_string(cap.width) + "x" + std::to_string(cap.height) +
                                      " texels (refused before " + "decoding)");
        if (const std::string problem = hdr_pixels_problem(bytes, header.pixels, width, height);
            !problem.empty())
            throw FileError(path, problem);
        std::unique_ptr<float, void (*)(void*)> data(
            stbi_loadf_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height,
                                   &channels, 3),
            stbi_image_free);
        if (!data) throw FileError(path, std::string("cannot decode: ") + stbi_failure_reason());
        HdrImage image(width, height);
        for (int y = 0; y < height; ++y) {
            const float* row = data.get() + static_cast<std::size_t>(height - 1 - y) * width * 3;
            for (int x = 0; x < width; ++x) {
                const float* p = row + static_cast<std::size_t>(x) * 3;
                image.set(x, y, vec4{p[0], p[1], p[2], 1.0f});
            }
        }
        return image;
    } catch (const std::bad_alloc&) {
        throw FileError(path, "out of memory decoding the image");
    }
}

std::vector<std::uint8_t> encode_hdr(const std::filesystem::path& path, const HdrImage& image) {
    std::vector<float> rgb;
    rgb.reserve(static_cast<std::size_t>(image.width()) * image.height() * 3);
    for (int y = image.height() - 1; y >= 0; --y)
        for (int x = 0; x < image.width(); ++x) {
            const vec4 v = image.get(x, y);
            for (float c : {v.x, v.y, v.z}) {
                if (!(c >= 0) || !std::isfinite(c))
                    throw FileError(path, "an .hdr holds finite values of 0 or more, not " +
                                              std::to_string(c) + " (pixel " + std::to_string(x) +
                                              ", " + std::to_string(y) + ")");
                rgb.push_back(c);
            }
        }
    std::vector<std::uint8_t> hdr;
    if (!stbi_write_hdr_to_func(append_bytes, &hdr, image.width(), image.height(), 3, rgb.data()))
        throw FileError(path, "HDR encoding failed");
    return hdr;
}

void write_png(const std::filesystem::path& path, const Image& image) {
    write_file_atomically(path, encode_png(path, image));
}

std::vector<std::uint8_t> encode_image(const std::filesystem::path& path, const Image& image,
                                       bool keep_alpha) {
    check_extension(path);
    if (lower_extension(path) == ".png") return encode_png(path, image);
    TgaWriteOptions options;
    options.format = keep_alpha ? TgaPixelFormat::bgra32 : TgaPixelFormat::bgr24;
    return encode_tga(image, options);
}

void check_image_output(const std::filesystem::path& path) {
    // The path first: -o somedir is "a directory", not "unknown extension ''".
    check_output(path);
    check_extension(path);
}

void save_image(const std::filesystem::path& path, const Image& image, bool keep_alpha) {
    write_file_atomically(path, encode_image(path, image, keep_alpha));
}

}  // namespace rl
