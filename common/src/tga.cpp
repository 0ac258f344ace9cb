// TGA reading and writing. The header layout, the origin bit and the RLE
// packets are explained in docs/00_framebuffer.md.
#include "rasterlab/tga.hpp"

#include <algorithm>
#include <cstring>

namespace rl {
namespace {

std::uint16_t little_endian16(const std::uint8_t* p) {
    return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}

void put_little_endian16(std::vector<std::uint8_t>& out, int value) {
    out.push_back(static_cast<std::uint8_t>(value & 0xff));
    out.push_back(static_cast<std::uint8_t>((value >> 8) & 0xff));
}

[[noreturn]] void fail(const std::string& name, const std::string& problem) {
    throw TgaError(name, problem);
}

// One pixel as the file stores it: grey, or blue-green-red(-alpha).
Rgba decode_pixel(const std::uint8_t* p, int bytes_per_pixel) {
    switch (bytes_per_pixel) {
        case 1:
            return {p[0], p[0], p[0], 255};
        case 3:
            return {p[2], p[1], p[0], 255};
        default:
            return {p[2], p[1], p[0], p[3]};
    }
}

// A forward-only reader over the file's bytes that refuses to run past the end.
class ByteReader {
  public:
    ByteReader(std::span<const std::uint8_t> bytes, const std::string& name)
        : bytes_(bytes), name_(name) {}

    const std::uint8_t* take(std::size_t count, const char* what) {
        if (bytes_.size() - position_ < count)
            fail(name_, std::string("truncated ") + what + " (needs " + std::to_string(count) +
                            " more bytes at offset " + std::to_string(position_) + ", file has " +
                            std::to_string(bytes_.size()) + ")");
        const std::uint8_t* start = bytes_.data() + position_;
        position_ += count;
        return start;
    }

    std::size_t remaining() const { return bytes_.size() - position_; }

  private:
    std::span<const std::uint8_t> bytes_;
    const std::string& name_;
    std::size_t position_ = 0;
};

// Fills `pixels` in file order (the order the rows and columns are stored).
// [doc:tga-rle-decode]
void decode_rle_pixels(ByteReader& reader, int bytes_per_pixel, std::vector<Rgba>& pixels,
                       const std::string& name) {
    std::size_t done = 0;
    while (done < pixels.size()) {
        const std::uint8_t packet = *reader.take(1, "RLE packet header");
        const std::size_t count = (packet & 0x7f) + 1u;  // 1..128 pixels
        if (count > pixels.size() - done)
            fail(name, "RLE packet of " + std::to_string(count) + " pixels at pixel " +
                           std::to_string(done) + " overruns the image's " +
                           std::to_string(pixels.size()) + " pixels");
        if (packet & 0x80) {  // run-length packet: one pixel value, repeated
            const Rgba value =
                decode_pixel(reader.take(bytes_per_pixel, "RLE run"), bytes_per_pixel);
            std::fill_n(pixels.begin() + static_cast<std::ptrdiff_t>(done), count, value);
        } else {  // raw packet: `count` literal pixels
            const std::uint8_t* raw = reader.take(count * bytes_per_pixel, "RLE raw packet");
            for (std::size_t i = 0; i < count; ++i)
                pixels[done + i] = decode_pixel(raw + i * bytes_per_pixel, bytes_per_pixel);
        }
        done += count;
    }
}
// [/doc:tga-rle-decode]

int bytes_per_pixel(TgaPixelFormat format) {
    switch (format) {
        case TgaPixelFormat::grey8:
            return 1;
        case TgaPixelFormat::bgr24:
            return 3;
        default:
            return 4;
    }
}

void encode_pixel(Rgba c, TgaPixelFormat format, std::uint8_t* out) {
    switch (format) {
        case TgaPixelFormat::grey8:
            // Rec. 709 luma in 8.8 fixed point; exact for pixels that are already grey.
            out[0] = static_cast<std::uint8_t>((c.r * 54 + c.g * 183 + c.b * 19 + 128) >> 8);
            break;
        case TgaPixelFormat::bgr24:
            out[0] = c.b, out[1] = c.g, out[2] = c.r;
            break;
        case TgaPixelFormat::bgra32:
            out[0] = c.b, out[1] = c.g, out[2] = c.r, out[3] = c.a;
            break;
    }
}

// Packets never cross a row, as the TGA specification asks.
// [doc:tga-rle-encode]
void encode_rle_row(const std::vector<std::uint8_t>& row, int bpp, std::vector<std::uint8_t>& out) {
    const int n = static_cast<int>(row.size()) / bpp;
    auto same = [&](int a, int b) {
        return std::memcmp(&row[a * bpp], &row[b * bpp], static_cast<std::size_t>(bpp)) == 0;
    };
    int i = 0;
    while (i < n) {
        int run = 1;
        while (i + run < n && run < 128 && same(i, i + run)) ++run;
        if (run >= 2) {  // a repeat is worth a run packet: 1 + bpp bytes for `run` pixels
            out.push_back(static_cast<std::uint8_t>(0x80 | (run - 1)));
            out.insert(out.end(), row.begin() + i * bpp, row.begin() + (i + 1) * bpp);
            i += run;
            continue;
        }
        int literal = 1;  // extend the raw packet until the next repeat starts
        while (i + literal < n && literal < 128 &&
               !(i + literal + 1 < n && same(i + literal, i + literal + 1)))
            ++literal;
        out.push_back(static_cast<std::uint8_t>(literal - 1));
        out.insert(out.end(), row.begin() + i * bpp, row.begin() + (i + literal) * bpp);
        i += literal;
    }
}
// [/doc:tga-rle-encode]

}  // namespace

// [doc:tga-header]
TgaHeader parse_tga_header(std::span<const std::uint8_t> bytes, const std::string& name) {
    if (bytes.size() < kTgaHeaderSize)
        fail(name, "truncated header (" + std::to_string(bytes.size()) + " of 18 bytes)");
    const std::uint8_t* p = bytes.data();
    TgaHeader h;
    h.id_length = p[0];        // bytes of free text after the header
    h.colour_map_type = p[1];  // 1 if a palette follows
    h.image_type = p[2];       // 2, 3, 10, 11 are the ones we read
    h.colour_map_length = little_endian16(p + 5);
    h.colour_map_entry_bits = p[7];
    h.width = little_endian16(p + 12);   // bytes 8..11 hold an x/y screen
    h.height = little_endian16(p + 14);  // position that nothing uses
    h.bits_per_pixel = p[16];
    h.descriptor = p[17];  // bits 0-3: alpha bits; bit 4: right-to-left; bit 5: top row first
    // [/doc:tga-header]

    using enum TgaImageType;
    switch (h.image_type) {
        case static_cast<std::uint8_t>(true_colour):
        case static_cast<std::uint8_t>(true_colour_rle):
            if (h.bits_per_pixel != 24 && h.bits_per_pixel != 32)
                fail(name, std::to_string(h.bits_per_pixel) +
                               " bits per pixel does not fit a true-colour image (24 or 32)");
            break;
        case static_cast<std::uint8_t>(grey):
        case static_cast<std::uint8_t>(grey_rle):
            if (h.bits_per_pixel != 8)
                fail(name, std::to_string(h.bits_per_pixel) +
                               " bits per pixel does not fit a greyscale image (8)");
            break;
        case 1:
        case 9:
            fail(name,
                 "colour-mapped TGA (type " + std::to_string(h.image_type) + ") is not supported");
        case 0:
            fail(name, "TGA of type 0 holds no image data");
        default:
            fail(name, "unknown TGA image type " + std::to_string(h.image_type));
    }
    if (h.colour_map_type > 1)
        fail(name, "invalid colour map type " + std::to_string(h.colour_map_type));
    if (h.width == 0 || h.height == 0)
        fail(name, "zero image size " + std::to_string(h.width) + "x" + std::to_string(h.height));
    if (static_cast<std::size_t>(h.width) * h.height > kMaxPixels)
        fail(name, "image size " + std::to_string(h.width) + "x" + std::to_string(h.height) +
                       " exceeds the limit of " + std::to_string(kMaxPixels) + " pixels");
    return h;
}

Image decode_tga(std::span<const std::uint8_t> bytes, const std::string& name) {
    const TgaHeader h = parse_tga_header(bytes, name);
    ByteReader reader(bytes, name);
    reader.take(kTgaHeaderSize, "header");
    reader.take(h.id_length, "image ID field");
    if (h.colour_map_type == 1)  // a palette a true-colour image does not use: skip it
        reader.take(
            static_cast<std::size_t>(h.colour_map_length) * ((h.colour_map_entry_bits + 7u) / 8u),
            "colour map");

    // Check that the bytes the header promises are there before allocating:
    // an 18-byte file claiming 65535 x 4096 pixels must not cost a gigabyte.
    const std::size_t pixel_count = static_cast<std::size_t>(h.width) * h.height;
    const int bpp = h.bytes_per_pixel();
    const std::size_t least_bytes =  // RLE: at best one run packet per 128 pixels
        h.rle() ? (pixel_count + 127) / 128 * (1u + static_cast<std::size_t>(bpp))
                : pixel_count * static_cast<std::size_t>(bpp);
    if (reader.remaining() < least_bytes)
        fail(name, "truncated pixel data: a " + std::to_string(h.width) + "x" +
                       std::to_string(h.height) + (h.rle() ? " RLE" : "") +
                       " image needs at least " + std::to_string(least_bytes) +
                       " bytes, the file has " + std::to_string(reader.remaining()) +
                       " after its header");
    std::vector<Rgba> file_order(pixel_count);
    if (h.rle()) {
        decode_rle_pixels(reader, bpp, file_order, name);
    } else {
        const std::uint8_t* raw = reader.take(file_order.size() * bpp, "pixel data");
        for (std::size_t i = 0; i < file_order.size(); ++i)
            file_order[i] = decode_pixel(raw + i * bpp, bpp);
    }

    // [doc:tga-origin]
    // The file lists rows from its origin; our images are bottom row first.
    Image image(h.width, h.height);
    for (int row = 0; row < h.height; ++row) {
        const int y = h.top_row_first() ? h.height - 1 - row : row;
        for (int column = 0; column < h.width; ++column) {
            const int x = h.right_to_left() ? h.width - 1 - column : column;
            image.set(x, y, file_order[static_cast<std::size_t>(row) * h.width + column]);
        }
    }
    // [/doc:tga-origin]
    return image;
}

std::vector<std::uint8_t> encode_tga(const Image& image, const TgaWriteOptions& options) {
    if (image.width() > 0xffff || image.height() > 0xffff)
        throw std::invalid_argument("TGA cannot store an image wider or taller than 65535");
    const int bpp = bytes_per_pixel(options.format);
    const bool grey = options.format == TgaPixelFormat::grey8;
    std::vector<std::uint8_t> out;
    out.reserve(kTgaHeaderSize + static_cast<std::size_t>(image.width()) * image.height() * bpp);
    out.push_back(0);  // no image ID
    out.push_back(0);  // no colour map
    const TgaImageType type =
        grey ? (options.rle ? TgaImageType::grey_rle : TgaImageType::grey)
             : (options.rle ? TgaImageType::true_colour_rle : TgaImageType::true_colour);
    out.push_back(static_cast<std::uint8_t>(type));
    out.insert(out.end(), 5, 0);  // colour map specification: unused
    put_little_endian16(out, 0);  // x origin
    put_little_endian16(out, 0);  // y origin
    put_little_endian16(out, image.width());
    put_little_endian16(out, image.height());
    out.push_back(static_cast<std::uint8_t>(bpp * 8));
    const std::uint8_t alpha_bits = options.format == TgaPixelFormat::bgra32 ? 8 : 0;
    out.push_back(static_cast<std::uint8_t>(alpha_bits | (options.top_row_first ? 0x20 : 0)));

    std::vector<std::uint8_t> row(static_cast<std::size_t>(image.width()) * bpp);
    for (int r = 0; r < image.height(); ++r) {
        const int y = options.top_row_first ? image.height() - 1 - r : r;
        for (int x = 0; x < image.width(); ++x)
            encode_pixel(image.get(x, y), options.format, &row[static_cast<std::size_t>(x) * bpp]);
        if (options.rle)
            encode_rle_row(row, bpp, out);
        else
            out.insert(out.end(), row.begin(), row.end());
    }

    // TGA 2.0 footer: no extension or developer area, then the signature.
    out.insert(out.end(), 8, 0);
    const char signature[] = "TRUEVISION-XFILE.";  // with its terminating NUL: 18 bytes
    out.insert(out.end(), signature, signature + sizeof signature);
    return out;
}

Image read_tga(const std::filesystem::path& path) {
    const std::vector<std::uint8_t> bytes = read_file(path);
    return decode_tga(bytes, path.string());
}

void write_tga(const std::filesystem::path& path, const Image& image,
               const TgaWriteOptions& options) {
    write_file_atomically(path, encode_tga(image, options));
}

}  // namespace rl
