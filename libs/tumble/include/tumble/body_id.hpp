// BodyId: the handle users hold for a body (index plus generation, so stale ids are detected).
#pragma once

#include <cstdint>

namespace tumble {

/// Handle of a body in a World. A default-constructed id is invalid.
struct BodyId {
    static constexpr std::uint32_t kInvalidIndex = 0xffffffffu;

    std::uint32_t index = kInvalidIndex;
    std::uint32_t generation = 0;

    [[nodiscard]] bool isNull() const { return index == kInvalidIndex; }
    friend bool operator==(const BodyId&, const BodyId&) = default;
};

} // namespace tumble
