#include "sink_stream.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>

namespace tumble::cli {
namespace {

/// The stream's write function (fopencookie): writes all of `data` to the descriptor and keeps
/// the errno of the first failure.
ssize_t writeToSink(void* cookie, const char* data, std::size_t size)
{
    auto* sink = static_cast<SinkStream*>(cookie);
    std::size_t written = 0;
    while (written < size) {
        const ssize_t count = ::write(sink->descriptor, data + written, size - written);
        if (count < 0 && errno == EINTR) {
            continue;
        }
        if (count <= 0) {
            sink->error = sink->error != 0 ? sink->error : (count < 0 ? errno : EIO);
            // fewer bytes than asked for is how a cookie stream reports an error
            return static_cast<ssize_t>(written);
        }
        written += static_cast<std::size_t>(count);
    }
    return static_cast<ssize_t>(size);
}

int closeSink(void* cookie)
{
    auto* sink = static_cast<SinkStream*>(cookie);
    if (::close(sink->descriptor) != 0) {
        sink->error = sink->error != 0 ? sink->error : errno;
        return -1;
    }
    return 0;
}

} // namespace

std::FILE* openSinkStream(const std::string& path, SinkStream& sink)
{
    sink.descriptor = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (sink.descriptor < 0) {
        return nullptr;
    }
    std::FILE* file = fopencookie(&sink, "wb", {nullptr, writeToSink, nullptr, closeSink});
    if (file == nullptr) {
        const int error = errno;
        ::close(sink.descriptor);
        errno = error;
    }
    return file;
}

std::FILE* wrapSinkStream(SinkStream& sink)
{
    return fopencookie(&sink, "wb", {nullptr, writeToSink, nullptr, nullptr});
}

} // namespace tumble::cli
