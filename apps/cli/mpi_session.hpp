// MpiSession: the processes `mpirun -n P tumble throw` starts, as ranks that split the throws.
// Without MPI (not built, or not started by mpirun) it is one rank of one.
#pragma once

#include "tumble/scenario/throw.hpp"
#include "tumble/scenario/throw_dice.hpp"

#include <cstddef>

#include <cstdint>
#include <span>

namespace tumble::cli {

/// Initialises MPI when tumble was built with it and started by an MPI launcher, and finalises
/// it on destruction; otherwise a single rank. Only rank 0 prints and writes files.
class MpiSession {
public:
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    [[nodiscard]] int rank() const { return m_rank; }
    [[nodiscard]] int size() const { return m_size; }
    [[nodiscard]] bool isRoot() const { return m_rank == 0; }

    /// Throws [begin, end) of `count` that this rank runs: contiguous blocks, rank r from
    /// count r / P to count (r + 1) / P.
    [[nodiscard]] std::int64_t blockBegin(std::int64_t count) const;
    [[nodiscard]] std::int64_t blockEnd(std::int64_t count) const;

    /// Sums `counts` over the ranks into rank 0's `counts` (MPI_Reduce); others keep theirs.
    void sumToRoot(std::span<std::int64_t> counts) const;
    /// Gathers every rank's block of outcomes, in rank order, into `all` on rank 0 (all.size()
    /// is the total there; ignored elsewhere).
    void gatherToRoot(std::span<const scenario::ThrowOutcome> block,
                      std::span<scenario::ThrowOutcome> all, std::int64_t count) const;
    /// The same for throws of `dice` dice each (block and all hold dice outcomes per throw).
    void gatherToRoot(std::span<const scenario::DieOutcome> block,
                      std::span<scenario::DieOutcome> all, std::int64_t count,
                      std::size_t dice) const;
    /// Whether every rank reports `ok` (a logical AND across ranks).
    [[nodiscard]] bool allOk(bool ok) const;

    /// "MPI" when built with it, or why not.
    [[nodiscard]] static const char* buildDescription();

private:
    void gatherBytesToRoot(std::span<const std::byte> block, std::span<std::byte> all,
                           std::int64_t count, std::size_t bytesPerThrow) const;

    int m_rank = 0;
    int m_size = 1;
    bool m_initialised = false;
};

} // namespace tumble::cli
