#include "core/output.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
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

namespace {

double peak_memory_mib()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0; // Linux reports KiB
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

} // namespace

Table::Table(const fs::path& path, const std::vector<Column>& columns, const std::string& preamble)
    : stream_(path), width_(columns.size())
{
    if (!stream_) throw std::runtime_error("cannot write " + path.string());
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
    for (std::size_t i = 0; i < values.size(); ++i)
        stream_ << (i ? " " : "") << values[i];
    stream_ << "\n";
}

void Table::close()
{
    stream_.close();
    if (stream_.fail()) throw std::runtime_error("writing a table failed (disk full?)");
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
                       bool quiet)
    : final_dir_(out_dir / scene_name),
      partial_dir_(out_dir / ("." + scene_name + ".partial-" + std::to_string(getpid()))),
      scene_name_(std::move(scene_name)), parameters_json_(parameters.to_json()), quiet_(quiet),
      start_(std::chrono::steady_clock::now())
{
    fs::remove_all(partial_dir_);
    fs::create_directories(partial_dir_);
    std::ostringstream preamble;
    preamble << "# generator: softgrain " << software_version() << "\n"
             << "# scene: " << scene_name_ << "\n"
             << "# parameters: " << parameters_json_.dump() << "\n";
    preamble_ = preamble.str();
}

RunContext::~RunContext()
{
    if (committed_) return;
    std::error_code ignored;
    tables_.clear();
    fs::remove_all(partial_dir_, ignored);
}

Table& RunContext::table(const std::string& file_name, const std::vector<Column>& columns)
{
    tables_.push_back(std::make_unique<Table>(partial_dir_ / file_name, columns, preamble_));
    return *tables_.back();
}

fs::path RunContext::commit()
{
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
    if (checkpoints_) {
        summary_["checkpoints_written"] = checkpoints_->saved();
        summary_["resumed_from_checkpoint"] = checkpoints_->resumed();
    }
    {
        std::ofstream out(partial_dir_ / "summary.json");
        out << summary_.dump(2) << "\n";
        out.close();
        if (out.fail()) throw std::runtime_error("writing summary.json failed (disk full?)");
    }
    fs::remove_all(final_dir_);
    fs::rename(partial_dir_, final_dir_);
    committed_ = true;
    if (checkpoints_) checkpoints_->discard();
    return final_dir_;
}

} // namespace softgrain
