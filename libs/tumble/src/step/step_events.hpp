// The events of one unit of work of a step (a batch of islands), merged into the world's lists
// in a fixed order afterwards, so the order never depends on which thread ran which unit.
#pragma once

#include "tumble/contact.hpp"
#include "tumble/events.hpp"

#include <vector>

namespace tumble {

struct StepEvents {
    std::vector<CollisionEvent> collisions;
    std::vector<RestEvent> restEvents;
    std::vector<ContactRecord> contactRecords;
    SolverStatistics statistics;

    void clear()
    {
        statistics = {};
        collisions.clear();
        restEvents.clear();
        contactRecords.clear();
    }
};

} // namespace tumble
