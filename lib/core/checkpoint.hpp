// Checkpoints of long runs: the complete state of a run in a binary file, so that `softgrain run ...
// --resume` continues from it bit-for-bit (the same binary and thread count give the same tables as an
// uninterrupted run).
//
// A state is listed once, in a `transfer(Archive&)` member (or a free `transfer(Archive&, T&)` found by
// argument-dependent lookup) that names each member: the same function writes and reads it, so the two
// directions cannot drift apart. Trivially copyable values (numbers, enums, structs of numbers) are copied as
// bytes, Eigen matrices as their sizes and coefficients, containers element by element.
//
// File: the line "softgrain checkpoint 2", then the scene name, the parameters (JSON), the software
// version, the scene's state, the companion state (Checkpoints::attach), an end marker, and the CRC-32 (zlib)
// of all that. It is written to a temporary file and renamed into place, so a run killed while writing leaves
// the previous checkpoint intact. A checkpoint whose checksum does not match (a flipped bit, a truncation) is
// refused before any of it is read, and every length read from it is bounded by the bytes that remain.
#pragma once

#include <Eigen/Core>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace softgrain {

class Archive;

template <class T>
concept MemberTransfer = requires(T& value, Archive& archive)
{
    value.transfer(archive);
};
template <class T>
concept FreeTransfer = requires(T& value, Archive& archive)
{
    transfer(archive, value);
};

class Archive
{
  public:
    explicit Archive(std::ostream& out) : out_(&out) {}
    // Reads `size` bytes from `in`: no length read from them may ask for more than remains.
    Archive(std::istream& in, std::uint64_t size) : in_(&in), size_(size) {}

    bool loading() const { return in_ != nullptr; }

    template <class T>
    void operator()(T& value)
    {
        if constexpr (MemberTransfer<T>)
            value.transfer(*this);
        else if constexpr (FreeTransfer<T>)
            transfer(*this, value);
        else {
            static_assert(std::is_trivially_copyable_v<T>, "give this type a transfer(Archive&)");
            bytes(&value, sizeof(T));
        }
    }
    void operator()(std::string& text);
    template <class A, class B>
    void operator()(std::pair<A, B>& pair)
    {
        (*this)(pair.first);
        (*this)(pair.second);
    }
    template <class T>
    void operator()(std::vector<T>& items)
    {
        std::uint64_t n = items.size();
        (*this)(n);
        if (loading()) {
            check_length(n, std::is_trivially_copyable_v<T> ? sizeof(T) : 1);
            items.resize(n);
        }
        if constexpr (std::is_trivially_copyable_v<T>)
            bytes(items.data(), n * sizeof(T));
        else
            for (T& item : items)
                (*this)(item);
    }
    template <class T>
    void operator()(std::optional<T>& maybe)
    {
        bool present = maybe.has_value();
        (*this)(present);
        if (loading()) {
            if (present)
                maybe.emplace();
            else
                maybe.reset();
        }
        if (present) (*this)(*maybe);
    }
    template <class Scalar, int Rows, int Cols, int Options, int MaxRows, int MaxCols>
    void operator()(Eigen::Matrix<Scalar, Rows, Cols, Options, MaxRows, MaxCols>& matrix)
    {
        std::int64_t rows = matrix.rows(), cols = matrix.cols();
        (*this)(rows);
        (*this)(cols);
        if (loading()) {
            if (rows < 0 || cols < 0 ||
                (cols > 0 &&
                 static_cast<std::uint64_t>(rows) > remaining() / static_cast<std::uint64_t>(cols)))
                throw_corrupt("a matrix of " + std::to_string(rows) + " x " + std::to_string(cols));
            check_length(static_cast<std::uint64_t>(rows * cols), sizeof(Scalar));
            matrix.resize(rows, cols);
        }
        bytes(matrix.data(), static_cast<std::size_t>(rows * cols) * sizeof(Scalar));
    }

    // Writes `value` through its transfer function (which takes a non-const reference so that one function
    // serves both directions; writing does not modify it).
    template <class T>
    void save(const T& value)
    {
        (*this)(const_cast<T&>(value));
    }

  private:
    void bytes(void* data, std::size_t size);
    std::uint64_t remaining() const;
    // Refuses a count of elements of `element_size` bytes that the rest of the file cannot hold.
    void check_length(std::uint64_t count, std::size_t element_size) const;
    [[noreturn]] void throw_corrupt(const std::string& what) const;
    std::ostream* out_ = nullptr;
    std::istream* in_ = nullptr;
    std::uint64_t size_ = 0;
};

// Where a run keeps its checkpoint and how often it writes one. Scenes that support checkpoints (Scene::
// checkpoints) call `due()` at points where their state is complete and then `save(...)`; at their start,
// `resume(...)` restores the last state if the run was asked to resume and a checkpoint exists.
class Checkpoints
{
  public:
    // file: the checkpoint's path; interval_seconds: wall time between checkpoints (0: never);
    // identity: scene name, parameters (JSON text) and software version, all of which must match to resume.
    // The file is held under an exclusive lock (file.lock) for the run's lifetime. Refused with InputError
    // (exit 2), so that a run never overwrites or deletes a checkpoint it did not write: a file that another
    // live run holds, and without `resume`, a checkpoint left by an earlier run.
    Checkpoints(std::filesystem::path file, double interval_seconds, bool resume, std::string scene,
                std::string parameters, std::string version);
    ~Checkpoints();
    Checkpoints(const Checkpoints&) = delete;
    Checkpoints& operator=(const Checkpoints&) = delete;

    // True once the interval has passed since the start or the last checkpoint.
    bool due() const;
    // Writes the state (atomically: temporary file, then rename).
    void save(const std::function<void(Archive&)>& state);
    // If resuming and a checkpoint exists: reads the state into the run and returns true. Throws
    // InputError (exit 2) when the checkpoint belongs to another scene, other parameters or another
    // version, or is incomplete.
    bool resume(const std::function<void(Archive&)>& state);
    // Removes the checkpoint (the run is complete).
    void discard();
    // A companion state saved after the scene's in every checkpoint and handed back on resume: the VTK
    // series' frames (core/vtk.hpp), so that a resumed run continues them. Absent: an empty one is saved.
    void attach(std::function<std::string()> save, std::function<void(const std::string&)> restore)
    {
        companion_save_ = std::move(save);
        companion_restore_ = std::move(restore);
    }
    // Whether this run continues from a checkpoint (asked to resume and the file exists).
    bool will_resume() const { return resume_ && std::filesystem::exists(file_); }
    const std::filesystem::path& file() const { return file_; }
    int saved() const { return saved_; }
    bool resumed() const { return resumed_; }

  private:
    bool acquire_lock(); // false: another live run holds the lock
    void release_lock();

    std::filesystem::path file_;
    std::filesystem::path lock_file_;
    int lock_descriptor_ = -1;
    double interval_;
    bool resume_;
    std::string scene_, parameters_, version_;
    mutable std::chrono::steady_clock::time_point last_;
    int saved_ = 0;
    bool resumed_ = false;
    std::function<std::string()> companion_save_;
    std::function<void(const std::string&)> companion_restore_;
};

} // namespace softgrain
