// OutputFile: a file the CLI writes whole or not at all. It is written under PATH.tmp and renamed
// to PATH by finish(); a run that fails or stops early removes the temporary file. A write that
// fails is reported with the system's reason, whenever it happened.
#pragma once

#include "sink_stream.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace tumble::cli {

/// An output file or stream that cannot be written (full disk, unwritable path): exit code 3.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class OutputFile {
public:

    /// "-" means stdout, and a path that exists but is not a regular file (/dev/stdout, a pipe)
    /// is written directly; any other path goes through PATH.tmp. Throws OutputError.
    explicit OutputFile(const std::string& path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    [[nodiscard]] std::FILE* handle() const { return m_file; }
    /// The file descriptor the stream writes to, for a child process to write into.
    [[nodiscard]] int descriptor() const;
    [[nodiscard]] bool toStdout() const { return m_toStdout; }
    /// Flushes, closes and renames the temporary file into place. Throws on a write error.
    void finish();

private:
    std::string m_path;
    std::filesystem::path m_temporary;
    std::FILE* m_file = nullptr;
    /// The file under m_file (not for stdout), keeping the reason of a failed write.
    SinkStream m_sink;
    bool m_toStdout = false;
    /// Written in place: stdout or a device, nothing to rename.
    bool m_direct = false;
    /// Slot of m_temporary in the interrupt handler's list (interrupt.hpp), or -1.
    int m_temporarySlot = -1;
};

/// A name as one CSV field: quoted (with doubled quotes) only when it needs to be.
std::string csvField(const std::string& text);

} // namespace tumble::cli
