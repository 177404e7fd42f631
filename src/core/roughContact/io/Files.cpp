// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/io/Files.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/TableReader.hpp" // detail::printable

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <sstream>

namespace roughContact {

namespace {

std::string kindOf(mode_t mode)
{
    if (S_ISDIR(mode)) {
        return "a directory";
    }
    if (S_ISFIFO(mode)) {
        return "a FIFO (a pipe)";
    }
    if (S_ISCHR(mode)) {
        return "a character device";
    }
    if (S_ISBLK(mode)) {
        return "a block device";
    }
    if (S_ISSOCK(mode)) {
        return "a socket";
    }
    return "not a regular file";
}

void requireName(const std::string& path)
{
    if (path.empty()) {
        throw InputError("''", 0, "the file name is empty");
    }
    if (path.find('\0') != std::string::npos) {
        // The operating system would open the name up to the NUL: another file than was named.
        throw InputError(detail::printable(path, 200), 0, "the file name holds a NUL byte; give the name alone");
    }
}

// A descriptor of `path` checked by the readers' rules; its size in `size`.
int openChecked(const std::string& path, std::uint64_t maxBytes, const std::string& kind, std::uint64_t& size)
{
    requireName(path);
    // O_NONBLOCK: opening a FIFO without a writer would wait for one for ever.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const int e = errno;
        throw InputError(path, 0, std::string("cannot open the file for reading: ") +
                                      (e == ENOENT ? "there is no such file" : std::strerror(e)));
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        const std::string what = ::fstat(fd, &st) != 0 ? std::string("cannot be examined") : "is " + kindOf(st.st_mode);
        ::close(fd);
        throw InputError(path, 0, what + ", not a " + kind + " file: the tools read regular files only");
    }
    size = static_cast<std::uint64_t>(st.st_size);
    if (size > maxBytes) {
        ::close(fd);
        throw InputError(path, 0, "is " + byteCount(size) + ", more than any " + kind + " the tools read (at most " +
                                      byteCount(maxBytes) + "): not a " + kind + " file?");
    }
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) {
        (void)::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    }
    return fd;
}

} // namespace

std::string byteCount(std::uint64_t bytes)
{
    std::ostringstream os;
    os.precision(3);
    if (bytes >= 1000000000ull) {
        os << double(bytes) / 1e9 << " GB (" << bytes << " bytes)";
    } else if (bytes >= 1000000ull) {
        os << double(bytes) / 1e6 << " MB (" << bytes << " bytes)";
    } else {
        os << bytes << " bytes";
    }
    return os.str();
}

// A read-only stream buffer over a descriptor that hands out at most `limit` bytes.
class InputFile::Buffer : public std::streambuf {
public:
    Buffer(int fd, std::uint64_t limit) : fd_(fd), remaining_(limit) {}
    ~Buffer() override { ::close(fd_); }
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

protected:
    int_type underflow() override
    {
        if (gptr() < egptr()) {
            return traits_type::to_int_type(*gptr());
        }
        if (remaining_ == 0) {
            return traits_type::eof();
        }
        const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(sizeof data_, remaining_));
        ssize_t n = 0;
        do {
            n = ::read(fd_, data_, want);
        } while (n < 0 && errno == EINTR);
        if (n < 0) {
            // The stream catches it and sets its badbit, which the readers report.
            throw std::ios_base::failure("read error");
        }
        if (n == 0) {
            return traits_type::eof();
        }
        remaining_ -= static_cast<std::uint64_t>(n);
        setg(data_, data_, data_ + n);
        return traits_type::to_int_type(*gptr());
    }

private:
    int fd_;
    std::uint64_t remaining_;
    char data_[1 << 16];
};

InputFile::InputFile(const std::string& path, std::uint64_t maxBytes, const std::string& kind)
    : std::istream(nullptr)
{
    const int fd = openChecked(path, maxBytes, kind, size_);
    buffer_ = std::make_unique<Buffer>(fd, maxBytes);
    rdbuf(buffer_.get());
}

InputFile::~InputFile() = default;

std::string readWholeFile(const std::string& path, std::uint64_t maxBytes, const std::string& kind)
{
    InputFile in(path, maxBytes, kind);
    std::string bytes;
    bytes.reserve(static_cast<std::size_t>(in.size()));
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
        bytes.append(chunk, static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) {
        throw InputError(path, 0, "cannot read the file (read error)");
    }
    return bytes;
}

ExistingFile existingFile(const std::string& path)
{
    ExistingFile e;
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        return e;
    }
    if (!S_ISREG(st.st_mode)) {
        e.kind = ExistingFile::Kind::other;
        e.what = kindOf(st.st_mode);
        return e;
    }
    e.kind = ExistingFile::Kind::regular;
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd >= 0) {
        char head[4096];
        ssize_t n = 0;
        do {
            n = ::read(fd, head, sizeof head);
        } while (n < 0 && errno == EINTR);
        if (n > 0) {
            e.start.assign(head, static_cast<std::size_t>(n));
        }
        ::close(fd);
    }
    return e;
}

std::string folderOf(const std::string& path)
{
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
}

void requireReplaceable(const std::string& path, const std::string& parameter, const std::string& kind,
                        const std::function<bool(const std::string& start)>& isOwn)
{
    if (path.empty()) {
        throw ParameterError(parameter, "the file name is empty: give the " + kind + "'s file");
    }
    if (path.find('\0') != std::string::npos) {
        throw ParameterError(parameter, "the file name holds a NUL byte");
    }
    const ExistingFile existing = existingFile(path);
    if (existing.kind == ExistingFile::Kind::other) {
        throw ParameterError(parameter, "'" + path + "' is " + existing.what + "; the " + kind +
                                            " is written to this name: remove it or choose another");
    }
    if (existing.kind == ExistingFile::Kind::regular && !isOwn(existing.start)) {
        throw ParameterError(parameter, "'" + path + "' exists and is not a " + kind + " (it begins '" +
                                            detail::printable(existing.start.substr(0, 60), 60) +
                                            "'): it is left as it is; give another name, or remove it");
    }
}

void replaceFile(const std::string& path, const std::string& contents, const std::string& parameter,
                 const std::string& kind, const std::function<bool(const std::string& start)>& isOwn)
{
    requireReplaceable(path, parameter, kind, isOwn);
    // Created exclusively (O_EXCL: never through a link or over a file already there) under a
    // fresh random name; its mode is what umask leaves of 0666, as for any new file.
    std::string temporary;
    int fd = -1;
    std::random_device random;
    for (int attempt = 0; attempt < 16 && fd < 0; ++attempt) {
        std::ostringstream name;
        name << path << ".tmp." << ::getpid() << "." << std::hex << random() << random();
        temporary = name.str();
        fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd < 0 && errno != EEXIST) {
            break;
        }
    }
    if (fd < 0) {
        const int e = errno;
        throw ParameterError(parameter, "cannot write into the folder '" + folderOf(path) + "' of '" + path + "' (" +
                                            std::strerror(e) + ")");
    }
    const char* p = contents.data();
    std::size_t left = contents.size();
    bool good = true;
    while (left > 0 && good) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        good = n > 0;
        if (good) {
            p += n;
            left -= static_cast<std::size_t>(n);
        }
    }
    const int writeError = good ? 0 : errno;
    good = ::close(fd) == 0 && good;
    if (!good) {
        ::unlink(temporary.c_str());
        throw ParameterError(parameter, "writing '" + temporary + "' failed" +
                                            (writeError ? " (" + std::string(std::strerror(writeError)) + ")" : ""));
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const int e = errno;
        ::unlink(temporary.c_str());
        throw ParameterError(parameter, "cannot rename '" + temporary + "' to '" + path + "' (" + std::strerror(e) + ")");
    }
}

} // namespace roughContact
