#include "core/advice.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace softgrain {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> words_of(const std::string& line)
{
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;)
        words.push_back(w);
    return words;
}

// strtod reads "nan" and "inf" as scripts/reproduce writes them (repr of a float).
double number_of(const std::string& word, const fs::path& file, int line)
{
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0')
        throw InputError("sweep table '" + file.string() + "', line " + std::to_string(line) + ": '" + word +
                         "' is not a number");
    return value;
}

std::size_t column_index(const std::vector<std::string>& names, const std::string& name, const fs::path& file)
{
    const auto at = std::find(names.begin(), names.end(), name);
    if (at == names.end())
        throw InputError(
            "sweep table '" + file.string() + "' has no column '" + name +
            "'; it is not the work-precision table of this scene (remake it with scripts/reproduce)");
    return static_cast<std::size_t>(at - names.begin());
}

std::string shown(double value)
{
    std::ostringstream out;
    out << value;
    return out.str();
}

std::string method_name(const SweepTable& table, double code, const std::optional<double>& variant,
                        const fs::path& file)
{
    const auto index = static_cast<long long>(code);
    if (!(code >= 0) || double(index) != code || index >= static_cast<long long>(table.methods.size()))
        throw InputError("sweep table '" + file.string() + "': " + table.method_column + " = " + shown(code) +
                         " is not a method code (0 .. " + std::to_string(table.methods.size() - 1) + ")");
    std::string name = table.methods[static_cast<std::size_t>(index)];
    if (variant && std::isfinite(*variant)) name += " (" + table.variant_column + " " + shown(*variant) + ")";
    return name;
}

bool within(const SweepRun& run, double tolerance)
{
    return std::isfinite(run.error) && std::isfinite(run.cost_s) && run.error <= tolerance;
}

} // namespace

std::vector<SweepRun> read_sweep(const fs::path& file, const SweepTable& table)
{
    std::ifstream in(file);
    if (!in) throw InputError("sweep table '" + file.string() + "' cannot be read");
    std::vector<std::string> names;
    std::vector<SweepRun> runs;
    int line_number = 0;
    for (std::string line; std::getline(in, line);) {
        ++line_number;
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> words = words_of(line);
        if (names.empty()) {
            names = words;
            continue;
        }
        if (words.size() != names.size())
            throw InputError("sweep table '" + file.string() + "', line " + std::to_string(line_number) +
                             ": " + std::to_string(words.size()) + " values for " +
                             std::to_string(names.size()) + " columns");
        const auto value = [&](const std::string& column) {
            return number_of(words[column_index(names, column, file)], file, line_number);
        };
        const double code = value(table.method_column);
        std::optional<double> variant;
        if (!table.variant_column.empty() && method_name(table, code, {}, file) == table.variant_method)
            variant = value(table.variant_column);
        runs.push_back({method_name(table, code, variant, file), value(table.resolution_column),
                        value(table.error_column), value(table.cost_column)});
    }
    if (runs.empty()) throw InputError("sweep table '" + file.string() + "' holds no runs");
    return runs;
}

std::string sweep_scale(const fs::path& file)
{
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    const std::string marker = ", scale ";
    const auto at = line.find(marker);
    return at == std::string::npos ? "" : line.substr(at + marker.size());
}

Advice advise(const std::vector<SweepRun>& runs, double tolerance)
{
    Advice advice;
    for (const SweepRun& run : runs) {
        auto entry = std::find_if(advice.methods.begin(), advice.methods.end(),
                                  [&](const Advice::PerMethod& m) { return m.run.method == run.method; });
        if (entry == advice.methods.end()) {
            advice.methods.push_back({run, within(run, tolerance)});
            continue;
        }
        const bool met = within(run, tolerance);
        const bool better =
            met ? !entry->met || run.cost_s < entry->run.cost_s
                : !entry->met && (!std::isfinite(entry->run.error) || run.error < entry->run.error);
        if (better) *entry = {run, met};
    }
    for (const Advice::PerMethod& m : advice.methods)
        if (m.met && (!advice.recommended || m.run.cost_s < advice.recommended->cost_s))
            advice.recommended = m.run;
    return advice;
}

fs::path locate_sweep(const SweepTable& table, const std::optional<fs::path>& given)
{
    if (given) {
        if (!fs::is_regular_file(*given))
            throw InputError("--sweep = '" + given->string() +
                             "': no such file; allowed: a work-precision table "
                             "written by scripts/reproduce (" +
                             table.paper + "/" + table.figure + ".dat)");
        return *given;
    }
    const fs::path name = fs::path(table.paper) / (table.figure + ".dat");
    for (const fs::path& place : {fs::path("figures") / name, fs::path("data") / name})
        if (fs::is_regular_file(place)) return place;
    throw InputError("no stored sweep: neither figures/" + name.string() + " nor data/" + name.string() +
                     " exists here; make one with `scripts/reproduce figure " + table.paper + "/" +
                     table.figure +
                     "` (or `make reproduce-figures`) in the checkout, or name a table with --sweep FILE");
}

} // namespace softgrain
