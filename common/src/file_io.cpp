#include "rasterlab/file_io.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <system_error>

namespace rl {

std::vector<std::uint8_t> read_file(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw FileError(path, "is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, std::string("cannot open for reading: ") + std::strerror(errno));
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
    if (in.bad()) throw FileError(path, "read failed");
    return bytes;
}

void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    // A random suffix keeps two writers of the same file from sharing a temporary.
    std::random_device entropy;
    std::filesystem::path temporary = path;
    temporary += ".tmp" + std::to_string(entropy());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out)
            throw FileError(path, std::string("cannot open for writing: ") + std::strerror(errno));
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
        out.flush();
        if (!out) {
            out.close();
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            throw FileError(path, "write failed (disk full?)");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw FileError(path, "cannot replace file: " + ec.message());
    }
}

}  // namespace rl
