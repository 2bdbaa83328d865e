// SinkStream: a stdio stream over a file descriptor that keeps the errno of its first failed
// write or close. stdio keeps only an error flag, so a write that failed before the final flush
// (a CSV written in one piece, a console line on a full disk) could only be reported as
// "write error"; with the errno kept, every output error names the system's reason.
#pragma once

#include <cstdio>
#include <string>

namespace tumble::cli {

struct SinkStream {
    int descriptor = -1;
    /// errno of the first write or close that failed; 0 while none has.
    int error = 0;
};

/// Opens `path` for writing (created or truncated, as fopen "wb") as a stream over `sink`, which
/// must outlive the stream; fclose closes the descriptor. Returns null with errno set when the
/// file cannot be opened.
std::FILE* openSinkStream(const std::string& path, SinkStream& sink);

/// A stream over the descriptor already in `sink` (standard output), left open by fclose.
std::FILE* wrapSinkStream(SinkStream& sink);

} // namespace tumble::cli
