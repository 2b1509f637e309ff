// Checkpoints refuse what they did not write whole: a CRC-32 over the content catches a flipped bit or a
// truncation before anything is read (exit 2 at the command line), and no length read from a file may ask
// for more than the file holds.
#include "core/checkpoint.hpp"
#include "core/errors.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <zlib.h>

namespace fs = std::filesystem;
using softgrain::Archive;
using softgrain::Checkpoints;
using softgrain::InputError;

namespace {

struct State
{
    std::vector<double> positions;
    std::string label;
    void transfer(Archive& archive)
    {
        archive(positions);
        archive(label);
    }
};

fs::path checkpoint_file()
{
    return fs::temp_directory_path() / ("softgrain-checkpoint-" + std::to_string(getpid()) + ".checkpoint");
}

Checkpoints checkpoints(bool resume)
{
    return Checkpoints(checkpoint_file(), 0.0, resume, "test.scene", "{\"n\":3}", "test-version");
}

std::string read_bytes(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The CRC-32 trailer for `content`, as the writer appends it, so that a crafted file passes the checksum.
std::string with_checksum(const std::string& content)
{
    const auto crc = static_cast<std::uint32_t>(
        crc32_z(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(content.data()), content.size()));
    return content + std::string(reinterpret_cast<const char*>(&crc), sizeof crc);
}

} // namespace

TEST_CASE("a checkpoint resumes exactly what was saved")
{
    State saved{{1.0, -2.5, 3.25e-300}, "ring 7"};
    checkpoints(false).save([&](Archive& a) { saved.transfer(a); });
    State restored;
    CHECK(checkpoints(true).resume([&](Archive& a) { restored.transfer(a); }));
    CHECK(restored.positions == saved.positions);
    CHECK(restored.label == saved.label);
    fs::remove(checkpoint_file());
}

TEST_CASE("a checkpoint with any one byte changed, or truncated, is refused before it is read")
{
    State saved{std::vector<double>(64, 0.5), "packing"};
    checkpoints(false).save([&](Archive& a) { saved.transfer(a); });
    const std::string good = read_bytes(checkpoint_file());
    int refused = 0;
    for (std::size_t at = 0; at < good.size(); ++at) { // every byte, the checksum's own included
        std::string damaged = good;
        damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
        write_bytes(checkpoint_file(), damaged);
        State restored;
        try {
            checkpoints(true).resume([&](Archive& a) { restored.transfer(a); });
        } catch (const InputError&) {
            ++refused;
        }
    }
    CHECK(refused == static_cast<int>(good.size()));
    write_bytes(checkpoint_file(), good.substr(0, good.size() / 2));
    State restored;
    CHECK_THROWS_AS(checkpoints(true).resume([&](Archive& a) { restored.transfer(a); }), InputError);
    fs::remove(checkpoint_file());
}

TEST_CASE("a length larger than the rest of the file is refused, not allocated, even with a valid checksum")
{
    State saved{{1.0, 2.0}, "x"};
    checkpoints(false).save([&](Archive& a) { saved.transfer(a); });
    std::string content = read_bytes(checkpoint_file());
    content.resize(content.size() - 4); // drop the checksum
    // The vector's element count follows the four identity strings; find it by its value, 2, and make it
    // 2^40 elements (8 TiB of doubles).
    const std::uint64_t two = 2, huge = std::uint64_t{1} << 40;
    const auto at = content.find(std::string(reinterpret_cast<const char*>(&two), sizeof two));
    REQUIRE(at != std::string::npos);
    content.replace(at, sizeof huge, std::string(reinterpret_cast<const char*>(&huge), sizeof huge));
    write_bytes(checkpoint_file(), with_checksum(content));
    State restored;
    try {
        checkpoints(true).resume([&](Archive& a) { restored.transfer(a); });
        FAIL("a corrupt length was read");
    } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("corrupt") != std::string::npos);
    }
    fs::remove(checkpoint_file());
}
