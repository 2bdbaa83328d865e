#include "viewer/log_buffer.hpp"

namespace tumble::viewer {

void LogBuffer::append(std::string_view text)
{
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        m_lines.push(std::string(text.substr(0, end)));
        if (end == std::string_view::npos) {
            break;
        }
        text.remove_prefix(end + 1);
    }
}

} // namespace tumble::viewer
