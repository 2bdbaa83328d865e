// TUMBLE_ASSERT: contract checks, on in Debug builds and in the tests, off in Release.
#pragma once

#include <cassert>

#define TUMBLE_ASSERT(condition) assert(condition)
