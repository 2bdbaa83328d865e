// What a contact manifold reports: the feature touching the ground, the average point, the depth.
#include "tumble/contact.hpp"

#include <algorithm>

namespace tumble {

const char* featureName(ContactFeature feature)
{
    switch (feature) {
    case ContactFeature::None: return "none";
    case ContactFeature::Vertex: return "vertex";
    case ContactFeature::Edge: return "edge";
    case ContactFeature::Face: return "face";
    }
    return "?";
}

const char* restitutionStateName(RestitutionState state)
{
    switch (state) {
    case RestitutionState::None: return "none";
    case RestitutionState::Applied: return "applied";
    case RestitutionState::Suppressed: return "suppressed";
    }
    return "?";
}

const char* contactPhaseName(ContactPhase phase)
{
    switch (phase) {
    case ContactPhase::Impact: return "impact";
    case ContactPhase::Resting: return "resting";
    case ContactPhase::Average: return "average";
    }
    return "?";
}

ContactFeature ContactManifold::feature() const
{
    // The lowest vertices of a cuboid near a plane are 1 (a vertex), 2 (an edge) or 4 (a face);
    // 3 within the tolerance happens only for a face a hair off level, so it is a face too.
    switch (pointCount) {
    case 0: return ContactFeature::None;
    case 1: return ContactFeature::Vertex;
    case 2: return ContactFeature::Edge;
    default: return ContactFeature::Face;
    }
}

Vec3 ContactManifold::averagePoint() const
{
    if (pointCount == 0) {
        return Vec3(0.0);
    }
    Vec3 sum(0.0);
    for (int i = 0; i < pointCount; ++i) {
        sum += points[i].position;
    }
    return sum / static_cast<Real>(pointCount);
}

Real ContactManifold::maxPenetration() const
{
    Real deepest = 0.0;
    for (int i = 0; i < pointCount; ++i) {
        deepest = std::max(deepest, points[i].penetration);
    }
    return deepest;
}

} // namespace tumble
