// WorldState: the World a Python tumble.World owns, shared with the body handles it gives out,
// and BodyHandle, the Python body handle (a World plus a generational id, so a handle to a
// destroyed body is detected and raises instead of reading freed state).
#pragma once

#include "tumble/body.hpp"
#include "tumble/body_id.hpp"
#include "tumble/world.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace tumble::python {

/// A World with its bodies in creation order. Shared by the Python World and every handle, so a
/// handle keeps its world alive and the world is freed with the last of them.
struct WorldState {
    World world;
    /// Id of the body with each serial number (the order add_body created them).
    std::vector<BodyId> ids;
    std::vector<std::string> names;
    /// True while a call runs the world without the GIL; every other call then raises. Read and
    /// written only with the GIL held.
    bool running = false;

    /// The world, or RuntimeError while a run holds it (another Python thread's call).
    World& checked();
    /// The serial number of a live body id (ids is searched; bodies are few in Python scenes).
    [[nodiscard]] std::size_t serialOf(BodyId id) const;
    /// Adds a body created in `world` under the next serial number.
    std::size_t adopt(BodyId id, std::string name);
};

/// What tumble.Body holds: which body of which world.
class BodyHandle {
public:
    BodyHandle(std::shared_ptr<WorldState> state, std::size_t serial)
        : m_state(std::move(state)), m_serial(serial)
    {
    }

    /// The body's state; raises StaleBodyError when it was removed.
    [[nodiscard]] const Body& body() const;
    /// The body's id; raises StaleBodyError when it was removed.
    [[nodiscard]] BodyId id() const;
    /// The id of a dynamic body; ValueError for a static one, which `what` (a velocity, an
    /// impulse) cannot move.
    [[nodiscard]] BodyId dynamicId(const char* what) const;
    [[nodiscard]] bool alive() const;
    [[nodiscard]] std::size_t serial() const { return m_serial; }
    [[nodiscard]] const std::string& name() const { return m_state->names[m_serial]; }
    [[nodiscard]] WorldState& state() const { return *m_state; }
    [[nodiscard]] const std::shared_ptr<WorldState>& sharedState() const { return m_state; }

private:
    std::shared_ptr<WorldState> m_state;
    std::size_t m_serial;
};

/// Raised (as tumble.StaleBodyError) for a handle whose body was removed.
class StaleBodyError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Raised (as tumble.WorldBusyError) when a world is used while a run holds it.
class WorldBusyError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace tumble::python
