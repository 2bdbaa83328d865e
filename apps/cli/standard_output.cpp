#include "standard_output.hpp"

#include "sink_stream.hpp"

#include <ext/stdio_sync_filebuf.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace tumble::cli {
namespace {

SinkStream g_standardOutput{STDOUT_FILENO, 0};

} // namespace

void openStandardOutput(bool lineBuffered)
{
    std::FILE* stream = wrapSinkStream(g_standardOutput);
    if (stream == nullptr) {
        if (lineBuffered) {
            std::setvbuf(stdout, nullptr, _IOLBF, 0);
        }
        return;
    }
    if (lineBuffered) {
        std::setvbuf(stream, nullptr, _IOLBF, 0);
    }
    std::fflush(stdout);
    // glibc's stdout is a variable a program may set: printf and puts now write to the stream
    stdout = stream;
    // std::cout writes through stdio in step with printf; its buffer is never freed, because
    // std::cout is flushed after every static object is gone
    static auto* const buffer = new __gnu_cxx::stdio_sync_filebuf<char>(stream);
    std::cout.rdbuf(buffer);
}

int standardOutputError() { return g_standardOutput.error; }

} // namespace tumble::cli
