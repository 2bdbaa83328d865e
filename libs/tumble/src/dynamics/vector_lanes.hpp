// kLanes doubles side by side, one per vector lane, and the lane-by-lane forms of the few
// operations the contact steps need, each the IEEE operation of each lane, so that a lane rounds
// exactly as the scalar code does (docs/physics/11-island-solver.md, (11.5d);
// docs/physics/12-soft-step.md, (12.9)). For dynamics/wide_sweep.cpp and dynamics/soft_lane*.
#pragma once

#include "tumble/math.hpp"

#include <cmath>
#include <cstdint>

// The vectors below never cross the lane passes' files, so how a target without registers of
// their width passes them (the -Wpsabi note of GCC and Clang) does not matter.
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace tumble::lanes {

#ifndef TUMBLE_VECTOR_LANES
#define TUMBLE_VECTOR_LANES 4
#endif
/// Manifolds a lane pass takes at once: eight where the build is for a machine with AVX-512, else
/// four (libs/tumble/CMakeLists.txt). A colour's manifolds share no dynamic body, so the order in
/// which its blocks take them changes no bit: the results are the same for either.
constexpr int kLanes = TUMBLE_VECTOR_LANES;
static_assert(kLanes == 4 || kLanes == 8);

// Each lane function is built three times on x86-64 with GCC: for x86-64-v4 (AVX-512: 32
// registers, of eight doubles, so the lane passes keep their rows in registers rather than on the
// stack), for AVX2, and for the baseline; the loader picks the one the processor runs. No build
// fuses a multiply and an add (-ffp-contract=off), so all three give the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define TUMBLE_WIDE_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define TUMBLE_WIDE_CLONES
#endif
/// The helpers are inlined into each compiled copy of sweepBlocks, so each copy uses its own
/// instructions throughout.
#define TUMBLE_WIDE_INLINE inline __attribute__((always_inline))

/// kLanes doubles, one per lane (GCC and Clang vector extensions: each operation is the IEEE
/// operation of each lane, so a lane rounds exactly as the scalar step).
/// Aligned to its size explicitly: without AVX, GCC gives a 32-byte vector only 16-byte
/// alignment, which the wider copies' aligned loads would not meet.
using Wide = double __attribute__((vector_size(kLanes * 8), aligned(kLanes * 8)));
/// A lane mask: all bits set where true (the result of comparing two Wide).
using Mask = std::int64_t __attribute__((vector_size(kLanes * 8), aligned(kLanes * 8)));

TUMBLE_WIDE_INLINE Wide splat(Real x) { return Wide{} + x; }

TUMBLE_WIDE_INLINE Wide select(Mask where, Wide yes, Wide no)
{
    return __builtin_bit_cast(Wide, (where & __builtin_bit_cast(Mask, yes)) |
                                  (~where & __builtin_bit_cast(Mask, no)));
}

TUMBLE_WIDE_INLINE bool any(Mask m)
{
    std::int64_t bits = 0;
    for (int lane = 0; lane < kLanes; ++lane) {
        bits |= m[lane];
    }
    return bits != 0;
}

TUMBLE_WIDE_INLINE Mask less(Wide a, Wide b) { return __builtin_bit_cast(Mask, a < b); }
TUMBLE_WIDE_INLINE Mask lessEqual(Wide a, Wide b) { return __builtin_bit_cast(Mask, a <= b); }

TUMBLE_WIDE_INLINE Wide absolute(Wide x)
{
    const Mask signless = Mask{} + INT64_MAX;
    const Mask magnitude = __builtin_bit_cast(Mask, x) & signless;
    return __builtin_bit_cast(Wide, magnitude);
}

/// std::max(a, b) lane by lane: b where a < b, else a.
TUMBLE_WIDE_INLINE Wide maximum(Wide a, Wide b) { return select(less(a, b), b, a); }

TUMBLE_WIDE_INLINE Wide squareRoot(Wide x)
{
    Wide root = x;
    for (int lane = 0; lane < kLanes; ++lane) {
        root[lane] = std::sqrt(x[lane]);
    }
    return root;
}

struct Wide3 {
    Wide x, y, z;
};

/// glm's dot: (a.x b.x + a.y b.y) + a.z b.z.
TUMBLE_WIDE_INLINE Wide dot(const Wide3& a, const Wide3& b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// a -= s d (or a += s d with `add`), lane by lane.
TUMBLE_WIDE_INLINE void addScaled(Wide3& a, Wide s, const Wide3& d, bool add)
{
    a = add ? Wide3{a.x + s * d.x, a.y + s * d.y, a.z + s * d.z}
            : Wide3{a.x - s * d.x, a.y - s * d.y, a.z - s * d.z};
}

/// addScaled where `where`, else a: one body's part of applyAlong.
TUMBLE_WIDE_INLINE void pushAlong(Wide3& a, Wide s, const Wide3& d, Mask where, bool add)
{
    Wide3 moved = a;
    addScaled(moved, s, d, add);
    a = {select(where, moved.x, a.x), select(where, moved.y, a.y), select(where, moved.z, a.z)};
}

TUMBLE_WIDE_INLINE void setLane(Wide3& wide, int lane, const Vec3& v)
{
    wide.x[lane] = v.x;
    wide.y[lane] = v.y;
    wide.z[lane] = v.z;
}

TUMBLE_WIDE_INLINE Vec3 laneOf(const Wide3& wide, int lane)
{
    return {wide.x[lane], wide.y[lane], wide.z[lane]};
}

/// frictionOnCone (friction_cone.cpp, (6.4)) lane by lane, the same operations in the same
/// order; `shift` changes only in the lanes on the cone's edge.
TUMBLE_WIDE_INLINE void frictionOnConeWide(const Wide (&k)[4], const Wide (&mass)[4],
                        Wide current1, Wide current2, Wide bound, Wide v1, Wide v2, Wide& shift,
                        Wide& impulse1, Wide& impulse2)
{
    const Wide free1 = v1 - (k[0] * current1 + k[1] * current2);
    const Wide free2 = v2 - (k[2] * current1 + k[3] * current2);
    impulse1 = -(mass[0] * free1 + mass[1] * free2);
    impulse2 = -(mass[2] * free1 + mass[3] * free2);
    const Wide freeMagnitude = squareRoot(impulse1 * impulse1 + impulse2 * impulse2);
    const Mask outside = ~lessEqual(freeMagnitude, bound);
    const Mask negligible = outside & lessEqual(bound, splat(1e-15) * freeMagnitude);
    const Mask edge = outside & ~negligible;
    if (any(edge)) {
        Wide scaled1 = splat(0.0);
        Wide scaled2 = splat(0.0);
        Wide scaledMagnitude = splat(0.0);
        const Wide inverseBound = splat(1.0) / bound;
        Mask running = edge;
        for (int iteration = 0; iteration < 50 && any(running); ++iteration) {
            const Wide a = k[0] + shift;
            const Wide d = k[3] + shift;
            const Wide determinant = a * d - k[1] * k[1];
            const Wide next1 = d * free1 - k[1] * free2;
            const Wide next2 = a * free2 - k[1] * free1;
            const Wide nextMagnitude = squareRoot(next1 * next1 + next2 * next2);
            scaled1 = select(running, next1, scaled1);
            scaled2 = select(running, next2, scaled2);
            scaledMagnitude = select(running, nextMagnitude, scaledMagnitude);
            const Wide boundTimesDeterminant = bound * determinant;
            const Mask converged = lessEqual(absolute(nextMagnitude - boundTimesDeterminant),
                                             splat(1e-15) * boundTimesDeterminant);
            running = running & ~converged;
            const Wide quadratic = d * next1 * next1 - splat(2.0) * k[1] * next1 * next2 +
                                   a * next2 * next2;
            const Wide stepped = maximum(
                splat(0.0), shift - nextMagnitude * nextMagnitude *
                                        (determinant - nextMagnitude * inverseBound) / quadratic);
            shift = select(running, stepped, shift);
        }
        const Wide scale = -bound / scaledMagnitude;
        impulse1 = select(edge, scale * scaled1, impulse1);
        impulse2 = select(edge, scale * scaled2, impulse2);
    }
    impulse1 = select(negligible, splat(0.0), impulse1);
    impulse2 = select(negligible, splat(0.0), impulse2);
}

} // namespace tumble::lanes
