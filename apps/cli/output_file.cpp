#include "output_file.hpp"

#include "interrupt.hpp"
#include "standard_output.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>

namespace tumble::cli {
namespace {

/// "cannot write PATH: REASON" from `error` (an errno value), or from errno.
OutputError writeError(const std::string& path, int error = errno)
{
    return OutputError("cannot write " + path + ": " +
                       (error != 0 ? std::strerror(error) : "write error"));
}

} // namespace

OutputFile::OutputFile(const std::string& path) : m_path(path), m_toStdout(path == "-")
{
    if (m_toStdout) {
        m_file = stdout;
        m_direct = true;
        return;
    }
    std::error_code ignored;
    const auto status = std::filesystem::status(path, ignored);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
        m_direct = true;
        m_file = openSinkStream(path, m_sink);
        if (m_file == nullptr) {
            throw writeError(path);
        }
        return;
    }
    m_temporary = std::filesystem::path(path + ".tmp");
    m_file = openSinkStream(m_temporary.string(), m_sink);
    if (m_file == nullptr) {
        throw writeError(m_temporary.string());
    }
    m_temporarySlot = registerTemporaryFile(m_temporary.string());
}

OutputFile::~OutputFile()
{
    unregisterTemporaryFile(m_temporarySlot);
    // an unfinished file is removed: only complete runs leave a file behind
    if (!m_toStdout && m_file != nullptr) {
        std::fclose(m_file);
        if (!m_direct) {
            std::error_code ignored;
            std::filesystem::remove(m_temporary, ignored);
        }
    }
}

int OutputFile::descriptor() const
{
    return m_toStdout ? STDOUT_FILENO : m_sink.descriptor;
}

void OutputFile::finish()
{
    errno = 0;
    if (m_toStdout) {
        if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
            throw writeError("standard output", standardOutputError() != 0 ? standardOutputError()
                                                                            : errno);
        }
        return;
    }
    const bool flushFailed = std::fflush(m_file) != 0;
    const bool failed = flushFailed || std::ferror(m_file) != 0;
    const bool closeFailed = std::fclose(m_file) != 0;
    m_file = nullptr;
    const std::string written = m_direct ? m_path : m_temporary.string();
    unregisterTemporaryFile(m_temporarySlot);
    m_temporarySlot = -1;
    if (failed || closeFailed) {
        const OutputError problem = writeError(written, m_sink.error);
        std::error_code ignored;
        if (!m_direct) {
            std::filesystem::remove(m_temporary, ignored);
        }
        throw problem;
    }
    if (m_direct) {
        return;
    }
    std::error_code error;
    std::filesystem::rename(m_temporary, m_path, error);
    if (error) {
        std::error_code ignored;
        std::filesystem::remove(m_temporary, ignored);
        throw OutputError("cannot rename " + m_temporary.string() + " to " + m_path + ": " +
                          error.message());
    }
}

std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\r\n") == std::string::npos) {
        return text;
    }
    std::string quoted = "\"";
    for (const char c : text) {
        quoted += c;
        if (c == '"') {
            quoted += '"';
        }
    }
    return quoted + "\"";
}

} // namespace tumble::cli
