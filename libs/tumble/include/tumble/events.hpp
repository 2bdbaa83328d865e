// What a step reports besides the new state: impacts (contact.hpp) and bodies coming to rest.
#pragma once

#include "tumble/body_id.hpp"
#include "tumble/math.hpp"
#include "tumble/shape.hpp"

#include <cstddef>

namespace tumble {

/// A body that has just come to rest.
struct RestEvent {
    BodyId body{};
    /// End of the first step after which the body was slow and stayed so, s.
    Real time = 0.0;
    /// The face lying on the ground.
    CuboidFace faceDown = CuboidFace::MinusY;
};

/// What the island solver did in one step, summed over the islands of touching bodies (bodies
/// alone on the exact path are not counted): where the time of a scene goes.
struct SolverStatistics {
    /// Islands solved together, and the bodies in them.
    std::size_t islands = 0;
    std::size_t bodies = 0;
    /// Contact points of the first sub-step of each island (speculative ones included).
    std::size_t contactPoints = 0;
    /// Sub-steps, Gauss-Seidel solves (impacts, sub-steps, re-solves after a cut) and sweeps.
    std::size_t substeps = 0;
    std::size_t solves = 0;
    std::size_t sweeps = 0;
    /// Islands whose first sub-step kept the last step's constraints, unmoved (11.6a).
    std::size_t keptIslands = 0;

    SolverStatistics& operator+=(const SolverStatistics& other)
    {
        islands += other.islands;
        bodies += other.bodies;
        contactPoints += other.contactPoints;
        substeps += other.substeps;
        solves += other.solves;
        sweeps += other.sweeps;
        keptIslands += other.keptIslands;
        return *this;
    }
};

} // namespace tumble
