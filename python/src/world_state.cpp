// WorldState and BodyHandle: the checks that turn a stale handle or a busy world into a Python
// exception.
#include "world_state.hpp"

#include <algorithm>
#include <stdexcept>

namespace tumble::python {

World& WorldState::checked()
{
    if (running) {
        throw WorldBusyError("this tumble.World is running in another thread; wait for its run "
                             "to return");
    }
    return world;
}

std::size_t WorldState::serialOf(BodyId id) const
{
    const auto found = std::find(ids.begin(), ids.end(), id);
    if (found == ids.end()) {
        throw std::logic_error("tumble: a body id that this world never gave out");
    }
    return static_cast<std::size_t>(found - ids.begin());
}

std::size_t WorldState::adopt(BodyId id, std::string name)
{
    ids.push_back(id);
    names.push_back(std::move(name));
    return ids.size() - 1;
}

bool BodyHandle::alive() const { return m_state->world.isValid(m_state->ids[m_serial]); }

BodyId BodyHandle::id() const
{
    World& world = m_state->checked();
    const BodyId id = m_state->ids[m_serial];
    if (!world.isValid(id)) {
        throw StaleBodyError("body " + name() + " was removed from its world; this handle is "
                             "stale");
    }
    return id;
}

BodyId BodyHandle::dynamicId(const char* what) const
{
    const BodyId dynamic = id();
    if (m_state->world.body(dynamic).isStatic()) {
        throw std::invalid_argument("body " + name() + " is static: " + what +
                                    " cannot move it");
    }
    return dynamic;
}

const Body& BodyHandle::body() const { return m_state->world.body(id()); }

} // namespace tumble::python
