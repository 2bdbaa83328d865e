// Standard output through a SinkStream, so a console line that cannot be written is reported with
// the system's reason: stdio's own stdout keeps only an error flag, and a line that failed before
// the final flush was reported as "write error".
#pragma once

namespace tumble::cli {

/// Points stdout and std::cout at a SinkStream over descriptor 1, line-buffered when asked (lines
/// written stay written when a signal ends the process), else fully buffered. Call once, before
/// any output. Where no such stream can be made, stdio's stdout stays.
void openStandardOutput(bool lineBuffered);

/// The errno of the first write to standard output that failed, or 0.
int standardOutputError();

} // namespace tumble::cli
