// Ensembles of independent members (packings, seeds) spread over the ranks of an MPI run (DESIGN.md,
// "Scaling out"). Under `mpirun -n R` (or `srun`) every rank runs the same scene; run_ensemble gives member k
// to rank k mod R (a static, deterministic assignment), runs each rank's members in parallel with OpenMP and
// hands every rank all members' results in member order. Member k depends on k alone (its seed comes from
// k), and the results travel losslessly (CBOR keeps every double's bits), so a scene computes the same
// summary and tables for every R, and the same as a run without MPI. Only the first rank writes anything
// (RunContext, the command line's messages).
//
// A failure on any rank reaches every rank: all of them end with the same error (of the lowest failing
// member, else of the lowest failing rank), its message and its exit code, and none waits for a partner
// that has stopped. Without MPI (built without it, or not started by a launcher) there is one rank.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace softgrain {

// The program's MPI session, in main only: MPI_Init when a launcher started the process (mpirun, srun; an
// environment variable of Open MPI, PMIx or PMI names its rank), MPI_Finalize when it ends. A process
// started without a launcher does not initialise MPI, so that it costs nothing (an Open MPI singleton takes
// 0.7-0.9 s to start here) and behaves as before MPI was added.
class ParallelSession
{
  public:
    ParallelSession(int& argc, char**& argv);
    ~ParallelSession();
    ParallelSession(const ParallelSession&) = delete;
    ParallelSession& operator=(const ParallelSession&) = delete;

  private:
    bool initialised_ = false;
};

int rank_count();  // R: 1 without MPI
int this_rank();   // 0 ... R - 1
bool first_rank(); // the rank that writes

// A failure as it reaches the user: the kind of exception (which sets the exit code) and its message.
struct Failure
{
    enum class Kind { input, numerical, io, out_of_memory, internal };
    Kind kind = Kind::internal;
    std::string what;
};
Failure failure_of(const std::exception_ptr& error);
int exit_code(const Failure& failure);            // 2 input, 3 numerical, 4 I/O or memory, 5 internal
std::string user_message(const Failure& failure); // the line the command line prints after "softgrain: "

// A failure that every rank of an MPI run throws, whichever rank it came from (with one rank the original
// exception is thrown instead).
struct AgreedFailure : std::runtime_error
{
    explicit AgreedFailure(Failure agreed) : std::runtime_error(agreed.what), failure(std::move(agreed)) {}
    Failure failure;
};

// Runs `body` on every rank and agrees on the outcome: when it fails on any rank, every rank throws that
// failure as an AgreedFailure. Holds the run of a scene; the ensembles inside it agree on their members'
// failures themselves.
void on_every_rank(const std::function<void()>& body);

namespace ensemble_detail {

// k = this_rank(), this_rank() + R, ... below count.
std::vector<int> members_of_this_rank(int count);

// This rank's members, encoded (CBOR), or the failure of its lowest failing member.
struct LocalMembers
{
    std::vector<std::vector<std::uint8_t>> encoded;
    std::exception_ptr failure;
    int failed_member = 0;
};

// Every member's encoding in member order, on every rank; throws the failure of the lowest failing member of
// any rank (or of a rank that failed outside its members) as an AgreedFailure on every rank.
std::vector<std::vector<std::uint8_t>> gather(int count, const LocalMembers& local);

} // namespace ensemble_detail

// member(k) for k = 0 ... count - 1 over the ranks (OpenMP, dynamic schedule, inside each rank), every
// rank receiving all results in order k. A Member converts to and from JSON (nlohmann's to_json/from_json).
// With one rank the first failure in member order is rethrown as it was thrown.
template <class Member>
std::vector<Member> run_ensemble(int count, const std::function<Member(int)>& member)
{
    const std::vector<int> mine = ensemble_detail::members_of_this_rank(count);
    const int local_count = static_cast<int>(mine.size());
    std::vector<Member> results(mine.size());
    std::vector<std::exception_ptr> errors(mine.size());
#pragma omp parallel for schedule(dynamic)
    for (int i = 0; i < local_count; ++i) {
        try {
            results[i] = member(mine[i]);
        } catch (...) {
            errors[i] = std::current_exception();
        }
    }
    const auto failed = std::find_if(errors.begin(), errors.end(), [](const auto& e) { return bool(e); });
    if (rank_count() == 1) {
        if (failed != errors.end()) std::rethrow_exception(*failed);
        return results;
    }
    ensemble_detail::LocalMembers local;
    if (failed != errors.end()) {
        local.failure = *failed;
        local.failed_member = mine[failed - errors.begin()];
    } else {
        for (const Member& result : results)
            local.encoded.push_back(nlohmann::json::to_cbor(nlohmann::json(result)));
    }
    std::vector<Member> members;
    members.reserve(static_cast<std::size_t>(count));
    for (const auto& bytes : ensemble_detail::gather(count, local))
        members.push_back(nlohmann::json::from_cbor(bytes).get<Member>());
    return members;
}

} // namespace softgrain
