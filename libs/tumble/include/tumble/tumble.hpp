// Umbrella include: the whole public API of the tumble library.
#pragma once

#include "tumble/body.hpp"
#include "tumble/body_id.hpp"
#include "tumble/contact.hpp"
#include "tumble/energy_ledger.hpp"
#include "tumble/events.hpp"
#include "tumble/impulse_target.hpp"
#include "tumble/material.hpp"
#include "tumble/settings.hpp"
#include "tumble/math.hpp"
#include "tumble/shape.hpp"
#include "tumble/world.hpp"
