// `tumble view FILE --throw I`: throw I of a [throw] scenario written as a replay file in the
// temporary directory, which the viewer then opens as any scenario (and which is removed after).
#pragma once

#include "view_command.hpp"

#include <filesystem>

namespace tumble::cli {

/// Without --throw, the options as given. With it, writes the replay of throw I (every die,
/// the static geometry) and gives options whose file is that replay and whose overrides are
/// empty (they are in the file). Throws ScenarioError when the file has no [throw] table.
class ThrowViewFile {
public:
    explicit ThrowViewFile(const ViewOptions& given);
    ~ThrowViewFile();
    ThrowViewFile(const ThrowViewFile&) = delete;
    ThrowViewFile& operator=(const ThrowViewFile&) = delete;

    [[nodiscard]] const ViewOptions& options() const { return m_options; }

private:
    ViewOptions m_options;
    std::filesystem::path m_written;
};

} // namespace tumble::cli
