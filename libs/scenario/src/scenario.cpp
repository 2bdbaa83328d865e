// ScenarioError: the one-line "FILE:LINE: KEY: problem" message every scenario failure carries.
#include "tumble/scenario/scenario.hpp"

#include <string>
#include <utility>

namespace tumble::scenario {

namespace {

/// Line breaks from quoted user text are written as \n and \r so the message stays one line.
std::string oneLine(const std::string& text)
{
    std::string result;
    result.reserve(text.size());
    for (const char c : text) {
        if (c == '\n') {
            result += "\\n";
        } else if (c == '\r') {
            result += "\\r";
        } else {
            result += c;
        }
    }
    return result;
}

std::string formatMessage(const SourceLocation& where, const std::string& key,
                          const std::string& problem)
{
    std::string message = where.file;
    if (where.line > 0) {
        message += ':';
        message += std::to_string(where.line);
    }
    message += ": ";
    if (!key.empty()) {
        message += key;
        message += ": ";
    }
    message += problem;
    return oneLine(message);
}

} // namespace

ScenarioError::ScenarioError(SourceLocation where, std::string key, const std::string& problem)
    : std::runtime_error(formatMessage(where, key, problem)), m_where(std::move(where)),
      m_key(std::move(key)), m_problem(problem)
{
}

} // namespace tumble::scenario
