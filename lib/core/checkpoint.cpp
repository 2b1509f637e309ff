#include "core/checkpoint.hpp"

#include "core/errors.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

namespace softgrain {

namespace fs = std::filesystem;

namespace {
const std::string format_line = "softgrain checkpoint 1";
const std::string end_marker = "end of checkpoint";

// "key = a in the checkpoint, b here" for the first parameter that differs between two JSON objects.
std::string first_difference(const std::string& saved, const std::string& current)
{
    const auto a = nlohmann::json::parse(saved, nullptr, false), b = nlohmann::json::parse(current);
    if (a.is_discarded()) return "unreadable parameters in the checkpoint";
    for (const auto& [key, value] : b.items())
        if (!a.contains(key) || a[key] != value)
            return "'" + key + "' = " + (a.contains(key) ? a[key].dump() : "(absent)") +
                   " in the checkpoint, " + value.dump() + " here";
    return "a parameter of the checkpoint is unknown to this run";
}
} // namespace

void Archive::bytes(void* data, std::size_t size)
{
    if (size == 0) return;
    if (out_) {
        out_->write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    } else {
        in_->read(static_cast<char*>(data), static_cast<std::streamsize>(size));
        if (!*in_) throw InputError("the checkpoint ends early (truncated or written by another version)");
    }
}

void Archive::operator()(std::string& text)
{
    std::uint64_t n = text.size();
    (*this)(n);
    if (loading()) {
        // A corrupt length would ask for an absurd allocation: strings of a checkpoint are short.
        if (n > (1u << 26))
            throw InputError("the checkpoint is corrupt (a text field of " + std::to_string(n) + " bytes)");
        text.resize(n);
    }
    bytes(text.data(), n);
}

Checkpoints::Checkpoints(fs::path file, double interval_seconds, bool resume, std::string scene,
                         std::string parameters, std::string version)
    : file_(std::move(file)), interval_(interval_seconds), resume_(resume), scene_(std::move(scene)),
      parameters_(std::move(parameters)), version_(std::move(version)),
      last_(std::chrono::steady_clock::now())
{
}

bool Checkpoints::due() const
{
    if (!(interval_ > 0)) return false;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - last_).count() >= interval_;
}

void Checkpoints::save(const std::function<void(Archive&)>& state)
{
    const fs::path temporary = file_.string() + ".writing";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error("cannot write the checkpoint " + temporary.string());
        Archive archive(out);
        std::string format = format_line, scene = scene_, parameters = parameters_, version = version_,
                    end = end_marker;
        archive(format);
        archive(scene);
        archive(parameters);
        archive(version);
        state(archive);
        archive(end);
        out.close();
        if (out.fail())
            throw std::runtime_error("writing the checkpoint " + temporary.string() + " failed (disk full?)");
    }
    fs::rename(temporary, file_);
    last_ = std::chrono::steady_clock::now();
    ++saved_;
}

bool Checkpoints::resume(const std::function<void(Archive&)>& state)
{
    if (!resume_ || !fs::exists(file_)) return false;
    std::ifstream in(file_, std::ios::binary);
    if (!in) throw InputError("--resume: cannot read the checkpoint " + file_.string());
    Archive archive(in);
    std::string format, scene, parameters, version, end;
    archive(format);
    if (format != format_line)
        throw InputError("--resume: " + file_.string() + " is not a softgrain checkpoint");
    archive(scene);
    archive(parameters);
    archive(version);
    const std::string allowed = "; allowed: the scene, parameters and software version of the checkpoint, or "
                                "delete " +
                                file_.string() + " to start afresh";
    if (scene != scene_)
        throw InputError("--resume: the checkpoint is of scene '" + scene + "', this run is '" + scene_ +
                         "'" + allowed);
    if (parameters != parameters_)
        throw InputError("--resume: the checkpoint was written with other parameters: " +
                         first_difference(parameters, parameters_) + allowed);
    if (version != version_)
        throw InputError("--resume: the checkpoint was written by softgrain " + version + ", this is " +
                         version_ + " (a state is only read by the binary that wrote it)" + allowed);
    state(archive);
    archive(end);
    if (end != end_marker) throw InputError("--resume: the checkpoint " + file_.string() + " is incomplete");
    last_ = std::chrono::steady_clock::now();
    resumed_ = true;
    return true;
}

void Checkpoints::discard()
{
    std::error_code ignored;
    fs::remove(file_, ignored);
}

} // namespace softgrain
