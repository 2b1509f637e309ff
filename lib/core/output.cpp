#include "core/output.hpp"

#include "core/errors.hpp"
#include "core/leftovers.hpp"

#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

#ifndef SOFTGRAIN_VERSION
#error "SOFTGRAIN_VERSION must be defined by the build"
#endif

namespace softgrain {

namespace fs = std::filesystem;

std::string software_version()
{
    return SOFTGRAIN_VERSION;
}

nlohmann::json value_or_null(std::optional<double> value)
{
    return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json finite_or_null(double value)
{
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

namespace {

double peak_memory_mib()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0; // Linux reports KiB
}

// JSON has no NaN or infinity, and nlohmann::json writes both as null, which summary.json keeps for "not
// applicable" (a quantity this run does not have). A number that was computed and is not finite (a failed
// fit, 0/0, a blow-up) is spelled as the string "nan", "inf" or "-inf" instead, so the two never mix.
void spell_non_finite_numbers(nlohmann::json& value)
{
    if (value.is_number_float()) {
        const double x = value.get<double>();
        if (std::isnan(x))
            value = "nan";
        else if (std::isinf(x))
            value = x > 0 ? "inf" : "-inf";
    } else if (value.is_structured()) {
        for (auto& item : value)
            spell_non_finite_numbers(item);
    }
}

std::string format_duration(double seconds)
{
    std::ostringstream out;
    const auto s = static_cast<long long>(seconds + 0.5);
    if (s >= 3600)
        out << s / 3600 << "h" << std::setw(2) << std::setfill('0') << (s % 3600) / 60 << "m";
    else if (s >= 60)
        out << s / 60 << "m" << std::setw(2) << std::setfill('0') << s % 60 << "s";
    else
        out << s << "s";
    return out.str();
}

// Partial or set-aside directories of runs into `out_dir` whose process is gone (killed with SIGKILL, or a
// machine that went down): `.<name>.partial-<pid>` and `.<name>.replaced-<pid>`. Those of live processes
// are other runs' and stay.
void remove_stale_partial_directories(const fs::path& out_dir)
{
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(out_dir, error)) {
        const std::string name = entry.path().filename().string();
        for (const std::string marker : {".partial-", ".replaced-"}) {
            const auto at = name.rfind(marker);
            if (name.front() != '.' || at == std::string::npos) continue;
            const std::string pid_text = name.substr(at + marker.size());
            if (pid_text.empty() || pid_text.find_first_not_of("0123456789") != std::string::npos) continue;
            const long pid = std::stol(pid_text);
            if (pid != getpid() && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
                fs::remove_all(entry.path(), error);
        }
    }
}

// A directory that a completed softgrain run wrote: the only thing a new run may replace.
bool is_softgrain_result(const fs::path& dir)
{
    return fs::is_directory(dir) && fs::is_regular_file(dir / "summary.json");
}

// A run never deletes what it did not create: a plain file, or a directory that holds no summary.json.
void refuse_to_replace_foreign(const fs::path& final_dir)
{
    if (fs::exists(fs::symlink_status(final_dir)) && !is_softgrain_result(final_dir))
        throw IoError(final_dir.string() +
                      " exists and is not the result of a softgrain run (no summary.json in it): refusing to "
                      "replace it; choose another --out or move it away");
}

// Moves the completed partial directory into place. Runs that finish into the same place at once each move
// what stands there aside (under a name of their own) and try again: the last complete result wins.
void move_into_place(const fs::path& partial, const fs::path& final_dir)
{
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict, its bug 105329) on "." + a string + ...
    std::string aside_name = ".";
    aside_name += final_dir.filename().string();
    aside_name += ".replaced-";
    aside_name += std::to_string(getpid());
    const fs::path aside = final_dir.parent_path() / aside_name;
    for (int attempt = 0; attempt < 100; ++attempt) {
        std::error_code error;
        fs::rename(partial, final_dir, error);
        if (!error) {
            fs::remove_all(aside, error);
            return;
        }
        if (error != std::errc::directory_not_empty && error != std::errc::file_exists)
            throw fs::filesystem_error("moving the result into place", partial, final_dir, error);
        refuse_to_replace_foreign(final_dir);
        fs::remove_all(aside);
        fs::rename(final_dir, aside, error); // fails when another run moved it first: then just try again
    }
    throw IoError("could not move " + partial.string() + " to " + final_dir.string() +
                  ": other runs kept replacing it");
}

// DIR/.<scene>.vtk-frames: where a run with checkpoints keeps its VTK frames until it completes. Appended
// piece by piece (GCC 12's false -Wrestrict, as in move_into_place).
fs::path vtk_frames_directory(const fs::path& final_dir)
{
    std::string name = ".";
    name += final_dir.filename().string();
    name += ".vtk-frames";
    return final_dir.parent_path() / name;
}

} // namespace

Table::Table(const fs::path& path, const std::vector<Column>& columns, const std::string& preamble)
    : path_(path), stream_(path), width_(columns.size())
{
    if (!stream_) throw IoError("cannot write " + path.string() + ": " + std::strerror(errno));
    stream_ << preamble;
    for (const auto& c : columns)
        stream_ << "# column " << c.name << " [" << c.unit << "]: " << c.description << "\n";
    for (std::size_t i = 0; i < columns.size(); ++i)
        stream_ << (i ? " " : "") << columns[i].name;
    stream_ << "\n" << std::setprecision(12);
}

void Table::row(const std::vector<double>& values)
{
    if (values.size() != width_)
        throw std::logic_error("table row has " + std::to_string(values.size()) + " values for " +
                               std::to_string(width_) + " columns");
    if (!written_) return;
    for (std::size_t i = 0; i < values.size(); ++i)
        stream_ << (i ? " " : "") << values[i];
    stream_ << "\n";
}

void Table::close()
{
    if (!written_) return;
    stream_.close();
    if (stream_.fail()) throw IoError("writing " + path_.string() + " failed (disk full?)");
}

Progress::Progress(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled && isatty(fileno(stderr))),
      start_(std::chrono::steady_clock::now()), last_print_(start_)
{
}

void Progress::update(double fraction_done)
{
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_print_ < std::chrono::milliseconds(500)) return;
    last_print_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double remaining = fraction_done > 0 ? elapsed * (1.0 - fraction_done) / fraction_done : 0.0;
    std::cerr << "\r" << label_ << ": " << std::fixed << std::setprecision(1) << 100.0 * fraction_done
              << "%  elapsed " << format_duration(elapsed) << "  remaining ~" << format_duration(remaining)
              << "   " << std::flush;
    printed_ = true;
}

void Progress::finish()
{
    if (printed_) std::cerr << "\n";
    printed_ = false;
}

RunContext::RunContext(const fs::path& out_dir, std::string scene_name, const Parameters& parameters,
                       bool quiet, Output output)
    : final_dir_(out_dir / scene_name),
      partial_dir_(out_dir / ("." + scene_name + ".partial-" + std::to_string(getpid()))),
      scene_name_(std::move(scene_name)), parameters_json_(parameters.to_json()),
      quiet_(quiet || output == Output::discarded), output_(output), start_(std::chrono::steady_clock::now())
{
    if (output_ == Output::discarded) return;
    refuse_to_replace_foreign(final_dir_); // before the run, not after hours of it
    remove_stale_partial_directories(out_dir);
    fs::remove_all(partial_dir_); // a leftover of an earlier process with this pid
    fs::create_directories(partial_dir_);
    remove_on_signal(partial_dir_);
    std::ostringstream preamble;
    preamble << "# generator: softgrain " << software_version() << "\n"
             << "# scene: " << scene_name_ << "\n"
             << "# parameters: " << parameters_json_.dump() << "\n";
    preamble_ = preamble.str();
}

RunContext::~RunContext()
{
    if (output_ == Output::discarded) return;
    keep_on_signal(partial_dir_);
    if (!vtk_frames_dir_.empty()) keep_on_signal(vtk_frames_dir_);
    if (committed_) return;
    std::error_code ignored;
    tables_.clear();
    fs::remove_all(partial_dir_, ignored);
    // Frames beside a checkpoint stay for --resume; without one they have nothing to continue.
    if (!vtk_frames_dir_.empty() && !(checkpoints_ && fs::exists(checkpoints_->file())))
        fs::remove_all(vtk_frames_dir_, ignored);
}

void RunContext::enable_vtk(std::optional<std::int64_t> every)
{
    if (output_ == Output::discarded) return; // vtk() stays nullptr: no frames
    const std::string name = final_dir_.filename().string();
    if (!checkpoints_) {
        vtk_ = std::make_unique<vtk::Series>(partial_dir_ / "vtk", name, every);
        return;
    }
    // The frames directory is this run's: it holds the checkpoint's lock. Frames of an earlier run that
    // left no checkpoint to resume are removed; those of a resumed one are trimmed to the checkpoint's.
    vtk_frames_dir_ = vtk_frames_directory(final_dir_);
    if (!checkpoints_->will_resume()) {
        fs::remove_all(vtk_frames_dir_);
        // Until a checkpoint records them, a signal leaves nothing for --resume to continue: the frames go.
        remove_on_signal(vtk_frames_dir_);
    }
    vtk_ = std::make_unique<vtk::Series>(vtk_frames_dir_, name, every);
    checkpoints_->attach(
        [this] {
            keep_on_signal(vtk_frames_dir_); // this checkpoint records them: they stay for --resume
            return vtk_->state();
        },
        [this](const std::string& state) { vtk_->restore(state); });
}

Table& RunContext::table(const std::string& file_name, const std::vector<Column>& columns)
{
    tables_.push_back(output_ == Output::discarded
                          ? std::make_unique<Table>(columns.size())
                          : std::make_unique<Table>(partial_dir_ / file_name, columns, preamble_));
    return *tables_.back();
}

fs::path RunContext::commit()
{
    if (output_ == Output::discarded) {
        committed_ = true;
        return final_dir_;
    }
    for (auto& table : tables_)
        table->close();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    summary_["scene"] = scene_name_;
    summary_["parameters"] = parameters_json_;
    summary_["software_version"] = software_version();
    summary_["wall_time_s"] = wall;
    summary_["steps"] = steps_;
    // A resumed run's wall time covers only this process, its steps the whole run: no honest ratio.
    const bool resumed = checkpoints_ && checkpoints_->resumed();
    summary_["time_per_step_s"] =
        steps_ > 0 && !resumed ? nlohmann::json(wall / static_cast<double>(steps_)) : nlohmann::json();
    summary_["peak_memory_mib"] = peak_memory_mib();
    if (vtk_) {
        summary_["vtk_frames"] = vtk_->frames();
        summary_["vtk_bytes"] = vtk_->bytes();
        summary_["vtk_write_time_s"] = vtk_->write_seconds();
        if (!vtk_frames_dir_.empty()) fs::rename(vtk_frames_dir_, partial_dir_ / "vtk");
    } else if (checkpoints_) {
        // Frames of a checkpoint resumed without --vtk: this result has no series to continue them.
        std::error_code ignored;
        fs::remove_all(vtk_frames_directory(final_dir_), ignored);
    }
    if (checkpoints_) {
        summary_["checkpoints_written"] = checkpoints_->saved();
        summary_["resumed_from_checkpoint"] = checkpoints_->resumed();
    }
    {
        spell_non_finite_numbers(summary_);
        std::ofstream out(partial_dir_ / "summary.json");
        out << summary_.dump(2) << "\n";
        out.close();
        if (out.fail())
            throw IoError("writing " + (partial_dir_ / "summary.json").string() + " failed (disk full?)");
    }
    move_into_place(partial_dir_, final_dir_);
    committed_ = true;
    if (checkpoints_) checkpoints_->discard();
    return final_dir_;
}

} // namespace softgrain
