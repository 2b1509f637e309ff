// Ensembles (core/ensemble.hpp) in one process, as the verification binary runs (no MPI launcher): every
// member in order k, the first failure in member order, failures mapped to the command line's exit codes,
// and a context that discards its output writing nothing (the MPI ranks other than the first). Several
// ranks are tested through the program itself: verification/dpm/protocols/ensemble_mpi.py.
#include "core/ensemble.hpp"
#include "core/errors.hpp"
#include "core/output.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <new>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

TEST_CASE("run_ensemble without MPI: one rank, every member in order k, the lowest failing member rethrown")
{
    REQUIRE(softgrain::rank_count() == 1);
    CHECK(softgrain::first_rank());
    const std::vector<int> squares = softgrain::run_ensemble<int>(7, [](int k) { return k * k; });
    CHECK(squares == std::vector<int>{0, 1, 4, 9, 16, 25, 36});
    // Members 3 and 5 fail (in whatever order the threads reach them): member 3's error is the run's, as in
    // a run over any number of ranks.
    const auto failing = [](int k) {
        if (k == 3 || k == 5) throw softgrain::InputError("member " + std::to_string(k));
        return k;
    };
    CHECK_THROWS_WITH_AS(softgrain::run_ensemble<int>(8, failing), "member 3", softgrain::InputError);
}

TEST_CASE("failures keep the command line's exit codes and messages (README, exit codes)")
{
    const auto failure = [](auto error) { return softgrain::failure_of(std::make_exception_ptr(error)); };
    const softgrain::Failure input = failure(softgrain::InputError("parameter 'x'"));
    CHECK(softgrain::exit_code(input) == softgrain::exit_bad_input);
    CHECK(softgrain::user_message(input) == "bad input: parameter 'x'");
    const softgrain::Failure numerical = failure(softgrain::NumericalError("energy", 7, "a step too large"));
    CHECK(softgrain::exit_code(numerical) == softgrain::exit_numerical_failure);
    CHECK(softgrain::user_message(numerical) ==
          "numerical failure: energy at step 7; likely cause: a step too large");
    CHECK(softgrain::exit_code(failure(softgrain::IoError("disk full"))) == softgrain::exit_io_failure);
    CHECK(softgrain::exit_code(failure(std::bad_alloc())) == softgrain::exit_io_failure);
    CHECK(softgrain::exit_code(failure(std::logic_error("defect"))) == softgrain::exit_internal_error);
    // A failure agreed between ranks ends every rank as the original would.
    CHECK(softgrain::exit_code(failure(softgrain::AgreedFailure(numerical))) ==
          softgrain::exit_numerical_failure);
    CHECK(softgrain::user_message(failure(softgrain::AgreedFailure(numerical))) ==
          softgrain::user_message(numerical));
}

TEST_CASE("a context that discards its output writes nothing, checks its tables and commits")
{
    const fs::path dir = fs::temp_directory_path() / ("softgrain-ensemble-" + std::to_string(getpid()));
    softgrain::Parameters parameters({softgrain::ParameterSpec::real("x", 1.0, "1", "unused")});
    {
        softgrain::RunContext context(dir, "discarded", parameters, false,
                                      softgrain::RunContext::Output::discarded);
        auto& table = context.table("t.dat", {{"a", "1", "a"}, {"b", "1", "b"}});
        table.row({1.0, 2.0});
        CHECK_THROWS_AS(table.row({1.0}), std::logic_error); // the same check as a written table's
        context.summary()["value"] = 1.0;
        CHECK(context.vtk() == nullptr);
        context.enable_vtk(std::nullopt);
        CHECK(context.vtk() == nullptr);
        context.commit();
    }
    CHECK_FALSE(fs::exists(dir));
}
