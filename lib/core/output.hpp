// What a run writes: `DIR/<scene>/summary.json` and self-describing `*.dat` tables.
//
// Everything is written into a hidden partial directory beside the target and moved into place by
// `commit()` only when the run has finished; a run that throws leaves nothing behind that looks complete.
//
// A table file starts with `#` lines (generator, version, scene, parameters, one line per column with
// its unit and meaning), then one plain line with the column names, then whitespace-separated rows.
// gnuplot reads it directly: `set datafile columnheaders; plot "f.dat" using "t":"x"`.
#pragma once

#include "core/checkpoint.hpp"
#include "core/parameters.hpp"
#include "core/vtk.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace softgrain {

// summary.json spells a quantity this run does not have ("not applicable": no flat contact yet, a fit with
// too few points, no failure before the end) as null; a computed value that is not finite is spelled "nan",
// "inf" or "-inf" when the summary is written (RunContext::commit), so the two never mix.
nlohmann::json value_or_null(std::optional<double> value);
// For the laws that mark "not applicable" with NaN: null for NaN (and infinities), the value otherwise.
nlohmann::json finite_or_null(double value);

// Wall-clock seconds since `start`: costs reported in summaries and benchmarks, never asserted.
inline double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string software_version();

struct Column
{
    std::string name;        // a gnuplot-friendly identifier, e.g. "dt_over_dtc"
    std::string unit;        // "1" for dimensionless
    std::string description; // meaning, with the paper's symbol or equation where there is one
};

class Table
{
  public:
    Table(const std::filesystem::path& path, const std::vector<Column>& columns, const std::string& preamble);
    // A table of a run that writes nothing (RunContext::Output::discarded): rows are checked and dropped.
    explicit Table(std::size_t width) : width_(width), written_(false) {}
    void row(const std::vector<double>& values); // one value per column, in order
    void close();

  private:
    std::filesystem::path path_;
    std::ofstream stream_;
    std::size_t width_;
    bool written_ = true;
};

// Progress on stderr (percent, elapsed, estimated remaining) for long runs; silent when quiet or when
// stderr is not a terminal. Prints at most twice a second.
class Progress
{
  public:
    Progress(std::string label, bool enabled);
    void update(double fraction_done);
    void finish();

  private:
    std::string label_;
    bool enabled_;
    std::chrono::steady_clock::time_point start_, last_print_;
    bool printed_ = false;
};

class RunContext
{
  public:
    // `discarded`: the run's results are computed but nothing is written or shown (no directory, tables,
    // summary, frames or progress): the MPI ranks other than the first (core/ensemble.hpp).
    enum class Output { written, discarded };
    RunContext(const std::filesystem::path& out_dir, std::string scene_name, const Parameters& parameters,
               bool quiet, Output output = Output::written);
    ~RunContext(); // removes the partial directory if the run did not commit

    RunContext(const RunContext&) = delete;
    RunContext& operator=(const RunContext&) = delete;

    // Scalar results of the run; summary()["key"] = value.
    nlohmann::json& summary() { return summary_; }
    Table& table(const std::string& file_name, const std::vector<Column>& columns);
    Progress progress(const std::string& label) const { return Progress(label, !quiet_); }

    // Checkpoints of a scene that writes them (Scene::checkpoints), else nullptr. A committed run removes
    // its checkpoint.
    void enable_checkpoints(std::unique_ptr<Checkpoints> checkpoints)
    {
        checkpoints_ = std::move(checkpoints);
    }
    Checkpoints* checkpoints() { return checkpoints_.get(); }

    // The ParaView time series of `run --vtk` (core/vtk.hpp), after enable_checkpoints: frames go to
    // DIR/<scene>/vtk/ with the result. With checkpoints they are written into DIR/.<scene>.vtk-frames/
    // beside the checkpoint instead, kept there when the run stops (a resumed run continues them; each
    // checkpoint records the frames so far) and moved into the result when it completes.
    void enable_vtk(std::optional<std::int64_t> every);
    // The series, or nullptr without --vtk: scenes write frames where their state is complete.
    vtk::Series* vtk() { return vtk_.get(); }

    // Time steps (or minimiser iterations) taken; with the wall time they give the cost per step.
    void count_steps(std::int64_t steps) { steps_ += steps; }
    void record_seed(std::uint64_t seed) { summary_["seed"] = seed; }

    // Finishes the summary (parameters, version, wall time, time per step, peak memory), closes the
    // tables and moves the directory into place. Returns the final directory (not made when discarded).
    std::filesystem::path commit();

  private:
    std::filesystem::path final_dir_, partial_dir_;
    std::string scene_name_;
    nlohmann::json parameters_json_;
    std::string preamble_;
    bool quiet_;
    Output output_;
    bool committed_ = false;
    nlohmann::json summary_ = nlohmann::json::object();
    std::vector<std::unique_ptr<Table>> tables_;
    std::int64_t steps_ = 0;
    std::chrono::steady_clock::time_point start_;
    std::unique_ptr<Checkpoints> checkpoints_;
    std::unique_ptr<vtk::Series> vtk_;
    std::filesystem::path vtk_frames_dir_; // DIR/.<scene>.vtk-frames: the frames of a run with checkpoints
};

} // namespace softgrain
