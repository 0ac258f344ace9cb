#include "rasterlab/file_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <mutex>
#include <new>
#include <random>
#include <utility>

namespace rl {
namespace {

std::string errno_text() {
    return std::strerror(errno);
}

// "3 MiB" for sizes of a mebibyte or more (the caps are whole MiB), bytes below.
std::string mebibytes(std::uintmax_t bytes) {
    if (bytes < (std::uintmax_t{1} << 20)) return std::to_string(bytes) + " bytes";
    return std::to_string(bytes >> 20) + " MiB";
}

// Closes a file descriptor on every path out of a function.
class Descriptor {
  public:
    explicit Descriptor(int fd) : fd_(fd) {}
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    int get() const { return fd_; }
    int release() { return std::exchange(fd_, -1); }

  private:
    int fd_;
};

// ---------------------------------------------------------------------------
// Temporaries left by a process stopped with Ctrl-C or `kill`: the signal
// handler removes those still registered, then lets the signal take its course.
// Fixed-size storage, since a signal handler may not allocate. Threads (the
// Python module saves from several at once) each claim a free slot with a
// compare-and-swap and free only their own, by its index: no two share a
// slot, and no thread reads another's name. The handler reads a name only
// once its slot is marked ready, after the name is complete (a signal taken
// while another thread frees and refills that very slot could still catch a
// name half-copied: the window is one memcpy).
constexpr int kMaxPending = 16;
enum PendingSlot : int { kFree, kFilling, kReady };
char g_pending[kMaxPending][PATH_MAX];
std::atomic<int> g_pending_state[kMaxPending];
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler reads the slots");

extern "C" void remove_pending_and_reraise(int signal_number) {
    for (int i = 0; i < kMaxPending; ++i)
        if (g_pending_state[i].load() == kReady) ::unlink(g_pending[i]);
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    sigaction(signal_number, &default_action, nullptr);
    ::raise(signal_number);
}

void install_cleanup_handlers() {
    static const bool installed = [] {
        for (int s : {SIGINT, SIGTERM, SIGHUP}) {
            struct sigaction current {};
            sigaction(s, nullptr, &current);
            if (current.sa_handler != SIG_DFL) continue;  // the program has its own plan
            struct sigaction cleanup {};
            cleanup.sa_handler = remove_pending_and_reraise;
            sigemptyset(&cleanup.sa_mask);
            sigaction(s, &cleanup, nullptr);
        }
        return true;
    }();
    (void)installed;
}

// Remembers a temporary for the signal handler; returns its slot, for
// unregister_pending(). Beyond kMaxPending at once (no program here stages
// more than three) it returns -1: the temporary is still removed on an
// error, only not on a signal.
int register_pending(const std::filesystem::path& temporary) {
    install_cleanup_handlers();
    const std::string& text = temporary.native();
    if (text.size() >= PATH_MAX) return -1;
    for (int i = 0; i < kMaxPending; ++i) {
        int expected = kFree;
        if (!g_pending_state[i].compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(g_pending[i], text.c_str(), text.size() + 1);
        g_pending_state[i].store(kReady);
        return i;
    }
    return -1;
}

void unregister_pending(int slot) {
    if (slot >= 0) g_pending_state[slot].store(kFree);
}

void remove_temporary(const std::filesystem::path& temporary, int slot) {
    ::unlink(temporary.c_str());
    unregister_pending(slot);
}

// ".rasterlab-tmp-<6 random letters>-<target name>", cut so that it is no
// longer than the longest name a folder holds (255 bytes here) even when the
// target's own name is that long. One generator for the process, behind a
// lock: threads save at once.
std::filesystem::path temporary_beside(const std::filesystem::path& target) {
    static std::mutex random_mutex;
    static std::mt19937_64 random{std::random_device{}()};
    static constexpr char letters[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    std::string name = kTemporaryPrefix;
    {
        const std::lock_guard<std::mutex> lock(random_mutex);
        for (int i = 0; i < 6; ++i) name += letters[random() % (sizeof letters - 1)];
    }
    name += '-';
    name += target.filename().string();
    constexpr std::size_t kNameMax = 255;
    if (name.size() > kNameMax) name.resize(kNameMax);
    return target.parent_path() / name;
}

void write_all(int fd, std::span<const std::uint8_t> bytes, const std::filesystem::path& path) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw FileError(path, "write failed: " + errno_text());
        done += static_cast<std::size_t>(n);
    }
}

// Every file this run has read: device, inode and the path it was read by.
struct InputFile {
    dev_t device;
    ino_t inode;
    std::filesystem::path path;
};
std::mutex inputs_mutex;
std::vector<InputFile>& inputs() {
    static std::vector<InputFile> files;
    return files;
}

void remember_input(const struct stat& info, const std::filesystem::path& path) {
    const std::lock_guard<std::mutex> lock(inputs_mutex);
    for (const InputFile& f : inputs())
        if (f.device == info.st_dev && f.inode == info.st_ino) return;
    inputs().push_back({info.st_dev, info.st_ino, path});
}

}  // namespace

std::filesystem::path read_as_input(const std::filesystem::path& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) return {};
    const std::lock_guard<std::mutex> lock(inputs_mutex);
    for (const InputFile& f : inputs())
        if (f.device == info.st_dev && f.inode == info.st_ino) return f.path;
    return {};
}

void forget_inputs() {
    const std::lock_guard<std::mutex> lock(inputs_mutex);
    inputs().clear();
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
    struct stat x {
    }, y{};
    const bool a_exists = ::stat(a.c_str(), &x) == 0, b_exists = ::stat(b.c_str(), &y) == 0;
    if (a_exists && b_exists) return x.st_dev == y.st_dev && x.st_ino == y.st_ino;
    if (a_exists != b_exists) return false;
    // Neither exists yet: where a write would land, through links that point
    // at a file not yet made (ln -s f.tga l.tga: -o f.tga and -o l.tga are one file).
    const auto landing = [](const std::filesystem::path& p, std::error_code& ec) {
        std::filesystem::path target;
        try {
            target = resolve_output(p);
        } catch (const FileError&) {
            target = p;  // a loop: check_output() refuses it
        }
        return std::filesystem::weakly_canonical(std::filesystem::absolute(target), ec);
    };
    std::error_code ec_a, ec_b;
    const std::filesystem::path ca = landing(a, ec_a), cb = landing(b, ec_b);
    return !ec_a && !ec_b && ca == cb;
}

std::vector<std::uint8_t> read_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
    // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below.
    Descriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    if (fd.get() < 0) throw FileError(path, "cannot open for reading: " + errno_text());
    struct stat info {};
    if (::fstat(fd.get(), &info) != 0) throw FileError(path, "cannot inspect: " + errno_text());
    if (S_ISDIR(info.st_mode)) throw FileError(path, "is a directory");
    if (!S_ISREG(info.st_mode))
        throw FileError(path,
                        "is not a regular file (a device, FIFO or socket); refusing to read it");
    const auto size = static_cast<std::uintmax_t>(info.st_size);
    if (size > max_bytes)
        throw FileError(path, "is " + mebibytes(size) + ", more than the " + mebibytes(max_bytes) +
                                  " this program reads");
    remember_input(info, path);
    std::vector<std::uint8_t> bytes;
    try {
        bytes.resize(static_cast<std::size_t>(size));
    } catch (const std::bad_alloc&) {
        throw FileError(path, "out of memory reading " + mebibytes(size));
    }
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::read(fd.get(), bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw FileError(path, "read failed: " + errno_text());
        if (n == 0) break;  // the file shrank while we read it
        done += static_cast<std::size_t>(n);
    }
    bytes.resize(done);
    return bytes;
}

std::filesystem::path resolve_output(const std::filesystem::path& path) {
    std::filesystem::path target = path;
    for (int hops = 0; hops < 40; ++hops) {
        std::error_code ec;
        if (!std::filesystem::is_symlink(target, ec)) return target;
        const std::filesystem::path link = std::filesystem::read_symlink(target, ec);
        if (ec) throw FileError(path, "cannot read symbolic link: " + ec.message());
        target = link.is_absolute() ? link : target.parent_path() / link;
    }
    throw FileError(path, "too many levels of symbolic links");
}

void check_output(const std::filesystem::path& path) {
    if (path.empty()) throw FileError(path, "empty output path");
    const std::filesystem::path target = resolve_output(path);
    if (!target.has_filename()) throw FileError(path, "names a folder, not a file");
    std::filesystem::path folder = target.parent_path();
    if (folder.empty()) folder = ".";
    struct stat info {};
    if (::stat(folder.c_str(), &info) != 0)
        throw FileError(path, "cannot write into " + folder.string() + ": " + errno_text());
    if (!S_ISDIR(info.st_mode))
        throw FileError(path, "cannot write into " + folder.string() + ": not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw FileError(path, "cannot write into " + folder.string() + ": " + errno_text());
    if (::lstat(target.c_str(), &info) != 0) {
        if (errno == ENOENT) return;  // a new file
        throw FileError(path, "cannot inspect: " + errno_text());
    }
    if (S_ISDIR(info.st_mode)) throw FileError(path, "is a directory; refusing to replace it");
    if (!S_ISREG(info.st_mode))
        throw FileError(path,
                        "is not a regular file (a device, FIFO or socket); refusing to replace it");
    // Root may write anything, so ask the permission bits rather than access().
    if ((info.st_mode & S_IWUSR) == 0)
        throw FileError(path, "is read-only; refusing to replace it");
    const std::filesystem::path input = read_as_input(target);
    if (!input.empty())
        throw FileError(path, "is a file this run read as an input (" + input.string() +
                                  "); refusing to replace it");
}

void OutputFiles::claim(const std::filesystem::path& path) {
    for (const std::filesystem::path& earlier : claimed_)
        if (same_file(earlier, path))
            throw FileError(path, "is the same file as the output " + earlier.string() +
                                      "; refusing to write one over the other");
    claimed_.push_back(path);
}

void OutputFiles::check(const std::filesystem::path& path) {
    check_output(path);
    claim(path);
}

OutputFiles::~OutputFiles() {
    for (const Staged& s : staged_) remove_temporary(s.temporary, s.pending);
}

void OutputFiles::stage(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    check_output(path);
    for (const Staged& s : staged_)
        if (same_file(s.requested, path))
            throw FileError(path, "is the same file as the output " + s.requested.string() +
                                      "; refusing to write one over the other");
    // A path check() claimed is this output itself; any other is claimed now.
    if (std::find(claimed_.begin(), claimed_.end(), path) == claimed_.end()) claim(path);
    Staged s{path, resolve_output(path), {}};
    // Keep an existing file's permission bits; a new file gets 0666 less the umask.
    mode_t mode = 0666;
    struct stat info {};
    const bool exists = ::stat(s.target.c_str(), &info) == 0;
    if (exists) mode = info.st_mode & 07777;
    int raw_fd = -1;
    for (int attempt = 0; attempt < 16 && raw_fd < 0; ++attempt) {
        s.temporary = temporary_beside(s.target);
        raw_fd = ::open(s.temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
        if (raw_fd < 0 && errno != EEXIST)
            throw FileError(path, "cannot open for writing: " + errno_text());
    }
    if (raw_fd < 0) throw FileError(path, "cannot create a temporary file beside it");
    s.pending = register_pending(s.temporary);
    Descriptor fd(raw_fd);
    try {
        if (exists && ::fchmod(fd.get(), mode) != 0)
            throw FileError(path, "cannot keep its permissions: " + errno_text());
        write_all(fd.get(), bytes, path);
        if (::close(fd.release()) != 0) throw FileError(path, "write failed: " + errno_text());
    } catch (...) {
        remove_temporary(s.temporary, s.pending);
        throw;
    }
    staged_.push_back(std::move(s));
}

void OutputFiles::commit() {
    // Every output is complete on disk before the first rename; a rename
    // within one folder does not fail for want of space.
    for (std::size_t i = 0; i < staged_.size(); ++i) {
        const Staged& s = staged_[i];
        if (::rename(s.temporary.c_str(), s.target.c_str()) != 0) {
            const std::string problem = "cannot replace file: " + errno_text();
            staged_.erase(staged_.begin(), staged_.begin() + static_cast<std::ptrdiff_t>(i));
            throw FileError(s.requested, problem);
        }
        unregister_pending(s.pending);
    }
    staged_.clear();
}

void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    OutputFiles out;
    out.stage(path, bytes);
    out.commit();
}

}  // namespace rl
