// MpiSession: the processes `mpirun -n P tumble throw` starts, as ranks that split the throws.
#include "mpi_session.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#if TUMBLE_HAS_MPI
#include <mpi.h>
#endif

namespace tumble::cli {
namespace {

/// Whether an MPI launcher started this process (Open MPI, MPICH/PMI, PMIx). MPI is not
/// initialised otherwise: a plain `tumble throw` should not start Open MPI's singleton runtime.
[[maybe_unused]] bool launchedByMpi()
{
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
        if (std::getenv(variable) != nullptr) {
            return true;
        }
    }
    return false;
}

} // namespace

MpiSession::MpiSession()
{
#if TUMBLE_HAS_MPI
    if (!launchedByMpi()) {
        return;
    }
    MPI_Init(nullptr, nullptr);
    m_initialised = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &m_size);
#endif
}

MpiSession::~MpiSession()
{
#if TUMBLE_HAS_MPI
    if (m_initialised) {
        MPI_Finalize();
    }
#endif
}

std::int64_t MpiSession::blockBegin(std::int64_t count) const { return count * m_rank / m_size; }

std::int64_t MpiSession::blockEnd(std::int64_t count) const
{
    return count * (m_rank + 1) / m_size;
}

void MpiSession::sumToRoot(std::span<std::int64_t> counts) const
{
#if TUMBLE_HAS_MPI
    if (m_initialised) {
        std::vector<std::int64_t> total(counts.size(), 0);
        MPI_Reduce(counts.data(), total.data(), static_cast<int>(counts.size()), MPI_INT64_T,
                   MPI_SUM, 0, MPI_COMM_WORLD);
        if (isRoot()) {
            std::copy(total.begin(), total.end(), counts.begin());
        }
    }
#else
    (void)counts;
#endif
}

void MpiSession::gatherToRoot(std::span<const scenario::ThrowOutcome> block,
                              std::span<scenario::ThrowOutcome> all, std::int64_t count) const
{
    gatherBytesToRoot(std::as_bytes(block), std::as_writable_bytes(all), count,
                      sizeof(scenario::ThrowOutcome));
}

void MpiSession::gatherToRoot(std::span<const scenario::DieOutcome> block,
                              std::span<scenario::DieOutcome> all, std::int64_t count,
                              std::size_t dice) const
{
    gatherBytesToRoot(std::as_bytes(block), std::as_writable_bytes(all), count,
                      sizeof(scenario::DieOutcome) * dice);
}

void MpiSession::gatherBytesToRoot(std::span<const std::byte> block, std::span<std::byte> all,
                                   std::int64_t count, std::size_t bytesPerThrow) const
{
#if TUMBLE_HAS_MPI
    if (m_initialised) {
        // outcomes travel as bytes: every rank runs the same program on the same machine type
        const auto bytes = static_cast<std::int64_t>(bytesPerThrow);
        std::vector<int> sizes(static_cast<std::size_t>(m_size));
        std::vector<int> offsets(static_cast<std::size_t>(m_size));
        for (int r = 0; r < m_size; ++r) {
            const std::int64_t begin = count * r / m_size;
            const std::int64_t end = count * (r + 1) / m_size;
            sizes[static_cast<std::size_t>(r)] = static_cast<int>((end - begin) * bytes);
            offsets[static_cast<std::size_t>(r)] = static_cast<int>(begin * bytes);
        }
        MPI_Gatherv(block.data(), static_cast<int>(block.size()), MPI_BYTE, all.data(),
                    sizes.data(), offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
        return;
    }
#endif
    (void)count;
    (void)bytesPerThrow;
    std::copy(block.begin(), block.end(), all.begin());
}

bool MpiSession::allOk(bool ok) const
{
#if TUMBLE_HAS_MPI
    if (m_initialised) {
        int local = ok ? 1 : 0;
        int all = 0;
        MPI_Allreduce(&local, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
        return all == 1;
    }
#endif
    return ok;
}

const char* MpiSession::buildDescription()
{
#if TUMBLE_HAS_MPI
    return "MPI";
#else
    return "without MPI";
#endif
}

} // namespace tumble::cli
