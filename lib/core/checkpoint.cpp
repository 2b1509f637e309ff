#include "core/checkpoint.hpp"

#include "core/errors.hpp"
#include "core/leftovers.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <zlib.h>

namespace softgrain {

namespace fs = std::filesystem;

namespace {
const std::string format_line = "softgrain checkpoint 2";
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
// CRC-32 (zlib) of a checkpoint's content: detects a flipped bit or a truncation before anything is read.
std::uint32_t crc32_of(const std::string& bytes)
{
    return static_cast<std::uint32_t>(
        crc32_z(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
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

std::uint64_t Archive::remaining() const
{
    const auto position = static_cast<std::uint64_t>(in_->tellg());
    return position <= size_ ? size_ - position : 0;
}

void Archive::check_length(std::uint64_t count, std::size_t element_size) const
{
    if (count > remaining() / element_size)
        throw_corrupt(std::to_string(count) + " elements of " + std::to_string(element_size) +
                      " bytes, with " + std::to_string(remaining()) + " bytes left");
}

void Archive::throw_corrupt(const std::string& what) const
{
    throw InputError("the checkpoint is corrupt (" + what + ")");
}

void Archive::operator()(std::string& text)
{
    std::uint64_t n = text.size();
    (*this)(n);
    if (loading()) {
        check_length(n, 1);
        text.resize(n);
    }
    bytes(text.data(), n);
}

Checkpoints::Checkpoints(fs::path file, double interval_seconds, bool resume, std::string scene,
                         std::string parameters, std::string version)
    : file_(std::move(file)), lock_file_(file_.string() + ".lock"), interval_(interval_seconds),
      resume_(resume), scene_(std::move(scene)), parameters_(std::move(parameters)),
      version_(std::move(version)), last_(std::chrono::steady_clock::now())
{
    fs::create_directories(file_.parent_path());
    if (!acquire_lock())
        throw InputError("the checkpoint " + file_.string() + " belongs to another run that is still going" +
                         "; allowed: another --out, or waiting for that run to end");
    if (!resume_ && fs::exists(file_)) {
        release_lock();
        throw InputError("the checkpoint " + file_.string() +
                         " of an earlier run is there, and this run would overwrite it; allowed: --resume to "
                         "continue that run, another --out, or removing the file");
    }
}

Checkpoints::~Checkpoints()
{
    release_lock();
}

// flock on DIR/<name>.checkpoint.lock. A run that releases the lock unlinks the file first, so a run that
// opened the old file just before may still win the lock on it, while a third run creates a new file under
// the name and locks that: two holders. The lock therefore counts only if the name still refers to the file
// that was locked (same device and inode); otherwise it is taken again on the new file.
bool Checkpoints::acquire_lock()
{
    for (;;) {
        const int descriptor = ::open(lock_file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (descriptor < 0)
            throw IoError("cannot create the checkpoint lock " + lock_file_.string() + ": " +
                          std::strerror(errno));
        if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0) {
            ::close(descriptor); // the lock file is the other run's: leave it
            return false;
        }
        struct stat held
        {
        }, named{};
        if (::fstat(descriptor, &held) == 0 && ::stat(lock_file_.c_str(), &named) == 0 &&
            held.st_dev == named.st_dev && held.st_ino == named.st_ino) {
            lock_descriptor_ = descriptor;
            remove_on_signal(lock_file_);
            return true;
        }
        ::close(descriptor);
    }
}

// The lock file goes first, then the lock: a run that opens the name afterwards creates a new file.
void Checkpoints::release_lock()
{
    if (lock_descriptor_ < 0) return;
    keep_on_signal(lock_file_);
    ::unlink(lock_file_.c_str());
    ::close(lock_descriptor_);
    lock_descriptor_ = -1;
}

bool Checkpoints::due() const
{
    if (!(interval_ > 0)) return false;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - last_).count() >= interval_;
}

void Checkpoints::save(const std::function<void(Archive&)>& state)
{
    const fs::path temporary = file_.string() + ".writing";
    const auto refuse = [&](const std::string& what) {
        std::error_code ignored;
        fs::remove(temporary, ignored); // a half-written checkpoint is never left behind
        keep_on_signal(temporary);
        throw IoError(what + " " + temporary.string() + ": " + std::strerror(errno));
    };
    std::ostringstream content(std::ios::binary);
    Archive archive(content);
    std::string format = format_line, scene = scene_, parameters = parameters_, version = version_,
                end = end_marker;
    archive(format);
    archive(scene);
    archive(parameters);
    archive(version);
    state(archive);
    std::string companion = companion_save_ ? companion_save_() : std::string();
    archive(companion);
    archive(end);
    const std::string bytes = content.str();
    const std::uint32_t checksum = crc32_of(bytes);
    remove_on_signal(temporary);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) refuse("cannot write the checkpoint");
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
        out.close();
        if (out.fail()) refuse("writing failed (disk full?): the checkpoint");
    }
    fs::rename(temporary, file_);
    keep_on_signal(temporary);
    last_ = std::chrono::steady_clock::now();
    ++saved_;
}

bool Checkpoints::resume(const std::function<void(Archive&)>& state)
{
    if (!resume_ || !fs::exists(file_)) return false;
    std::ifstream file(file_, std::ios::binary);
    if (!file) throw InputError("--resume: cannot read the checkpoint " + file_.string());
    std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    std::uint32_t checksum = 0;
    if (bytes.size() < sizeof checksum)
        throw InputError("--resume: the checkpoint " + file_.string() + " is truncated");
    std::memcpy(&checksum, bytes.data() + bytes.size() - sizeof checksum, sizeof checksum);
    bytes.resize(bytes.size() - sizeof checksum);
    if (checksum != crc32_of(bytes))
        throw InputError(
            "--resume: the checkpoint " + file_.string() +
            " is damaged (its CRC-32 does not match: a changed byte or a truncation); delete it to "
            "start afresh");
    std::istringstream in(bytes, std::ios::binary);
    Archive archive(in, bytes.size());
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
    std::string companion;
    archive(companion);
    archive(end);
    if (end != end_marker) throw InputError("--resume: the checkpoint " + file_.string() + " is incomplete");
    if (companion_restore_) companion_restore_(companion);
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
