// LogBuffer: the last lines of `tumble run` style console output, for the log panel.
#pragma once

#include "viewer/ring_buffer.hpp"

#include <string>
#include <string_view>

namespace tumble::viewer {

class LogBuffer {
public:
    /// Lines kept at most.
    static constexpr std::size_t kDefaultCapacity = 4000;

    explicit LogBuffer(std::size_t capacity = kDefaultCapacity) : m_lines(capacity) {}

    /// Appends `text` split into lines (a trailing newline ends the last line, adding none).
    void append(std::string_view text);
    void clear() { m_lines.clear(); }
    [[nodiscard]] const RingBuffer<std::string>& lines() const { return m_lines; }

private:
    RingBuffer<std::string> m_lines;
};

} // namespace tumble::viewer
