#include "core/ensemble.hpp"

#include "core/errors.hpp"

#include <climits>
#include <cstdlib>
#include <filesystem>
#include <new>
#include <optional>
#include <stdexcept>
#include <utility>

#ifdef SOFTGRAIN_MPI
#include <mpi.h>
#endif

namespace softgrain {

namespace {

int rank_count_ = 1;
int this_rank_ = 0;

[[maybe_unused]] bool started_by_mpi_launcher()
{
    // Open MPI's mpirun, PMIx (mpirun, srun --mpi=pmix) and PMI (srun --mpi=pmi2, MPICH) name the rank.
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
        if (std::getenv(name)) return true;
    return false;
}

#ifdef SOFTGRAIN_MPI
// What a rank brings to an agreement: the index of its failed member, a failure outside any member (it
// sorts after every member) or none.
constexpr int no_failure = INT_MAX;
constexpr int failure_outside_members = INT_MAX - 1;

// Every rank calls this at the same point of its run, or at the point where it failed: the least (failure
// key, rank) wins, and its failure is sent to every rank.
std::optional<Failure> agree(int failure_key, const std::exception_ptr& error)
{
    struct
    {
        int key, rank;
    } mine{failure_key, this_rank_}, least{};
    MPI_Allreduce(&mine, &least, 1, MPI_2INT, MPI_MINLOC, MPI_COMM_WORLD);
    if (least.key == no_failure) return std::nullopt;
    Failure failure = least.rank == this_rank_ ? failure_of(error) : Failure{};
    int kind = static_cast<int>(failure.kind), length = static_cast<int>(failure.what.size());
    MPI_Bcast(&kind, 1, MPI_INT, least.rank, MPI_COMM_WORLD);
    MPI_Bcast(&length, 1, MPI_INT, least.rank, MPI_COMM_WORLD);
    failure.kind = static_cast<Failure::Kind>(kind);
    failure.what.resize(static_cast<std::size_t>(length));
    MPI_Bcast(failure.what.data(), length, MPI_CHAR, least.rank, MPI_COMM_WORLD);
    return failure;
}
#endif

} // namespace

ParallelSession::ParallelSession([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv)
{
#ifdef SOFTGRAIN_MPI
    if (!started_by_mpi_launcher()) return;
    // MPI is called from the main thread only, outside OpenMP's parallel regions.
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    initialised_ = true;
    MPI_Comm_size(MPI_COMM_WORLD, &rank_count_);
    MPI_Comm_rank(MPI_COMM_WORLD, &this_rank_);
#endif
}

ParallelSession::~ParallelSession()
{
#ifdef SOFTGRAIN_MPI
    if (initialised_) MPI_Finalize();
#endif
}

int rank_count()
{
    return rank_count_;
}
int this_rank()
{
    return this_rank_;
}
bool first_rank()
{
    return this_rank_ == 0;
}

Failure failure_of(const std::exception_ptr& error)
{
    using Kind = Failure::Kind;
    try {
        std::rethrow_exception(error);
    } catch (const AgreedFailure& e) {
        return e.failure;
    } catch (const InputError& e) {
        return {Kind::input, e.what()};
    } catch (const NumericalError& e) {
        return {Kind::numerical, e.what()};
    } catch (const IoError& e) {
        return {Kind::io, e.what()};
    } catch (const std::filesystem::filesystem_error& e) {
        return {Kind::io, e.what()};
    } catch (const std::bad_alloc& e) {
        return {Kind::out_of_memory, e.what()};
    } catch (const std::exception& e) {
        return {Kind::internal, e.what()};
    } catch (...) {
        return {Kind::internal, "an exception that is not a std::exception"};
    }
}

int exit_code(const Failure& failure)
{
    switch (failure.kind) {
    case Failure::Kind::input:
        return exit_bad_input;
    case Failure::Kind::numerical:
        return exit_numerical_failure;
    case Failure::Kind::io:
    case Failure::Kind::out_of_memory:
        return exit_io_failure;
    case Failure::Kind::internal:
        break;
    }
    return exit_internal_error;
}

std::string user_message(const Failure& failure)
{
    switch (failure.kind) {
    case Failure::Kind::input:
        return "bad input: " + failure.what;
    case Failure::Kind::numerical:
        return failure.what;
    case Failure::Kind::io:
        return "I/O failure: " + failure.what;
    case Failure::Kind::out_of_memory:
        return "out of memory: the run needs more memory than the machine gives it";
    case Failure::Kind::internal:
        break;
    }
    return "internal error (a defect of softgrain; please report it with the command line): " + failure.what;
}

void on_every_rank(const std::function<void()>& body)
{
    if (rank_count_ == 1) {
        body();
        return;
    }
#ifdef SOFTGRAIN_MPI
    std::exception_ptr error;
    try {
        body();
    } catch (const AgreedFailure&) {
        throw; // agreed inside an ensemble: every rank throws it now
    } catch (...) {
        error = std::current_exception();
    }
    if (auto failure = agree(error ? failure_outside_members : no_failure, error))
        throw AgreedFailure(std::move(*failure));
#endif
}

namespace ensemble_detail {

std::vector<int> members_of_this_rank(int count)
{
    std::vector<int> mine;
    for (int k = this_rank_; k < count; k += rank_count_)
        mine.push_back(k);
    return mine;
}

std::vector<std::vector<std::uint8_t>> gather([[maybe_unused]] int count,
                                              [[maybe_unused]] const LocalMembers& local)
{
#ifdef SOFTGRAIN_MPI
    if (auto failure = agree(local.failure ? local.failed_member : no_failure, local.failure))
        throw AgreedFailure(std::move(*failure));
    // Rank r holds members r, r + R, ...: first every member's length, then the bytes, rank by rank.
    const int ranks = rank_count_;
    std::vector<int> members_per_rank(ranks), first_member(ranks, 0);
    for (int r = 0; r < ranks; ++r) {
        members_per_rank[r] = r < count ? (count - r + ranks - 1) / ranks : 0;
        if (r > 0) first_member[r] = first_member[r - 1] + members_per_rank[r - 1];
    }
    std::vector<int> my_lengths;
    std::vector<std::uint8_t> my_bytes;
    for (const auto& encoded : local.encoded) {
        my_lengths.push_back(static_cast<int>(encoded.size()));
        my_bytes.insert(my_bytes.end(), encoded.begin(), encoded.end());
    }
    std::vector<int> lengths(static_cast<std::size_t>(count));
    MPI_Allgatherv(my_lengths.data(), static_cast<int>(my_lengths.size()), MPI_INT, lengths.data(),
                   members_per_rank.data(), first_member.data(), MPI_INT, MPI_COMM_WORLD);
    std::vector<int> bytes_per_rank(ranks, 0), first_byte(ranks, 0);
    for (int r = 0; r < ranks; ++r) {
        for (int i = 0; i < members_per_rank[r]; ++i)
            bytes_per_rank[r] += lengths[first_member[r] + i];
        if (r > 0) first_byte[r] = first_byte[r - 1] + bytes_per_rank[r - 1];
    }
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(first_byte.back() + bytes_per_rank.back()));
    MPI_Allgatherv(my_bytes.data(), static_cast<int>(my_bytes.size()), MPI_BYTE, bytes.data(),
                   bytes_per_rank.data(), first_byte.data(), MPI_BYTE, MPI_COMM_WORLD);
    std::vector<std::vector<std::uint8_t>> members(static_cast<std::size_t>(count));
    auto next = bytes.begin();
    for (int r = 0; r < ranks; ++r)
        for (int i = 0; i < members_per_rank[r]; ++i) {
            const int length = lengths[first_member[r] + i];
            members[r + i * ranks].assign(next, next + length);
            next += length;
        }
    return members;
#else
    throw std::logic_error("ensemble gather without MPI: one rank never gathers");
#endif
}

} // namespace ensemble_detail

} // namespace softgrain
