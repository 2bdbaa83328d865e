// What a step reports besides the new state: impacts (contact.hpp) and bodies coming to rest.
#pragma once

#include "tumble/body_id.hpp"
#include "tumble/math.hpp"
#include "tumble/shape.hpp"

namespace tumble {

/// A body that has just come to rest.
struct RestEvent {
    BodyId body{};
    /// End of the first step after which the body was slow and stayed so, s.
    Real time = 0.0;
    /// The face lying on the ground.
    CuboidFace faceDown = CuboidFace::MinusY;
};

} // namespace tumble
